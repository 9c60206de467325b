/* SPDX-License-Identifier: BSD-3-Clause */
/* test_existence.c - Markov chain one prediction (TV7) and the L-form
 * existence update with its clamping (ALGORITHMS.md §6, §11, §16).
 *
 * Runs in every build.  Fixed point (docs/FIXED_POINT.md §7): the inputs are
 * Q30 probabilities and a Q16 L, and each tolerance is derived from the
 * formats: PRED_TOL and upd_tol() below. */
#include "mtt_internal.h"
#include "tv_assert.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

/* p11 p + p21 (1 - p): two Q30 multiplies (<= 0.5007 ulp each) and three
 * Q30 inputs rounded to 0.5 ulp, each with condition factor <= 1:
 * 2.51 ulp of Q30. */
#define PRED_TOL (2.51 / 1073741824.0)

/* P' = num / den, num = L P and den = (1 - P) + num held in Q16 (existence.c).
 * Input quantisation: L to 2^-17, P to 2^-31; num rounds to 2^-17 and
 * den's 1 - P to 2^-17, so |d num| <= 2^-17 (1 + P) and
 * |d den| <= 2^-17 + |d num|; then |dP'| <= (|d num| + P' |d den|) / den
 * plus the final Q30 rounding (2^-31). */
static double upd_tol(double p, double l)
{
    const double q = 1.0 / 131072.0;
    const double den = 1.0 - p + l * p;
    const double post = l * p / den;
    const double dnum = q * (1.0 + p) + l / 2147483648.0;
    return (dnum + post * (q + dnum)) / den + 1.0 / 2147483648.0;
}

static void test_tv7_predict(void)
{
    /* TV7 */
    TV_ASSERT_PROB(0.882, mtt_existence_predict(MTT_P(0.9), MTT_P(0.98), MTT_P(0.0)), PRED_TOL);
    TV_ASSERT_PROB(0.883, mtt_existence_predict(MTT_P(0.9), MTT_P(0.98), MTT_P(0.01)), PRED_TOL);
    TV_ASSERT_PROB(0.098, mtt_existence_predict(MTT_P(0.1), MTT_P(0.98), MTT_P(0.0)), PRED_TOL);
}

static void test_predict_clamps(void)
{
    TEST_ASSERT_TRUE(mtt_existence_predict(MTT_P(1.5), MTT_P(1.0), MTT_P(0.0)) == MTT_P(1.0));
    TEST_ASSERT_TRUE(mtt_existence_predict(MTT_P(-0.5), MTT_P(1.0), MTT_P(0.0)) == MTT_P(0.0));
#ifndef MTT_REAL_FIXED
    TEST_ASSERT_TRUE(mtt_existence_predict((mtt_real)NAN, MTT_P(0.98), MTT_P(0.0)) == MTT_P(0.0));
#endif
    /* boundaries stay put */
    TEST_ASSERT_TRUE(mtt_existence_predict(MTT_P(1.0), MTT_P(1.0), MTT_P(0.0)) == MTT_P(1.0));
    TEST_ASSERT_TRUE(mtt_existence_predict(MTT_P(0.0), MTT_P(0.98), MTT_P(0.0)) == MTT_P(0.0));
}

/* P = L P / (1 - P + L P) */
#define ASSERT_UPD(expected, p, l) \
    TV_ASSERT_PROB(expected, mtt_existence_update(MTT_P(p), MTT_RATIO(l)), upd_tol(p, l))

static void test_update_values(void)
{
    ASSERT_UPD(0.9115449069, 0.6, 6.870114355);   /* TV5 z2 */
    ASSERT_UPD(0.1405242802, 0.6, 1.0 - 0.891);   /* TV5 m = 0 */
    ASSERT_UPD(0.942486148, 0.6, 10.92474382);    /* TV6 */
    ASSERT_UPD(0.9865483275, 0.8, 18.33504949);   /* TV8 LM-IPDA T1 */
    ASSERT_UPD(0.8990549324, 0.5, 8.906378035);   /* TV8 LM-IPDA T2 */
}

static void test_update_clamps(void)
{
#ifdef MTT_REAL_FIXED
    const mtt_ratio huge = MTT_FX_MAX; /* the largest Q16 ratio, 32768 */
#else
    const mtt_ratio huge = MTT_RATIO(1e30);
#endif
    /* L = 1 leaves P unchanged; huge L gives at most 1; P = 0 or 1 are fixed points. */
    ASSERT_UPD(0.6, 0.6, 1.0);
    TEST_ASSERT_TRUE(mtt_existence_update(MTT_P(0.6), huge) <= MTT_P(1.0));
    TEST_ASSERT_TRUE(mtt_existence_update(MTT_P(0.6), huge) > MTT_P(0.99));
    TEST_ASSERT_TRUE(mtt_existence_update(MTT_P(1.0), MTT_RATIO(0.109)) == MTT_P(1.0));
    TEST_ASSERT_TRUE(mtt_existence_update(MTT_P(0.0), MTT_RATIO(50.0)) == MTT_P(0.0));
    /* a non-positive denominator or NaN gives 0, never a value outside [0, 1] */
    TEST_ASSERT_TRUE(mtt_existence_update(MTT_P(0.5), MTT_RATIO(-3.0)) == MTT_P(0.0));
#ifndef MTT_REAL_FIXED
    TEST_ASSERT_TRUE(mtt_existence_update(MTT_P(0.5), (mtt_real)NAN) == MTT_P(0.0));
#endif
    /* L = 0 (delta = 1): existence 0 */
    TEST_ASSERT_TRUE(mtt_existence_update(MTT_P(0.5), MTT_RATIO(0.0)) == MTT_P(0.0));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_tv7_predict);
    RUN_TEST(test_predict_clamps);
    RUN_TEST(test_update_values);
    RUN_TEST(test_update_clamps);
    return UNITY_END();
}
