/* SPDX-License-Identifier: BSD-3-Clause */
/* test_measure.c - measurement validation and the MTT_MAX_MEAS cap, the
 * stage of measure.c (ALGORITHMS.md §15, §16): which detections are kept,
 * and in which order. */
#include <string.h>

#include "mtt_internal.h"
#include "tv_assert.h"
#include "tv_fixture.h"
#include "sim.h"
#include "unity.h"

static mtt_tracker trk;
static mtt_meas many[3 * MTT_MAX_MEAS];

void setUp(void)
{
    mtt_params p;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    tv_init(&trk, &p);
}
void tearDown(void) {}

/* 3 x MTT_MAX_MEAS detections: exactly the strongest MTT_MAX_MEAS stay,
 * in the canonical order (x, then y). */
static void test_cap_keeps_strongest_in_canonical_order(void)
{
    const uint32_t n = 3u * MTT_MAX_MEAS;
    uint32_t i;
    TEST_ASSERT_TRUE(n % 7u != 0u);
    sim_amplitude_permutation(many, n);
    mtt_measure_select(&trk, many, NULL, NULL, n);
    TEST_ASSERT_EQUAL_UINT(MTT_MAX_MEAS, tv_meas_count(&trk));
    TEST_ASSERT_EQUAL_UINT32(2u * MTT_MAX_MEAS, TV_STATS(&trk).last.meas_dropped);
    for (i = 0; i < MTT_MAX_MEAS; ++i) {
        const uint32_t src = tv_meas_src(&trk, (uint16_t)i);
        TEST_ASSERT_TRUE((src * 7u) % n >= 2u * MTT_MAX_MEAS);
        if (i > 0u) {
            const mtt_mstore *a = &TV_MEAS(&trk, i - 1u), *b = &TV_MEAS(&trk, i);
            TEST_ASSERT_TRUE(a->x < b->x || (a->x == b->x && a->y < b->y));
        }
    }
}

/* Without amplitudes the first MTT_MAX_MEAS in the canonical order stay
 * (here the first inputs: x = i). */
static void test_cap_without_amplitude_keeps_first(void)
{
    const uint32_t n = MTT_MAX_MEAS + 5u;
    uint32_t i;
    for (i = 0; i < n; ++i) {
        many[i] = sim_meas((mtt_real)i, MTT_R(0.0), MTT_R(0.0), 0);
    }
    mtt_measure_select(&trk, many, NULL, NULL, n);
    TEST_ASSERT_EQUAL_UINT(MTT_MAX_MEAS, tv_meas_count(&trk));
    for (i = 0; i < MTT_MAX_MEAS; ++i) {
        TEST_ASSERT_EQUAL_UINT32(i, tv_meas_src(&trk, (uint16_t)i));
    }
}

/* Exactly MTT_MAX_MEAS valid detections (amplitudes in no order, two bad
 * ones among them, x = i): nothing is dropped and all stay in the
 * canonical order, here the input's, as below the cap.  (The cap's heap is built on reaching MTT_MAX_MEAS even
 * when no further detection comes.) */
static void test_exactly_max_valid_keeps_input_order(void)
{
    const uint32_t n = MTT_MAX_MEAS + 2u;
    volatile mtt_real zero = MTT_R(0.0);
    uint32_t i, j = 0;
    for (i = 0; i < n; ++i) {
        /* amplitudes (i * 37) mod 101: repeated values and no monotone order */
        many[i] = sim_meas((mtt_real)i, MTT_R(1.0), (mtt_real)((i * 37u) % 101u), 1);
    }
    many[3].x = zero / zero; /* NaN */
    many[n / 2u].amplitude = MTT_R(-1.0);
    mtt_measure_select(&trk, many, NULL, NULL, n);
    TEST_ASSERT_EQUAL_UINT32(2u, TV_STATS(&trk).last.meas_bad);
    TEST_ASSERT_EQUAL_UINT32(0u, TV_STATS(&trk).last.meas_dropped);
    TEST_ASSERT_EQUAL_UINT(MTT_MAX_MEAS, tv_meas_count(&trk));
    for (i = 0; i < n; ++i) {
        if (i == 3u || i == n / 2u) {
            continue;
        }
        TEST_ASSERT_EQUAL_UINT32(i, tv_meas_src(&trk, (uint16_t)j));
        TEST_ASSERT_EQUAL_FLOAT((float)i, (float)TV_MEAS_X(&trk, j));
        TEST_ASSERT_EQUAL_FLOAT((float)((i * 37u) % 101u), (float)TV_MEAS_AMP(&trk, j));
        ++j;
    }
    TEST_ASSERT_EQUAL_UINT32(MTT_MAX_MEAS, j);
}

/* Bad detections are skipped and counted; the good ones keep their input
 * index, stored in the canonical order ((5, 5) before (10, 20)). */
static void test_bad_detections_skipped(void)
{
    mtt_meas m[7];
    sim_bad_mix(m);
    mtt_measure_select(&trk, m, NULL, NULL, 7);
    TEST_ASSERT_EQUAL_UINT32(5u, TV_STATS(&trk).last.meas_bad);
    TEST_ASSERT_EQUAL_UINT(2u, tv_meas_count(&trk));
    TEST_ASSERT_EQUAL_UINT32(5u, tv_meas_src(&trk, 0));
    TEST_ASSERT_EQUAL_UINT32(4u, tv_meas_src(&trk, 1));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_cap_keeps_strongest_in_canonical_order);
    RUN_TEST(test_cap_without_amplitude_keeps_first);
    RUN_TEST(test_exactly_max_valid_keeps_input_order);
    RUN_TEST(test_bad_detections_skipped);
    return UNITY_END();
}
