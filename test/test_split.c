/* SPDX-License-Identifier: BSD-3-Clause */
/* test_split.c - split-target models (ALGORITHMS.md §14.3): model 5 "just
 * split", model 6 "split" (joint events, coupled update, likelihood), the
 * decoupling test and the conversion into two track states.
 *
 * Expected numbers: the output of `python3 tools/ci/split_vectors.py`
 * (an independent numpy implementation with brute-force event enumeration),
 * pasted below as ref*; the inputs are the literals of that script.
 * Properties: joint event probabilities sum to 1, symmetric positive
 * definite covariances, the stacked update with PD = PG = 1 and one
 * measurement per target equals two independent Kalman updates
 * (kalman.c), the decoupling boundary; with range rates (polar, §3.2)
 * their factors and EKF steps against the formulas in double. */
#include <string.h>

#include "mtt_internal.h"
#include "tv_assert.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

#if MTT_WITH_SPLIT

/* ---- inputs (tools/ci/split_vectors.py: R, XP, PP, Z5, B5, XPS, P22, P12, Z6;
 * Z5, Z6 not const: the split functions take measurements as mtt_real[][2]) ---- */
static const mtt_real R[3] = {MTT_R(9.0), MTT_R(1.5), MTT_R(12.0)};
static const mtt_real XP[MTT_MAX_STATE] = {MTT_R(100.0), MTT_R(50.0), MTT_R(10.0), MTT_R(-5.0)};
static const double PP[4][4] = {{30, 2, 10, 0}, {2, 25, 0, 8}, {10, 0, 9, 0.5}, {0, 8, 0.5, 7}};
static const double P22[4][4] = {{28, 1, 9, 0}, {1, 26, 0, 7}, {9, 0, 8, 0.3}, {0, 7, 0.3, 6}};
static const double P12[4][4] = {{12, 1, 4, 0}, {0.5, 10, 0, 3}, {4, 0, 3, 0.2}, {0, 3, 0.1, 2.5}};
static mtt_real Z5[5][2] = {{MTT_R(104.0), MTT_R(48.0)}, {MTT_R(93.0), MTT_R(57.0)},
                                  {MTT_R(108.0), MTT_R(44.0)}, {MTT_R(97.0), MTT_R(59.0)},
                                  {MTT_R(110.0), MTT_R(53.0)}};
static const mtt_real B5[5] = {MTT_R(0.30), MTT_R(0.22), MTT_R(0.18), MTT_R(0.12), MTT_R(0.08)};
static const mtt_real XPS[MTT_SPLIT_STATE] = {MTT_R(100.0), MTT_R(50.0), MTT_R(10.0), MTT_R(-5.0),
                                MTT_R(112.0), MTT_R(47.0), MTT_R(12.0), MTT_R(-1.0)};
static mtt_real Z6[4][2] = {{MTT_R(103.0), MTT_R(49.0)}, {MTT_R(110.0), MTT_R(46.0)},
                                  {MTT_R(106.0), MTT_R(52.0)}, {MTT_R(140.0), MTT_R(80.0)}};
/* the split arithmetic's work matrices (the caller's, src/split/split.c) */
static mtt_split_work wk;
#define PD6 MTT_R(0.9)
#define PG6 MTT_R(0.99)
#define GAMMA MTT_R(9.210340371976182)

/* ---- expected: python3 tools/ci/split_vectors.py ---- */
static const double ref5_V = 1094.478992;
static const int ref5_cluster[5] = {0, 1, 0, 1, 0};
static const double ref5_beta_n[5] = {0.5357142857, 0.6470588235, 0.3214285714, 0.3529411765, 0.1428571429};
static const double ref5_xs[8] = {104.7842041, 48.20229151, 11.65148149, -5.680961534, 95.54647398, 55.26628362, 8.366344266, -3.210235274};
static const double ref5_Ps[64] = {10.28632078, 0.9730889993, 3.421070261, 0.09243998307, 1.60046456, 0.3659696876, 0.5265371933, 0.08341191966, 0.9730889993, 11.93993154, 0.005996808288, 3.820394298, 0.3659696876, 2.630080718, 0.05213244979, 0.8382893529, 3.421070261, 0.005996808288, 6.79510406, 0.6430323188, 0.5265371933, 0.05213244979, 5.823849396, 0.7199560226, 0.09243998307, 3.820394298, 0.6430323188, 5.653372107, 0.08341191966, 0.8382893529, 0.7199560226, 4.694175407, 1.60046456, 0.3659696876, 0.5265371933, 0.08341191966, 9.028827215, 1.844940986, 2.976284161, 0.3998989293, 0.3659696876, 2.630080718, 0.05213244979, 0.8382893529, 1.844940986, 8.499811596, 0.3904008239, 2.694954058, 0.5265371933, 0.05213244979, 5.823849396, 0.7199560226, 2.976284161, 0.3904008239, 6.635741319, 0.7762408193, 0.08341191966, 0.8382893529, 0.7199560226, 4.694175407, 0.3998989293, 2.694954058, 0.7762408193, 5.284705886};
static const double ref5_lik = 2.294999627;
static const struct { int j1, j2; double p; } ref6p_events[13] = {
    {-1, -1, 1.555348617e-05},
    {-1, 0, 0.0008355800172},
    {-1, 1, 0.002562358385},
    {-1, 2, 0.00114135053},
    {0, -1, 0.002355080585},
    {0, 1, 0.3879876458},
    {0, 2, 0.1728212211},
    {1, -1, 0.0005406242138},
    {1, 0, 0.0290439574},
    {1, 2, 0.0396722462},
    {2, -1, 0.001654111067},
    {2, 0, 0.08886381733},
    {2, 1, 0.2725064539},};
static const double ref6p_lik = 763.8801917;
static const double ref6_V = 2177.036038;
static const struct { int j1, j2; double p; } ref6_events[13] = {
    {-1, -1, 0.0009336180605},
    {-1, 0, 0.005459654555},
    {-1, 1, 0.01674237217},
    {-1, 2, 0.007457549834},
    {0, -1, 0.0153880253},
    {0, 1, 0.3679335372},
    {0, 2, 0.1638885255},
    {1, -1, 0.003532422258},
    {1, 0, 0.02754274807},
    {1, 2, 0.03762168727},
    {2, -1, 0.01080791168},
    {2, 0, 0.08427066944},
    {2, 1, 0.2584212786},};
static const double ref6_beta[2][4] = {{0.5472100881, 0.0686968576, 0.3534998597, 0}, {0.1172730721, 0.643097188, 0.2089677626, 0}};
static const double ref6_miss[2] = {0.03059319462, 0.03066197729};
static const double ref6_lik = 12.72576068;
static const double ref6_beta0 = 0.0009336180605;
static const double ref6_xs[8] = {103.0269863, 49.93201489, 11.01551537, -5.107039386, 109.7236358, 47.5177354, 11.28609725, -0.8709390483};
static const double ref6_Ps[64] = {9.169007113, 1.017747451, 3.046883788, 0.1190175819, 0.5706637783, 0.249106033, 0.2336317804, 0.01176338741, 1.017747451, 8.978809984, 0.1083371402, 2.890028213, 0.1959382375, 0.9732840502, 0.03761348556, 0.3841415425, 3.046883788, 0.1083371402, 6.667128512, 0.6791631364, 0.1887683474, 0.02711544722, 1.739821536, 0.2838116633, 0.1190175819, 2.890028213, 0.6791631364, 5.360283917, 0.1106281238, 0.2086306985, 0.1799196792, 1.684350513, 0.5706637783, 0.1959382375, 0.1887683474, 0.1106281238, 10.15556981, -1.65782109, 3.26447769, -0.5060243828, 0.249106033, 0.9732840502, 0.02711544722, 0.2086306985, -1.65782109, 10.49830943, -0.652316814, 2.794883904, 0.2336317804, 0.03761348556, 1.739821536, 0.1799196792, 3.26447769, -0.652316814, 6.153271432, 0.1933703285, 0.01176338741, 0.3841415425, 0.2838116633, 1.684350513, -0.5060243828, 2.794883904, 0.1933703285, 4.853789519};
static const double ref_d2 = 2.103813559;
static const double ref_d2_far = 69.22245763;

static void prior1(mtt_real P[][MTT_MAX_STATE])
{
    int i, k;
    for (i = 0; i < 4; ++i) {
        for (k = 0; k < 4; ++k) {
            P[i][k] = (mtt_real)PP[i][k];
        }
    }
}

/* Stacked prior [[PP, c P12], [c P12', P22]]. */
static void prior_s(mtt_split_cov Ps, double c)
{
    int i, k;
    memset(Ps, 0, sizeof(mtt_split_cov));
    for (i = 0; i < 4; ++i) {
        for (k = 0; k < 4; ++k) {
            Ps[i][k] = (mtt_real)PP[i][k];
            Ps[4 + i][4 + k] = (mtt_real)P22[i][k];
            Ps[i][4 + k] = (mtt_real)(c * P12[i][k]);
            Ps[4 + k][i] = (mtt_real)(c * P12[i][k]);
        }
    }
}

/* Covariance entries: the tolerance of tv_assert.h relative to the
 * matrix's largest entry (float loses digits of the small entries of a
 * matrix, not of the matrix). */
static void assert_cov8(const double ref[64], mtt_split_cov P, const char *what)
{
    double big = 0.0;
    int i, k;
    char msg[96];
    for (i = 0; i < 64; ++i) {
        big = fabs(ref[i]) > big ? fabs(ref[i]) : big;
    }
    for (i = 0; i < 8; ++i) {
        for (k = 0; k < 8; ++k) {
            const double e = ref[8 * i + k], a = (double)P[i][k];
            snprintf(msg, sizeof msg, "%s[%d][%d]: expected %.10g, actual %.10g", what, i, k, e, a);
            TEST_ASSERT_TRUE_MESSAGE(fabs(a - e) <= TV_REL * big, msg);
        }
    }
}

/* Exactly symmetric and positive semi-definite: P + eps I has a Cholesky
 * factor (in double), eps = TV_REL x the largest diagonal entry.  Model
 * 5's stacked covariance is singular (the two halves differ only by W
 * times the difference of their innovations), so definiteness is not
 * required of it. */
static void assert_psd(mtt_split_cov P, int N)
{
    double L[MTT_SPLIT_STATE][MTT_SPLIT_STATE], eps = 0.0;
    int i, j, k;
    for (i = 0; i < N; ++i) {
        eps = (double)P[i][i] > eps ? (double)P[i][i] : eps;
        for (j = 0; j < N; ++j) {
            TEST_ASSERT_TRUE_MESSAGE(P[i][j] == P[j][i], "covariance not symmetric");
        }
    }
    eps *= TV_REL;
    for (i = 0; i < N; ++i) {
        for (j = 0; j <= i; ++j) {
            double s = (double)P[i][j] + ((i == j) ? eps : 0.0);
            for (k = 0; k < j; ++k) {
                s -= L[i][k] * L[j][k];
            }
            if (i == j) {
                TEST_ASSERT_TRUE_MESSAGE(s > 0.0, "covariance not positive semi-definite");
                L[i][i] = sqrt(s);
            } else {
                L[i][j] = s / L[j][j];
            }
        }
    }
}

/* ---- stacking and prediction ---- */

/* One estimate as a stacked state: [x; x], [[P, P], [P, P]] ([S3] eq. 5,
 * 11), n = 4. */
static void stack4(const mtt_real x[], mtt_real P[][MTT_MAX_STATE], mtt_split_state xs, mtt_split_cov Ps)
{
    int i, k;
    for (i = 0; i < 4; ++i) {
        xs[i] = x[i];
        xs[4 + i] = x[i];
        for (k = 0; k < 4; ++k) {
            const mtt_real v = MTT_R(0.5) * (P[i][k] + P[k][i]);
            Ps[i][k] = v;
            Ps[i][4 + k] = v;
            Ps[4 + i][k] = v;
            Ps[4 + i][4 + k] = v;
        }
    }
}

/* [x; x] with [[P, P], [P, P]]; its prediction with the CV model: each
 * half is the single-target prediction of kalman.c, the cross block is
 * F P F' (no Q: the process noises are independent). */
static void test_stack_predict(void)
{
    mtt_real P[MTT_MAX_STATE][MTT_MAX_STATE], Pk[MTT_MAX_STATE][MTT_MAX_STATE], xk[MTT_MAX_STATE];
    mtt_real F[MTT_MAX_STATE][MTT_MAX_STATE], Q[MTT_MAX_STATE][MTT_MAX_STATE], FPF;
    mtt_split_state xs, xps;
    mtt_split_cov Ps, Pps;
    const mtt_real dt = MTT_R(0.5), sw = MTT_R(5.0);
    int i, k, l, h;
    prior1(P);
    stack4(XP, P, xs, Ps);
    memset(F, 0, sizeof F);
    for (i = 0; i < 4; ++i) {
        F[i][i] = MTT_R(1.0);
    }
    F[0][2] = dt;
    F[1][3] = dt;
    mtt_motion_q(dt, sw, Q);
    TEST_ASSERT_EQUAL_INT(0, mtt_split_predict(&wk, 4, F, Q, xs, Ps, xps, Pps));
    mtt_kalman_predict(dt, sw, XP, P, xk, Pk);
    for (h = 0; h < 2; ++h) {
        for (i = 0; i < 4; ++i) {
            TV_ASSERT_REAL(xk[i], xps[4 * h + i]);
            for (k = 0; k < 4; ++k) {
                TV_ASSERT_REAL(Pk[i][k], Pps[4 * h + i][4 * h + k]);
            }
        }
    }
    for (i = 0; i < 4; ++i) {
        for (k = 0; k < 4; ++k) {
            FPF = MTT_R(0.0);
            for (l = 0; l < 4; ++l) {
                int c;
                for (c = 0; c < 4; ++c) {
                    FPF += F[i][l] * P[l][c] * F[k][c];
                }
            }
            TV_ASSERT_REAL(FPF, Pps[i][4 + k]);
            TV_ASSERT_REAL(Pk[i][k] - Q[i][k], Pps[4 + i][k]);
        }
    }
    assert_psd(Pps, 8);
}

/* ---- model 5 ---- */

static void test_just_split_reference(void)
{
    mtt_real P[MTT_MAX_STATE][MTT_MAX_STATE];
    mtt_split_state xs;
    mtt_split_cov Ps;
    uint8_t cl[5];
    mtt_real bn[5], lik = MTT_R(0.0);
    int j;
    prior1(P);
    TEST_ASSERT_EQUAL_INT(0, mtt_split_just(&wk, 4, XP, P, R, NULL, NULL, 5, Z5, B5, (mtt_real)ref5_V, xs, Ps, cl,
                                            bn, &lik));
    for (j = 0; j < 5; ++j) {
        TEST_ASSERT_EQUAL_INT(ref5_cluster[j], cl[j]);
    }
    TV_ASSERT_VEC(ref5_beta_n, bn, 5);
    TV_ASSERT_VEC(ref5_xs, xs, 8);
    assert_cov8(ref5_Ps, Ps, "Ps");
    assert_psd(Ps, 8);
    /* eq. 13 with V^-(m_i - 1), as a ratio to V^-m; the printed exponent
     * -(m_i + 1) would give V^-4 times this. */
    TV_ASSERT_REAL(ref5_lik, lik);
}

static void test_just_split_refuses(void)
{
    mtt_real P[MTT_MAX_STATE][MTT_MAX_STATE];
    mtt_split_state xs;
    mtt_split_cov Ps;
    uint8_t cl[5] = {7, 7, 7, 7, 7};
    mtt_real bn[5] = {MTT_R(-1.0)}, lik = MTT_R(-1.0);
    prior1(P);
    /* one measurement: no split; n out of range; V not positive */
    TEST_ASSERT_EQUAL_INT(-1, mtt_split_just(&wk, 4, XP, P, R, NULL, NULL, 1, Z5, B5, MTT_R(1000.0), xs, Ps, cl, bn, &lik));
    TEST_ASSERT_EQUAL_INT(-1, mtt_split_just(&wk, 3, XP, P, R, NULL, NULL, 5, Z5, B5, MTT_R(1000.0), xs, Ps, cl, bn, &lik));
    TEST_ASSERT_EQUAL_INT(-1, mtt_split_just(&wk, 4, XP, P, R, NULL, NULL, 5, Z5, B5, MTT_R(0.0), xs, Ps, cl, bn, &lik));
    TEST_ASSERT_EQUAL_INT(7, cl[0]);
    TV_ASSERT_REAL(-1.0, lik);
}

/* Two measurements: each is its own cluster (beta_n = 1), the halves are
 * the Kalman updates with either measurement, the cross covariance is
 * (I - KH) Pp (I - KH)', and the likelihood is V^2 N_1 N_2. */
static void test_just_split_two(void)
{
    mtt_real P[MTT_MAX_STATE][MTT_MAX_STATE], Pk[MTT_MAX_STATE][MTT_MAX_STATE];
    mtt_real S[3], Si[3], det, K[MTT_MAX_STATE][2], xk[MTT_MAX_STATE];
    mtt_real nu[1][2], one[1] = {MTT_R(1.0)}, bn[2], lik;
    mtt_split_state xs;
    mtt_split_cov Ps;
    uint8_t cl[2];
    const mtt_real b[2] = {MTT_R(0.2), MTT_R(0.6)}; /* the larger beta is cluster 1 */
    int h, i, k;
    double n1, n2;
    prior1(P);
    TEST_ASSERT_EQUAL_INT(0, mtt_split_just(&wk, 4, XP, P, R, NULL, NULL, 2, Z5, b, MTT_R(500.0), xs, Ps, cl, bn, &lik));
    TEST_ASSERT_EQUAL_INT(1, cl[0]);
    TEST_ASSERT_EQUAL_INT(0, cl[1]);
    TV_ASSERT_REAL(1.0, bn[0]);
    TV_ASSERT_REAL(1.0, bn[1]);
    TEST_ASSERT_EQUAL_INT(0, mtt_kalman_innov(P, R, S, Si, &det, K));
    for (h = 0; h < 2; ++h) {
        const int o = 4 * h, j = 1 - h; /* half 0 is measurement 1 */
        nu[0][0] = Z5[j][0] - XP[0];
        nu[0][1] = Z5[j][1] - XP[1];
        mtt_kalman_pda(XP, P, K, Si, R, 1, nu, one, MTT_R(0.0), xk, Pk);
        for (i = 0; i < 4; ++i) {
            TV_ASSERT_REAL(xk[i], xs[o + i]);
            for (k = 0; k < 4; ++k) {
                TV_ASSERT_REAL(Pk[i][k], Ps[o + i][o + k]);
                /* P_c - K R K' = (I - KH) Pp (I - KH)' */
                const mtt_real krk = K[i][0] * (R[0] * K[k][0] + R[1] * K[k][1]) +
                                     K[i][1] * (R[1] * K[k][0] + R[2] * K[k][1]);
                TV_ASSERT_REAL((double)Pk[i][k] - (double)krk, Ps[i][4 + k]);
            }
        }
    }
    n1 = exp(-0.5 * (double)mtt_mahal2(Si, Z5[0][0] - XP[0], Z5[0][1] - XP[1])) /
         (2.0 * 3.14159265358979 * sqrt((double)det));
    n2 = exp(-0.5 * (double)mtt_mahal2(Si, Z5[1][0] - XP[0], Z5[1][1] - XP[1])) /
         (2.0 * 3.14159265358979 * sqrt((double)det));
    TV_ASSERT_REAL(500.0 * 500.0 * n1 * n2, lik);
    assert_psd(Ps, 8);
}

/* ---- model 5, a split of known speed (split_known_speed) ---- */

/* python3 tools/ci/split_vectors.py, "a split of known speed": on model 5's
 * clusters of test_just_split_reference, dt 1 */
static const struct {
    double dv;
    int n_off;
    double x2[4], P2[16], lik;
} ref_known[3] = {
    {5, 1, {96.28487662, 57.08255102, 10.01863882, 0.102090865}, {9.088331934, 1.961490023, 2.967068343, 0.3741499153, 1.961490023, 8.713150505, 0.3770316708, 2.649904598, 2.967068343, 0.3770316708, 6.74108813, 0.9893145163, 0.3741499153, 2.649904598, 0.9893145163, 5.715453552}, 1.726447858},
    {2, 1, {95.84749966, 56.006724, 9.025495378, -1.888778884}, {9.038774858, 1.864417832, 2.974745748, 0.395596931, 1.864417832, 8.535441264, 0.3881735637, 2.687433645, 2.974745748, 0.3881735637, 6.652595132, 0.8103469469, 0.395596931, 2.687433645, 0.8103469469, 5.353688378}, 1.518264686},
    {2, 2, {96.08404294, 56.5885554, 8.838608529, -2.260074067}, {9.038774858, 1.864417832, 2.974745748, 0.395596931, 1.864417832, 8.535441264, 0.3881735637, 2.687433645, 2.974745748, 0.3881735637, 6.652595132, 0.8103469469, 0.395596931, 2.687433645, 0.8103469469, 5.353688378}, 0.8562730135},
};

static void test_known_split_reference(void)
{
    mtt_real P[MTT_MAX_STATE][MTT_MAX_STATE];
    mtt_split_state xs, xs0;
    mtt_split_cov Ps, Ps0;
    uint8_t cl[5];
    mtt_real bn[5], lik = MTT_R(0.0), lk = MTT_R(0.0);
    int c, i, k;
    prior1(P);
    TEST_ASSERT_EQUAL_INT(0, mtt_split_just(&wk, 4, XP, P, R, NULL, NULL, 5, Z5, B5, (mtt_real)ref5_V, xs0, Ps0, cl,
                                            bn, &lik));
    for (c = 0; c < 3; ++c) {
        memcpy(xs, xs0, sizeof xs);
        memcpy(Ps, Ps0, sizeof Ps);
        TEST_ASSERT_EQUAL_INT(0, mtt_split_known(&wk, 4, XP, P, R, NULL, NULL, 5, Z5, cl, bn, (mtt_real)ref_known[c].dv,
                                                 MTT_R(1.0), (uint8_t)ref_known[c].n_off, (mtt_real)ref5_V,
                                                 xs, Ps, &lk));
        TV_ASSERT_REAL(ref_known[c].lik, lk);
        for (i = 0; i < 4; ++i) {
            TV_ASSERT_REAL(ref_known[c].x2[i], xs[4 + i]);
            TV_ASSERT_REAL(ref5_xs[i], xs[i]); /* the parent's half untouched */
            for (k = 0; k < 4; ++k) {
                TV_ASSERT_REAL(ref_known[c].P2[4 * i + k], Ps[4 + i][4 + k]);
                TV_ASSERT_REAL(ref5_Ps[8 * i + k], Ps[i][k]);
                TEST_ASSERT_EQUAL_FLOAT(0.0f, (float)Ps[i][4 + k]); /* no cross covariance */
                TEST_ASSERT_EQUAL_FLOAT(0.0f, (float)Ps[4 + i][k]);
            }
        }
    }
    /* refused: no speed, no offset, more offsets than the bound, one cluster */
    TEST_ASSERT_EQUAL_INT(-1, mtt_split_known(&wk, 4, XP, P, R, NULL, NULL, 5, Z5, cl, bn, MTT_R(0.0), MTT_R(1.0), 1u,
                                              (mtt_real)ref5_V, xs, Ps, &lk));
    TEST_ASSERT_EQUAL_INT(-1, mtt_split_known(&wk, 4, XP, P, R, NULL, NULL, 5, Z5, cl, bn, MTT_R(5.0), MTT_R(1.0), 0u,
                                              (mtt_real)ref5_V, xs, Ps, &lk));
    TEST_ASSERT_EQUAL_INT(-1, mtt_split_known(&wk, 4, XP, P, R, NULL, NULL, 5, Z5, cl, bn, MTT_R(5.0), MTT_R(1.0),
                                              (uint8_t)(MTT_SPLIT_KNOWN_MAX_OFFSETS + 1u), (mtt_real)ref5_V,
                                              xs, Ps, &lk));
    {
        const uint8_t one[5] = {0, 0, 0, 0, 0};
        TEST_ASSERT_EQUAL_INT(-1, mtt_split_known(&wk, 4, XP, P, R, NULL, NULL, 5, Z5, one, bn, MTT_R(5.0), MTT_R(1.0),
                                                  1u, (mtt_real)ref5_V, xs, Ps, &lk));
    }
}

/* ---- model 6 ---- */

static void test_split_events_reference(void)
{
    mtt_split_cov Pps;
    mtt_split_assoc as;
    double sum = 0.0;
    int e, t, j, j1, j2, found;
    prior_s(Pps, 1.0);
    TEST_ASSERT_EQUAL_INT(0, mtt_split_assoc_init(4, XPS, Pps, R, NULL, NULL, 4, Z6, PD6, PG6, GAMMA,
                                                  (mtt_real)ref6_V, MTT_R(0.0), &as));
    TEST_ASSERT_EQUAL_INT(0, mtt_split_joint(&as));
    /* every event of the brute-force enumeration, and no other */
    for (j1 = -1; j1 < 4; ++j1) {
        for (j2 = -1; j2 < 4; ++j2) {
            const double p = (double)mtt_split_event_weight(&as, (int16_t)j1, (int16_t)j2) / (double)as.lik;
            found = 0;
            for (e = 0; e < 13; ++e) {
                if (ref6_events[e].j1 == j1 && ref6_events[e].j2 == j2) {
                    TV_ASSERT_REAL_MSG(ref6_events[e].p, p, "P(theta)");
                    found = 1;
                }
            }
            if (!found) {
                TEST_ASSERT_TRUE_MESSAGE(p == 0.0, "an infeasible event has weight");
            }
            sum += p;
        }
    }
    TV_ASSERT_REAL(1.0, sum);
    for (t = 0; t < 2; ++t) {
        double s = (double)as.beta_miss[t];
        TV_ASSERT_VEC(ref6_beta[t], as.beta[t], 4);
        TV_ASSERT_REAL(ref6_miss[t], as.beta_miss[t]);
        for (j = 0; j < 4; ++j) {
            s += (double)as.beta[t][j];
        }
        TV_ASSERT_REAL(1.0, s);
    }
    TV_ASSERT_REAL(ref6_beta0, as.beta0);
    TV_ASSERT_REAL(ref6_lik, as.lik);
}

/* Known clutter density (lambda = 2e-4): the parametric events. */
static void test_split_events_parametric(void)
{
    mtt_split_cov Pps;
    mtt_split_assoc as;
    double sum = 0.0;
    int e;
    prior_s(Pps, 1.0);
    TEST_ASSERT_EQUAL_INT(0, mtt_split_assoc_init(4, XPS, Pps, R, NULL, NULL, 4, Z6, PD6, PG6, GAMMA, MTT_R(0.0),
                                                  MTT_R(2e-4), &as));
    TEST_ASSERT_EQUAL_INT(0, mtt_split_joint(&as));
    for (e = 0; e < 13; ++e) {
        const double p = (double)mtt_split_event_weight(&as, (int16_t)ref6p_events[e].j1,
                                                        (int16_t)ref6p_events[e].j2) / (double)as.lik;
        TV_ASSERT_REAL_MSG(ref6p_events[e].p, p, "P(theta)");
        sum += p;
    }
    TV_ASSERT_REAL(1.0, sum);
    TV_ASSERT_REAL(ref6p_lik, as.lik);
    /* neither a clutter density nor a volume: refused */
    TEST_ASSERT_EQUAL_INT(-1, mtt_split_assoc_init(4, XPS, Pps, R, NULL, NULL, 4, Z6, PD6, PG6, GAMMA, MTT_R(0.0),
                                                   MTT_R(0.0), &as));
}

static void test_split_update_reference(void)
{
    mtt_split_cov Pps, Ps;
    mtt_split_state xs;
    mtt_split_assoc as;
    prior_s(Pps, 1.0);
    TEST_ASSERT_EQUAL_INT(0, mtt_split_assoc_init(4, XPS, Pps, R, NULL, NULL, 4, Z6, PD6, PG6, GAMMA,
                                                  (mtt_real)ref6_V, MTT_R(0.0), &as));
    TEST_ASSERT_EQUAL_INT(0, mtt_split_joint(&as));
    TEST_ASSERT_EQUAL_INT(0, mtt_split_update(&wk, &as, XPS, Pps, R, NULL, NULL, Z6, xs, Ps));
    TV_ASSERT_VEC(ref6_xs, xs, 8);
    assert_cov8(ref6_Ps, Ps, "Ps");
    assert_psd(Ps, 8);
}

/* PD = PG = 1, no cross covariance, one measurement z[t] in each target's
 * gate only: a single event, and the coupled update (xs, Ps) is two Kalman
 * updates, each with its measurement's R (rj[t]; rj NULL: R). */
static void check_independent(const mtt_real *const rj[2], mtt_real z[2][2], mtt_split_state xs, mtt_split_cov Ps)
{
    mtt_split_cov Pps;
    mtt_split_state xps;
    mtt_split_assoc as;
    mtt_real P[MTT_MAX_STATE][MTT_MAX_STATE], Pk[MTT_MAX_STATE][MTT_MAX_STATE];
    mtt_real S[3], Si[3], det, K[MTT_MAX_STATE][2], xk[MTT_MAX_STATE], nu[1][2];
    mtt_real one[1] = {MTT_R(1.0)};
    int t, i, k;
    memcpy(xps, XPS, sizeof XPS);
    xps[4] += MTT_R(60.0);
    prior_s(Pps, 0.0);
    TEST_ASSERT_EQUAL_INT(0, mtt_split_assoc_init(4, xps, Pps, R, rj, NULL, 2, z, MTT_R(1.0), MTT_R(1.0), GAMMA,
                                                  MTT_R(2000.0), MTT_R(0.0), &as));
    TEST_ASSERT_EQUAL_INT(0, mtt_split_joint(&as));
    TV_ASSERT_REAL(1.0, as.beta[0][0]);
    TV_ASSERT_REAL(1.0, as.beta[1][1]);
    TEST_ASSERT_TRUE(as.beta0 == MTT_R(0.0));
    TEST_ASSERT_EQUAL_INT(0, mtt_split_update(&wk, &as, xps, Pps, R, rj, NULL, z, xs, Ps));
    for (t = 0; t < 2; ++t) {
        const int o = 4 * t;
        const mtt_real *Rt = (rj != NULL) ? rj[t] : R;
        for (i = 0; i < 4; ++i) {
            for (k = 0; k < 4; ++k) {
                P[i][k] = Pps[o + i][o + k];
            }
        }
        TEST_ASSERT_EQUAL_INT(0, mtt_kalman_innov(P, Rt, S, Si, &det, K));
        nu[0][0] = z[t][0] - xps[o];
        nu[0][1] = z[t][1] - xps[o + 1];
        mtt_kalman_pda(&xps[o], P, K, Si, Rt, 1, nu, one, MTT_R(0.0), xk, Pk);
        for (i = 0; i < 4; ++i) {
            TV_ASSERT_REAL(xk[i], xs[o + i]);
            for (k = 0; k < 4; ++k) {
                TV_ASSERT_REAL(Pk[i][k], Ps[o + i][o + k]);
                TEST_ASSERT_TRUE(fabs((double)Ps[i][4 + k]) <= 1e-4); /* no cross covariance appears */
            }
        }
    }
    assert_psd(Ps, 8);
}

static void test_split_update_independent(void)
{
    mtt_real z[2][2] = {{MTT_R(103.0), MTT_R(49.0)}, {MTT_R(174.0), MTT_R(45.0)}};
    mtt_split_state xs;
    mtt_split_cov Ps;
    check_independent(NULL, z, xs, Ps);
}

/* No measurement: beta0 = 1, the prediction stays, Lambda_6 = (1 - PD PG)^2. */
static void test_split_no_measurement(void)
{
    mtt_split_cov Pps, Ps;
    mtt_split_state xs;
    mtt_split_assoc as;
    int i, k;
    prior_s(Pps, 1.0);
    TEST_ASSERT_EQUAL_INT(0, mtt_split_assoc_init(4, XPS, Pps, R, NULL, NULL, 0, Z6, PD6, PG6, GAMMA, MTT_R(100.0), MTT_R(0.0), &as));
    TEST_ASSERT_EQUAL_INT(0, mtt_split_joint(&as));
    TV_ASSERT_REAL(1.0, as.beta0);
    TV_ASSERT_REAL((1.0 - 0.9 * 0.99) * (1.0 - 0.9 * 0.99), as.lik);
    TEST_ASSERT_EQUAL_INT(0, mtt_split_update(&wk, &as, XPS, Pps, R, NULL, NULL, Z6, xs, Ps));
    for (i = 0; i < 8; ++i) {
        TV_ASSERT_REAL(XPS[i], xs[i]);
        for (k = 0; k < 8; ++k) {
            TV_ASSERT_REAL(Pps[i][k], Ps[i][k]);
        }
    }
    /* PD = PG = 1 and nothing gated: every event weighs 0 -> refused */
    TEST_ASSERT_EQUAL_INT(0, mtt_split_assoc_init(4, XPS, Pps, R, NULL, NULL, 0, Z6, MTT_R(1.0), MTT_R(1.0), GAMMA,
                                                  MTT_R(100.0), MTT_R(0.0), &as));
    TEST_ASSERT_EQUAL_INT(-1, mtt_split_joint(&as));
}

/* ---- model 5's velocity impulse ---- */

/* dv = 5, dt = 2: per axis position dv^2 dt^2 / 2 = 50, cross dv^2 dt / 2
 * = 25, velocity dv^2 = 25.  Across the course (3, 4)/5 the normal is
 * (-0.8, 0.6): each block times n n' = [0.64 -0.48; -0.48 0.36], nothing
 * along the course. */
static void test_impulse_q(void)
{
    mtt_cov Q;
    /* along the course in position and in velocity */
    const mtt_real u[4] = {MTT_R(0.6), MTT_R(0.8), MTT_R(0.6), MTT_R(0.8)};
    int a, b;
    mtt_split_impulse_q(MTT_R(2.0), MTT_R(5.0), 0, MTT_R(3.0), MTT_R(4.0), Q);
    TV_ASSERT_REAL(50.0, Q[0][0]);
    TV_ASSERT_REAL(50.0, Q[1][1]);
    TV_ASSERT_REAL(0.0, Q[0][1]);
    TV_ASSERT_REAL(25.0, Q[0][2]);
    TV_ASSERT_REAL(25.0, Q[3][3]);
    mtt_split_impulse_q(MTT_R(2.0), MTT_R(5.0), 1, MTT_R(3.0), MTT_R(4.0), Q);
    TV_ASSERT_REAL(0.64 * 50.0, Q[0][0]);
    TV_ASSERT_REAL(-0.48 * 50.0, Q[0][1]);
    TV_ASSERT_REAL(0.36 * 50.0, Q[1][1]);
    TV_ASSERT_REAL(0.64 * 25.0, Q[0][2]);
    TV_ASSERT_REAL(-0.48 * 25.0, Q[1][2]);
    TV_ASSERT_REAL(0.36 * 25.0, Q[3][3]);
    for (a = 0; a < 4; ++a) { /* Q u = 0 and Q symmetric: no impulse along the course */
        mtt_real s = MTT_R(0.0);
        for (b = 0; b < 4; ++b) {
            s += Q[a][b] * u[b];
            TV_ASSERT_REAL(Q[b][a], Q[a][b]);
        }
        TEST_ASSERT_TRUE(mtt_fabs(s) < MTT_R(1e-4)); /* against entries of 50: rounding only */
    }
    /* at rest there is no course: per axis */
    mtt_split_impulse_q(MTT_R(2.0), MTT_R(5.0), 1, MTT_R(0.0), MTT_R(0.0), Q);
    TV_ASSERT_REAL(50.0, Q[1][1]);
    TV_ASSERT_REAL(0.0, Q[0][1]);
    TV_ASSERT_REAL(0.0, Q[1][2]);
}

/* ---- decoupling and conversion ---- */

static void test_decouple_reference(void)
{
    mtt_split_cov Pps;
    mtt_split_state xps;
    mtt_real d2 = MTT_R(0.0);
    prior_s(Pps, 1.0);
    TEST_ASSERT_EQUAL_INT(0, mtt_split_decouple(4, XPS, Pps, R, MTT_SPLIT_CHI2_99, &d2));
    TV_ASSERT_REAL(ref_d2, d2);
    memcpy(xps, XPS, sizeof XPS);
    xps[4] += MTT_R(60.0);
    TEST_ASSERT_EQUAL_INT(1, mtt_split_decouple(4, xps, Pps, R, MTT_SPLIT_CHI2_99, &d2));
    TV_ASSERT_REAL(ref_d2_far, d2);
    TV_ASSERT_REAL(9.210340371976184, MTT_SPLIT_CHI2_99);
}

/* S1 + S2 = 4 I: d2 = |z1 - z2|^2 / 4; inclusive boundary (>= c). */
static void test_decouple_boundary(void)
{
    mtt_split_cov Pps;
    mtt_split_state xps;
    const mtt_real Ri[3] = {MTT_R(1.0), MTT_R(0.0), MTT_R(1.0)};
    mtt_real d2;
    int i;
    memset(Pps, 0, sizeof Pps);
    memset(xps, 0, sizeof xps);
    for (i = 0; i < 8; ++i) {
        Pps[i][i] = MTT_R(1.0);
    }
    xps[4] = MTT_R(6.0); /* d2 = 36 / 4 = 9 exactly */
    TEST_ASSERT_EQUAL_INT(1, mtt_split_decouple(4, xps, Pps, Ri, MTT_R(9.0), &d2));
    TEST_ASSERT_TRUE(d2 == MTT_R(9.0));
    xps[4] = MTT_R(5.99);
    TEST_ASSERT_EQUAL_INT(0, mtt_split_decouple(4, xps, Pps, Ri, MTT_R(9.0), &d2));
    /* the chi-square 0.99 threshold: sqrt(4 * 9.2103) = 6.0697 */
    xps[4] = MTT_R(6.0700);
    TEST_ASSERT_EQUAL_INT(1, mtt_split_decouple(4, xps, Pps, Ri, MTT_SPLIT_CHI2_99, &d2));
    xps[4] = MTT_R(6.0694);
    TEST_ASSERT_EQUAL_INT(0, mtt_split_decouple(4, xps, Pps, Ri, MTT_SPLIT_CHI2_99, &d2));
    Pps[0][0] = MTT_R(-5.0); /* S1 not positive definite */
    TEST_ASSERT_EQUAL_INT(-1, mtt_split_decouple(4, xps, Pps, Ri, MTT_SPLIT_CHI2_99, &d2));
}

static void test_separate(void)
{
    mtt_real P[MTT_MAX_STATE][MTT_MAX_STATE], x1[MTT_MAX_STATE], x2[MTT_MAX_STATE];
    mtt_real P1[MTT_MAX_STATE][MTT_MAX_STATE], P2[MTT_MAX_STATE][MTT_MAX_STATE];
    mtt_split_state xs;
    mtt_split_cov Ps;
    uint8_t cl[5];
    mtt_real bn[5], lik;
    int i, k;
    /* the model-5 result: parent = half 1 (largest beta), child = half 2 */
    prior1(P);
    TEST_ASSERT_EQUAL_INT(0, mtt_split_just(&wk, 4, XP, P, R, NULL, NULL, 5, Z5, B5, (mtt_real)ref5_V, xs, Ps, cl, bn, &lik));
    TEST_ASSERT_EQUAL_INT(0, mtt_split_separate(&wk, 4, xs, Ps, x1, P1, x2, P2));
    for (i = 0; i < 4; ++i) {
        TV_ASSERT_REAL(ref5_xs[i], x1[i]);
        TV_ASSERT_REAL(ref5_xs[4 + i], x2[i]);
        for (k = 0; k < 4; ++k) {
            TV_ASSERT_REAL(ref5_Ps[8 * i + k], P1[i][k]);
            TV_ASSERT_REAL(ref5_Ps[8 * (4 + i) + 4 + k], P2[i][k]);
            TEST_ASSERT_TRUE(P1[i][k] == P1[k][i] && P2[i][k] == P2[k][i]);
        }
    }
    /* a half that is not positive definite: refused, nothing written */
    Ps[5][5] = MTT_R(-1.0);
    x1[0] = MTT_R(-7.0);
    TEST_ASSERT_EQUAL_INT(-1, mtt_split_separate(&wk, 4, xs, Ps, x1, P1, x2, P2));
    TV_ASSERT_REAL(-7.0, x1[0]);
}

/* Deterministic pseudo-random cases (an LCG): for any stacked prior and any
 * measurements, the event probabilities sum to 1, each target's marginals
 * sum to 1, and the updated covariances of models 5 and 6 are symmetric
 * positive semi-definite. */
static uint32_t lcg_state = 12345u;
static double urand(double lo, double hi)
{
    lcg_state = lcg_state * 1664525u + 1013904223u;
    return lo + (hi - lo) * (double)(lcg_state >> 8) / 16777216.0;
}

#if MTT_WITH_MEAS_COV
/* ---- a covariance per detection (ALGORITHMS.md §3.1, §14.3) ---- */

/* The same R for every measurement through Rj: the mixture of single
 * updates equals the shared-R forms, i.e. the numpy references. */
static void test_own_r_equal_is_the_shared_form(void)
{
    const mtt_real *rj[5] = {R, R, R, R, R};
    mtt_real P[MTT_MAX_STATE][MTT_MAX_STATE];
    mtt_split_state xs, xs0;
    mtt_split_cov Ps, Ps0, Pps;
    mtt_split_assoc as;
    uint8_t cl[5];
    mtt_real bn[5], lik = MTT_R(0.0), lk = MTT_R(0.0);
    int j, i, k;
    prior1(P);
    TEST_ASSERT_EQUAL_INT(0, mtt_split_just(&wk, 4, XP, P, R, rj, NULL, 5, Z5, B5, (mtt_real)ref5_V, xs0, Ps0, cl, bn,
                                            &lik));
    for (j = 0; j < 5; ++j) {
        TEST_ASSERT_EQUAL_INT(ref5_cluster[j], cl[j]);
    }
    TV_ASSERT_VEC(ref5_xs, xs0, 8);
    assert_cov8(ref5_Ps, Ps0, "Ps own");
    assert_psd(Ps0, 8);
    TV_ASSERT_REAL(ref5_lik, lik);
    memcpy(xs, xs0, sizeof xs);
    memcpy(Ps, Ps0, sizeof Ps);
    TEST_ASSERT_EQUAL_INT(0, mtt_split_known(&wk, 4, XP, P, R, rj, NULL, 5, Z5, cl, bn, (mtt_real)ref_known[0].dv,
                                             MTT_R(1.0), (uint8_t)ref_known[0].n_off, (mtt_real)ref5_V, xs, Ps,
                                             &lk));
    TV_ASSERT_REAL(ref_known[0].lik, lk);
    for (i = 0; i < 4; ++i) {
        TV_ASSERT_REAL(ref_known[0].x2[i], xs[4 + i]);
        for (k = 0; k < 4; ++k) {
            TV_ASSERT_REAL(ref_known[0].P2[4 * i + k], Ps[4 + i][4 + k]);
        }
    }
    prior_s(Pps, 1.0);
    TEST_ASSERT_EQUAL_INT(0, mtt_split_assoc_init(4, XPS, Pps, R, rj, NULL, 4, Z6, PD6, PG6, GAMMA, (mtt_real)ref6_V,
                                                  MTT_R(0.0), &as));
    TEST_ASSERT_EQUAL_INT(0, mtt_split_joint(&as));
    TV_ASSERT_REAL(ref6_lik, as.lik);
    TEST_ASSERT_EQUAL_INT(0, mtt_split_update(&wk, &as, XPS, Pps, R, rj, NULL, Z6, xs, Ps));
    TV_ASSERT_VEC(ref6_xs, xs, 8);
    assert_cov8(ref6_Ps, Ps, "Ps6 own");
    assert_psd(Ps, 8);
}

/* The Kalman update of (xp, P) with z of noise Rr, in double: x, P, A =
 * I - K H and N(z; H xp, S). */
static double kalman_gen_d(const double xp[4], double Pp[4][4], const double Rr[3], const mtt_real z[2],
                           double x[4], double Pu[4][4], double A[4][4])
{
    const double s0 = Pp[0][0] + Rr[0], s1 = Pp[0][1] + Rr[1], s2 = Pp[1][1] + Rr[2];
    const double det = s0 * s2 - s1 * s1, nx = (double)z[0] - xp[0], ny = (double)z[1] - xp[1];
    const double si[3] = {s2 / det, -s1 / det, s0 / det};
    double K[4][2], T[4][4];
    int i, k, l;
    for (i = 0; i < 4; ++i) {
        K[i][0] = Pp[i][0] * si[0] + Pp[i][1] * si[1];
        K[i][1] = Pp[i][0] * si[1] + Pp[i][1] * si[2];
        x[i] = xp[i] + K[i][0] * nx + K[i][1] * ny;
        for (k = 0; k < 4; ++k) {
            A[i][k] = (i == k ? 1.0 : 0.0) - (k == 0 ? K[i][0] : 0.0) - (k == 1 ? K[i][1] : 0.0);
        }
    }
    for (i = 0; i < 4; ++i) {
        for (k = 0; k < 4; ++k) {
            T[i][k] = 0.0;
            for (l = 0; l < 4; ++l) {
                T[i][k] += A[i][l] * Pp[l][k];
            }
        }
    }
    for (i = 0; i < 4; ++i) {
        for (k = 0; k < 4; ++k) {
            Pu[i][k] = K[i][0] * (Rr[0] * K[k][0] + Rr[1] * K[k][1]) + K[i][1] * (Rr[1] * K[k][0] + Rr[2] * K[k][1]);
            for (l = 0; l < 4; ++l) {
                Pu[i][k] += T[i][l] * A[k][l];
            }
        }
    }
    return exp(-0.5 * (si[0] * nx * nx + 2.0 * si[1] * nx * ny + si[2] * ny * ny)) / (2.0 * 3.14159265358979323846 * sqrt(det));
}

/* kalman_gen_d of (XP, PP). */
static double kalman_d(const double Rr[3], const mtt_real z[2], double x[4], double Pu[4][4], double A[4][4])
{
    const double xp[4] = {(double)XP[0], (double)XP[1], (double)XP[2], (double)XP[3]};
    double Pp[4][4];
    memcpy(Pp, PP, sizeof Pp);
    return kalman_gen_d(xp, Pp, Rr, z, x, Pu, A);
}

/* Model 5 with two measurements, the child's with an own R 25 times R:
 * each half is the Kalman update with its measurement's R, the cross
 * covariance A_1 PP A_2', the likelihood V N(z_1; S_1) V N(z_2; S_2)
 * (hand-derived in double above); the child half moves less towards its
 * measurement than with R. */
static void test_own_r_just_two_hand(void)
{
    const mtt_real Rbig[3] = {MTT_R(225.0), MTT_R(37.5), MTT_R(300.0)};
    const double Rd[2][3] = {{9.0, 1.5, 12.0}, {225.0, 37.5, 300.0}};
    const mtt_real *rj[2] = {R, Rbig}, *req[2] = {R, R};
    const mtt_real b[2] = {MTT_R(0.6), MTT_R(0.4)};
    const double V = 500.0;
    mtt_real z[2][2] = {{MTT_R(104.0), MTT_R(48.0)}, {MTT_R(93.0), MTT_R(57.0)}};
    mtt_real P[MTT_MAX_STATE][MTT_MAX_STATE], bn[2], lik = MTT_R(0.0), lik_eq = MTT_R(0.0);
    mtt_split_state xs, xq;
    mtt_split_cov Ps, Pq;
    uint8_t cl[2];
    double x[2][4], Pu[2][4][4], A[2][4][4], g[2], e_own, e_eq;
    int h, i, k, l, q;
    prior1(P);
    TEST_ASSERT_EQUAL_INT(0, mtt_split_just(&wk, 4, XP, P, R, rj, NULL, 2, z, b, (mtt_real)V, xs, Ps, cl, bn, &lik));
    TEST_ASSERT_EQUAL_INT(0, cl[0]);
    TEST_ASSERT_EQUAL_INT(1, cl[1]);
    for (h = 0; h < 2; ++h) {
        g[h] = kalman_d(Rd[h], z[h], x[h], Pu[h], A[h]);
        for (i = 0; i < 4; ++i) {
            TV_ASSERT_REAL(x[h][i], xs[4 * h + i]);
            for (k = 0; k < 4; ++k) {
                TV_ASSERT_REAL(Pu[h][i][k], Ps[4 * h + i][4 * h + k]);
            }
        }
    }
    for (i = 0; i < 4; ++i) {
        for (k = 0; k < 4; ++k) {
            double c = 0.0;
            for (l = 0; l < 4; ++l) {
                for (q = 0; q < 4; ++q) {
                    c += A[0][i][l] * PP[l][q] * A[1][k][q];
                }
            }
            TEST_ASSERT_TRUE(fabs(c - (double)Ps[i][4 + k]) <= 1e-4 * (1.0 + fabs(c)));
            TEST_ASSERT_TRUE(Ps[i][4 + k] == Ps[4 + k][i]);
        }
    }
    TV_ASSERT_REAL(V * g[0] * V * g[1], lik);
    assert_psd(Ps, 8);
    /* against R for both: the child half ends farther from its measurement */
    TEST_ASSERT_EQUAL_INT(0, mtt_split_just(&wk, 4, XP, P, R, req, NULL, 2, z, b, (mtt_real)V, xq, Pq, cl, bn, &lik_eq));
    e_own = hypot((double)xs[4] - (double)z[1][0], (double)xs[5] - (double)z[1][1]);
    e_eq = hypot((double)xq[4] - (double)z[1][0], (double)xq[5] - (double)z[1][1]);
    TEST_ASSERT_TRUE(e_own > e_eq + 3.0);
    TEST_ASSERT_TRUE(Ps[4][4] > Pq[4][4]);
    TV_ASSERT_REAL((double)xq[0], xs[0]); /* the parent's half is the same */
}

/* Model 6 with PD = PG = 1 and one measurement in each target's gate
 * (check_independent): with their own R the coupled update is two Kalman
 * updates, each with its measurement's R; target 2, whose R is 10 times
 * R, moves less towards its measurement than with R. */
static void test_own_r_split_update_independent(void)
{
    const mtt_real Rbig[3] = {MTT_R(90.0), MTT_R(15.0), MTT_R(120.0)};
    const mtt_real *rj[2] = {R, Rbig}, *req[2] = {R, R};
    mtt_real z[2][2] = {{MTT_R(103.0), MTT_R(49.0)}, {MTT_R(178.0), MTT_R(43.0)}};
    mtt_split_state xs, xq;
    mtt_split_cov Ps, Pq;
    check_independent(rj, z, xs, Ps);
    check_independent(req, z, xq, Pq);
    TEST_ASSERT_TRUE(hypot((double)(xs[4] - z[1][0]), (double)(xs[5] - z[1][1])) >
                     hypot((double)(xq[4] - z[1][0]), (double)(xq[5] - z[1][1])) + 1.0);
    TV_ASSERT_REAL((double)xq[0], xs[0]);
    TEST_ASSERT_TRUE(Ps[4][4] > Pq[4][4]);
}

/* ---- range rates (ALGORITHMS.md §3.2, §14.3): the formulas in double ---- */

static const mtt_real SENS[2] = {MTT_R(-200.0), MTT_R(300.0)};
#define RR_SIGMA 0.5
#define RR_VMAX 40.0

/* h = e . v (e the unit vector from SENS to the position) and its
 * Jacobian H over x, y, vx, vy, in double. */
static double rdot_hd(const double x[4], double H[4])
{
    const double dx = x[0] - (double)SENS[0], dy = x[1] - (double)SENS[1], r = hypot(dx, dy);
    const double ux = dx / r, uy = dy / r, h = ux * x[2] + uy * x[3];
    H[0] = (x[2] - ux * h) / r;
    H[1] = (x[3] - uy * h) / r;
    H[2] = ux;
    H[3] = uy;
    return h;
}

/* The scalar EKF step at x: K = P H' / (H P H' + s^2), x += K (rr - h(x)),
 * P = (I - K H) P (I - K H)' + K s^2 K'; M = I - K H. */
static void ekf_rdot_d(double x[4], double P[4][4], double rr, double M[4][4])
{
    double H[4], PH[4], K[4], T[4][4], s = RR_SIGMA * RR_SIGMA, h = rdot_hd(x, H);
    int i, k, l;
    for (i = 0; i < 4; ++i) {
        PH[i] = 0.0;
        for (k = 0; k < 4; ++k) {
            PH[i] += P[i][k] * H[k];
        }
    }
    for (k = 0; k < 4; ++k) {
        s += H[k] * PH[k];
    }
    for (i = 0; i < 4; ++i) {
        K[i] = PH[i] / s;
        x[i] += K[i] * (rr - h);
        for (k = 0; k < 4; ++k) {
            M[i][k] = (i == k ? 1.0 : 0.0) - K[i] * H[k];
        }
    }
    for (i = 0; i < 4; ++i) {
        for (k = 0; k < 4; ++k) {
            T[i][k] = 0.0;
            for (l = 0; l < 4; ++l) {
                T[i][k] += M[i][l] * P[l][k];
            }
        }
    }
    for (i = 0; i < 4; ++i) {
        for (k = 0; k < 4; ++k) {
            P[i][k] = K[i] * RR_SIGMA * RR_SIGMA * K[k];
            for (l = 0; l < 4; ++l) {
                P[i][k] += T[i][l] * M[k][l];
            }
        }
    }
}

/* The factor 2 vmax N(nu'; 0, s') of a range rate rr against (xp, P)
 * with a detection at z of noise Rr: nu' = rr - h - C S^-1 nu, s' = H P H'
 * + s^2 - C S^-1 C', C = H P_pos, S = P_pos + Rr; *nu2 = nu'^2 / s'. */
static double rdot_factor_d(const double xp[4], const double P[4][4], const double Rr[3], const mtt_real z[2],
                            double rr, double *nu2)
{
    const double s0 = P[0][0] + Rr[0], s1 = P[0][1] + Rr[1], s2 = P[1][1] + Rr[2], det = s0 * s2 - s1 * s1;
    const double nx = (double)z[0] - xp[0], ny = (double)z[1] - xp[1];
    double H[4], C[2], a0, a1, nu, s = RR_SIGMA * RR_SIGMA, h = rdot_hd(xp, H);
    int i, k;
    for (i = 0; i < 2; ++i) {
        C[i] = 0.0;
        for (k = 0; k < 4; ++k) {
            C[i] += H[k] * P[k][i];
        }
    }
    for (i = 0; i < 4; ++i) {
        for (k = 0; k < 4; ++k) {
            s += H[i] * P[i][k] * H[k];
        }
    }
    a0 = (s2 * C[0] - s1 * C[1]) / det;
    a1 = (s0 * C[1] - s1 * C[0]) / det;
    nu = rr - h - (a0 * nx + a1 * ny);
    s -= a0 * C[0] + a1 * C[1];
    *nu2 = nu * nu / s;
    return 2.0 * RR_VMAX * exp(-0.5 * nu * nu / s) / sqrt(2.0 * 3.14159265358979323846 * s);
}

static mtt_split_rdot rdot_set(const mtt_real *const *rr)
{
    mtt_split_rdot rd;
    rd.rr = rr;
    rd.sensor = SENS;
    rd.gamma = GAMMA;
    rd.vmax = MTT_R(RR_VMAX);
    return rd;
}

/* Model 5 with two measurements that have range rates: each half is the
 * Kalman update with its measurement, then the scalar EKF step of its
 * range rate at that state; the cross covariance (M_1 A_1) PP (M_2 A_2)';
 * the likelihood V N_1 f_1 V N_2 f_2, f the range rate's factor (all in
 * double above). */
static void test_rdot_just_two_hand(void)
{
    const double Rd[3] = {9.0, 1.5, 12.0}, xp[4] = {100.0, 50.0, 10.0, -5.0};
    const mtt_real *rj[2] = {R, R};
    const mtt_real b[2] = {MTT_R(0.6), MTT_R(0.4)};
    const double V = 500.0;
    mtt_real z[2][2] = {{MTT_R(104.0), MTT_R(48.0)}, {MTT_R(93.0), MTT_R(57.0)}};
    mtt_real rrv[2][2], P[MTT_MAX_STATE][MTT_MAX_STATE], bn[2], lik = MTT_R(0.0);
    const mtt_real *rr[2] = {rrv[0], rrv[1]};
    mtt_split_rdot rd = rdot_set(rr);
    mtt_split_state xs;
    mtt_split_cov Ps;
    uint8_t cl[2];
    double x[2][4], Pu[2][4][4], A[2][4][4], M[4][4], MA[2][4][4], g[2], f[2], H[4], nu2, h0;
    int c, i, k, l, q;
    h0 = rdot_hd(xp, H);
    rrv[0][0] = (mtt_real)(h0 + 1.5); /* inside the gate, off the prediction */
    rrv[1][0] = (mtt_real)(h0 - 2.0);
    rrv[0][1] = rrv[1][1] = (mtt_real)(RR_SIGMA * RR_SIGMA);
    prior1(P);
    TEST_ASSERT_EQUAL_INT(0, mtt_split_just(&wk, 4, XP, P, R, rj, &rd, 2, z, b, (mtt_real)V, xs, Ps, cl, bn, &lik));
    TEST_ASSERT_EQUAL_INT(0, cl[0]);
    TEST_ASSERT_EQUAL_INT(1, cl[1]);
    for (c = 0; c < 2; ++c) {
        g[c] = kalman_d(Rd, z[c], x[c], Pu[c], A[c]);
        f[c] = rdot_factor_d(xp, PP, Rd, z[c], (double)rrv[c][0], &nu2);
        TEST_ASSERT_TRUE(nu2 > 0.01 && nu2 < (double)GAMMA);
        ekf_rdot_d(x[c], Pu[c], (double)rrv[c][0], M);
        for (i = 0; i < 4; ++i) {
            for (k = 0; k < 4; ++k) {
                MA[c][i][k] = 0.0;
                for (l = 0; l < 4; ++l) {
                    MA[c][i][k] += M[i][l] * A[c][l][k];
                }
            }
        }
        for (i = 0; i < 4; ++i) {
            TV_ASSERT_REAL(x[c][i], xs[4 * c + i]);
            for (k = 0; k < 4; ++k) {
                TV_ASSERT_REAL(Pu[c][i][k], Ps[4 * c + i][4 * c + k]);
            }
        }
    }
    for (i = 0; i < 4; ++i) {
        for (k = 0; k < 4; ++k) {
            double v = 0.0;
            for (l = 0; l < 4; ++l) {
                for (q = 0; q < 4; ++q) {
                    v += MA[0][i][l] * PP[l][q] * MA[1][k][q];
                }
            }
            TEST_ASSERT_TRUE(fabs(v - (double)Ps[i][4 + k]) <= 1e-4 * (1.0 + fabs(v)));
        }
    }
    TV_ASSERT_REAL(V * g[0] * f[0] * V * g[1] * f[1], lik);
    assert_psd(Ps, 8);
}

/* Model 6's event factors: two detections at target 1's predicted
 * position, one whose range rate is target 1's predicted radial velocity,
 * one 8 sigma_rdot off, and one far outside the range rate's gate.  The
 * factor ratio is exp(nu'^2 / (2 s')) (nu = 0: nu' = rr - h), from the
 * formulas in double; the third is not feasible for target 1.  Target 2
 * is 60 away (outside every gate): the association weights follow. */
static void test_rdot_events_weigh_the_matching_range_rate(void)
{
    const double Rd[3] = {9.0, 1.5, 12.0}, xp[4] = {100.0, 50.0, 10.0, -5.0};
    const mtt_real *rj[3] = {R, R, R};
    mtt_real z[3][2] = {{MTT_R(100.0), MTT_R(50.0)}, {MTT_R(100.0), MTT_R(50.0)}, {MTT_R(100.0), MTT_R(50.0)}};
    mtt_real rrv[3][2];
    const mtt_real *rr[3] = {rrv[0], rrv[1], rrv[2]};
    mtt_split_rdot rd = rdot_set(rr);
    mtt_split_cov Pps;
    mtt_split_state xps;
    mtt_split_assoc as, as0;
    double H[4], h, f0, f1, nu2;
    int j;
    memcpy(xps, XPS, sizeof XPS);
    xps[4] += MTT_R(60.0);
    prior_s(Pps, 0.0);
    h = rdot_hd(xp, H);
    for (j = 0; j < 3; ++j) {
        rrv[j][1] = (mtt_real)(RR_SIGMA * RR_SIGMA);
    }
    rrv[0][0] = (mtt_real)h;
    rrv[1][0] = (mtt_real)(h + 8.0 * RR_SIGMA);
    rrv[2][0] = (mtt_real)(h + 200.0);
    TEST_ASSERT_EQUAL_INT(0, mtt_split_assoc_init(4, xps, Pps, R, rj, &rd, 3, z, PD6, PG6, GAMMA, MTT_R(0.0),
                                                  MTT_R(1e-3), &as));
    TEST_ASSERT_EQUAL_INT(0, mtt_split_assoc_init(4, xps, Pps, R, rj, NULL, 3, z, PD6, PG6, GAMMA, MTT_R(0.0),
                                                  MTT_R(1e-3), &as0));
    f0 = rdot_factor_d(xp, PP, Rd, z[0], (double)rrv[0][0], &nu2);
    f1 = rdot_factor_d(xp, PP, Rd, z[1], (double)rrv[1][0], &nu2);
    TEST_ASSERT_TRUE(nu2 > 1.0 && nu2 < (double)GAMMA); /* several sigma off, inside the gate */
    TV_ASSERT_REAL(f0 * (double)as0.a[0][0], as.a[0][0]);
    TV_ASSERT_REAL(f0 / f1, (double)as.a[0][0] / (double)as.a[0][1]);
    TEST_ASSERT_TRUE(f0 / f1 > 1.5);
    TEST_ASSERT_TRUE(as0.a[0][2] > MTT_R(0.0));
    TEST_ASSERT_TRUE(as.a[0][2] == MTT_R(0.0)); /* outside the range rate's gate */
    TEST_ASSERT_EQUAL_INT(0, mtt_split_joint(&as));
    TV_ASSERT_REAL(f0 / f1, (double)as.beta[0][0] / (double)as.beta[0][1]);
    TEST_ASSERT_TRUE(as.beta[0][2] == MTT_R(0.0));
}

/* Model 6 with PD = PG = 1, no cross covariance and one detection with a
 * range rate in each target's gate (check_independent's single event):
 * each target's block is its Kalman update, then the scalar EKF step of
 * its detection's range rate (K = P H' / (H P H' + s^2), in double); its
 * radial velocity moves toward the measured range rate. */
static void test_rdot_split_update_ekf_step(void)
{
    const double Rd[3] = {9.0, 1.5, 12.0};
    const mtt_real *rj[2] = {R, R};
    mtt_real z[2][2] = {{MTT_R(103.0), MTT_R(49.0)}, {MTT_R(174.0), MTT_R(45.0)}};
    mtt_real rrv[2][2];
    const mtt_real *rr[2] = {rrv[0], rrv[1]};
    mtt_split_rdot rd = rdot_set(rr);
    mtt_split_cov Pps, Ps;
    mtt_split_state xps, xs;
    mtt_split_assoc as;
    double xp[2][4], P[2][4][4], x[4], Pu[4][4], A[4][4], M[4][4], H[4], h_pos;
    int t, i, k;
    memcpy(xps, XPS, sizeof XPS);
    xps[4] += MTT_R(60.0);
    prior_s(Pps, 0.0);
    for (t = 0; t < 2; ++t) {
        for (i = 0; i < 4; ++i) {
            xp[t][i] = (double)xps[4 * t + i];
            for (k = 0; k < 4; ++k) {
                P[t][i][k] = (double)Pps[4 * t + i][4 * t + k];
            }
        }
        rrv[t][0] = (mtt_real)(rdot_hd(xp[t], H) + ((t == 0) ? 2.0 : -1.5));
        rrv[t][1] = (mtt_real)(RR_SIGMA * RR_SIGMA);
    }
    TEST_ASSERT_EQUAL_INT(0, mtt_split_assoc_init(4, xps, Pps, R, rj, &rd, 2, z, MTT_R(1.0), MTT_R(1.0), GAMMA,
                                                  MTT_R(2000.0), MTT_R(0.0), &as));
    TEST_ASSERT_EQUAL_INT(0, mtt_split_joint(&as));
    TV_ASSERT_REAL(1.0, as.beta[0][0]);
    TV_ASSERT_REAL(1.0, as.beta[1][1]);
    TEST_ASSERT_EQUAL_INT(0, mtt_split_update(&wk, &as, xps, Pps, R, rj, &rd, z, xs, Ps));
    for (t = 0; t < 2; ++t) {
        (void)kalman_gen_d(xp[t], P[t], Rd, z[t], x, Pu, A);
        h_pos = rdot_hd(x, H);
        ekf_rdot_d(x, Pu, (double)rrv[t][0], M);
        for (i = 0; i < 4; ++i) {
            TV_ASSERT_REAL(x[i], xs[4 * t + i]);
            for (k = 0; k < 4; ++k) {
                TV_ASSERT_REAL(Pu[i][k], Ps[4 * t + i][4 * t + k]);
                TEST_ASSERT_TRUE(fabs((double)Ps[i][4 + k]) <= 1e-4);
            }
        }
        {
            const double hx[4] = {(double)xs[4 * t], (double)xs[4 * t + 1], (double)xs[4 * t + 2],
                                  (double)xs[4 * t + 3]};
            TEST_ASSERT_TRUE(fabs(rdot_hd(hx, H) - (double)rrv[t][0]) < 0.5 * fabs(h_pos - (double)rrv[t][0]));
        }
    }
    assert_psd(Ps, 8);
}

/* The known-speed child with range rates: none (every rr NULL) is the
 * form without; range rates far outside their gate leave no likelihood. */
static void test_rdot_known(void)
{
    const mtt_real *rj[5] = {R, R, R, R, R}, *none[5] = {NULL, NULL, NULL, NULL, NULL};
    mtt_real rrv[2] = {MTT_R(500.0), MTT_R(RR_SIGMA * RR_SIGMA)};
    const mtt_real *far[5] = {rrv, rrv, rrv, rrv, rrv};
    mtt_split_rdot rn = rdot_set(none), rf = rdot_set(far);
    mtt_real P[MTT_MAX_STATE][MTT_MAX_STATE], bn[5], lik = MTT_R(0.0), l0 = MTT_R(0.0), l1 = MTT_R(-1.0);
    mtt_split_state xs;
    mtt_split_cov Ps;
    uint8_t cl[5];
    prior1(P);
    TEST_ASSERT_EQUAL_INT(0, mtt_split_just(&wk, 4, XP, P, R, rj, NULL, 5, Z5, B5, MTT_R(1000.0), xs, Ps, cl, bn, &lik));
    TEST_ASSERT_EQUAL_INT(0, mtt_split_known(&wk, 4, XP, P, R, rj, NULL, 5, Z5, cl, bn, MTT_R(5.0), MTT_R(1.0), 1u,
                                             MTT_R(1000.0), xs, Ps, &l0));
    TEST_ASSERT_EQUAL_INT(0, mtt_split_known(&wk, 4, XP, P, R, rj, &rn, 5, Z5, cl, bn, MTT_R(5.0), MTT_R(1.0), 1u,
                                             MTT_R(1000.0), xs, Ps, &l1));
    TEST_ASSERT_TRUE(l0 > MTT_R(0.0) && l1 == l0);
    TEST_ASSERT_EQUAL_INT(0, mtt_split_known(&wk, 4, XP, P, R, rj, &rf, 5, Z5, cl, bn, MTT_R(5.0), MTT_R(1.0), 1u,
                                             MTT_R(1000.0), xs, Ps, &l1));
    TEST_ASSERT_TRUE(l1 == MTT_R(0.0));
    TEST_ASSERT_EQUAL_INT(0, mtt_split_just(&wk, 4, XP, P, R, rj, &rf, 5, Z5, B5, MTT_R(1000.0), xs, Ps, cl, bn, &lik));
    TEST_ASSERT_TRUE(lik == MTT_R(0.0));
}

/* An R that makes S not positive definite: refused, nothing written. */
static void test_own_r_not_positive_refused(void)
{
    const mtt_real bad[3] = {MTT_R(-1000.0), MTT_R(0.0), MTT_R(1000.0)}; /* det S < 0 */
    const mtt_real *rb[5] = {R, bad, R, R, R}, *rc[5] = {R, R, R, R, bad}, *rg[4] = {R, R, R, R};
    const mtt_real *rx[4] = {R, R, bad, R};
    mtt_real P[MTT_MAX_STATE][MTT_MAX_STATE], bn[5], lik = MTT_R(-7.0);
    mtt_split_state xs;
    mtt_split_cov Ps, Pps;
    mtt_split_assoc as;
    uint8_t cl[5];
    prior1(P);
    xs[0] = MTT_R(-3.0);
    TEST_ASSERT_EQUAL_INT(-1, mtt_split_just(&wk, 4, XP, P, R, rb, NULL, 5, Z5, B5, MTT_R(1000.0), xs, Ps, cl, bn, &lik));
    TEST_ASSERT_EQUAL_FLOAT(-7.0f, (float)lik);
    TEST_ASSERT_EQUAL_FLOAT(-3.0f, (float)xs[0]);
    TEST_ASSERT_EQUAL_INT(0, mtt_split_just(&wk, 4, XP, P, R, NULL, NULL, 5, Z5, B5, MTT_R(1000.0), xs, Ps, cl, bn, &lik));
    /* a child-cluster measurement (Z5[4] is the parent's: ref5_cluster) and a parent's */
    TEST_ASSERT_EQUAL_INT(-1, mtt_split_known(&wk, 4, XP, P, R, rb, NULL, 5, Z5, cl, bn, MTT_R(5.0), MTT_R(1.0), 1u,
                                              MTT_R(1000.0), xs, Ps, &lik));
    TEST_ASSERT_EQUAL_INT(-1, mtt_split_known(&wk, 4, XP, P, R, rc, NULL, 5, Z5, cl, bn, MTT_R(5.0), MTT_R(1.0), 1u,
                                              MTT_R(1000.0), xs, Ps, &lik));
    prior_s(Pps, 1.0);
    as.m = 77u;
    TEST_ASSERT_EQUAL_INT(-1, mtt_split_assoc_init(4, XPS, Pps, R, rx, NULL, 4, Z6, PD6, PG6, GAMMA, MTT_R(100.0),
                                                   MTT_R(0.0), &as));
    TEST_ASSERT_EQUAL_UINT16(77u, as.m);
    TEST_ASSERT_EQUAL_INT(0, mtt_split_assoc_init(4, XPS, Pps, R, rg, NULL, 4, Z6, PD6, PG6, GAMMA, MTT_R(100.0),
                                                  MTT_R(0.0), &as));
    TEST_ASSERT_EQUAL_INT(0, mtt_split_joint(&as));
    xs[0] = MTT_R(-3.0);
    TEST_ASSERT_EQUAL_INT(-1, mtt_split_update(&wk, &as, XPS, Pps, R, rx, NULL, Z6, xs, Ps));
    TEST_ASSERT_EQUAL_FLOAT(-3.0f, (float)xs[0]);
}
#endif

static void test_split_random_properties(void)
{
    int c, i, k, l, t;
    for (c = 0; c < 200; ++c) {
        double A[8][8];
        mtt_split_cov Pps, Ps;
        mtt_split_state xps, xs;
        mtt_split_assoc as;
        mtt_real z[8][2], b[8], P[MTT_MAX_STATE][MTT_MAX_STATE], bn[8], lik;
        uint8_t cl[8];
        const uint16_t m = (uint16_t)(urand(0.0, 8.999));
        const mtt_real pd = (mtt_real)urand(0.5, 1.0);
        double sum = 0.0;
        int16_t j1, j2;
        for (i = 0; i < 8; ++i) {
            for (k = 0; k < 8; ++k) {
                A[i][k] = urand(-2.0, 2.0);
            }
            xps[i] = (mtt_real)urand(-10.0, 10.0);
        }
        for (i = 0; i < 8; ++i) {
            for (k = 0; k < 8; ++k) {
                double v = (i == k) ? 1.0 : 0.0;
                for (l = 0; l < 8; ++l) {
                    v += A[i][l] * A[k][l];
                }
                Pps[i][k] = (mtt_real)v;
            }
        }
        for (i = 0; i < (int)m; ++i) {
            t = (urand(0.0, 1.0) < 0.5) ? 0 : 4;
            z[i][0] = xps[t] + (mtt_real)urand(-6.0, 6.0);
            z[i][1] = xps[t + 1] + (mtt_real)urand(-6.0, 6.0);
            b[i] = (mtt_real)urand(0.0, 1.0);
        }
        TEST_ASSERT_EQUAL_INT(0, mtt_split_assoc_init(4, xps, Pps, R, NULL, NULL, m, z, pd, PG6, GAMMA, MTT_R(500.0),
                                                      MTT_R(0.0), &as));
        TEST_ASSERT_EQUAL_INT(0, mtt_split_joint(&as));
        for (j1 = -1; j1 < (int16_t)m; ++j1) {
            for (j2 = -1; j2 < (int16_t)m; ++j2) {
                sum += (double)mtt_split_event_weight(&as, j1, j2) / (double)as.lik;
            }
        }
        TV_ASSERT_REAL(1.0, sum);
        for (t = 0; t < 2; ++t) {
            double s = (double)as.beta_miss[t];
            for (i = 0; i < (int)m; ++i) {
                s += (double)as.beta[t][i];
            }
            TV_ASSERT_REAL(1.0, s);
        }
        TEST_ASSERT_EQUAL_INT(0, mtt_split_update(&wk, &as, xps, Pps, R, NULL, NULL, z, xs, Ps));
        assert_psd(Ps, 8);
        if (m >= 2u) {
            for (i = 0; i < 4; ++i) {
                for (k = 0; k < 4; ++k) {
                    P[i][k] = Pps[i][k];
                }
            }
            TEST_ASSERT_EQUAL_INT(0, mtt_split_just(&wk, 4, xps, P, R, NULL, NULL, m, z, b, MTT_R(500.0), xs, Ps, cl, bn, &lik));
            assert_psd(Ps, 8);
            TEST_ASSERT_TRUE(lik >= MTT_R(0.0));
        }
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_stack_predict);
    RUN_TEST(test_just_split_reference);
    RUN_TEST(test_just_split_refuses);
    RUN_TEST(test_just_split_two);
    RUN_TEST(test_known_split_reference);
    RUN_TEST(test_split_events_reference);
    RUN_TEST(test_split_events_parametric);
    RUN_TEST(test_split_update_reference);
    RUN_TEST(test_split_update_independent);
    RUN_TEST(test_split_no_measurement);
    RUN_TEST(test_split_random_properties);
    RUN_TEST(test_impulse_q);
    RUN_TEST(test_decouple_reference);
    RUN_TEST(test_decouple_boundary);
    RUN_TEST(test_separate);
#if MTT_WITH_MEAS_COV
    RUN_TEST(test_own_r_equal_is_the_shared_form);
    RUN_TEST(test_own_r_just_two_hand);
    RUN_TEST(test_own_r_split_update_independent);
    RUN_TEST(test_own_r_not_positive_refused);
    RUN_TEST(test_rdot_just_two_hand);
    RUN_TEST(test_rdot_events_weigh_the_matching_range_rate);
    RUN_TEST(test_rdot_split_update_ekf_step);
    RUN_TEST(test_rdot_known);
#endif
    return UNITY_END();
}

#else /* MTT_WITH_SPLIT == 0: the split models are compiled out */

static void test_split_compiled_out(void)
{
    TEST_ASSERT_EQUAL_INT(0, MTT_WITH_SPLIT);
    TEST_IGNORE_MESSAGE("built with MTT_WITH_SPLIT=0");
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_split_compiled_out);
    return UNITY_END();
}

#endif
