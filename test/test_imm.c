/* SPDX-License-Identifier: BSD-3-Clause */
/* test_imm.c - IMM arithmetic of one track (ALGORITHMS.md §14.1, §14.2):
 * mixing, mode-probability update, combination, the model-mixed likelihood
 * and the apportionment of an association result into per-model quantities.
 * Expected numbers: docs/TEST_VECTORS.md TV14, and the output of
 * `python3 tools/ci/imm_vectors.py` (sections "IMM mixing", "IMM-IPDA",
 * "IMM-IHPDA"), which derives them independently (numpy, the textbook
 * full-dimensional forms). */
#include <string.h>

#include "mtt_internal.h"
#include "tv_assert.h"
#include "tv_fixture.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

#if MTT_WITH_IMM

#define S MTT_MAX_STATE


static mtt_real g_Pi[MTT_MAX_MODELS][MTT_MAX_MODELS];
static mtt_real g_x[MTT_MAX_MODELS][S], g_P[MTT_MAX_MODELS][S][S];
static mtt_real g_x0[MTT_MAX_MODELS][S], g_P0[MTT_MAX_MODELS][S][S];
static mtt_real g_mix[MTT_MAX_MODELS][MTT_MAX_MODELS];

static void clear_all(void)
{
    memset(g_Pi, 0, sizeof g_Pi);
    memset(g_x, 0, sizeof g_x);
    memset(g_P, 0, sizeof g_P);
    memset(g_x0, 0, sizeof g_x0);
    memset(g_P0, 0, sizeof g_P0);
    memset(g_mix, 0, sizeof g_mix);
}

/* n x n block of a MTT_MAX_STATE-sized matrix against row-major doubles. */
static void assert_block(const double *expected, mtt_real M[S][S], int n, const char *what)
{
    int i, j;
    char w[64];
    for (i = 0; i < n; ++i) {
        for (j = 0; j < n; ++j) {
            snprintf(w, sizeof w, "%s[%d][%d]", what, i, j);
            TV_ASSERT_REAL_MSG(expected[n * i + j], M[i][j], w);
        }
    }
}

static void set_block(mtt_real M[S][S], const double *v, int n)
{
    int i, j;
    for (i = 0; i < n; ++i) {
        for (j = 0; j < n; ++j) {
            M[i][j] = (mtt_real)v[n * i + j];
        }
    }
}

/* Mixing weights of the 2-model cases against expected c̄ and μ_{i|j}
 * (row i, column j, row-major). */
static void check_mix_weights(const mtt_real mu[2], const double cbar_e[2], const double mix_e[4],
                              mtt_real cbar[2])
{
    int i, j;
    TEST_ASSERT_EQUAL_INT(0, mtt_imm_mix_weights(2, g_Pi, mu, cbar, g_mix));
    TV_ASSERT_VEC(cbar_e, cbar, 2);
    for (i = 0; i < 2; ++i) {
        for (j = 0; j < 2; ++j) {
            TV_ASSERT_REAL_MSG(mix_e[2 * i + j], g_mix[i][j], "mu_{i|j}");
        }
    }
}

/* ---- TV14 ---- */

static void tv14_inputs(mtt_real mu[2])
{
    static const double P1[16] = {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    static const double P2[16] = {4, 0, 0, 0, 0, 4, 0, 0, 0, 0, 3, 0, 0, 0, 0, 3};
    static const mtt_real x1[4] = {MTT_R(100.0), MTT_R(50.0), MTT_R(10.0), MTT_R(-5.0)};
    static const mtt_real x2[4] = {MTT_R(101.0), MTT_R(49.0), MTT_R(12.0), MTT_R(-4.0)};
    clear_all();
    g_Pi[0][0] = MTT_R(0.95); g_Pi[0][1] = MTT_R(0.05);
    g_Pi[1][0] = MTT_R(0.1);  g_Pi[1][1] = MTT_R(0.9);
    mu[0] = MTT_R(0.8);
    mu[1] = MTT_R(0.2);
    memcpy(g_x[0], x1, sizeof x1);
    memcpy(g_x[1], x2, sizeof x2);
    set_block(g_P[0], P1, 4);
    set_block(g_P[1], P2, 4);
}

static void test_tv14_mixing(void)
{
    static const double cbar_e[2] = {0.78, 0.22};
    static const double mix_e[4] = {0.9743589744, 0.1818181818, 0.02564102564, 0.8181818182};
    static const double x01[4] = {100.025641, 49.97435897, 10.05128205, -4.974358974};
    static const double P01[16] = {
        2.076265615,   -0.02498356345, 0.04996712689,  0.02498356345,
        -0.02498356345, 2.076265615,   -0.04996712689, -0.02498356345,
        0.04996712689, -0.04996712689, 1.151216305,    0.04996712689,
        0.02498356345, -0.02498356345, 0.04996712689,  1.076265615};
    static const double x02[4] = {100.8181818, 49.18181818, 11.63636364, -4.181818182};
    static const double P02[16] = {
        3.785123967,   -0.1487603306, 0.2975206612,  0.1487603306,
        -0.1487603306, 3.785123967,   -0.2975206612, -0.1487603306,
        0.2975206612,  -0.2975206612, 3.231404959,   0.2975206612,
        0.1487603306,  -0.1487603306, 0.2975206612,  2.785123967};
    static const uint8_t n[2] = {4, 4};
    mtt_real mu[2], cbar[2];
    tv14_inputs(mu);
    check_mix_weights(mu, cbar_e, mix_e, cbar);
    TEST_ASSERT_EQUAL_INT(0, mtt_imm_mix(2, n, g_mix, g_x, g_P, g_x0, g_P0));
    TV_ASSERT_VEC(x01, g_x0[0], 4);
    TV_ASSERT_MAT4(P01, g_P0[0]);
    TV_ASSERT_VEC(x02, g_x0[1], 4);
    TV_ASSERT_MAT4(P02, g_P0[1]);
    TV_ASSERT_SYM4(g_P0[0]);
    TV_ASSERT_SYM4(g_P0[1]);
}

static void test_tv14_combine(void)
{
    static const double mu_e[2] = {0.5416666667, 0.4583333333};
    static const double xc_e[4] = {100.4583333, 49.54166667, 10.91666667, -4.541666667};
    static const double Pc_e[16] = {
        3.164930556,   -0.2482638889, 0.4965277778,  0.2482638889,
        -0.2482638889, 3.164930556,   -0.4965277778, -0.2482638889,
        0.4965277778,  -0.4965277778, 2.909722222,   0.4965277778,
        0.2482638889,  -0.2482638889, 0.4965277778,  2.164930556};
    mtt_real mu[2], muk[2], xc[4], Pc[4][MTT_MAX_STATE];
    tv14_inputs(mu);
    /* TV14's mode update (mu_j = Lambda_j cbar_j / c, lam = {0.01, 0.03}),
     * then its combination example: the inputs as if they were the updates. */
    muk[0] = (mtt_real)mu_e[0];
    muk[1] = (mtt_real)mu_e[1];
    TEST_ASSERT_EQUAL_INT(0, mtt_imm_combine(2, muk, g_x, g_P, xc, Pc));
    TV_ASSERT_VEC(xc_e, xc, 4);
    TV_ASSERT_MAT4(Pc_e, Pc);
    TV_ASSERT_SYM4(Pc);
}

static void test_bad_arguments(void)
{
    static const uint8_t n_bad[2] = {4, MTT_MAX_STATE + 1};
    mtt_real mu[2], cbar[2], muk[2] = {MTT_R(-1.0), MTT_R(-1.0)};
    const mtt_real lam0[2] = {MTT_R(0.0), MTT_R(0.0)};
    tv14_inputs(mu);
    TEST_ASSERT_EQUAL_INT(-1, mtt_imm_mix_weights(0, g_Pi, mu, cbar, g_mix));
    TEST_ASSERT_EQUAL_INT(-1, mtt_imm_mix_weights(MTT_MAX_MODELS + 1, g_Pi, mu, cbar, g_mix));
    TEST_ASSERT_EQUAL_INT(0, mtt_imm_mix_weights(2, g_Pi, mu, cbar, g_mix));
    g_x0[0][0] = MTT_R(7.0);
    TEST_ASSERT_EQUAL_INT(-1, mtt_imm_mix(2, n_bad, g_mix, g_x, g_P, g_x0, g_P0));
    TEST_ASSERT_TRUE(g_x0[0][0] == MTT_R(7.0)); /* nothing written */
    /* r out of range: nothing read, PD* = p* = 0 */
    muk[0] = MTT_R(1.0);
    TV_ASSERT_REAL(0.0, mtt_imm_meas_mix(MTT_MAX_MODELS + 1, cbar, lam0, lam0, &muk[0]));
    TV_ASSERT_REAL(0.0, muk[0]);
}

/* ---- CV (4) and CA (6) mixed: tools/ci/imm_vectors.py "IMM mixing" ---- */

static void test_mix_cv_ca(void)
{
    static const double P_cv[16] = {30, 4, 6, 1, 4, 25, 1, 5, 6, 1, 9, 0.5, 1, 5, 0.5, 8};
    static const double P_ca[36] = {
        36, 3, 9, 1.2, 1.8, -0.6, 3, 25.25, 2.25, 5.6, -0.85, 1.95,
        9, 2.25, 18.34, 2.23, 5.19, 0.77, 1.2, 5.6, 2.23, 13.66, 0.67, 5.05,
        1.8, -0.85, 5.19, 0.67, 7.83, 1.76, -0.6, 1.95, 0.77, 5.05, 1.76, 7.1};
    static const double x_cv[4] = {1000, 2000, 150, -20};
    static const double x_ca[6] = {1003, 1996, 146, -12, 8, -15};
    static const double cbar_e[2] = {0.69, 0.31};
    static const double mix_e[4] = {0.9130434783, 0.2258064516, 0.08695652174, 0.7741935484};
    static const double x00[4] = {1000.26087, 1999.652174, 149.6521739, -19.30434783};
    static const double P00[16] = {
        31.2362949, 2.960302457, 5.308128544, 2.922873346, 2.960302457, 26.29206049,
        2.379017013, 2.511531191, 5.308128544, 2.379017013, 11.08249527, -1.89020794,
        2.922873346, 2.511531191, -1.89020794, 13.57345936};
    static const double x01[6] = {1002.322581, 1996.903226, 146.9032258, -13.80645161, 8, -15};
    static const double P01[36] = {
        36.21852237,   1.127991675,   6.224765869,   5.350468262,   1.393548387,   -0.464516129,
        1.127991675,   27.99063476,   4.764828304,   -0.1296566077, -0.6580645161, 1.509677419,
        6.224765869,   4.764828304,   19.02805411,   -3.754817898,  4.018064516,   0.5961290323,
        5.350468262,   -0.1296566077, -3.754817898,  23.57028096,   0.5187096774,  3.909677419,
        1.393548387,   -0.6580645161, 4.018064516,   0.5187096774,  7.83,          1.76,
        -0.464516129,  1.509677419,   0.5961290323,  3.909677419,   1.76,          7.1};
    static const double muk_e[2] = {0.3437110834, 0.6562889166};
    static const double xc_e[4] = {1001.968867, 1997.374844, 147.3748443, -14.74968867};
    static const double Pc_e[16] = {
        35.96789747, 0.6368257887, 5.261981455,  6.545028373, 0.6368257887, 28.77325262,
        5.429541539, -1.824587436, 5.261981455,  5.429541539, 18.73891887,  -5.58298096,
        6.545028373, -1.824587436, -5.58298096,  26.15131684};
    static const uint8_t n[2] = {4, 6};
    mtt_real mu[2] = {MTT_R(0.7), MTT_R(0.3)}, cbar[2], muk[2], xc[4], Pc[4][MTT_MAX_STATE];
    int i, j;
    clear_all();
    g_Pi[0][0] = MTT_R(0.9); g_Pi[0][1] = MTT_R(0.1);
    g_Pi[1][0] = MTT_R(0.2); g_Pi[1][1] = MTT_R(0.8);
    for (i = 0; i < 6; ++i) {
        g_x[0][i] = (i < 4) ? (mtt_real)x_cv[i] : MTT_R(99.0); /* unused components */
        g_x[1][i] = (mtt_real)x_ca[i];
    }
    set_block(g_P[0], P_cv, 4);
    set_block(g_P[1], P_ca, 6);
    check_mix_weights(mu, cbar_e, mix_e, cbar);
    TEST_ASSERT_EQUAL_INT(0, mtt_imm_mix(2, n, g_mix, g_x, g_P, g_x0, g_P0));
    TV_ASSERT_VEC(x00, g_x0[0], 4);
    assert_block(P00, g_P0[0], 4, "P0_cv");
    TV_ASSERT_VEC(x01, g_x0[1], 6);
    assert_block(P01, g_P0[1], 6, "P0_ca");
    for (i = 0; i < 6; ++i) {
        for (j = 0; j < 6; ++j) {
            TEST_ASSERT_TRUE(g_P0[1][i][j] == g_P0[1][j][i]);
        }
    }
    /* The extras keep their own block exactly. */
    TEST_ASSERT_TRUE(g_P0[1][4][4] == g_P[1][4][4] && g_P0[1][4][5] == g_P[1][4][5] &&
                     g_P0[1][5][5] == g_P[1][5][5]);
    muk[0] = (mtt_real)muk_e[0]; /* the mode update with lam = {0.4, 1.7} */
    muk[1] = (mtt_real)muk_e[1];
    TEST_ASSERT_EQUAL_INT(0, mtt_imm_combine(2, muk, g_x, g_P, xc, Pc));
    TV_ASSERT_VEC(xc_e, xc, 4);
    TV_ASSERT_MAT4(Pc_e, Pc);
}

/* ---- association apportioned over the models: tools/ci/imm_vectors.py "IMM-IPDA", "IMM-IHPDA" ---- */

static const mtt_real g_cb[2] = {MTT_R(0.78), MTT_R(0.22)};
static const mtt_real g_pd[2] = {MTT_R(0.9), MTT_R(0.9)};
#define G_PG MTT_R(0.99)

static void test_ipda_apportion(void)
{
    /* p[i][j] = p_i^j, gate-normalised likelihood of measurement i, model j */
    static const mtt_real p[3][2] = {{MTT_R(0.02), MTT_R(0.01)},
                                     {MTT_R(0.004), MTT_R(0.006)},
                                     {MTT_R(0.0005), MTT_R(0.003)}};
    static const mtt_real lamc[3] = {MTT_R(1e-3), MTT_R(1e-3), MTT_R(2e-3)};
    static const double pmix_e[3] = {0.0178, 0.00444, 0.00105};
    static const double mu_e[2] = {0.8306087768, 0.1693912232};
    static const double b0_e[2] = {0.005019398363, 0.00694201191};
    static const double bj_e[2][3] = {{0.8206025581, 0.1641205116, 0.01025753198},
                                      {0.5674617075, 0.3404770245, 0.08511925612}};
    mtt_real pm[3], pdm = MTT_R(0.0), beta[3], beta0, L;
    mtt_real e0[2], e[MTT_MAX_GATED][MTT_MAX_MODELS], mu[2], b0j[2];
    mtt_real bj[MTT_MAX_MODELS][MTT_MAX_GATED];
    int i, j;
    for (i = 0; i < 3; ++i) {
        pm[i] = mtt_imm_meas_mix(2, g_cb, g_pd, p[i], &pdm);
        TV_ASSERT_REAL_MSG(pmix_e[i], pm[i], "p*");
    }
    TV_ASSERT_REAL(0.9, pdm);
    /* Track-level IPDA on the mixed quantities: L is §14.2's Σ c̄_j Λ_j. */
    tv_ipda_betas(pdm, G_PG, pm, lamc, 3, beta, &beta0, &L);
    TV_ASSERT_REAL(20.392615, L);
    for (j = 0; j < 2; ++j) {
        e0[j] = MTT_R(1.0) - g_pd[j] * G_PG;
        for (i = 0; i < 3; ++i) {
            e[i][j] = g_pd[j] * p[i][j];
        }
    }
    TEST_ASSERT_EQUAL_INT(0, mtt_imm_apportion(2, g_cb, 3, beta0, beta, e0, e, mu, b0j, bj));
    /* The textbook IMM-PDA: μ_j = c̄_j Λ_j / c, β^j from model j alone. */
    TV_ASSERT_VEC(mu_e, mu, 2);
    TV_ASSERT_VEC(b0_e, b0j, 2);
    for (j = 0; j < 2; ++j) {
        TV_ASSERT_VEC(bj_e[j], bj[j], 3);
    }
}

static void test_ihpda_apportion(void)
{
    static const mtt_real ps[2] = {MTT_R(0.02), MTT_R(0.01)};
    static const double mu_e[2] = {0.8655264904, 0.1344735096};
    static const double bj_e[2] = {0.8983128279, 0.8153973747};
    /* per-model A^j, C^j of the selected measurement (the script's numbers) */
    mtt_real e0[2] = {MTT_R(3.2275), MTT_R(3.2275)};
    mtt_real e[MTT_MAX_GATED][MTT_MAX_MODELS];
    mtt_cand c[3];
    mtt_real prank[3], beta[3], L[3], pdm, mu[2], b0j[2], bj[MTT_MAX_MODELS][MTT_MAX_GATED];
    int i;
    memset(c, 0, sizeof c);
    TV_CAND_P(&c[0]) = mtt_imm_meas_mix(2, g_cb, g_pd, ps, &pdm); /* selected: the strongest */
    TV_CAND_AMP(&c[0]) = MTT_R(5.0);
    TV_CAND_P(&c[1]) = MTT_R(0.003);
    TV_CAND_AMP(&c[1]) = MTT_R(1.0);
    TV_CAND_P(&c[2]) = MTT_R(0.001);
    TV_CAND_AMP(&c[2]) = MTT_R(2.0);
    for (i = 0; i < 3; ++i) {
        TV_CAND_LAM(&c[i]) = MTT_R(1e-3);
        TV_CAND_IDX(&c[i]) = (uint16_t)i;
    }
    TV_ASSERT_REAL(0.0178, TV_CAND_P(&c[0]));
    mtt_ihpda_prank(3, MTT_R(1.0), prank);
    TV_ASSERT_REAL(0.5333333333, prank[0]);
    mtt_ihpda_betas(pdm, G_PG, MTT_R(400.0), prank, c, 3, beta, L, NULL);
    TV_ASSERT_REAL(28.60318, L[0]); /* = Σ_j c̄_j L^j */
    e[0][0] = MTT_R(28.512);
    e[0][1] = MTT_R(14.256);
    TEST_ASSERT_EQUAL_INT(0, mtt_imm_apportion(2, g_cb, 1, MTT_R(1.0) - beta[0], beta, e0, e, mu, b0j, bj));
    TV_ASSERT_VEC(mu_e, mu, 2);
    TV_ASSERT_REAL(bj_e[0], bj[0][0]);
    TV_ASSERT_REAL(bj_e[1], bj[1][0]);
    TV_ASSERT_REAL(1.0 - bj_e[0], b0j[0]);
    TV_ASSERT_REAL(1.0 - bj_e[1], b0j[1]);
}

/* ---- property: r identical CV models are the CV filter ---- */

static void test_identical_cv_models(void)
{
    enum { R = MTT_MAX_MODELS, FRAMES = 6, M = 3 };
    static const mtt_real z[FRAMES][M][2] = {
        {{MTT_R(1149.0), MTT_R(482.0)}, {MTT_R(1180.0), MTT_R(530.0)}, {MTT_R(1120.0), MTT_R(470.0)}},
        {{MTT_R(1305.0), MTT_R(455.0)}, {MTT_R(1290.0), MTT_R(470.0)}, {MTT_R(1340.0), MTT_R(420.0)}},
        {{MTT_R(1452.0), MTT_R(437.0)}, {MTT_R(1470.0), MTT_R(400.0)}, {MTT_R(1430.0), MTT_R(460.0)}},
        {{MTT_R(1598.0), MTT_R(424.0)}, {MTT_R(1620.0), MTT_R(430.0)}, {MTT_R(1575.0), MTT_R(400.0)}},
        {{MTT_R(1751.0), MTT_R(402.0)}, {MTT_R(1730.0), MTT_R(390.0)}, {MTT_R(1790.0), MTT_R(410.0)}},
        {{MTT_R(1903.0), MTT_R(381.0)}, {MTT_R(1880.0), MTT_R(400.0)}, {MTT_R(1920.0), MTT_R(360.0)}}};
    const mtt_real dt = MTT_R(1.0), sw = MTT_R(20.0), pg = MTT_R(0.999), pd = MTT_R(0.9);
    const mtt_real R3[3] = {MTT_R(225.0), MTT_R(0.0), MTT_R(225.0)};
    const mtt_real lamc[M] = {MTT_R(1e-5), MTT_R(1e-5), MTT_R(1e-5)};
    mtt_state x = {MTT_R(1000.0), MTT_R(500.0), MTT_R(150.0), MTT_R(-20.0)};
    mtt_real mu[R], cbar[R], pdv[R];
    mtt_cov P;
    uint8_t n[R];
    int f, i, j, k;
    memset(P, 0, sizeof P);
    P[0][0] = P[1][1] = MTT_R(225.0);
    P[2][2] = P[3][3] = MTT_R(450.0);
    P[0][2] = P[2][0] = P[1][3] = P[3][1] = MTT_R(225.0);
    clear_all();
    for (j = 0; j < R; ++j) {
        n[j] = 4;
        pdv[j] = pd;
        mu[j] = MTT_R(1.0) / (mtt_real)R;
        memcpy(g_x[j], x, sizeof x);
        for (i = 0; i < 4; ++i) {
            memcpy(g_P[j][i], P[i], sizeof P[i]);
        }
        for (k = 0; k < R; ++k) {
            g_Pi[j][k] = (j == k) ? MTT_R(0.9) : MTT_R(0.1) / (mtt_real)(R - 1);
        }
    }
    for (f = 0; f < FRAMES; ++f) {
        /* single CV filter (the reference) */
        mtt_real Sm[3], Si[3], det, K[MTT_MAX_STATE][2], nu[M][2], p[M], beta[M], beta0, L;
        mtt_state xp;
        mtt_cov Pp;
        /* IMM */
        mtt_real L_imm, b0_imm, b_imm[M], pm[M], e0[R], e[MTT_MAX_GATED][MTT_MAX_MODELS];
        mtt_real b0j[R], bj[MTT_MAX_MODELS][MTT_MAX_GATED], xc[4], Pc[4][MTT_MAX_STATE];
        mtt_kalman_predict(dt, sw, x, P, xp, Pp);
        TEST_ASSERT_EQUAL_INT(0, mtt_kalman_innov(Pp, R3, Sm, Si, &det, K));
        for (i = 0; i < M; ++i) {
            nu[i][0] = z[f][i][0] - xp[0];
            nu[i][1] = z[f][i][1] - xp[1];
            p[i] = mtt_gate_likelihood(mtt_mahal2(Si, nu[i][0], nu[i][1]), det, pg);
        }
        tv_ipda_betas(pd, pg, p, lamc, M, beta, &beta0, &L);
        mtt_kalman_pda(xp, Pp, K, Si, R3, M, nu, beta, beta0, x, P);

        TEST_ASSERT_EQUAL_INT(0, mtt_imm_mix_weights(R, g_Pi, mu, cbar, g_mix));
        TEST_ASSERT_EQUAL_INT(0, mtt_imm_mix(R, n, g_mix, g_x, g_P, g_x0, g_P0));
        for (j = 0; j < R && f == 0; ++j) {
            /* Mixing equal estimates is exact: x0_j = x_j, P0_j = P_j bit for
             * bit (after the first update the models' estimates differ by
             * the round-off of their apportioned betas). */
            TEST_ASSERT_EQUAL_MEMORY(g_x[j], g_x0[j], 4 * sizeof(mtt_real));
            for (i = 0; i < 4; ++i) {
                TEST_ASSERT_EQUAL_MEMORY(g_P[j][i], g_P0[j][i], 4 * sizeof(mtt_real));
            }
        }
        for (j = 0; j < R; ++j) {
            mtt_real Kj[MTT_MAX_STATE][2], nuj[M][2];
            mtt_state xpj;
            mtt_cov Ppj, P0j;
            for (i = 0; i < 4; ++i) {
                memcpy(P0j[i], g_P0[j][i], sizeof P0j[i]);
            }
            mtt_kalman_predict(dt, sw, g_x0[j], P0j, xpj, Ppj);
            TEST_ASSERT_EQUAL_INT(0, mtt_kalman_innov(Ppj, R3, Sm, Si, &det, Kj));
            for (i = 0; i < M; ++i) {
                mtt_real pj;
                nuj[i][0] = z[f][i][0] - xpj[0];
                nuj[i][1] = z[f][i][1] - xpj[1];
                pj = mtt_gate_likelihood(mtt_mahal2(Si, nuj[i][0], nuj[i][1]), det, pg);
                e[i][j] = pd * pj;
            }
            e0[j] = MTT_R(1.0) - pd * pg;
            /* park the prediction in g_x0 / g_P0 until the apportionment is known */
            memcpy(g_x0[j], xpj, sizeof xpj);
            for (i = 0; i < 4; ++i) {
                memcpy(g_P0[j][i], Ppj[i], sizeof Ppj[i]);
            }
        }
        for (i = 0; i < M; ++i) {
            mtt_real pj[R], pdm;
            for (j = 0; j < R; ++j) {
                pj[j] = e[i][j] / pd;
            }
            pm[i] = mtt_imm_meas_mix(R, cbar, pdv, pj, &pdm);
            TV_ASSERT_REAL(pd, pdm);
            TV_ASSERT_REAL(p[i], pm[i]);
        }
        tv_ipda_betas(pd, pg, pm, lamc, M, b_imm, &b0_imm, &L_imm);
        TV_ASSERT_REAL(L, L_imm);
        TEST_ASSERT_EQUAL_INT(0, mtt_imm_apportion(R, cbar, M, b0_imm, b_imm, e0, e, mu, b0j, bj));
        for (j = 0; j < R; ++j) {
            mtt_real Kj[MTT_MAX_STATE][2], nuj[M][2];
            mtt_cov Ppj, Pj;
            TV_ASSERT_REAL(b0_imm, b0j[j]);
            TV_ASSERT_VEC(b_imm, bj[j], M);
            for (i = 0; i < 4; ++i) {
                memcpy(Ppj[i], g_P0[j][i], sizeof Ppj[i]);
            }
            TEST_ASSERT_EQUAL_INT(0, mtt_kalman_innov(Ppj, R3, Sm, Si, &det, Kj));
            for (i = 0; i < M; ++i) {
                nuj[i][0] = z[f][i][0] - g_x0[j][0];
                nuj[i][1] = z[f][i][1] - g_x0[j][1];
            }
            mtt_kalman_pda(g_x0[j], Ppj, Kj, Si, R3, M, nuj, bj[j], b0j[j], g_x[j], Pj);
            for (i = 0; i < 4; ++i) {
                memcpy(g_P[j][i], Pj[i], sizeof Pj[i]);
            }
        }
        TEST_ASSERT_EQUAL_INT(0, mtt_imm_combine(R, mu, g_x, g_P, xc, Pc));
        for (i = 0; i < 4; ++i) {
            TV_ASSERT_REAL_MSG(x[i], xc[i], "combined x against CV");
            for (k = 0; k < 4; ++k) {
                TV_ASSERT_REAL_MSG(P[i][k], Pc[i][k], "combined P against CV");
            }
        }
        /* The modes learn nothing from equal likelihoods: μ = c̄ = uniform. */
        for (j = 0; j < R; ++j) {
            TV_ASSERT_REAL(1.0 / R, mu[j]);
        }
    }
    /* the run went somewhere: six updates away from the start */
    TEST_ASSERT_TRUE(x[0] > MTT_R(1800.0) && x[0] < MTT_R(2000.0));
}

/* Combining equal estimates is exact as well. */
static void test_combine_equal_exact(void)
{
    static const double Pd[16] = {30, 4, 6, 1, 4, 25, 1, 5, 6, 1, 9, 0.5, 1, 5, 0.5, 8};
    mtt_real mu[MTT_MAX_MODELS], xc[4], Pc[4][MTT_MAX_STATE];
    int j, i;
    clear_all();
    for (j = 0; j < MTT_MAX_MODELS; ++j) {
        g_x[j][0] = MTT_R(123456.7);
        g_x[j][1] = MTT_R(-98765.4);
        g_x[j][2] = MTT_R(151.3);
        g_x[j][3] = MTT_R(-7.1);
        set_block(g_P[j], Pd, 4);
        mu[j] = MTT_R(1.0) / (mtt_real)MTT_MAX_MODELS;
    }
    TEST_ASSERT_EQUAL_INT(0, mtt_imm_combine(MTT_MAX_MODELS, mu, g_x, g_P, xc, Pc));
    TEST_ASSERT_EQUAL_MEMORY(g_x[0], xc, sizeof xc);
    for (i = 0; i < 4; ++i) {
        TEST_ASSERT_EQUAL_MEMORY(g_P[0][i], Pc[i], 4 * sizeof Pc[i][0]);
    }
}

#else /* !MTT_WITH_IMM */

static void test_bounds_without_imm(void)
{
    /* IMM left out: one 4-state model per track. */
    TEST_ASSERT_EQUAL_INT(1, MTT_MAX_MODELS);
    TEST_ASSERT_EQUAL_INT(4, MTT_MAX_STATE);
}

#endif

int main(void)
{
    UNITY_BEGIN();
#if MTT_WITH_IMM
    RUN_TEST(test_tv14_mixing);
    RUN_TEST(test_tv14_combine);
    RUN_TEST(test_bad_arguments);
    RUN_TEST(test_mix_cv_ca);
    RUN_TEST(test_ipda_apportion);
    RUN_TEST(test_ihpda_apportion);
    RUN_TEST(test_identical_cv_models);
    RUN_TEST(test_combine_equal_exact);
#else
    RUN_TEST(test_bounds_without_imm);
#endif
    return UNITY_END();
}
