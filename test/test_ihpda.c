/* SPDX-License-Identifier: BSD-3-Clause */
/* test_ihpda.c - intensity order statistics (TV4) and the IHPDA
 * per-candidate quantities, selection and update (TV5), ALGORITHMS.md §7. */
#include <string.h>

#include "mtt_internal.h"
#include "tv_assert.h"
#include "tv_fixture.h"
#include "unity.h"

static mtt_tracker trk;

void setUp(void) {}
void tearDown(void) {}

/* ---- TV4 ---- */

static void check_prank(uint16_t m, mtt_real rho, const double *want, double last)
{
    mtt_real out[16];
    double sum = 0.0;
    uint16_t l;
    mtt_ihpda_prank(m, rho, out);
    for (l = 0; l < m; ++l) {
        TV_ASSERT_REAL_MSG(want[l], out[l], "TV4 Prank[l]");
        sum += (double)out[l];
    }
    TV_ASSERT_REAL(1.0, sum);                        /* TV4: Prank sums to 1 */
    TV_ASSERT_REAL(last, out[m - 1u]);               /* TV4 1/(m+(m-1)rho) = Prank[m] */
}

static void test_tv4_m1_rho0(void)
{
    static const double w[1] = {1}; /* TV4 m = 1, rho = 0 */
    check_prank(1, MTT_R(0.0), w, 1.0);
}

static void test_tv4_m3_rho0(void)
{
    static const double w[3] = {0.3333333333, 0.3333333333, 0.3333333333}; /* TV4 m = 3, rho = 0 */
    check_prank(3, MTT_R(0.0), w, 0.3333333333);
}

static void test_tv4_m3_rho3(void)
{
    static const double w[3] = {0.7111111111, 0.1777777778, 0.1111111111}; /* TV4 m = 3, rho = 3 */
    check_prank(3, MTT_R(3.0), w, 0.1111111111);
}

static void test_tv4_m5_rho3(void)
{
    static const double w[5] = {0.6177978884, 0.1544494721, 0.09653092006, 0.07239819005,
                                0.05882352941}; /* TV4 m = 5, rho = 3 */
    check_prank(5, MTT_R(3.0), w, 0.05882352941);
}

static void test_tv4_m8_rho10(void)
{
    static const double w[8] = {0.7947332571, 0.07224847792, 0.03940826068, 0.02746636351,
                                0.02122400816, 0.01736509759, 0.0147340222,  0.01282051282};
    /* TV4 m = 8, rho = 10 */
    check_prank(8, MTT_R(10.0), w, 0.01282051282);
}

/* TV4 precision study: the product/recurrence form in float32 has a worst
 * relative error of 2.15e-06 for all l, m = 1..64, rho in {0, 0.5, 1, 3, 10,
 * 100}.  The reference is the same closed form in long double; the float
 * bound allows a factor 2 over the generator's figure (operation order). */
static void test_tv4_precision_to_64(void)
{
    static const double rhos[6] = {0.0, 0.5, 1.0, 3.0, 10.0, 100.0};
#ifdef MTT_REAL_DOUBLE
    const double bound = 1e-12;
#else
    const double bound = 2 * 2.15e-6; /* TV4 precision study, m <= 64 */
#endif
    double worst = 0.0;
    int r;
    uint16_t m, l;
    for (r = 0; r < 6; ++r) {
        for (m = 1; m <= 64; ++m) {
            mtt_real out[64];
            long double a = 1.0L / (1.0L + (long double)rhos[r]), ref = 1.0L, sum = 0.0L;
            mtt_ihpda_prank(m, (mtt_real)rhos[r], out);
            for (l = 1; l < m; ++l) {
                ref *= (long double)l / ((long double)l + a);
            }
            for (l = 1; l <= m; ++l) {
                double rel = (double)(fabsl((long double)out[l - 1u] - ref) / ref);
                if (rel > worst) {
                    worst = rel;
                }
                TEST_ASSERT_TRUE(out[l - 1u] > MTT_R(0.0));
                sum += (long double)out[l - 1u];
                ref = ref * ((long double)l - 1.0L + a) / (long double)l;
            }
            TV_ASSERT_REAL_MSG(1.0, (double)sum, "sum of Prank");
            /* P_r(m) = 1/(m + (m-1) rho) (TV4) */
            TV_ASSERT_REAL_MSG(1.0 / ((double)m + (double)(m - 1u) * rhos[r]), out[m - 1u], "Prank[m]");
        }
    }
    if (!(worst <= bound)) {
        char msg[96];
        snprintf(msg, sizeof msg, "worst relative error of Prank %.3g > %.3g", worst, bound);
        TEST_FAIL_MESSAGE(msg);
    }
}

static void test_tracker_prank_table(void)
{
    /* mtt_tracker_init tabulates rows m = 1..MTT_MAX_GATED for the configured rho. */
    mtt_params p;
    static const double w5[5] = {0.6177978884, 0.1544494721, 0.09653092006, 0.07239819005,
                                 0.05882352941}; /* TV4 m = 5, rho = 3 */
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.lm_ihpda_variant = MTT_LM_IHPDA_S0; /* the [S0] vectors */
    p.snr_rho = MTT_R(3.0);
    tv_init(&trk, &p);
#if MTT_MAX_GATED >= 5
    TV_ASSERT_VEC(w5, &TV_PRANK(&trk, MTT_PRANK_ROW(5)), 5);
#endif
    TV_ASSERT_REAL(1.0, TV_PRANK(&trk, MTT_PRANK_ROW(1))); /* TV4 m = 1 */
    TV_ASSERT_REAL(0.7111111111, TV_PRANK(&trk, MTT_PRANK_ROW(3))); /* TV4 m = 3, rho = 3 */
    TV_ASSERT_REAL(0.1111111111, TV_PRANK(&trk, MTT_PRANK_ROW(3) + 2u));
}

/* ---- TV5 ---- */

/* TV5 inputs: prediction from TV2, R from TV2, PD 0.9, PG 0.99, lambda 0.002, rho 3. */
static const mtt_real tv5_R[3] = {MTT_R(1.0), MTT_R(0.3), MTT_R(2.0)};
static const mtt_real tv5_z[3][2] = {{MTT_R(110.8), MTT_R(44.5)},
                                     {MTT_R(106.5), MTT_R(47.4)},
                                     {MTT_R(115.0), MTT_R(48.0)}};
static const mtt_real tv5_amp[3] = {MTT_R(40.0), MTT_R(95.0), MTT_R(60.0)};
#define PD MTT_R(0.9)
#define PG MTT_R(0.99)
#define LAMBDA MTT_R(0.002)

static const double tv5_d2[3] = {0.1013924342, 2.052695582, 3.10257562};
static const double tv5_p[3] = {0.01517412536, 0.005719835949, 0.003383802596};
static const uint8_t tv5_rank[3] = {3, 1, 2};
static const double tv5_prank[3] = {0.1111111111, 0.7111111111, 0.1777777778};
static const double tv5_L[3] = {6.439226139, 6.870114355, 4.68409488};
static const double tv5_beta[3] = {0.3499423017, 0.7912724307, 0.1716428718};
static const double tv5_beta0[3] = {0.6500576983, 0.2087275693, 0.8283571282};
static const double tv5_delta[3] = {-5.439226139, -5.870114355, -3.68409488};
static const double tv5_xupd[4] = {107.481207, 46.56073435, 8.579750984, -4.025743815};
static const double tv5_Pupd[16] = {
    4.189872991,   -0.6399013683, 2.243720278,   -0.5911472809, -0.6399013683, 3.737083804,
    -0.5636540844, 2.005445908,   2.243720278,   -0.5636540844, 4.846887268,   -0.1596150748,
    -0.5911472809, 2.005445908,   -0.1596150748, 4.723167884};

struct tv5 {
    mtt_real S[3], Si[3], det, K[MTT_MAX_STATE][2], vg;
    mtt_state xp;
    mtt_cov Pp;
    mtt_cand c[3];
};

static void tv5_setup(struct tv5 *t)
{
    const mtt_state x0 = {MTT_R(100.0), MTT_R(50.0), MTT_R(10.0), MTT_R(-5.0)};
    mtt_cov P0 = {{MTT_R(4.0), MTT_R(1.0), MTT_R(1.0), MTT_R(0.0)},
                         {MTT_R(1.0), MTT_R(4.0), MTT_R(0.0), MTT_R(1.0)},
                         {MTT_R(1.0), MTT_R(0.0), MTT_R(1.0), MTT_R(0.0)},
                         {MTT_R(0.0), MTT_R(1.0), MTT_R(0.0), MTT_R(1.0)}};
    int j;
    mtt_kalman_predict(MTT_R(1.0), MTT_R(5.0), x0, P0, t->xp, t->Pp);
    TEST_ASSERT_EQUAL_INT(0, mtt_kalman_innov(t->Pp, tv5_R, t->S, t->Si, &t->det, t->K));
    t->vg = mtt_gate_volume(mtt_gate_gamma(PG), t->det);
    TV_ASSERT_REAL(9.210340372, mtt_gate_gamma(PG)); /* TV5 gamma */
    TV_ASSERT_REAL(291.4001257, t->vg);              /* TV5 V_G */
    for (j = 0; j < 3; ++j) {
        mtt_real d2 = mtt_mahal2(t->Si, tv5_z[j][0] - t->xp[0], tv5_z[j][1] - t->xp[1]);
        TV_ASSERT_REAL_MSG(tv5_d2[j], d2, "TV5 d2");
        TV_CAND_P(&t->c[j]) = mtt_gate_likelihood(d2, t->det, PG);
        TV_ASSERT_REAL_MSG(tv5_p[j], TV_CAND_P(&t->c[j]), "TV5 p");
        TV_CAND_LAM(&t->c[j]) = LAMBDA;
        TV_CAND_AMP(&t->c[j]) = tv5_amp[j];
        TV_CAND_IDX(&t->c[j]) = (uint16_t)j;
    }
}

static void test_tv5_candidates(void)
{
    struct tv5 t;
    mtt_real prank[3], beta[3], L[3];
    uint8_t rank[3];
    int j;
    tv5_setup(&t);
    mtt_ihpda_prank(3, MTT_R(3.0), prank);
    mtt_ihpda_betas(PD, PG, t.vg, prank, t.c, 3, beta, L, rank);
    for (j = 0; j < 3; ++j) {
        double A = tv5_beta[j] * tv5_L[j];  /* A_j = beta_j L_j  (TV5) */
        double C = tv5_beta0[j] * tv5_L[j]; /* C_j = beta_0 L_j  (TV5) */
        TEST_ASSERT_EQUAL_UINT8(tv5_rank[j], rank[j]);              /* TV5 rank */
        TV_ASSERT_REAL_MSG(tv5_prank[j], prank[rank[j] - 1u], "TV5 Prank");
        TV_ASSERT_REAL_MSG(tv5_L[j], L[j], "TV5 L");
        TV_ASSERT_REAL_MSG(tv5_beta[j], beta[j], "TV5 beta_j");
        TV_ASSERT_REAL_MSG(tv5_beta0[j], MTT_R(1.0) - beta[j], "TV5 beta_0");
        TV_ASSERT_REAL_MSG(tv5_delta[j], MTT_R(1.0) - L[j], "TV5 delta");
        TV_ASSERT_REAL_MSG(A, beta[j] * L[j], "TV5 A_j");
        TV_ASSERT_REAL_MSG(C, L[j] - beta[j] * L[j], "TV5 C_j");
        /* C_j from its definition with the library's Prank (ALGORITHMS.md §7.3). */
        TV_ASSERT_REAL_MSG(C, 1.0 - 0.9 * 0.99 + 0.9 * 0.99 * (3.0 / (0.002 * (double)t.vg)) *
                                                      (1.0 - tv5_prank[j]), "TV5 C_j formula");
    }
}

static void test_tv5_candidates_order_independent(void)
{
    /* Candidates in another order: each keeps its rank and values. */
    struct tv5 t;
    mtt_cand c[3];
    mtt_real prank[3], beta[3], L[3];
    uint8_t rank[3];
    static const int perm[3] = {2, 0, 1};
    int j;
    tv5_setup(&t);
    for (j = 0; j < 3; ++j) {
        c[j] = t.c[perm[j]];
    }
    mtt_ihpda_prank(3, MTT_R(3.0), prank);
    mtt_ihpda_betas(PD, PG, t.vg, prank, c, 3, beta, L, rank);
    for (j = 0; j < 3; ++j) {
        TEST_ASSERT_EQUAL_UINT8(tv5_rank[perm[j]], rank[j]);
        TV_ASSERT_REAL_MSG(tv5_beta[perm[j]], beta[j], "TV5 beta_j");
        TV_ASSERT_REAL_MSG(tv5_L[perm[j]], L[j], "TV5 L");
    }
}

static void test_rank_ties_lower_index_stronger(void)
{
    /* ALGORITHMS.md §7.1: equal intensities, the lower measurement index ranks stronger. */
    struct tv5 t;
    mtt_real prank[3], beta[3], L[3];
    uint8_t rank[3];
    tv5_setup(&t);
    TV_CAND_AMP(&t.c[0]) = MTT_R(95.0);
    TV_CAND_AMP(&t.c[1]) = MTT_R(95.0);
    TV_CAND_AMP(&t.c[2]) = MTT_R(95.0);
    mtt_ihpda_prank(3, MTT_R(3.0), prank);
    mtt_ihpda_betas(PD, PG, t.vg, prank, t.c, 3, beta, L, rank);
    TEST_ASSERT_EQUAL_UINT8(1, rank[0]);
    TEST_ASSERT_EQUAL_UINT8(2, rank[1]);
    TEST_ASSERT_EQUAL_UINT8(3, rank[2]);
}

static void test_tv5_m1_any_rho_equals_ipda(void)
{
    /* TV5 sub-case m = 1 (only z1): same for rho = 0 and rho = 3, and IPDA. */
    struct tv5 t;
    mtt_real pr0[1], pr3[1], beta[1], L[1], b0, Lp, bp[1];
    const mtt_real lam[1] = {LAMBDA};
    mtt_real p1[1];
    tv5_setup(&t);
    p1[0] = TV_CAND_P(&t.c[0]);
    mtt_ihpda_prank(1, MTT_R(0.0), pr0);
    mtt_ihpda_prank(1, MTT_R(3.0), pr3);
    mtt_ihpda_betas(PD, PG, t.vg, pr0, t.c, 1, beta, L, NULL);
    TV_ASSERT_REAL(6.869072848, L[0]);            /* TV5 m = 1, rho = 0: L */
    TV_ASSERT_REAL(0.9841317741, beta[0]);        /* beta_1 */
    TV_ASSERT_REAL(0.01586822595, MTT_R(1.0) - beta[0]); /* beta_0 */
    TV_ASSERT_REAL(0.9115326816, mtt_existence_update(MTT_R(0.6), L[0]));
    mtt_ihpda_betas(PD, PG, t.vg, pr3, t.c, 1, beta, L, NULL);
    TV_ASSERT_REAL(6.869072848, L[0]);            /* TV5 m = 1, rho = 3 */
    TV_ASSERT_REAL(0.9841317741, beta[0]);
    TV_ASSERT_REAL(0.9115326816, mtt_existence_update(MTT_R(0.6), L[0]));
    mtt_ihpda_betas(PD, PG, t.vg, NULL, t.c, 1, beta, L, NULL); /* no intensity */
    TV_ASSERT_REAL(6.869072848, L[0]);
    tv_ipda_betas(PD, PG, p1, lam, 1, bp, &b0, &Lp);
    TV_ASSERT_REAL(6.869072848, Lp);              /* IPDA with z1 alone */
    TV_ASSERT_REAL(0.9841317741, bp[0]);
    TV_ASSERT_REAL(0.01586822595, b0);
}

static void test_tv5_rho0_equivalence(void)
{
    /* TV5 sub-case rho = 0, m = 3, candidate z1: IHPDA L = IPDA L with p2,
     * p3 replaced by 1/V_G = 9.92672424. */
    struct tv5 t;
    mtt_real beta[3], L[3], pr0[3], p[3], lam[3], bp[3], b0, Lp;
    int j;
    tv5_setup(&t);
    mtt_ihpda_betas(PD, PG, t.vg, NULL, t.c, 3, beta, L, NULL);
    TV_ASSERT_REAL(9.92672424, L[0]); /* TV5 rho = 0: L (both ways) */
    mtt_ihpda_prank(3, MTT_R(0.0), pr0);
    mtt_ihpda_betas(PD, PG, t.vg, pr0, t.c, 3, beta, L, NULL);
    TV_ASSERT_REAL(9.92672424, L[0]);
    for (j = 0; j < 3; ++j) {
        p[j] = MTT_R(1.0) / t.vg;
        lam[j] = LAMBDA;
    }
    p[0] = TV_CAND_P(&t.c[0]);
    tv_ipda_betas(PD, PG, p, lam, 3, bp, &b0, &Lp);
    TV_ASSERT_REAL(9.92672424, Lp);
}

static void test_tv5_m0(void)
{
    /* TV5 sub-case m = 0: delta = PD PG = 0.891, P(exist|Z^k) = 0.1405242802. */
    TV_ASSERT_REAL(0.891, PD * PG);
    TV_ASSERT_REAL(0.1405242802, mtt_existence_update(MTT_R(0.6), MTT_R(1.0) - PD * PG));
}

static void test_tv5_selected_update(void)
{
    /* Selected z2 (largest beta); x_upd, P_upd through the single-measurement
     * PDA update with beta0 = 1 - beta; existence with L_s. */
    struct tv5 t;
    mtt_real prank[3], beta[3], L[3], nu[1][2], b1[1];
    mtt_state x;
    mtt_cov P;
    uint8_t rank[3];
    int j, s = 0;
    tv5_setup(&t);
    mtt_ihpda_prank(3, MTT_R(3.0), prank);
    mtt_ihpda_betas(PD, PG, t.vg, prank, t.c, 3, beta, L, rank);
    for (j = 1; j < 3; ++j) {
        if (beta[j] > beta[s]) {
            s = j;
        }
    }
    TEST_ASSERT_EQUAL_INT(1, s); /* TV5 selected: z2 */
    nu[0][0] = tv5_z[s][0] - t.xp[0];
    nu[0][1] = tv5_z[s][1] - t.xp[1];
    b1[0] = beta[s];
    mtt_kalman_pda(t.xp, t.Pp, t.K, t.Si, tv5_R, 1, nu, b1, MTT_R(1.0) - beta[s], x, P);
    TV_ASSERT_VEC(tv5_xupd, x, 4);  /* TV5 x_upd */
    TV_ASSERT_MAT4(tv5_Pupd, P);    /* TV5 P_upd */
    TV_ASSERT_SYM4(P);
    TV_ASSERT_REAL(0.9115449069, mtt_existence_update(MTT_R(0.6), L[s])); /* TV5 P(exist|Z^k) */
}

/* The same through the tracker stages in `ihpda` mode. */
static void tv5_tracker(mtt_assoc mode)
{
    mtt_params p;
    struct tv5 t;
    int j;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.lm_ihpda_variant = MTT_LM_IHPDA_S0; /* the [S0] vectors */
    p.association = mode;
    p.pd = PD;
    p.pg = PG;
    p.clutter_density = LAMBDA;
    p.snr_rho = MTT_R(3.0);
    tv_init(&trk, &p);
    TV_R(&trk)[0] = tv5_R[0];
    TV_R(&trk)[1] = tv5_R[1];
    TV_R(&trk)[2] = tv5_R[2];
    tv5_setup(&t);
    (void)tv_add_track_xp(&trk, t.xp, t.Pp, MTT_R(0.6));
    for (j = 0; j < 3; ++j) {
        (void)tv_add_meas(&trk, tv5_z[j][0], tv5_z[j][1], tv5_amp[j], 1);
    }
    mtt_gate_frame(&trk);
    mtt_clutter_frame(&trk, 0);
}

static void test_tv5_row_and_ihpda_mode_update(void)
{
    int16_t best = -2;
    uint16_t m;
    int k;
    tv5_tracker(MTT_ASSOC_IHPDA);
    TEST_ASSERT_EQUAL_UINT(3, TV_N_PAIRS(&trk));
    m = mtt_ihpda_row(&trk, 0, 0, -1, 1, &best);
    TEST_ASSERT_EQUAL_UINT(3, m);
    TEST_ASSERT_EQUAL_INT(1, best); /* TV5: z2 */
    for (k = 0; k < 3; ++k) {
        TV_ASSERT_REAL_MSG(tv5_beta[k], TV_PAIR_BETA(&trk, k), "TV5 beta_j");
        TV_ASSERT_REAL_MSG(tv5_L[k], TV_PAIR_L(&trk, k), "TV5 L");
    }
    mtt_associate_frame(&trk); /* the ihpda selection */
    mtt_update_frame(&trk);
    TEST_ASSERT_EQUAL_INT(1, TV_ASSIGNED(&trk, 0));
    TEST_ASSERT_EQUAL_INT(1, TV_TRACK_MEAS(&trk, 0));
    TV_ASSERT_VEC(tv5_xupd, TV_X(&trk, 0), 4);
    TV_ASSERT_MAT4(tv5_Pupd, TV_P(&trk, 0));
    TV_ASSERT_REAL(0.9115449069, TV_EXISTENCE(&trk, 0)); /* TV5 */
    TEST_ASSERT_EQUAL_UINT(0, TV_USED(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(1, TV_USED(&trk, 1));
    TEST_ASSERT_EQUAL_UINT(0, TV_USED(&trk, 2));
}

static void test_row_excludes_used_measurements(void)
{
    /* With z2 used by another track, the row has m = 2 over {z1, z3}:
     * ranks 2 and 1 (z3 = 60 > z1 = 40); z2's beta is 0. */
    int16_t best = -2;
    uint16_t m;
    tv5_tracker(MTT_ASSOC_LM_IHPDA);
    TV_USED(&trk, 1) = 1;
    m = mtt_ihpda_row(&trk, 0, 1, -1, 0, &best);
    TEST_ASSERT_EQUAL_UINT(2, m);
    TEST_ASSERT_TRUE(TV_PAIR_BETA(&trk, 1) == MTT_R(0.0));
    TEST_ASSERT_TRUE(TV_PAIR_BETA(&trk, 0) > MTT_R(0.0));
    TEST_ASSERT_TRUE(TV_PAIR_BETA(&trk, 2) > MTT_R(0.0));
    /* keep = pair 1 brings it back: the TV5 full row again */
    m = mtt_ihpda_row(&trk, 0, 1, 1, 0, &best);
    TEST_ASSERT_EQUAL_UINT(3, m);
    TV_ASSERT_REAL(0.7912724307, TV_PAIR_BETA(&trk, 1)); /* TV5 z2 beta_j */
    TV_ASSERT_REAL(0.3499423017, TV_PAIR_BETA(&trk, 0)); /* TV5 z1 beta_j */
}

static void test_row_missing_amplitude_uses_rho0(void)
{
    /* ALGORITHMS.md §7.1: a gated measurement without amplitude: P_r = 1/m; z1's L is
     * then the TV5 rho = 0 value 9.92672424. */
    int16_t best;
    tv5_tracker(MTT_ASSOC_IHPDA);
    TV_HAS_AMP(&trk, 2) = 0;
    TV_ALL_AMP(&trk, 0) = 0;
    (void)mtt_ihpda_row(&trk, 0, 0, -1, 1, &best);
    TV_ASSERT_REAL(9.92672424, TV_PAIR_L(&trk, 0)); /* TV5 rho = 0 sub-case */
}

static void test_tv5_m0_through_update(void)
{
    /* TV5 m = 0: x = x_pred, P = P_pred, existence 0.1405242802. */
    struct tv5 t;
    tv5_tracker(MTT_ASSOC_LM_IHPDA);
    tv5_setup(&t);
    TV_N_MEAS(&trk) = 0;
    mtt_gate_frame(&trk);
    mtt_clutter_frame(&trk, 1);
    TV_ASSIGNED(&trk, 0) = -1;
    mtt_update_frame(&trk);
    TV_ASSERT_REAL(0.1405242802, TV_EXISTENCE(&trk, 0)); /* TV5 m = 0 */
    TEST_ASSERT_EQUAL_INT(-1, TV_TRACK_MEAS(&trk, 0));
    {
        static const double xpred[4] = {110, 45, 10, -5}; /* TV2 x_pred */
        static const double Ppred[16] = {8.666666667, 1, 4.5, 0, 1, 8.666666667, 0, 4.5,
                                         4.5, 0, 6, 0, 0, 4.5, 0, 6}; /* TV2 P_pred */
        TV_ASSERT_VEC(xpred, TV_X(&trk, 0), 4);
        TV_ASSERT_MAT4(Ppred, TV_P(&trk, 0));
    }
}

static void test_row_tie_rules(void)
{
    /* Two candidates at +nu and -nu have exactly equal d2, p and (rho = 0,
     * P_r = 1/m) equal beta.  Rule 0 (ALGORITHMS.md §10.1): the lower measurement
     * index wins; rule 1 (ALGORITHMS.md §7.4): the smaller rank (stronger) wins. */
    mtt_params p;
    int16_t best = -2;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.lm_ihpda_variant = MTT_LM_IHPDA_S0; /* the [S0] vectors */
    p.pg = PG;
    p.clutter_density = LAMBDA;
    p.snr_rho = MTT_R(0.0);
    tv_init(&trk, &p);
    (void)tv_add_track_s(&trk, MTT_R(0.0), MTT_R(0.0), MTT_R(4.0), MTT_R(1.0), MTT_R(3.0), MTT_R(0.8));
    (void)tv_add_meas(&trk, MTT_R(0.5), MTT_R(0.25), MTT_R(10.0), 1);   /* weaker, index 0 */
    (void)tv_add_meas(&trk, MTT_R(-0.5), MTT_R(-0.25), MTT_R(50.0), 1); /* stronger, index 1 */
    mtt_gate_frame(&trk);
    mtt_clutter_frame(&trk, 0);
    TEST_ASSERT_EQUAL_UINT(2, mtt_ihpda_row(&trk, 0, 0, -1, 0, &best));
    TEST_ASSERT_TRUE(TV_PAIR_BETA(&trk, 0) == TV_PAIR_BETA(&trk, 1));
    TEST_ASSERT_EQUAL_INT(0, best);
    TEST_ASSERT_EQUAL_UINT(2, mtt_ihpda_row(&trk, 0, 0, -1, 1, &best));
    TEST_ASSERT_EQUAL_INT(1, best);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_tv4_m1_rho0);
    RUN_TEST(test_tv4_m3_rho0);
    RUN_TEST(test_tv4_m3_rho3);
    RUN_TEST(test_tv4_m5_rho3);
    RUN_TEST(test_tv4_m8_rho10);
    RUN_TEST(test_tv4_precision_to_64);
    RUN_TEST(test_tracker_prank_table);
    RUN_TEST(test_tv5_candidates);
    RUN_TEST(test_tv5_candidates_order_independent);
    RUN_TEST(test_rank_ties_lower_index_stronger);
    RUN_TEST(test_tv5_m1_any_rho_equals_ipda);
    RUN_TEST(test_tv5_rho0_equivalence);
    RUN_TEST(test_tv5_m0);
    RUN_TEST(test_tv5_selected_update);
    RUN_TEST(test_tv5_row_and_ihpda_mode_update);
    RUN_TEST(test_row_excludes_used_measurements);
    RUN_TEST(test_row_missing_amplitude_uses_rho0);
    RUN_TEST(test_tv5_m0_through_update);
    RUN_TEST(test_row_tie_rules);
    return UNITY_END();
}
