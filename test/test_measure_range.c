/* SPDX-License-Identifier: BSD-3-Clause */
/* test_measure_range.c - input that the build cannot represent is skipped
 * and counted, never wrapped or clamped into range (measure.c,
 * ALGORITHMS.md §16; docs/FIXED_POINT.md §3).  Float and double: NaN and
 * Inf coordinates or amplitudes, malformed (meas_bad).  Fixed point:
 * coordinates beyond the declared +-MTT_FX_POS_LIMIT and saturated
 * amplitudes (what the boundary conversion makes of unrepresentable
 * input), counted apart in meas_out_of_range.  A negative amplitude is
 * malformed in every build. */
#include <string.h>

#include "mtt_internal.h"
#include "tv_assert.h"
#include "tv_fixture.h"
#include "sim.h"
#include "unity.h"

static mtt_tracker trk; /* measure.c reads no parameter: zeroed is enough */

void setUp(void)
{
    memset(&trk, 0, sizeof trk);
}
void tearDown(void) {}

static void test_unrepresentable_skipped_and_counted(void)
{
#ifdef MTT_REAL_FIXED
    const mtt_real big = MTT_FX_POS_LIMIT + 1; /* one LSB beyond the declared range */
    const mtt_real edge = MTT_FX_POS_LIMIT;    /* the range's own edge is valid */
    const mtt_real sat = MTT_FX_MAX;           /* the saturation marker */
#else
    const mtt_real big = (mtt_real)INFINITY;
    const mtt_real edge = MTT_REAL_MAX;
    const mtt_real sat = (mtt_real)NAN;
#endif
    mtt_meas in[9];
    in[0] = sim_meas(MTT_POS(1.0), MTT_POS(2.0), MTT_ZERO, 0); /* kept */
    in[1] = sim_meas(big, MTT_POS(2.0), MTT_ZERO, 0);
    in[2] = sim_meas(MTT_POS(1.0), -big, MTT_ZERO, 0);
    in[3] = sim_meas(edge, -edge, MTT_ZERO, 0);                /* kept */
    in[4] = sim_meas(MTT_POS(3.0), MTT_POS(4.0), sat, 1);
    in[5] = sim_meas(MTT_POS(3.0), MTT_POS(4.0), -sat, 1);
    in[6] = sim_meas(sat, MTT_POS(4.0), MTT_ZERO, 0);
    in[7] = sim_meas(MTT_POS(-5.0), MTT_POS(6.0), MTT_ZERO, 1); /* kept: amplitude 0 */
    in[8] = sim_meas(MTT_POS(7.0), MTT_POS(8.0), -MTT_AMP(1.0), 1); /* malformed */
    mtt_measure_select(&trk, in, NULL, NULL, 9u);
    TEST_ASSERT_EQUAL_UINT(3u, tv_meas_count(&trk));
#ifdef MTT_REAL_FIXED
    TEST_ASSERT_EQUAL_UINT32(1u, TV_STATS(&trk).last.meas_bad);
    TEST_ASSERT_EQUAL_UINT32(5u, TV_STATS(&trk).last.meas_out_of_range);
#else
    TEST_ASSERT_EQUAL_UINT32(6u, TV_STATS(&trk).last.meas_bad);
    TEST_ASSERT_EQUAL_UINT32(0u, TV_STATS(&trk).last.meas_out_of_range);
#endif
    TEST_ASSERT_EQUAL_UINT32(0u, TV_STATS(&trk).last.meas_dropped);
    /* stored in the canonical (x) order */
    TEST_ASSERT_EQUAL_UINT32(7u, tv_meas_src(&trk, 0));
    TEST_ASSERT_EQUAL_UINT32(0u, tv_meas_src(&trk, 1));
    TEST_ASSERT_EQUAL_UINT32(3u, tv_meas_src(&trk, 2));
    /* kept values are stored exactly, the edge included */
    TEST_ASSERT_TRUE(TV_MEAS_X(&trk, 2) == edge && TV_MEAS(&trk, 2).y == -edge);
    TEST_ASSERT_TRUE(TV_MEAS_X(&trk, 0) == MTT_POS(-5.0) && TV_MEAS(&trk, 0).y == MTT_POS(6.0));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_unrepresentable_skipped_and_counted);
    return UNITY_END();
}
