/* test_existence.c - Markov chain one prediction (TV7) and the L-form
 * existence update with its clamping (ALGORITHMS.md §6, §11, §16). */
#include "mtt_internal.h"
#include "tv_assert.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

static void test_tv7_predict(void)
{
    /* TV7 */
    TV_ASSERT_REAL(0.882, mtt_existence_predict(MTT_R(0.9), MTT_R(0.98), MTT_R(0.0)));
    TV_ASSERT_REAL(0.883, mtt_existence_predict(MTT_R(0.9), MTT_R(0.98), MTT_R(0.01)));
    TV_ASSERT_REAL(0.098, mtt_existence_predict(MTT_R(0.1), MTT_R(0.98), MTT_R(0.0)));
}

static void test_predict_clamps(void)
{
    TEST_ASSERT_TRUE(mtt_existence_predict(MTT_R(1.5), MTT_R(1.0), MTT_R(0.0)) == MTT_R(1.0));
    TEST_ASSERT_TRUE(mtt_existence_predict(MTT_R(-0.5), MTT_R(1.0), MTT_R(0.0)) == MTT_R(0.0));
    TEST_ASSERT_TRUE(mtt_existence_predict((mtt_real)NAN, MTT_R(0.98), MTT_R(0.0)) == MTT_R(0.0));
    /* boundaries stay put */
    TEST_ASSERT_TRUE(mtt_existence_predict(MTT_R(1.0), MTT_R(1.0), MTT_R(0.0)) == MTT_R(1.0));
    TEST_ASSERT_TRUE(mtt_existence_predict(MTT_R(0.0), MTT_R(0.98), MTT_R(0.0)) == MTT_R(0.0));
}

static void test_update_values(void)
{
    /* P = L P / (1 - P + L P) */
    TV_ASSERT_REAL(0.9115449069, mtt_existence_update(MTT_R(0.6), MTT_R(6.870114355))); /* TV5 z2 */
    TV_ASSERT_REAL(0.1405242802, mtt_existence_update(MTT_R(0.6), MTT_R(1.0) - MTT_R(0.891))); /* TV5 m = 0 */
    TV_ASSERT_REAL(0.942486148, mtt_existence_update(MTT_R(0.6), MTT_R(10.92474382)));  /* TV6 */
    TV_ASSERT_REAL(0.9865483275, mtt_existence_update(MTT_R(0.8), MTT_R(18.33504949))); /* TV8 LM-IPDA T1 */
    TV_ASSERT_REAL(0.8990549324, mtt_existence_update(MTT_R(0.5), MTT_R(8.906378035))); /* TV8 LM-IPDA T2 */
}

static void test_update_clamps(void)
{
    /* L = 1 leaves P unchanged; huge L gives at most 1; P = 0 or 1 are fixed points. */
    TV_ASSERT_REAL(0.6, mtt_existence_update(MTT_R(0.6), MTT_R(1.0)));
    TEST_ASSERT_TRUE(mtt_existence_update(MTT_R(0.6), MTT_R(1e30)) <= MTT_R(1.0));
    TEST_ASSERT_TRUE(mtt_existence_update(MTT_R(0.6), MTT_R(1e30)) > MTT_R(0.99));
    TEST_ASSERT_TRUE(mtt_existence_update(MTT_R(1.0), MTT_R(0.109)) == MTT_R(1.0));
    TEST_ASSERT_TRUE(mtt_existence_update(MTT_R(0.0), MTT_R(50.0)) == MTT_R(0.0));
    /* a non-positive denominator or NaN gives 0, never a value outside [0, 1] */
    TEST_ASSERT_TRUE(mtt_existence_update(MTT_R(0.5), MTT_R(-3.0)) == MTT_R(0.0));
    TEST_ASSERT_TRUE(mtt_existence_update(MTT_R(0.5), (mtt_real)NAN) == MTT_R(0.0));
    /* L = 0 (delta = 1): existence 0 */
    TEST_ASSERT_TRUE(mtt_existence_update(MTT_R(0.5), MTT_R(0.0)) == MTT_R(0.0));
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
