/* test_measure.c - measurement validation and the MTT_MAX_MEAS cap, the
 * stage of measure.c (ALGORITHMS.md §15, §16): which detections are kept,
 * and in which order. */
#include <string.h>

#include "mtt_internal.h"
#include "tv_assert.h"
#include "tv_fixture.h"
#include "unity.h"

static mtt_tracker trk;
static mtt_meas big[3 * MTT_MAX_MEAS];

void setUp(void) {}
void tearDown(void) {}

static void init_default(void)
{
    mtt_params p;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    tv_init(&trk, &p);
}

static mtt_meas mk(mtt_real x, mtt_real y, mtt_real a, int has)
{
    mtt_meas m;
    m.x = x;
    m.y = y;
    m.amplitude = a;
    m.has_amplitude = has;
    return m;
}

/* 3 x MTT_MAX_MEAS detections: exactly the strongest MTT_MAX_MEAS stay,
 * in input order. */
static void test_cap_keeps_strongest_in_input_order(void)
{
    const uint32_t n = 3u * MTT_MAX_MEAS;
    uint32_t i, prev = 0;
    init_default();
    /* Amplitude is a permutation of 0..n-1 (i * 7 mod n, n not a multiple
     * of 7), so the inputs with amplitude >= 2 MTT_MAX_MEAS are the strongest. */
    TEST_ASSERT_TRUE(n % 7u != 0u);
    for (i = 0; i < n; ++i) {
        big[i] = mk((mtt_real)(i % 97u), (mtt_real)(i / 97u), (mtt_real)((i * 7u) % n), 1);
    }
    mtt_measure_select(&trk, big, n);
    TEST_ASSERT_EQUAL_UINT(MTT_MAX_MEAS, tv_meas_count(&trk));
    TEST_ASSERT_EQUAL_UINT32(2u * MTT_MAX_MEAS, trk.stats.last.meas_dropped);
    for (i = 0; i < MTT_MAX_MEAS; ++i) {
        const uint32_t src = tv_meas_src(&trk, (uint16_t)i);
        TEST_ASSERT_TRUE((src * 7u) % n >= 2u * MTT_MAX_MEAS);
        if (i > 0u) {
            TEST_ASSERT_TRUE(src > prev); /* input order kept */
        }
        prev = src;
    }
}

/* Without amplitudes the first MTT_MAX_MEAS inputs stay. */
static void test_cap_without_amplitude_keeps_first(void)
{
    const uint32_t n = MTT_MAX_MEAS + 5u;
    uint32_t i;
    init_default();
    for (i = 0; i < n; ++i) {
        big[i] = mk((mtt_real)i, MTT_R(0.0), MTT_R(0.0), 0);
    }
    mtt_measure_select(&trk, big, n);
    TEST_ASSERT_EQUAL_UINT(MTT_MAX_MEAS, tv_meas_count(&trk));
    for (i = 0; i < MTT_MAX_MEAS; ++i) {
        TEST_ASSERT_EQUAL_UINT32(i, tv_meas_src(&trk, (uint16_t)i));
    }
}

/* Bad detections are skipped and counted; the good ones keep their input index. */
static void test_bad_detections_skipped(void)
{
    mtt_meas m[7];
    volatile mtt_real zero = MTT_R(0.0);
    init_default();
    m[0] = mk(zero / zero, MTT_R(1.0), MTT_R(1.0), 1);       /* NaN x */
    m[1] = mk(MTT_R(1.0), MTT_R(1.0) / zero, MTT_R(1.0), 1); /* Inf y */
    m[2] = mk(MTT_R(5.0), MTT_R(5.0), MTT_R(-1.0), 1);       /* negative amplitude */
    m[3] = mk(MTT_R(5.0), MTT_R(5.0), zero / zero, 1);       /* NaN amplitude */
    m[4] = mk(MTT_R(10.0), MTT_R(20.0), MTT_R(2.0), 1);      /* good */
    m[5] = mk(MTT_R(5.0), MTT_R(5.0), MTT_R(-1.0), 0);       /* no amplitude: value ignored, good */
    m[6] = mk(MTT_R(5.0), MTT_R(5.0), MTT_R(1.0) / zero, 1); /* Inf amplitude */
    mtt_measure_select(&trk, m, 7);
    TEST_ASSERT_EQUAL_UINT32(5u, trk.stats.last.meas_bad);
    TEST_ASSERT_EQUAL_UINT(2u, tv_meas_count(&trk));
    TEST_ASSERT_EQUAL_UINT32(4u, tv_meas_src(&trk, 0));
    TEST_ASSERT_EQUAL_UINT32(5u, tv_meas_src(&trk, 1));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_cap_keeps_strongest_in_input_order);
    RUN_TEST(test_cap_without_amplitude_keeps_first);
    RUN_TEST(test_bad_detections_skipped);
    return UNITY_END();
}
