/* SPDX-License-Identifier: BSD-3-Clause */
/* test_ipda_rows.c - IPDA betas and L (ALGORITHMS.md §6) on TV5's
 * likelihoods (docs/TEST_VECTORS.md TV6), in every build, the fixed-point
 * one included.  The likelihoods are given relative to the clutter
 * density (p_j / lambda and lambda_j / lambda = 1), as the fixed-point
 * build holds them (docs/FIXED_POINT.md §2); the betas do not depend on
 * that scale.  test_ipda.c runs the same vectors through the Kalman
 * stages on absolute densities. */
#include "mtt_internal.h"
#include "tv_assert.h"
#include "tv_fixture.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

#define PD MTT_P(0.9)
#define PG MTT_P(0.99)
#define LAMBDA 0.002
static const double tv5_p[3] = {0.01517412536, 0.005719835949, 0.003383802596}; /* TV5 p */
static const double tv6_L = 10.92474382;
static const double tv6_beta[3] = {0.61878548, 0.233249123, 0.1379880464};
static const double tv6_beta0 = 0.009977350664;

/* Fixed-point tolerances from the formats (q = 2^-17, half a Q16 unit):
 * each p_j / lambda is quantised (q) and divided by lambda_j = 1 (q), so
 * Lambda carries 2 m q; L adds the roundings of 1 - PD PG and of
 * PD PG Lambda (2 q): dL <= (2 + 2 m) q.  beta_j's numerator PD PG p_j /
 * lambda_j carries 3 q, so d beta_j <= (3 q + beta_j dL) / L + 2^-31 (the
 * Q30 quotient); beta_0 = (1 - PD PG) / L: beta_0 dL / L + 2^-31. */
#define Q (1.0 / 131072.0)
static double dl(int m)
{
    return (2.0 + 2.0 * m) * Q;
}
static double beta_tol(double beta, double l, int m, double num_err)
{
    return (num_err + beta * dl(m)) / l + 1.0 / 2147483648.0;
}

static void rows(const double *p, int m, mtt_real *beta, mtt_real *beta0, mtt_real *L)
{
    mtt_real r[3] = {MTT_ZERO, MTT_ZERO, MTT_ZERO}, lam[3] = {MTT_ZERO, MTT_ZERO, MTT_ZERO};
    int j;
    for (j = 0; j < m; ++j) {
        r[j] = MTT_RATIO(p[j] / LAMBDA);
        lam[j] = MTT_RATIO(1.0);
    }
    tv_ipda_betas(PD, PG, r, lam, (uint16_t)m, beta, beta0, L);
}

static void test_tv6_betas(void)
{
    mtt_real beta[3], beta0, L;
    double sum;
    int j;
    rows(tv5_p, 3, beta, &beta0, &L);
    TV_ASSERT_RATIO(tv6_L, L, dl(3)); /* TV6 L = 1 - delta */
    for (j = 0; j < 3; ++j) {
        TV_ASSERT_PROB(tv6_beta[j], beta[j], beta_tol(tv6_beta[j], tv6_L, 3, 3.0 * Q));
    }
    TV_ASSERT_PROB(tv6_beta0, beta0, beta_tol(tv6_beta0, tv6_L, 3, 0.0));
    sum = TV_Q(beta0, 30);
    for (j = 0; j < 3; ++j) {
        sum += TV_Q(beta[j], 30);
    }
    /* ALGORITHMS.md §6: beta_0 + sum beta_j = 1, within the sum of the
     * four tolerances in fixed point */
#ifdef MTT_REAL_FIXED
    TEST_ASSERT_TRUE(fabs(sum - 1.0) <= (9.0 * Q + dl(3)) / tv6_L + 4.0 / 2147483648.0);
#else
    TV_ASSERT_REAL(1.0, sum);
#endif
}

static void test_tv6_m0(void)
{
    /* m = 0: L = 1 - PD PG, beta_0 = 1 (TV5 m = 0: delta = 0.891). */
    mtt_real beta[1], beta0, L;
    rows(NULL, 0, beta, &beta0, &L);
    TV_ASSERT_RATIO(0.109, L, dl(0));
    TV_ASSERT_PROB(1.0, beta0, beta_tol(1.0, 0.109, 0, 0.0));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_tv6_betas);
    RUN_TEST(test_tv6_m0);
    return UNITY_END();
}
