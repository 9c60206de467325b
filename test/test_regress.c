/* SPDX-License-Identifier: BSD-3-Clause */
/* test_regress.c - regressions found by the fuzzers and the soak
 * (docs/ROBUSTNESS.md).  The raw inputs are replayed by the ctests
 * fuzz.replay.*; these are the same findings as plain API calls. */
#include <string.h>

#include "mtt/mtt.h"
#include "real_ops.h" /* mtt_isfinite: private (src/) */
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

/* F1: a seed covariance that is singular or nearly so (correlation 1 up
 * to rounding) was accepted and later gave a singular track covariance.
 * Now refused; a wide but well-conditioned one (different scales per
 * state) is still accepted. */
void test_seed_covariance_conditioning(void)
{
    mtt_params p;
    mtt_real x[4] = {MTT_R(0.0), MTT_R(0.0), MTT_R(1.0), MTT_R(1.0)};
    mtt_real P[16];
    uint32_t id;
    int i;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    for (i = 0; i < 16; ++i) {
        P[i] = MTT_R(0.0);
    }
    P[0] = MTT_R(4.0);
    P[5] = MTT_R(4.0);
    P[10] = MTT_R(1.0);
    P[15] = MTT_R(1.0);
    P[1] = P[4] = MTT_R(4.0); /* corr(x, y) = 1: singular */
    TEST_ASSERT_EQUAL_INT(MTT_ERR_VALUE, mtt_tracker_add_track(&trk, x, P, &id));
    P[1] = P[4] = MTT_R(3.99999); /* corr 0.9999975: inside double's margin, not float's */
#ifndef MTT_REAL_DOUBLE
    TEST_ASSERT_EQUAL_INT(MTT_ERR_VALUE, mtt_tracker_add_track(&trk, x, P, &id));
#else
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&trk, x, P, &id));
#endif
    P[1] = P[4] = MTT_R(0.0);
    P[0] = MTT_R(1e12); /* 1e6 sigma beside 1: wide, but well conditioned */
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&trk, x, P, &id));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_R(0.0), NULL, 0));
    assert_tracks_sane();
}

/* F2: a meas_sigma whose square underflows (or overflows) made R = 0 and
 * collapsed covariances.  mtt_params_check now bounds sigma to [1e-9, 1e9]. */
void test_meas_sigma_bounds(void)
{
    mtt_params p;
    const char *field = NULL;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.meas_sigma[1] = MTT_R(1e-20);
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_check(&p, &field));
    TEST_ASSERT_EQUAL_STRING("meas_sigma", field);
    p.meas_sigma[1] = MTT_R(1e20);
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_check(&p, &field));
    p.meas_sigma[1] = MTT_R(1e-9);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_check(&p, &field));
}

/* F4: after a very long gap (dT = 1e6 with Sw = 5: position variance 1.7e18
 * against R = 1) the gain is 1 to float precision; 1 - K and the PDA spread
 * cancelled and a variance came out negative (P[1][1] = -65535 in
 * adaptive-jpda).  The update now forms I - K H from R S^-1 and the spread
 * as a sum of positive terms.  The exact fuzzer input, which fails on the
 * old update, is tools/fuzz/regress/tracker/f4-long-gap-adaptive-jpda.bin
 * (ctest fuzz.replay.tracker); this test runs the same kind of frame --
 * two seeded tracks on one state, a 1e6 gap -- through every mode. */
void test_long_gap_update_keeps_covariance_positive(void)
{
    int mode;
    for (mode = 0; mode < (int)MTT_ASSOC_COUNT; ++mode) {
        mtt_params p;
        const mtt_real x[4] = {MTT_R(82.8125), MTT_R(82.8125), MTT_R(0.828125), MTT_R(0.828125)};
        const mtt_real P0[16] = {MTT_R(3.3125), 0, MTT_R(0.4140625), 0, 0, MTT_R(3.3125), 0, MTT_R(0.4140625),
                                 MTT_R(0.4140625), 0, MTT_R(3.3125), 0, 0, MTT_R(0.4140625), 0, MTT_R(3.3125)};
        const mtt_real P1[16] = {MTT_R(3.3125), 0, MTT_R(0.5), 0, 0, MTT_R(3.3125), 0, MTT_R(0.5),
                                 MTT_R(0.5), 0, MTT_R(4.0), 0, 0, MTT_R(0.5), 0, MTT_R(4.0)};
        mtt_meas m[5];
        uint32_t id;
        int i;
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
        p.association = (mtt_assoc)mode;
        p.init_gate = MTT_INIT_GATE_INTENSITY;
        if (mtt_params_check(&p, NULL) != MTT_OK) {
            continue; /* mode not built in */
        }
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&trk, x, P0, &id));
        for (i = 0; i < 5; ++i) {
            m[i] = mk(MTT_R(2.0), MTT_R(2.0));
            m[i].amplitude = MTT_R(1.625);
            m[i].has_amplitude = 1;
        }
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_R(1e6), m, 5));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&trk, x, P1, &id));
        m[0] = mk(MTT_R(-7.625), MTT_R(14.375));
        m[1] = mk(MTT_R(14.625), MTT_R(6.875));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_R(2e6), m, 2));
        assert_tracks_sane();
    }
}

/* A track that is never deleted (terminate_threshold 0) and goes unseen
 * has its existence decay towards 0.  In jipda a denormal existence
 * (2.5e-39, coalesce3 seed run) made 1 / (P_t W) infinite and the state
 * NaN.  Existence below 1e-30 is now 0, and jipda divides by D_t + q_t U_t
 * directly, keeping the prediction when that vanishes.  Every mode: after
 * 200 empty frames the existence is exactly 0 and a detection on the track
 * leaves everything finite. */
void test_vanishing_existence_stays_finite(void)
{
    int mode;
    for (mode = 0; mode < (int)MTT_ASSOC_COUNT; ++mode) {
        mtt_params p;
        const mtt_real x[4] = {MTT_R(0.0), MTT_R(0.0), MTT_R(1.0), MTT_R(0.5)};
        mtt_real P[16];
        mtt_meas m[2];
        mtt_track_view v;
        uint32_t id;
        int i, k;
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
        p.association = (mtt_assoc)mode;
        p.terminate_threshold = MTT_R(0.0);
        p.initiate = 0;
        p.clutter_density = MTT_R(1e-4);
        if (mtt_params_check(&p, NULL) != MTT_OK) {
            continue;
        }
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
        for (i = 0; i < 16; ++i) {
            P[i] = (i % 5 == 0) ? MTT_R(1.0) : MTT_R(0.0);
        }
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&trk, x, P, &id));
        for (k = 0; k < 200; ++k) {
            TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, (mtt_real)k, NULL, 0));
        }
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, 0, &v));
        TEST_ASSERT_TRUE(v.existence == MTT_R(0.0));
        m[0] = mk(v.x[0] + MTT_R(1.0), v.x[1] + MTT_R(2.0));
        m[1] = mk(v.x[0] - MTT_R(2.0), v.x[1]);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_R(200.0), m, 2));
        assert_tracks_sane();
    }
}

/* F6: two detections 1e-6 apart in time with sigma 32 gave a newborn
 * track a velocity variance of 2e15 (2R/dT^2, ALGORITHMS.md §12.1); at the next
 * frame (dT = 1) its float covariance turned singular.  The two-point
 * velocity variance is now capped at vmax^2 (the velocity gate's own
 * bound), with the correlations kept. */
void test_tiny_interval_birth_stays_positive(void)
{
    mtt_params p;
    mtt_meas m[1];
    size_t n = 0;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.meas_sigma[0] = MTT_R(32.0);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    m[0] = mk(MTT_R(64.0), MTT_R(32.0));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_R(3.0), m, 1));
    m[0] = mk(MTT_R(64.0), MTT_R(32.0));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_R(3.0) + MTT_R(1e-6) * MTT_R(4.0), m, 1));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&trk, &n));
    TEST_ASSERT_EQUAL_UINT(1u, (unsigned)n); /* born */
    {
        mtt_track_view v;
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, 0, &v));
        /* velocity variance capped at vmax^2 = 3600 */
        TEST_ASSERT_TRUE(v.P[2][2] <= MTT_R(3600.0) * MTT_R(1.0001));
        TEST_ASSERT_TRUE(v.P[2][2] > MTT_R(0.0));
    }
    m[0] = mk(MTT_R(79.5), MTT_R(34.125));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_R(5.0), m, 1));
    assert_tracks_sane();
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_birth_with_huge_interval_is_not_singular);
    RUN_TEST(test_birth_with_tiny_interval_is_finite);
    RUN_TEST(test_seed_covariance_conditioning);
    RUN_TEST(test_meas_sigma_bounds);
    RUN_TEST(test_long_gap_update_keeps_covariance_positive);
    RUN_TEST(test_vanishing_existence_stays_finite);
    RUN_TEST(test_tiny_interval_birth_stays_positive);
    return UNITY_END();
}
