/* SPDX-License-Identifier: BSD-3-Clause */
/* test_caps.c - the per-gate and merge-candidate caps (README 'Limits',
 * ALGORITHMS.md §7.2, §12.3) at the configured bounds, through whole
 * frames: which entries stay, and the counts reported for the dropped. */
#include <string.h>

#include "mtt_internal.h"
#include "tv_assert.h"
#include "tv_fixture.h"
#include "unity.h"

static mtt_tracker trk;
static mtt_meas m[MTT_MAX_GATED + 8];

void setUp(void) {}
void tearDown(void) {}

static void seed(mtt_real x, mtt_real y)
{
    const mtt_real xs[4] = {x, y, MTT_R(0.0), MTT_R(0.0)};
    mtt_real P[16];
    int i;
    memset(P, 0, sizeof P);
    for (i = 0; i < 4; ++i) {
        P[i * 5] = MTT_R(1.0);
    }
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&trk, xs, P, NULL));
}

/* One track, MTT_MAX_GATED + 6 measurements in its gate (S = 2 I: the
 * first frame predicts nothing; d^2 = |z|^2 / 2), stored in the canonical
 * (x) order and met by the gate's x sweep in that order: G - 2 near ones
 * (inputs 3..G, x < 0); inputs 1 and 2 at (0, -1), which fill the gate;
 * input G + 1 at (0.5, 0), nearer than the worst kept, replaces input 2
 * (equal d^2: the higher stored index is the worst); input 0 at (1, 0)
 * does not replace input 1 (equal d^2, higher stored index), nor does
 * input G + 5 at (1, 0) too; three far ones do not.  Kept: the near ones,
 * 1 and G + 1; 6 dropped. */
static void test_gate_cap_keeps_smallest_d2_then_lower_index(void)
{
    const uint32_t G = MTT_MAX_GATED, n = MTT_MAX_GATED + 6u;
    mtt_params p;
    mtt_stats st;
    uint32_t i;
    uint16_t k;
    int kept[MTT_MAX_GATED + 8];
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.initiate = 0;
    p.merge_threshold = MTT_R(0.0);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    seed(MTT_R(0.0), MTT_R(0.0));
    memset(m, 0, sizeof m);
    m[0].x = MTT_R(1.0);
    m[1].y = MTT_R(-1.0);
    m[2].y = MTT_R(-1.0);
    for (i = 3; i <= G; ++i) {
        m[i].x = MTT_R(-0.02) * (mtt_real)(i - 2u);
    }
    m[G + 1u].x = MTT_R(0.5);
    for (i = 0; i < 3u; ++i) {
        m[G + 2u + i].x = MTT_R(1.1) + MTT_R(0.1) * (mtt_real)i;
    }
    m[G + 5u].x = MTT_R(1.0);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_R(1.0), m, n));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&trk, &st));
    TEST_ASSERT_EQUAL_UINT32(6u, st.last.gated_dropped);
    TEST_ASSERT_EQUAL_UINT32(MTT_MAX_GATED, st.last.pairs);
    TEST_ASSERT_EQUAL_UINT16(MTT_MAX_GATED, TV_PAIR_COUNT(&trk, 0));
    memset(kept, 0, sizeof kept);
    for (k = TV_PAIR_FIRST(&trk, 0); k < TV_PAIR_FIRST(&trk, 0) + TV_PAIR_COUNT(&trk, 0); ++k) {
        kept[TV_MEAS_SRC(&trk, TV_PAIR_MEAS(&trk, k))] = 1;
    }
    for (i = 0; i < n; ++i) {
        const int want = (i == 1u) || (i >= 3u && i <= G + 1u);
        TEST_ASSERT_EQUAL_INT_MESSAGE(want, kept[i], "input kept in the gate");
    }
}

/* MTT_MAX_TRACKS seeded tracks on a line, 0.001 apart, all gating one
 * measurement (one cluster): every pair is a merge candidate,
 * n (n - 1) / 2 of them, and MTT_MAX_MERGE_PAIRS stay. */
static void test_merge_candidates_capped(void)
{
    const uint32_t n = MTT_MAX_TRACKS;
    mtt_params p;
    mtt_stats st;
    mtt_meas z;
    size_t count;
    uint32_t i;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.initiate = 0;
    p.merge_threshold = MTT_R(10.0);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    for (i = 0; i < n; ++i) {
        seed(MTT_R(0.001) * (mtt_real)i, MTT_R(0.0));
    }
    z.x = MTT_R(0.0);
    z.y = MTT_R(0.5);
    z.has_amplitude = 0;
    z.amplitude = MTT_R(0.0);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_R(1.0), &z, 1));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&trk, &st));
    TEST_ASSERT_EQUAL_UINT32(n, st.max_cluster_tracks);
    TEST_ASSERT_EQUAL_UINT32(n * (n - 1u) / 2u - MTT_MAX_MERGE_PAIRS, st.last.merge_dropped);
    TEST_ASSERT_EQUAL_UINT16(MTT_MAX_MERGE_PAIRS, TV_N_MERGE(&trk));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&trk, &count));
    TEST_ASSERT_TRUE(st.last.merges >= n / 2u);
    TEST_ASSERT_EQUAL_UINT32(n, (uint32_t)count + st.last.merges);
    /* the kept candidates are the smallest d^2: none of them exceeds the
     * smallest d^2 of a pair of tracks 3 steps apart or more, whose
     * n - 3 + n - 4 + ... candidates cannot all fit beside the n - 1 + n - 2
     * nearer ones when MTT_MAX_MERGE_PAIRS = 2 n */
    for (i = 0; i < TV_N_MERGE(&trk); ++i) {
        const int gap = (int)TV_MERGE_B(&trk, i) - (int)TV_MERGE_A(&trk, i);
        TEST_ASSERT_TRUE(gap >= 1 && gap <= 3);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_gate_cap_keeps_smallest_d2_then_lower_index);
    RUN_TEST(test_merge_candidates_capped);
    return UNITY_END();
}
