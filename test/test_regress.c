/* test_regress.c - regressions found by the fuzzers and the soak (issue 6,
 * docs/ROBUSTNESS.md).  The raw inputs are replayed by the ctests
 * fuzz.replay.*; these are the same findings as plain API calls. */
#include <string.h>

#include "mtt/mtt.h"
#include "unity.h"

static mtt_tracker trk;

void setUp(void) {}
void tearDown(void) {}

static mtt_meas mk(mtt_real x, mtt_real y)
{
    mtt_meas m;
    m.x = x;
    m.y = y;
    m.amplitude = MTT_R(0.0);
    m.has_amplitude = 0;
    return m;
}

/* Every live track has a finite state and a covariance with a positive
 * diagonal and positive 2x2 position/velocity minors. */
static void assert_tracks_sane(void)
{
    size_t n = 0, i;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&trk, &n));
    for (i = 0; i < n; ++i) {
        mtt_track_view v;
        int a;
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, i, &v));
        for (a = 0; a < 4; ++a) {
            TEST_ASSERT_TRUE(mtt_isfinite(v.x[a]));
            TEST_ASSERT_TRUE(mtt_isfinite(v.P[a][a]));
            TEST_ASSERT_TRUE(v.P[a][a] > MTT_R(0.0));
        }
        for (a = 0; a < 2; ++a) {
            double det = (double)v.P[a][a] * (double)v.P[a + 2][a + 2] -
                         (double)v.P[a][a + 2] * (double)v.P[a][a + 2];
            TEST_ASSERT_TRUE(det > 0.0);
        }
    }
}

/* F3: a frame interval so long that R/dt^2 underflows gave a newborn track
 * a zero velocity variance (and with a denormal sigma, P = 0): a singular
 * covariance in the output.  Such births are now not started. */
void test_birth_with_huge_interval_is_not_singular(void)
{
    mtt_params p;
    mtt_meas m[2];
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.vmax = MTT_R(1e30); /* let the velocity gate pass anything */
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    m[0] = mk(MTT_R(24.0), MTT_R(0.0));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_R(0.0), m, 1));
    m[0] = mk(MTT_R(508.0), MTT_R(0.0));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_R(6.7e36), m, 1));
    assert_tracks_sane();
}

/* F3, the other end: an interval so short that the two-point velocity
 * overflows must not start a track with an infinite state. */
void test_birth_with_tiny_interval_is_finite(void)
{
    mtt_params p;
    mtt_meas m[1];
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.vmax = MTT_R(3e38);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    m[0] = mk(MTT_R(-1.5e38), MTT_R(0.0));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_R(1.0), m, 1));
    m[0] = mk(MTT_R(1.5e38), MTT_R(0.0));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_R(1.0) + MTT_R(0.0009765625), m, 1));
    assert_tracks_sane();
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_birth_with_huge_interval_is_not_singular);
    RUN_TEST(test_birth_with_tiny_interval_is_finite);
    return UNITY_END();
}
