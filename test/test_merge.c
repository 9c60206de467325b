/* SPDX-License-Identifier: BSD-3-Clause */
/* test_merge.c - track merge test and survivor rule (ALGORITHMS.md §12.3, TV11). */
#include <string.h>

#include "mtt_internal.h"
#include "tv_assert.h"
#include "tv_fixture.h"
#include "unity.h"

static mtt_tracker trk;

void setUp(void) {}
void tearDown(void) {}

/* TV11 inputs */
static const mtt_state xa = {MTT_R(100.0), MTT_R(50.0), MTT_R(10.0), MTT_R(-5.0)};
static const mtt_state xb1 = {MTT_R(100.6), MTT_R(49.7), MTT_R(10.3), MTT_R(-5.2)};
static const mtt_state xb2 = {MTT_R(101.5), MTT_R(49.0), MTT_R(10.3), MTT_R(-5.2)};

static void set_track(uint16_t i, const mtt_state x, mtt_real pos, mtt_real vel,
                      mtt_real existence, int confirmed, uint32_t id)
{
    memset(TV_TRACK(&trk, i), 0, sizeof *TV_TRACK(&trk, i));
    memcpy(TV_X(&trk, i), x, sizeof TV_X(&trk, i));
    TV_P(&trk, i)[0][0] = pos;
    TV_P(&trk, i)[1][1] = pos;
    TV_P(&trk, i)[2][2] = vel;
    TV_P(&trk, i)[3][3] = vel;
    TV_EXISTENCE(&trk, i) = existence;
    TV_CONFIRMED(&trk, i) = (uint8_t)confirmed;
    TV_TRACK_ID(&trk, i) = id;
    TV_TRACK_MEAS(&trk, i) = -1;
}

/* a: P_a = diag(1, 1, 0.5, 0.5); b: P_b = diag(2, 2, 1, 1) (TV11) */
static void set_a(uint16_t i, mtt_real ex, int conf, uint32_t id)
{
    set_track(i, xa, MTT_R(1.0), MTT_R(0.5), ex, conf, id);
}
static void set_b(uint16_t i, const mtt_real *xb, mtt_real ex, int conf, uint32_t id)
{
    set_track(i, xb, MTT_R(2.0), MTT_R(1.0), ex, conf, id);
}

static void test_tv11_d2(void)
{
    mtt_real d2 = MTT_R(-1.0);
    set_a(0, MTT_R(0.5), 0, 0);
    set_b(1, xb1, MTT_R(0.5), 0, 1);
    TEST_ASSERT_EQUAL_INT(0, mtt_merge_d2(TV_TRACK(&trk, 0), TV_TRACK(&trk, 1), &d2));
    TV_ASSERT_REAL(0.2366666667, d2);    /* TV11 case 1 d2 */
    TEST_ASSERT_TRUE(d2 < MTT_R(1.0));   /* TV11 case 1: merge = true */
    TEST_ASSERT_EQUAL_INT(0, mtt_merge_d2(TV_TRACK(&trk, 1), TV_TRACK(&trk, 0), &d2));
    TV_ASSERT_REAL(0.2366666667, d2);    /* symmetric in a, b */
    set_b(1, xb2, MTT_R(0.5), 0, 1);
    TEST_ASSERT_EQUAL_INT(0, mtt_merge_d2(TV_TRACK(&trk, 0), TV_TRACK(&trk, 1), &d2));
    TV_ASSERT_REAL(1.17, d2);            /* TV11 case 2 d2 */
    TEST_ASSERT_FALSE(d2 < MTT_R(1.0));  /* TV11 case 2: merge = false */
}

static void test_merge_d2_not_pd(void)
{
    mtt_real d2 = MTT_R(5.0);
    set_track(0, xa, MTT_R(0.0), MTT_R(0.0), MTT_R(0.5), 0, 0);
    set_track(1, xb1, MTT_R(0.0), MTT_R(0.0), MTT_R(0.5), 0, 1);
    TEST_ASSERT_EQUAL_INT(-1, mtt_merge_d2(TV_TRACK(&trk, 0), TV_TRACK(&trk, 1), &d2));
    TEST_ASSERT_TRUE(d2 == MTT_R(5.0));
}

/* Tracker with two tracks in one cluster, as the merge stage sees it. */
static void two_track_cluster(void)
{
    mtt_params p;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.merge_threshold = MTT_R(1.0); /* TV11 t_merge */
    tv_init(&trk, &p);
    TV_N_TRACKS(&trk) = 2;
    TV_N_CLUSTERS(&trk) = 1;
    TV_CL_FIRST(&trk, 0) = 0;
    TV_CL_FIRST(&trk, 1) = 2;
    TV_CL_LIST(&trk, 0) = 0;
    TV_CL_LIST(&trk, 1) = 1;
    TV_VALID(&trk, 0) = 1; /* as after an update that kept both tracks */
    TV_VALID(&trk, 1) = 1;
}

/* F8: a track the update found numerically invalid is deleted as such by
 * the manager, never merged (it would be counted twice). */
static void test_invalid_track_not_merged(void)
{
    two_track_cluster();
    set_a(0, MTT_R(0.3), 0, 0);
    set_b(1, xb1, MTT_R(0.9), 1, 1);
    TV_VALID(&trk, 1) = 0;
    mtt_merge_frame(&trk);
    TEST_ASSERT_EQUAL_UINT(0, TV_N_MERGE(&trk));
    TEST_ASSERT_EQUAL_UINT(0, TV_DEAD(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(0, TV_DEAD(&trk, 1));
}

static void test_tv11_case1_survivor_a(void)
{
    /* Survivor: a (position trace 2 < 4); existence = max, confirmed = OR;
     * a keeps its own state. */
    static const double want_x[4] = {100, 50, 10, -5}; /* TV11 x_a */
    two_track_cluster();
    set_a(0, MTT_R(0.3), 0, 0);
    set_b(1, xb1, MTT_R(0.9), 1, 1);
    mtt_merge_frame(&trk);
    TEST_ASSERT_EQUAL_UINT(1, TV_N_MERGE(&trk));
    TV_ASSERT_REAL(0.2366666667, TV_MERGE_D2(&trk, 0)); /* TV11 case 1 */
    TEST_ASSERT_EQUAL_UINT(0, TV_DEAD(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(1, TV_DEAD(&trk, 1));
    TV_ASSERT_REAL(0.9, TV_EXISTENCE(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(1, TV_CONFIRMED(&trk, 0));
    TV_ASSERT_VEC(want_x, TV_X(&trk, 0), 4);
    TV_ASSERT_REAL(1.0, TV_P(&trk, 0)[0][0]);
    TEST_ASSERT_EQUAL_UINT(1, TV_STATS(&trk).last.merges);
}

static void test_tv11_case1_survivor_a_at_higher_index(void)
{
    /* Same pair with b first: the survivor is still a (smaller trace). */
    two_track_cluster();
    set_b(0, xb1, MTT_R(0.2), 0, 0);
    set_a(1, MTT_R(0.7), 0, 1);
    mtt_merge_frame(&trk);
    TEST_ASSERT_EQUAL_UINT(1, TV_DEAD(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(0, TV_DEAD(&trk, 1));
    TV_ASSERT_REAL(0.7, TV_EXISTENCE(&trk, 1));       /* max(0.2, 0.7) */
    TEST_ASSERT_EQUAL_UINT(0, TV_CONFIRMED(&trk, 1)); /* 0 OR 0 */
    TV_ASSERT_REAL(100.0, TV_X(&trk, 1)[0]);          /* TV11 x_a */
}

static void test_tv11_case2_no_merge(void)
{
    two_track_cluster();
    set_a(0, MTT_R(0.3), 0, 0);
    set_b(1, xb2, MTT_R(0.9), 1, 1);
    mtt_merge_frame(&trk);
    TEST_ASSERT_EQUAL_UINT(0, TV_N_MERGE(&trk));             /* TV11 case 2: d2 = 1.17 >= 1 */
    TEST_ASSERT_EQUAL_UINT(0, TV_DEAD(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(0, TV_DEAD(&trk, 1));
    TV_ASSERT_REAL(0.3, TV_EXISTENCE(&trk, 0));
}

static void test_survivor_ties(void)
{
    /* Equal traces: the higher existence survives; then the lower index. */
    two_track_cluster();
    set_a(0, MTT_R(0.4), 0, 0);
    set_a(1, MTT_R(0.8), 1, 1);
    TV_X(&trk, 1)[0] = MTT_R(100.6); /* TV11 case 1 offset in x */
    mtt_merge_frame(&trk);
    TEST_ASSERT_EQUAL_UINT(1, TV_DEAD(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(0, TV_DEAD(&trk, 1));
    two_track_cluster();
    set_a(0, MTT_R(0.8), 0, 0);
    set_a(1, MTT_R(0.8), 1, 1);
    mtt_merge_frame(&trk);
    TEST_ASSERT_EQUAL_UINT(0, TV_DEAD(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(1, TV_DEAD(&trk, 1));
    TEST_ASSERT_EQUAL_UINT(1, TV_CONFIRMED(&trk, 0)); /* OR */
}

static void test_merge_order_by_d2(void)
{
    /* Three tracks: (0, 2) has the smallest d2 and merges first; 0 survives
     * (smallest trace) and the pair (0, 1) then merges too; (1, 2) is
     * skipped because 2 is already dead. */
    two_track_cluster();
    TV_N_TRACKS(&trk) = 3;
    TV_CL_FIRST(&trk, 1) = 3;
    TV_CL_LIST(&trk, 2) = 2;
    TV_VALID(&trk, 2) = 1;
    set_a(0, MTT_R(0.5), 0, 0);
    set_b(1, xb1, MTT_R(0.6), 0, 1); /* d2 = 0.2366666667 to track 0 */
    set_b(2, xa, MTT_R(0.95), 1, 2); /* d2 = 0 to track 0 */
    mtt_merge_frame(&trk);
    TEST_ASSERT_EQUAL_UINT(3, TV_N_MERGE(&trk));
    TEST_ASSERT_TRUE(TV_MERGE_D2(&trk, 0) == MTT_R(0.0));
    TEST_ASSERT_EQUAL_UINT(2, TV_MERGE_B(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(0, TV_DEAD(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(1, TV_DEAD(&trk, 1));
    TEST_ASSERT_EQUAL_UINT(1, TV_DEAD(&trk, 2));
    TV_ASSERT_REAL(0.95, TV_EXISTENCE(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(1, TV_CONFIRMED(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(2, TV_STATS(&trk).last.merges);
}

static void test_merge_disabled_and_other_clusters(void)
{
    two_track_cluster();
    TV_PAR(&trk).merge_threshold = MTT_R(0.0); /* 0 never merges */
    set_a(0, MTT_R(0.3), 0, 0);
    set_b(1, xb1, MTT_R(0.9), 1, 1);
    mtt_merge_frame(&trk);
    TEST_ASSERT_EQUAL_UINT(0, TV_DEAD(&trk, 1));
    /* different clusters are never candidates */
    two_track_cluster();
    TV_N_CLUSTERS(&trk) = 2;
    TV_CL_FIRST(&trk, 1) = 1;
    TV_CL_FIRST(&trk, 2) = 2;
    set_a(0, MTT_R(0.3), 0, 0);
    set_b(1, xb1, MTT_R(0.9), 1, 1);
    mtt_merge_frame(&trk);
    TEST_ASSERT_EQUAL_UINT(0, TV_N_MERGE(&trk));
    TEST_ASSERT_EQUAL_UINT(0, TV_DEAD(&trk, 1));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_tv11_d2);
    RUN_TEST(test_merge_d2_not_pd);
    RUN_TEST(test_tv11_case1_survivor_a);
    RUN_TEST(test_invalid_track_not_merged);
    RUN_TEST(test_tv11_case1_survivor_a_at_higher_index);
    RUN_TEST(test_tv11_case2_no_merge);
    RUN_TEST(test_survivor_ties);
    RUN_TEST(test_merge_order_by_d2);
    RUN_TEST(test_merge_disabled_and_other_clusters);
    return UNITY_END();
}
