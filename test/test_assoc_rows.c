/* SPDX-License-Identifier: BSD-3-Clause */
/* test_assoc_rows.c - the association arithmetic on given likelihoods, in
 * every build, the fixed-point one included: IHPDA rank probabilities (TV4,
 * ALGORITHMS.md §7.2), IHPDA rows (TV5, §7.3) and the LM clutter density
 * (TV8, §8.2).  Densities are given in units of the clutter density lambda
 * (p_j / lambda, lambda~ / lambda, lambda V_G), as the fixed-point build
 * holds them (docs/FIXED_POINT.md §2); every formula is homogeneous in the
 * densities, so the expected values are the vectors' own, scaled.
 * test_ihpda.c and test_lm_clutter.c run the same vectors through the
 * Kalman and gate stages on absolute densities.
 *
 * Fixed-point tolerances are derived from the formats (docs/FIXED_POINT.md
 * §7): q = 2^-17 is half a Q16 unit (ratios), c = 2^-25 half a Q24 unit
 * (counts), u = 2^-31 half a Q30 unit (probabilities); each function below
 * adds up the roundings on the way and the input quantisation times its
 * condition factor. */
#include <string.h>

#include "mtt_internal.h"
#include "tv_assert.h"
#include "tv_fixture.h"
#include "unity.h"

static mtt_tracker trk;

void setUp(void)
{
    memset(&trk, 0, sizeof trk);
}
void tearDown(void) {}

#define QH (1.0 / 131072.0)
#define CH (1.0 / 33554432.0)
#define UH (1.0 / 2147483648.0)

/* ---- TV4: P_r ----
 * a = 1/(1+rho) to u, its Q24 copy to c; each factor j/(j+a) of P_r(1) to
 * u + c/j, its product to 0.5007 ulp: relative <= sum_j (2c/j + 2u) <=
 * 4e-7 for m <= 64.  The recurrence forms out[j-1] (j-1+a) in Q24 (c, plus
 * c from a) and divides by j (u), the factor (j-1+a)/j <= 1 does not grow
 * the error: absolute <= m 2^-24 + 4e-7. */
static void check_prank(uint16_t m, mtt_ratio rho, const double *want)
{
    mtt_prob out[16];
    double sum = 0.0;
    uint16_t l;
    const double tol = (double)m / 16777216.0 + 4e-7;
    mtt_ihpda_prank(m, rho, out);
    for (l = 0; l < m; ++l) {
        TV_ASSERT_PROB(want[l], out[l], tol);
        sum += TV_Q(out[l], 30);
    }
#ifdef MTT_REAL_FIXED
    TEST_ASSERT_TRUE(fabs(sum - 1.0) <= (double)m * tol);
#else
    TV_ASSERT_REAL(1.0, sum); /* TV4: Prank sums to 1 */
#endif
}

static void test_tv4_prank(void)
{
    static const double w3[3] = {0.7111111111, 0.1777777778, 0.1111111111}; /* TV4 m = 3, rho = 3 */
    static const double w5[5] = {0.6177978884, 0.1544494721, 0.09653092006, 0.07239819005,
                                 0.05882352941}; /* TV4 m = 5, rho = 3 */
    static const double w8[8] = {0.7947332571, 0.07224847792, 0.03940826068, 0.02746636351,
                                 0.02122400816, 0.01736509759, 0.0147340222,  0.01282051282};
    static const double w1[1] = {1.0};
    check_prank(1, MTT_RATIO(0.0), w1);
    check_prank(3, MTT_RATIO(3.0), w3);
    check_prank(5, MTT_RATIO(3.0), w5);
    check_prank(8, MTT_RATIO(10.0), w8); /* TV4 m = 8, rho = 10 */
}

/* TV4 precision study in this build: every l, m = 1..64, rho in {0, 0.5,
 * 1, 3, 10, 100} against the closed form in long double, within the
 * tolerance above (fixed point) or the build's rule. */
static void test_tv4_prank_to_64(void)
{
    static const double rhos[6] = {0.0, 0.5, 1.0, 3.0, 10.0, 100.0};
    int r;
    uint16_t m, l;
    for (r = 0; r < 6; ++r) {
        for (m = 1; m <= 64; ++m) {
            mtt_prob out[64];
            long double a = 1.0L / (1.0L + (long double)rhos[r]), ref = 1.0L;
            const double tol = (double)m / 16777216.0 + 4e-7;
            mtt_ihpda_prank(m, MTT_RATIO(rhos[r]), out);
            for (l = 1; l < m; ++l) {
                ref *= (long double)l / ((long double)l + a);
            }
            for (l = 1; l <= m; ++l) {
                TV_ASSERT_PROB((double)ref, out[l - 1u], tol);
                ref = ref * ((long double)l - 1.0L + a) / (long double)l;
            }
        }
    }
}

/* ---- TV5: IHPDA rows (PD 0.9, PG 0.99, lambda 0.002, rho 3) ---- */
#define LAMBDA 0.002
static const double tv5_p[3] = {0.01517412536, 0.005719835949, 0.003383802596};
static const double tv5_vg = 291.4001257;
static const double tv5_amp[3] = {40.0, 95.0, 60.0};
static const uint8_t tv5_rank[3] = {3, 1, 2};
static const double tv5_L[3] = {6.439226139, 6.870114355, 4.68409488};
static const double tv5_beta[3] = {0.3499423017, 0.7912724307, 0.1716428718};
static const double tv5_prank[3] = {0.1111111111, 0.7111111111, 0.1777777778};

/* The fixed build forms D = lambda_j L = X + (1 - PD PG) lambda_j + PD PG
 * (m / V_G) (1 - P_r) with X = PD PG m p P_r (ihpda.c), and beta = X / D,
 * L = D / lambda_j; a product by a probability is the fast Q30 multiply,
 * 0.5007 unit (QM).  X: PD PG m to c (times p), times p (quantised to q)
 * to q, times P_r to QM, P_r's own 4e-7.  D: X's, (1 - PD PG) lambda_j to
 * QM, m / V_G with lambda V_G quantised to q and the quotient to q + X
 * 2q / (lambda V_G), times PD PG to QM, times 1 - P_r to QM.  L = D / 1
 * to q; beta = X / D to u.  (The fixed build returns D = lambda_j L as L,
 * divided by lambda_j where the update reads it; lambda_j = 1 here.)  (Float and double: the float text, A = X /
 * lambda_j, C, L = A + C, beta = A / L, held by the rule of ALGORITHMS.md
 * §16 by TV_ASSERT_RATIO/PROB, which do not use these.) */
#define QM (QH * 1.0015)
static void row_tol(int j, double *tl, double *tb)
{
    const double pdpg = 0.9 * 0.99, p = tv5_p[j] / LAMBDA, vgr = tv5_vg * LAMBDA;
    const double X = tv5_beta[j] * tv5_L[j], Xv = 3.0 / vgr;
    const double dX = QH + QM + pdpg * 3.0 * tv5_prank[j] * QH + X * 4e-7 / tv5_prank[j] + 3.0 * p * CH;
    const double dY = (1.0 - tv5_prank[j]) * (pdpg * (QH + Xv * 2.0 * QH / vgr) + QM) + QM;
    const double dD = dX + QM + dY;
    *tl = dD + QH;
    *tb = (dX + tv5_beta[j] * dD) / tv5_L[j] + UH;
}

static void test_tv5_rows(void)
{
    mtt_cand c[3];
    mtt_prob prank[3], beta[3];
    mtt_ratio L[3];
    uint8_t rank[3];
    int j;
    memset(c, 0, sizeof c);
    for (j = 0; j < 3; ++j) {
        TV_CAND_P(&c[j]) = MTT_RATIO(tv5_p[j] / LAMBDA);
        TV_CAND_LAM(&c[j]) = MTT_RATIO(1.0);
        TV_CAND_AMP(&c[j]) = MTT_AMP(tv5_amp[j]);
        TV_CAND_IDX(&c[j]) = (uint16_t)j;
    }
    mtt_ihpda_prank(3, MTT_RATIO(3.0), prank);
    mtt_ihpda_betas(MTT_P(0.9), MTT_P(0.99), MTT_GATE(291.4001257 * LAMBDA), prank, c, 3, beta, L,
                    rank);
    for (j = 0; j < 3; ++j) {
        double tl, tb;
        row_tol(j, &tl, &tb);
        TEST_ASSERT_EQUAL_UINT8(tv5_rank[j], rank[j]); /* TV5 rank */
        TV_ASSERT_RATIO(tv5_L[j], L[j], tl);           /* TV5 L */
        TV_ASSERT_PROB(tv5_beta[j], beta[j], tb);      /* TV5 beta_j */
    }
}

/* ---- TV8: LM clutter density (PD 0.9, PG 0.99, lambda 0.002) ----
 * Pairs in (track, measurement) order: (T1,z1) (T1,z2) (T2,z2) (T2,z3). */
static const uint16_t pt[4] = {0, 0, 1, 1}, pm[4] = {0, 1, 1, 2};
static const double tv8_p[4] = {0.03183372832, 0.02321079044, 0.01318017474, 0.01754581538};
static const double tv8_ptilde[4] = {0.4122314457, 0.3005685543, 0.1911010133, 0.2543989867};
static const double tv8_W[3] = {0.02232658374, 0.01308822926, 0.005986630349};
static const double tv8_lamt[4] = {0.002, 0.005113793921, 0.01197443534, 0.002};
static const double tv8_ex[2] = {0.8, 0.5};

/* Pt = PD PG P^ p / sum: the numerator to q (plus p's q), the sum of two
 * quantised p to 2q, the quotient to u.  (The fixed build forms p r with r
 * = 1/sum on 30 bits, then times PD PG P^: no Q16 rounding of the
 * numerator, which the q above covers, and 4 u for r's relative 2^-30, p
 * r's and the last product's roundings; the formula keeps the larger
 * count.)  w = p Pt / (1 - Pt): the product
 * to q (plus p's q times Pt and p times dPt), the quotient to q, grown by
 * 1/(1 - Pt) (and w dPt / (1 - Pt) from the denominator). */
static double w_tol(int k)
{
    const double p = tv8_p[k] / LAMBDA, ptl = tv8_ptilde[k];
    const double sum = (tv8_p[2 * (k / 2)] + tv8_p[2 * (k / 2) + 1]) / LAMBDA;
    const double dpt = (QH + QH * 0.891 * tv8_ex[k / 2] + ptl * 2.0 * QH) / sum + 4.0 * UH;
    const double dnum = QH + ptl * QH + p * dpt;
    const double w = p * ptl / (1.0 - ptl);
    return (dnum + w * dpt) / (1.0 - ptl) + QH;
}

static void test_tv8_lm_density(void)
{
    uint16_t k, j;
    trk.par.pd = MTT_P(0.9);
    trk.par.pg = MTT_P(0.99);
    trk.par.clutter_density = MTT_DENS(1.0); /* densities in units of lambda */
    TV_N_TRACKS(&trk) = 2;
    for (j = 0; j < 3; ++j) {
        (void)tv_add_meas(&trk, MTT_POS(0.0), MTT_POS(0.0), MTT_AMP(1.0), 1);
    }
    for (k = 0; k < 4; ++k) {
        tv_add_pair(&trk, pt[k], pm[k], MTT_ZERO);
        TV_PAIR_P(&trk, k) = MTT_RATIO(tv8_p[k] / LAMBDA);
    }
    tv_index_pairs(&trk);
    for (j = 0; j < 2; ++j) {
        TV_VALID(&trk, j) = 1;
        TV_EX_PRED(&trk, j) = MTT_P(tv8_ex[j]);
    }
    mtt_clutter_frame(&trk, 1);
    TV_ASSERT_RATIO(1.0, TV_LAMBDA(&trk, 0), 0.0);
    TV_ASSERT_RATIO(1.0, TV_LAMBDA(&trk, 1), 0.0);
    for (k = 0; k < 4; ++k) {
        const double w = tv8_p[k] * tv8_ptilde[k] / (1.0 - tv8_ptilde[k]) / LAMBDA;
        /* lambda~ = 1 + the w of the other track gating the same measurement */
        const double dlam = (k == 1u) ? w_tol(2) : (k == 2u) ? w_tol(1) : 0.0;
        TV_ASSERT_RATIO(w, TV_PAIR_W(&trk, k), w_tol(k));                    /* TV8 w */
        TV_ASSERT_RATIO(tv8_lamt[k] / LAMBDA, TV_PAIR_LAM(&trk, k), dlam);   /* TV8 lambda~ */
    }
    TV_ASSERT_RATIO(tv8_W[0] / LAMBDA, TV_WSUM(&trk, 0), w_tol(0));
    TV_ASSERT_RATIO(tv8_W[1] / LAMBDA, TV_WSUM(&trk, 1), w_tol(1) + w_tol(2));
    TV_ASSERT_RATIO(tv8_W[2] / LAMBDA, TV_WSUM(&trk, 2), w_tol(3));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_tv4_prank);
    RUN_TEST(test_tv4_prank_to_64);
    RUN_TEST(test_tv5_rows);
    RUN_TEST(test_tv8_lm_density);
    return UNITY_END();
}
