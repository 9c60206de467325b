/* SPDX-License-Identifier: BSD-3-Clause */
/* test_lost.c - the lost-track rule of ALGORITHMS.md §12.4 (track_table.c):
 * a track whose position variance (x or y) exceeds (vmax ΔT)^2 after its
 * update is deleted and counted in deletions, ΔT the longer of this frame's
 * interval and the last one's; terminate_threshold 0 keeps it.  One text for
 * float, double and the fixed-point build (MTT_POS / MTT_VAR constants).
 *
 * The track is seeded at (0, 0) with P = diag(a, a, 1, 1) and frames carry
 * no detection, so after a frame of dt its variance is the prediction's,
 * a + dt^2 + q dt^3 / 3 (IPDA with no detection keeps P̄). */
#include <string.h>

#include "mtt_internal.h"
#include "unity.h"

static mtt_tracker trk;

void setUp(void) {}
void tearDown(void) {}

#define QPSD 0.03 /* process_psd: q dt^3 / 3 = 0.01 at dt 1 */
#define VMAX 10.0

static void start(double a, mtt_real terminate)
{
    mtt_params p;
    mtt_real x[4] = {MTT_POS(0.0), MTT_POS(0.0), MTT_POS(0.0), MTT_POS(0.0)}, P[16];
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.association = MTT_ASSOC_IPDA;
    p.motion = MTT_MOTION_CV;
    p.process_psd = MTT_VAR(QPSD);
    p.vmax = MTT_POS(VMAX);
    p.initiate = 0;
    p.clutter_density = MTT_DENS(1e-3); /* the fixed build needs a declared density */
    p.terminate_threshold = terminate;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    memset(P, 0, sizeof P);
    P[0] = MTT_VAR(a);
    P[5] = MTT_VAR(a);
    P[10] = MTT_VAR(1.0);
    P[15] = MTT_VAR(1.0);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&trk, x, P, NULL));
    /* the first frame has no interval: the rule cannot apply */
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_TIME(0.0), NULL, 0));
}

static size_t count(void)
{
    size_t n = 0;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&trk, &n));
    return n;
}

static uint32_t deletions(void)
{
    mtt_stats st;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&trk, &st));
    return st.last.deletions;
}

/* (vmax ΔT)^2 = 100 at dt 1: a = 98 gives 99.01, kept; a = 99.5 gives
 * 100.51, deleted, though its existence (about 0.83) is far above the
 * terminate threshold. */
static void test_beyond_vmax_dt_is_deleted(void)
{
    start(98.0, MTT_P(0.01));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_TIME(1.0), NULL, 0));
    TEST_ASSERT_EQUAL_UINT(1, count());
    TEST_ASSERT_EQUAL_UINT32(0u, deletions());
    start(99.5, MTT_P(0.01));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_TIME(1.0), NULL, 0));
    TEST_ASSERT_EQUAL_UINT(0, count());
    TEST_ASSERT_EQUAL_UINT32(1u, deletions());
}

/* terminate_threshold 0 never deletes, this rule included. */
static void test_never_delete_keeps_it(void)
{
    start(99.5, MTT_P(0.0));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_TIME(1.0), NULL, 0));
    TEST_ASSERT_EQUAL_UINT(1, count());
}

/* Interleaved frames: after an interval of 10 a frame 0.5 later bounds at
 * (vmax 10)^2 = 10^4, not (vmax 0.5)^2 = 25.  a = 5000: 5110 after the
 * first interval, 5121 after the second; kept.  The next frame, 0.5 later
 * again, bounds at 25: deleted. */
static void test_interleaved_frames_use_the_longer_interval(void)
{
    start(5000.0, MTT_P(0.01));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_TIME(10.0), NULL, 0));
    TEST_ASSERT_EQUAL_UINT(1, count());
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_TIME(10.5), NULL, 0));
    TEST_ASSERT_EQUAL_UINT(1, count());
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_TIME(11.0), NULL, 0));
    TEST_ASSERT_EQUAL_UINT(0, count());
    TEST_ASSERT_EQUAL_UINT32(1u, deletions());
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_beyond_vmax_dt_is_deleted);
    RUN_TEST(test_never_delete_keeps_it);
    RUN_TEST(test_interleaved_frames_use_the_longer_interval);
    return UNITY_END();
}
