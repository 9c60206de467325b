/* SPDX-License-Identifier: BSD-3-Clause */
/* test_edges.c - argument checks and numeric edges of the public API and
 * of the stages that other tests reach only on the common path: what is
 * refused, and what a numerically invalid track does in every association
 * mode (ALGORITHMS.md §3: deleted, counted, never associated or merged). */
#include <float.h>
#include <string.h>

#include "mtt_internal.h"
#include "sim.h"
#include "tv_assert.h"
#include "tv_fixture.h"
#include "unity.h"

static mtt_tracker trk;

void setUp(void) {}
void tearDown(void) {}

static void diag(mtt_real P[16], mtt_real pos, mtt_real vel)
{
    memset(P, 0, 16 * sizeof P[0]);
    P[0] = pos;
    P[5] = pos;
    P[10] = vel;
    P[15] = vel;
}

/* Every argument that may be NULL is refused, and nothing changes. */
static void test_null_arguments(void)
{
    mtt_params p;
    mtt_real x[4] = {MTT_R(0.0)}, P[16];
    mtt_track_view v;
    mtt_stats st;
    size_t n = 7;
    diag(P, MTT_R(1.0), MTT_R(1.0));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_tracker_add_track(NULL, x, P, NULL));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_tracker_add_track(&trk, NULL, P, NULL));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_tracker_add_track(&trk, x, NULL, NULL));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_tracker_count(NULL, &n));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_tracker_count(&trk, NULL));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_tracker_track(NULL, 0, &v));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_tracker_track(&trk, 0, NULL));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_tracker_stats(NULL, &st));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_tracker_stats(&trk, NULL));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&trk, &n));
    TEST_ASSERT_EQUAL_UINT(0u, (unsigned)n);
}

/* An association value below the enumeration is out of range, for the
 * name and for the parameter check; so is an init_gate below it. */
static void test_enum_below_range(void)
{
    mtt_params p;
    const char *name = "unchanged", *bad = NULL;
    TEST_ASSERT_EQUAL_INT(MTT_ERR_RANGE, mtt_assoc_name((mtt_assoc)-1, &name));
    TEST_ASSERT_EQUAL_STRING("unchanged", name);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.association = (mtt_assoc)-1;
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_check(&p, &bad));
    TEST_ASSERT_EQUAL_STRING("association", bad);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.init_gate = (mtt_init_gate)-1;
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_check(&p, &bad));
    TEST_ASSERT_EQUAL_STRING("init_gate", bad);
}

/* An enumeration or flag setting takes a whole index in [0, hi] only. */
static void test_params_set_index_refused(void)
{
    mtt_params p, q;
    const double below = -1.0, half = 0.5, above = 1e6;
    double got = -1.0;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    q = p;
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_set(&p, "association", &below, 1));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_set(&p, "association", &half, 1));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_set(&p, "association", &above, 1));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_set(&p, "initiate", &half, 1));
    TEST_ASSERT_EQUAL_MEMORY(&q, &p, sizeof p);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_get(&p, "initiate", &got, 1));
    TEST_ASSERT_EQUAL_DOUBLE(1.0, got);
}

/* The two-point covariance refuses a non-finite sigma or interval. */
static void test_two_point_cov_not_finite(void)
{
    mtt_real P[4][4];
    volatile mtt_real zero = MTT_R(0.0);
    const mtt_real inf = MTT_R(1.0) / zero, nan = zero / zero;
    const mtt_real one = MTT_R(1.0);
    P[0][0] = MTT_R(-7.0);
    TEST_ASSERT_EQUAL_INT(MTT_ERR_VALUE, mtt_init_two_point_cov(inf, one, one, P));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_VALUE, mtt_init_two_point_cov(one, inf, one, P));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_VALUE, mtt_init_two_point_cov(one, one, inf, P));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_VALUE, mtt_init_two_point_cov(nan, one, one, P));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_VALUE, mtt_init_two_point_cov(one, nan, one, P));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_VALUE, mtt_init_two_point_cov(one, one, nan, P));
    TEST_ASSERT_EQUAL_FLOAT(-7.0f, (float)P[0][0]);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_init_two_point_cov(MTT_R(2.0), one, MTT_R(0.5), P));
    TEST_ASSERT_EQUAL_FLOAT(32.0f, (float)P[2][2]); /* 2 R / dT^2 = 2 * 4 / 0.25 */
}

/* P_r of an empty gate: nothing is written. */
static void test_prank_empty(void)
{
    mtt_real out[2] = {MTT_R(-3.0), MTT_R(-3.0)};
    mtt_ihpda_prank(0, MTT_R(1.0), out);
    TEST_ASSERT_EQUAL_FLOAT(-3.0f, (float)out[0]);
    mtt_ihpda_prank(2, MTT_R(0.0), out); /* rho = 0: 1/m each */
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.5f, (float)out[0]);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.5f, (float)out[1]);
}

/* In every association mode built: track 0 alone at x = 1000 with its own
 * measurement; tracks 1 and 3 share a measurement at the origin with a
 * velocity variance of 0.6 of the largest mtt_real (not in S: they gate),
 * so P_a + P_b overflows and they cannot be a merge candidate, however
 * large the threshold; track 2 sits at a quarter of the largest mtt_real,
 * moving at as much.  The first frame predicts nothing; the second
 * frame's prediction overflows tracks 1, 2 and 3 (S resp. the state not
 * finite).  They are deleted as numerically invalid, counted, never
 * merged; track 0 is updated as alone. */
static void test_invalid_tracks_every_mode(void)
{
    int mode;
    int runs = 0;
    for (mode = 0; mode < (int)MTT_ASSOC_COUNT; ++mode) {
        mtt_params p;
        mtt_real P[16];
        const mtt_real big = MTT_R(0.25) * MTT_REAL_MAX;
        const mtt_real x0[4] = {MTT_R(1000.0), MTT_R(0.0), MTT_R(0.0), MTT_R(0.0)};
        const mtt_real x1[4] = {MTT_R(0.0), MTT_R(0.0), MTT_R(0.0), MTT_R(0.0)};
        const mtt_real x2[4] = {big, MTT_R(0.0), big, MTT_R(0.0)};
        mtt_meas z[2];
        mtt_stats st;
        mtt_track_view v;
        size_t n;
        uint32_t id0;
        z[0] = sim_meas(MTT_R(0.3), MTT_R(0.0), MTT_R(5.0), 1);
        z[1] = sim_meas(MTT_R(1000.3), MTT_R(0.0), MTT_R(5.0), 1);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
        p.association = (mtt_assoc)mode;
        p.initiate = 0;
        p.merge_threshold = MTT_R(1e30);
        if (mtt_params_check(&p, NULL) != MTT_OK) {
            continue; /* not built in this configuration */
        }
        ++runs;
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
        diag(P, MTT_R(1.0), MTT_R(1.0));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&trk, x0, P, &id0));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&trk, x2, P, NULL));
        diag(P, MTT_R(1.0), MTT_R(0.6) * MTT_REAL_MAX);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&trk, x1, P, NULL));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&trk, x1, P, NULL));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_R(1.0), z, 2));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_R(10.0), z, 2));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&trk, &st));
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(0u, st.total.merges, "overflowing P_a + P_b merged");
        TEST_ASSERT_EQUAL_UINT32(3u, st.total.numeric_deletions);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&trk, &n));
        TEST_ASSERT_EQUAL_UINT(1u, (unsigned)n);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, 0, &v));
        TEST_ASSERT_EQUAL_UINT32(id0, v.id);
        TEST_ASSERT_TRUE(v.x[0] > MTT_R(1000.0) && v.x[0] < MTT_R(1000.3)); /* pulled towards z */
        TEST_ASSERT_EQUAL_INT32(1, v.meas);
    }
    /* the four modes of [S0] and [S4]; the baselines when built */
    TEST_ASSERT_EQUAL_INT(MTT_WITH_BASELINES ? (int)MTT_ASSOC_COUNT : 4, runs);
}

/* Births of a two-frame scene: z at the origin at t0, z2 at t1, both with
 * amplitude amp; returns the births of the second frame. */
static uint32_t births_of(const mtt_params *p, mtt_real t0, mtt_real t1, mtt_real x2, mtt_real amp)
{
    mtt_meas z = sim_meas(MTT_R(0.0), MTT_R(0.0), MTT_R(5.0), 1);
    mtt_stats st;
    z.amplitude = amp;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, p));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, t0, &z, 1));
    z.x = x2;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, t1, &z, 1));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&trk, &st));
    return st.last.births;
}

/* ALGORITHMS.md §12.2: I is clamped at the peak of the configured f2, and
 * not at all when f2 does not peak (a2 >= 0). */
static void test_intensity_f_clamp_follows_f2(void)
{
    mtt_params p;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    /* default f2 peaks at 1048.5: above it f stays at f2(1048.5) */
    TEST_ASSERT_FLOAT_WITHIN(1e-3f, (float)mtt_init_intensity_f(&p, MTT_R(1048.5)),
                             (float)mtt_init_intensity_f(&p, MTT_R(5000.0)));
    p.intensity_f2[0] = MTT_R(0.0);
    p.intensity_f2[1] = MTT_R(0.2);
    p.intensity_f2[2] = MTT_R(50.0);
    TEST_ASSERT_FLOAT_WITHIN(1e-3f, 1050.0f, (float)mtt_init_intensity_f(&p, MTT_R(5000.0)));
    /* I < 0 counts as 0: f1(0) = its constant term (39.70 by default) */
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, 39.70f, (float)mtt_init_intensity_f(&p, MTT_R(-3.0)));
}

/* The intensity gate: a pair whose f(I) is not positive starts nothing; a
 * vmax circle wider than the intensity gate does not widen it; a pair one
 * unit apart starts a track with the default f (about 83 at I = 100). */
static void test_intensity_gate_decides(void)
{
    mtt_params p;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.init_gate = MTT_INIT_GATE_INTENSITY;
    TEST_ASSERT_EQUAL_UINT32(1u, births_of(&p, MTT_R(1.0), MTT_R(2.0), MTT_R(1.0), MTT_R(100.0)));
    p.vmax = MTT_R(1000.0);
    TEST_ASSERT_EQUAL_UINT32(1u, births_of(&p, MTT_R(1.0), MTT_R(2.0), MTT_R(50.0), MTT_R(100.0)));
    TEST_ASSERT_EQUAL_UINT32(0u, births_of(&p, MTT_R(1.0), MTT_R(2.0), MTT_R(200.0), MTT_R(100.0)));
    p.intensity_f1[0] = p.intensity_f2[0] = MTT_R(0.0);
    p.intensity_f1[1] = p.intensity_f2[1] = MTT_R(0.0);
    p.intensity_f1[2] = p.intensity_f2[2] = MTT_R(-1.0);
    TEST_ASSERT_EQUAL_UINT32(0u, births_of(&p, MTT_R(1.0), MTT_R(2.0), MTT_R(0.0), MTT_R(100.0)));
}

/* ALGORITHMS.md §12.1 invalid birth: frames the smallest normal number apart
 * (the intensity gate does not scale with dT) give a velocity 10 / dT that
 * overflows: no track.  One time unit apart the same pair starts one. */
static void test_birth_velocity_overflow(void)
{
#ifdef MTT_REAL_DOUBLE
    const mtt_real tiny = DBL_MIN;
#else
    const mtt_real tiny = FLT_MIN;
#endif
    mtt_params p;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.init_gate = MTT_INIT_GATE_INTENSITY;
    TEST_ASSERT_EQUAL_UINT32(1u, births_of(&p, MTT_R(0.0), MTT_R(1.0), MTT_R(10.0), MTT_R(100.0)));
    TEST_ASSERT_EQUAL_UINT32(0u, births_of(&p, MTT_R(0.0), tiny, MTT_R(10.0), MTT_R(100.0)));
}

/* A tracker with p and two seeded tracks at rest, at the origin and at
 * (xb, 0), identity covariance. */
static void init_two(const mtt_params *p, mtt_real xb)
{
    mtt_real P[16];
    const mtt_real xa[4] = {MTT_R(0.0), MTT_R(0.0), MTT_R(0.0), MTT_R(0.0)};
    const mtt_real x2[4] = {xb, MTT_R(0.0), MTT_R(0.0), MTT_R(0.0)};
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, p));
    diag(P, MTT_R(1.0), MTT_R(1.0));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&trk, xa, P, NULL));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&trk, x2, P, NULL));
}

/* ALGORITHMS.md §8.1 range guard: with PD = 1, PG = 0.9999999 and P^ = 1
 * (the first frame predicts nothing), a track with one gated measurement has
 * Pt = PD PG above 1 - 1e-6: clamped.  Two such tracks share their one
 * measurement, so each pair's lambda~ is lambda plus the other's
 * w = p Pt / (1 - Pt) at the clamp. */
static void test_lm_pt_clamped(void)
{
    const mtt_real pt = MTT_R(1.0) - MTT_R(1e-6);
    mtt_params p;
    mtt_meas z = sim_meas(MTT_R(1.5), MTT_R(0.0), MTT_R(5.0), 1);
    int k;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.association = MTT_ASSOC_LM_IPDA;
    p.pd = MTT_R(1.0);
    p.pg = MTT_R(0.9999999);
    p.initiate = 0;
    p.merge_threshold = MTT_R(0.0);
    init_two(&p, MTT_R(3.0));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_R(1.0), &z, 1));
    TEST_ASSERT_EQUAL_UINT16(2u, TV_N_PAIRS(&trk));
    TEST_ASSERT_TRUE(p.pd * p.pg > pt);
    for (k = 0; k < 2; ++k) {
        const int me = k, other = 1 - k;
        const double w = (double)TV_PAIR_P(&trk, other) * (double)pt / (1.0 - (double)pt);
        TEST_ASSERT_FLOAT_WITHIN((float)(1e-3 * w), (float)w, (float)TV_PAIR_W(&trk, other));
        TEST_ASSERT_FLOAT_WITHIN((float)(1e-3 * w), (float)((double)p.clutter_density + w),
                                 (float)TV_PAIR_LAM(&trk, me));
    }
}

#if MTT_WITH_BASELINES
/* JPDA* pruning (ALGORITHMS.md §13.6): a threshold that every kept event
 * fails would drop them all, so none is dropped: the frame equals the one
 * without pruning, to the last bit. */
static void run_star(mtt_real threshold, mtt_track_view v[2])
{
    mtt_params p;
    mtt_meas z[2];
    size_t n;
    z[0] = sim_meas(MTT_R(0.8), MTT_R(0.1), MTT_R(5.0), 1);
    z[1] = sim_meas(MTT_R(1.2), MTT_R(-0.1), MTT_R(5.0), 1);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.association = MTT_ASSOC_JPDA_STAR;
    p.jpda_star_threshold = threshold;
    p.initiate = 0;
    p.merge_threshold = MTT_R(0.0);
    init_two(&p, MTT_R(2.0));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_R(1.0), z, 2));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&trk, &n));
    TEST_ASSERT_EQUAL_UINT(2u, (unsigned)n);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, 0, &v[0]));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, 1, &v[1]));
}

static void test_jpda_star_never_prunes_every_event(void)
{
    mtt_track_view a[2], b[2];
    run_star(MTT_R(0.0), a);
    run_star(MTT_R(0.99), b);
    TEST_ASSERT_EQUAL_MEMORY(a, b, sizeof a);
    TEST_ASSERT_TRUE(a[0].x[0] > MTT_R(0.0) && a[1].x[0] < MTT_R(2.0)); /* both updated inwards */
}
#endif

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_null_arguments);
    RUN_TEST(test_enum_below_range);
    RUN_TEST(test_params_set_index_refused);
    RUN_TEST(test_two_point_cov_not_finite);
    RUN_TEST(test_prank_empty);
    RUN_TEST(test_invalid_tracks_every_mode);
    RUN_TEST(test_intensity_f_clamp_follows_f2);
    RUN_TEST(test_intensity_gate_decides);
    RUN_TEST(test_birth_velocity_overflow);
    RUN_TEST(test_lm_pt_clamped);
#if MTT_WITH_BASELINES
    RUN_TEST(test_jpda_star_never_prunes_every_event);
#endif
    return UNITY_END();
}
