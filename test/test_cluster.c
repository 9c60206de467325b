/* SPDX-License-Identifier: BSD-3-Clause */
/* test_cluster.c - clusters of the gating graph by union-find (ALGORITHMS.md §9, TV8b). */
#include <string.h>

#include "mtt_internal.h"
#include "tv_assert.h"
#include "tv_fixture.h"
#include "unity.h"

static mtt_tracker trk;

void setUp(void) {}
void tearDown(void) {}

/* n tracks, m measurements, gating lists as (track, meas) pairs in order. */
static void build(uint16_t n, uint16_t m, const uint16_t (*pairs)[2], uint16_t np)
{
    mtt_params p;
    uint16_t t, j, k;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    tv_init(&trk, &p);
    for (t = 0; t < n; ++t) {
        (void)tv_add_track_s(&trk, MTT_R(0.0), MTT_R(0.0), MTT_R(2.0), MTT_R(0.0), MTT_R(2.0), MTT_R(0.5));
    }
    for (j = 0; j < m; ++j) {
        (void)tv_add_meas(&trk, (mtt_real)j, MTT_R(0.0), MTT_R(1.0), 1);
    }
    for (k = 0; k < np; ++k) {
        tv_add_pair(&trk, pairs[k][0], pairs[k][1], MTT_R(0.5));
    }
    tv_index_pairs(&trk);
}

/* Measurements of cluster c as a bit mask. */
static unsigned cluster_meas(uint16_t c)
{
    unsigned mask = 0;
    uint16_t k;
    for (k = 0; k < TV_N_PAIRS(&trk); ++k) {
        if (TV_CLUSTER_OF(&trk, TV_PAIR_TRACK(&trk, k)) == c) {
            mask |= 1u << TV_PAIR_MEAS(&trk, k);
        }
    }
    return mask;
}

static void test_tv8b(void)
{
    /* TV8b: T1 {z1, z2}, T2 {z2, z3}, T3 {z4}, T4 {z4}, T5 {}; z5 in no gate */
    static const uint16_t g[6][2] = {{0, 0}, {0, 1}, {1, 1}, {1, 2}, {2, 3}, {3, 3}};
    build(5, 5, g, 6);
    mtt_cluster_frame(&trk);
    TEST_ASSERT_EQUAL_UINT(3, TV_N_CLUSTERS(&trk));
    /* cluster 1: tracks {T1, T2}, measurements {z1, z2, z3} */
    TEST_ASSERT_EQUAL_UINT(0, TV_CL_FIRST(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(2, TV_CL_FIRST(&trk, 1));
    TEST_ASSERT_EQUAL_UINT(0, TV_CL_LIST(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(1, TV_CL_LIST(&trk, 1));
    TEST_ASSERT_EQUAL_HEX(0x7u, cluster_meas(0));
    /* cluster 2: tracks {T3, T4}, measurements {z4} */
    TEST_ASSERT_EQUAL_UINT(4, TV_CL_FIRST(&trk, 2));
    TEST_ASSERT_EQUAL_UINT(2, TV_CL_LIST(&trk, 2));
    TEST_ASSERT_EQUAL_UINT(3, TV_CL_LIST(&trk, 3));
    TEST_ASSERT_EQUAL_HEX(0x8u, cluster_meas(1));
    /* cluster 3: tracks {T5}, measurements {} */
    TEST_ASSERT_EQUAL_UINT(5, TV_CL_FIRST(&trk, 3));
    TEST_ASSERT_EQUAL_UINT(4, TV_CL_LIST(&trk, 4));
    TEST_ASSERT_EQUAL_HEX(0x0u, cluster_meas(2));
    TEST_ASSERT_EQUAL_UINT(0, TV_CLUSTER_OF(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(0, TV_CLUSTER_OF(&trk, 1));
    TEST_ASSERT_EQUAL_UINT(1, TV_CLUSTER_OF(&trk, 2));
    TEST_ASSERT_EQUAL_UINT(1, TV_CLUSTER_OF(&trk, 3));
    TEST_ASSERT_EQUAL_UINT(2, TV_CLUSTER_OF(&trk, 4));
    /* measurements in no gate: {z5} */
    TEST_ASSERT_EQUAL_UINT(TV_MP_FIRST(&trk, 4), TV_MP_FIRST(&trk, 5));
    TEST_ASSERT_EQUAL_UINT(3, TV_STATS(&trk).last.clusters);
    TEST_ASSERT_EQUAL_UINT(2, TV_STATS(&trk).max_cluster_tracks);
}

static void test_order_by_smallest_track(void)
{
    /* TV8b's structure with the tracks renumbered: T1 {z4}, T2 {z1, z2},
     * T3 {}, T4 {z4}, T5 {z2, z3}.  Clusters by smallest track index:
     * {T1, T4}, {T2, T5}, {T3}; tracks ascending inside. */
    static const uint16_t g[6][2] = {{0, 3}, {1, 0}, {1, 1}, {3, 3}, {4, 1}, {4, 2}};
    build(5, 5, g, 6);
    mtt_cluster_frame(&trk);
    TEST_ASSERT_EQUAL_UINT(3, TV_N_CLUSTERS(&trk));
    TEST_ASSERT_EQUAL_UINT(0, TV_CL_LIST(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(3, TV_CL_LIST(&trk, 1));
    TEST_ASSERT_EQUAL_UINT(1, TV_CL_LIST(&trk, 2));
    TEST_ASSERT_EQUAL_UINT(4, TV_CL_LIST(&trk, 3));
    TEST_ASSERT_EQUAL_UINT(2, TV_CL_LIST(&trk, 4));
    TEST_ASSERT_EQUAL_HEX(0x8u, cluster_meas(0));
    TEST_ASSERT_EQUAL_HEX(0x7u, cluster_meas(1));
    TEST_ASSERT_EQUAL_HEX(0x0u, cluster_meas(2));
}

static void test_chain_joins_transitively(void)
{
    /* T1-z1-T2-z2-T3-z3-T4: one cluster of four. */
    static const uint16_t g[6][2] = {{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}, {3, 2}};
    build(4, 3, g, 6);
    mtt_cluster_frame(&trk);
    TEST_ASSERT_EQUAL_UINT(1, TV_N_CLUSTERS(&trk));
    TEST_ASSERT_EQUAL_UINT(4, TV_CL_FIRST(&trk, 1));
    TEST_ASSERT_EQUAL_UINT(4, TV_STATS(&trk).max_cluster_tracks);
}

static void test_invalid_track_has_no_cluster(void)
{
    static const uint16_t g[2][2] = {{0, 0}, {2, 0}};
    build(3, 1, g, 2);
    TV_VALID(&trk, 1) = 0;
    mtt_cluster_frame(&trk);
    TEST_ASSERT_EQUAL_UINT(1, TV_N_CLUSTERS(&trk));
    TEST_ASSERT_EQUAL_UINT(MTT_NONE16, TV_CLUSTER_OF(&trk, 1));
    TEST_ASSERT_EQUAL_UINT(0, TV_CL_LIST(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(2, TV_CL_LIST(&trk, 1));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_tv8b);
    RUN_TEST(test_order_by_smallest_track);
    RUN_TEST(test_chain_joins_transitively);
    RUN_TEST(test_invalid_track_has_no_cluster);
    return UNITY_END();
}
