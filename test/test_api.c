/* SPDX-License-Identifier: BSD-3-Clause */
/* test_api.c - bounds, bad data and API misuse through the public API only
 * (docs/DESIGN.md "Errors and bad input"); which measurements the cap
 * keeps is checked stage-side in test_measure.c.  Every build: values are
 * written in their quantity's constant (MTT_POS, MTT_TIME, MTT_VAR, ...,
 * mtt/real.h), and the fixed-point build's "not finite" is a saturated or
 * out-of-range value (docs/FIXED_POINT.md §3). */
#include <math.h>
#include <string.h>

#include "mtt/mtt.h"
#include "sim.h"
#include "unity.h"

static mtt_tracker trk, copy;
static mtt_meas big[3 * MTT_MAX_MEAS];

void setUp(void) {}
void tearDown(void) {}

static void init_default(void)
{
    mtt_params p;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.clutter_density = MTT_DENS(1e-4);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
}

/* (d) 3 x MTT_MAX_MEAS measurements: the strongest MTT_MAX_MEAS stay, in
 * input order, and the rest are counted. */
void test_overflow_keeps_strongest(void)
{
    const uint32_t n = 3u * MTT_MAX_MEAS;
    mtt_stats st;
    init_default();
    TEST_ASSERT_EQUAL_INT(0, (int)(n % 7u == 0u));
    sim_amplitude_permutation(big, n);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_TIME(0.0), big, n));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&trk, &st));
    TEST_ASSERT_EQUAL_UINT32(n, st.last.meas_in);
    TEST_ASSERT_EQUAL_UINT32(2u * MTT_MAX_MEAS, st.last.meas_dropped);
    TEST_ASSERT_EQUAL_UINT32(0u, st.last.meas_bad);
}

/* Without amplitudes, the first MTT_MAX_MEAS inputs stay. */
void test_overflow_without_amplitude_keeps_first(void)
{
    const uint32_t n = MTT_MAX_MEAS + 5u;
    mtt_stats st;
    uint32_t i;
    init_default();
    for (i = 0; i < n; ++i) {
        big[i] = sim_meas((mtt_real)i * MTT_POS(1.0), MTT_POS(0.0), MTT_AMP(0.0), 0);
    }
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_TIME(0.0), big, n));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&trk, &st));
    TEST_ASSERT_EQUAL_UINT32(5u, st.last.meas_dropped);
    TEST_ASSERT_EQUAL_UINT32(0u, st.last.meas_bad);
}

/* (e) Bad data inside a valid call is skipped and counted: malformed in
 * meas_bad, outside the build's range (fixed point: the four saturated or
 * out-of-range values) in meas_out_of_range. */
#ifdef MTT_REAL_FIXED
#define N_MALFORMED 1u
#else
#define N_MALFORMED 5u
#endif
void test_bad_data_skipped_and_counted(void)
{
    mtt_meas m[7];
    mtt_stats st;
    init_default();
    sim_bad_mix(m); /* five bad, good ones at 4 and 5 */
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_TIME(0.0), m, 7));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&trk, &st));
    TEST_ASSERT_EQUAL_UINT32(7u, st.last.meas_in);
    TEST_ASSERT_EQUAL_UINT32(N_MALFORMED, st.last.meas_bad);
    TEST_ASSERT_EQUAL_UINT32(5u - N_MALFORMED, st.last.meas_out_of_range);
    TEST_ASSERT_EQUAL_UINT32(0u, st.last.meas_dropped);
    /* Both good detections still pair with the next frame's one (within
     * vmax = 60 of it: 2.2 and 17.5 away): two births. */
    m[0] = sim_meas(MTT_POS(12.0), MTT_POS(21.0), MTT_AMP(2.0), 1);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_TIME(1.0), m, 1));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&trk, &st));
    TEST_ASSERT_EQUAL_UINT32(2u, st.last.births);
    TEST_ASSERT_EQUAL_UINT32(N_MALFORMED, st.total.meas_bad);
    TEST_ASSERT_EQUAL_UINT32(5u - N_MALFORMED, st.total.meas_out_of_range);
}

/* (e) API misuse returns an error and changes nothing. */
void test_misuse_changes_nothing(void)
{
    mtt_meas m = sim_meas(MTT_POS(1.0), MTT_POS(2.0), MTT_AMP(1.0), 1);
#ifndef MTT_REAL_FIXED
    volatile mtt_real zero = MTT_R(0.0);
#endif
    mtt_params p;
    mtt_track_view v;
    mtt_stats st;
    size_t cnt;
    const char *field = "x";
    mtt_real x[4] = {MTT_POS(0.0), MTT_POS(0.0), MTT_POS(1.0), MTT_POS(1.0)};
    mtt_real P[16];
    uint32_t id;
    int i;

    init_default();
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_TIME(5.0), &m, 1));
    memcpy(&copy, &trk, sizeof trk);
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_tracker_step(NULL, MTT_TIME(6.0), &m, 1));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_tracker_step(&trk, MTT_TIME(6.0), NULL, 1));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_TIME, mtt_tracker_step(&trk, MTT_TIME(5.0), &m, 1)); /* equal */
    TEST_ASSERT_EQUAL_INT(MTT_ERR_TIME, mtt_tracker_step(&trk, MTT_TIME(4.0), &m, 1)); /* backwards */
#ifndef MTT_REAL_FIXED
    TEST_ASSERT_EQUAL_INT(MTT_ERR_TIME, mtt_tracker_step(&trk, zero / zero, &m, 1));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_TIME, mtt_tracker_step(&trk, MTT_R(1.0) / zero, &m, 1));
#else
    /* time modulo 2^32: 2^31 Q16 units (32768 frames) ahead reads as earlier */
    TEST_ASSERT_EQUAL_INT(MTT_ERR_TIME, mtt_tracker_step(&trk, MTT_TIME(5.0) + INT32_MIN, &m, 1));
#endif
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_tracker_count(&trk, NULL));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_tracker_track(&trk, 0, NULL));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_RANGE, mtt_tracker_track(&trk, 1000, &v));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_tracker_stats(NULL, &st));
    /* add_track: NULL, not finite, not symmetric, not positive definite */
    for (i = 0; i < 16; ++i) {
        P[i] = (i % 5 == 0) ? MTT_VAR(1.0) : MTT_VAR(0.0); /* identity */
    }
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_tracker_add_track(&trk, NULL, P, &id));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_tracker_add_track(&trk, x, NULL, &id));
#ifndef MTT_REAL_FIXED
    x[1] = zero / zero;
#else
    x[1] = MTT_FX_MAX; /* saturated: not finite */
#endif
    TEST_ASSERT_EQUAL_INT(MTT_ERR_VALUE, mtt_tracker_add_track(&trk, x, P, &id));
    x[1] = MTT_POS(0.0);
    P[1] = MTT_VAR(0.5); /* P[0][1] != P[1][0] */
    TEST_ASSERT_EQUAL_INT(MTT_ERR_VALUE, mtt_tracker_add_track(&trk, x, P, &id));
    P[1] = MTT_VAR(0.0);
    P[15] = MTT_VAR(-1.0); /* not positive definite */
    TEST_ASSERT_EQUAL_INT(MTT_ERR_VALUE, mtt_tracker_add_track(&trk, x, P, &id));
    TEST_ASSERT_EQUAL_MEMORY(&copy, &trk, sizeof trk);

    /* invalid parameters: error, the first bad field named, tracker untouched */
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.pd = MTT_P(1.5);
    p.pg = MTT_P(1.5);
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_check(&p, &field));
    TEST_ASSERT_EQUAL_STRING("pd", field);
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_tracker_init(&trk, &p));
    TEST_ASSERT_EQUAL_MEMORY(&copy, &trk, sizeof trk);
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_tracker_init(NULL, &p));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_tracker_init(&trk, NULL));

    /* an uninitialised tracker is an error, not undefined behaviour */
    memset(&trk, 0, sizeof trk);
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NOT_INIT, mtt_tracker_step(&trk, MTT_TIME(1.0), &m, 1));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NOT_INIT, mtt_tracker_count(&trk, &cnt));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NOT_INIT, mtt_tracker_track(&trk, 0, &v));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NOT_INIT, mtt_tracker_stats(&trk, &st));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NOT_INIT, mtt_tracker_add_track(&trk, x, P, &id));
}

/* A full table: seeding past MTT_MAX_TRACKS fails; births are counted as dropped. */
void test_full_table(void)
{
    mtt_real x[4] = {MTT_POS(0.0), MTT_POS(0.0), MTT_POS(0.0), MTT_POS(0.0)};
    mtt_real P[16];
    mtt_stats st;
    mtt_meas m[2];
    uint32_t id = 0;
    int i;
    init_default();
    for (i = 0; i < 16; ++i) {
        P[i] = (i % 5 == 0) ? MTT_VAR(4.0) : MTT_VAR(0.0);
    }
    for (i = 0; i < MTT_MAX_TRACKS; ++i) {
        x[0] = (mtt_real)i * MTT_POS(1000.0); /* far apart: no merging */
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&trk, x, P, &id));
        TEST_ASSERT_EQUAL_UINT32((uint32_t)i, id); /* identities 0, 1, ... */
    }
    TEST_ASSERT_EQUAL_INT(MTT_ERR_FULL, mtt_tracker_add_track(&trk, x, P, &id));
    /* two frames with a far-away detection pair: a birth is wanted, none possible */
    m[0] = sim_meas(MTT_POS(-5000.0), MTT_POS(-5000.0), MTT_AMP(1.0), 1);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_TIME(0.0), m, 1));
    m[0] = sim_meas(MTT_POS(-4998.0), MTT_POS(-5000.0), MTT_AMP(1.0), 1);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_TIME(1.0), m, 1));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&trk, &st));
    TEST_ASSERT_EQUAL_UINT32(0u, st.last.births);
    TEST_ASSERT_EQUAL_UINT32(1u, st.last.births_dropped);
}

/* Feed a and b the same `frames` frames of 20 detections each and require
 * the same live tracks, view for view (every byte of a view is defined). */
static void step_both_and_compare(mtt_tracker *a, mtt_tracker *b, int frames)
{
    mtt_meas m[20];
    mtt_track_view va, vb;
    size_t na, nb, i;
    int k, j;
    for (k = 0; k < frames; ++k) {
        for (j = 0; j < 20; ++j) {
            unsigned h = (unsigned)(k * 131 + j * 71) % 997u;
            m[j] = sim_meas((mtt_real)h * MTT_POS(0.3) + (mtt_real)k * MTT_POS(1.0),
                            (mtt_real)(j * 11) * MTT_POS(1.0), (mtt_real)(h % 13u) * MTT_AMP(1.0),
                            (int)(h % 3u != 0u));
        }
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(a, (mtt_real)k * MTT_TIME(1.0), m, 20));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(b, (mtt_real)k * MTT_TIME(1.0), m, 20));
    }
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(a, &na));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(b, &nb));
    TEST_ASSERT_TRUE(na > 0u);
    TEST_ASSERT_EQUAL_UINT((unsigned)na, (unsigned)nb);
    for (i = 0; i < na; ++i) {
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(a, i, &va));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(b, i, &vb));
        TEST_ASSERT_EQUAL_MEMORY(&va, &vb, sizeof va);
    }
}

/* Same input, same output: two trackers fed identically end bit-identical. */
void test_deterministic(void)
{
    static mtt_tracker a, b;
    mtt_params p;
    mtt_stats sa, sb;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.clutter_density = MTT_DENS(1e-3);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&a, &p));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&b, &p));
    step_both_and_compare(&a, &b, 30);
    memset(&sa, 0, sizeof sa);
    memset(&sb, 0, sizeof sb);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&a, &sa));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&b, &sb));
    TEST_ASSERT_EQUAL_MEMORY(&sa, &sb, sizeof sa);
}

/* The optional cycle counter fills per-stage costs. */
static uint32_t fake_clock;
static uint32_t tick(void *ctx)
{
    (void)ctx;
    fake_clock += 10u;
    return fake_clock;
}

void test_cycle_counter(void)
{
    mtt_params p;
    mtt_stats st;
    mtt_meas m = sim_meas(MTT_POS(1.0), MTT_POS(1.0), MTT_AMP(1.0), 1);
    int s;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.clutter_density = MTT_DENS(1e-4); /* fixed point: a declared density */
    p.cycle_counter = tick;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_TIME(0.0), &m, 1));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&trk, &st));
    for (s = 0; s < MTT_STAGE_COUNT; ++s) {
        TEST_ASSERT_EQUAL_UINT32(10u, st.stage_cycles[s]); /* one tick per stage */
    }
}

/* mtt_tracker_init passes the caller's sizeof(mtt_tracker) and
 * MTT_CONFIG_ID; another size or identity is refused before the tracker or
 * the parameters are touched (the consumer tests build real mismatches). */
static void test_init_refuses_other_configuration(void)
{
    static mtt_tracker t;
    mtt_params p;
    const unsigned char *b = (const unsigned char *)&t;
    size_t i;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.clutter_density = MTT_DENS(1e-4); /* fixed point: a declared density */
    memset(&t, 0xa5, sizeof t);
    TEST_ASSERT_EQUAL_INT(MTT_ERR_CONFIG,
                          mtt_tracker_init_checked(&t, &p, sizeof t - 4u, (uint32_t)(MTT_CONFIG_ID)));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_CONFIG,
                          mtt_tracker_init_checked(&t, &p, sizeof t, (uint32_t)(MTT_CONFIG_ID) ^ 1u));
    for (i = 0; i < sizeof t; ++i) {
        TEST_ASSERT_EQUAL_HEX8(0xa5, b[i]);
    }
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_tracker_init_checked(NULL, &p, sizeof t, 0u));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init_checked(&t, &p, sizeof t, (uint32_t)(MTT_CONFIG_ID)));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&t, &p));
}

/* mtt_params_prepare + mtt_tracker_load (a firmware's path, docs/FIRMWARE.md)
 * give the tracker mtt_tracker_init gives, byte for byte, and the same
 * frames; a set that is not prepared, or prepared by another configuration,
 * is refused before anything is written, and a bad parameter set leaves
 * the prepared set unchanged. */
void test_prepare_and_load(void)
{
    static mtt_tracker a, b;
    mtt_params p;
    mtt_prepared pp, keep;
    size_t i;
    const unsigned char *bb = (const unsigned char *)&b;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.clutter_density = MTT_DENS(1e-3);
    p.snr_rho = MTT_RATIO(2.0); /* a rank table that is not uniform */
    p.cycle_counter = tick;
    memset(&a, 0, sizeof a);
    memset(&b, 0, sizeof b);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&a, &p));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_prepare(&p, &pp));
    TEST_ASSERT_EQUAL_HEX32(MTT_PREPARED_MARK, pp.mark);
    TEST_ASSERT_EQUAL_HEX32((uint32_t)(MTT_CONFIG_ID), pp.config_id);
    TEST_ASSERT_NULL(pp.par.cycle_counter);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_load(&b, &pp, tick, NULL));
    TEST_ASSERT_EQUAL_MEMORY(&a, &b, sizeof a);
    step_both_and_compare(&a, &b, 20);
    /* refusals: nothing written */
    memset(&b, 0xa5, sizeof b);
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_tracker_load(&b, NULL, NULL, NULL));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_tracker_load(NULL, &pp, NULL, NULL));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_CONFIG,
                          mtt_tracker_load_checked(&b, &pp, NULL, NULL, sizeof b - 4u, (uint32_t)(MTT_CONFIG_ID)));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_CONFIG,
                          mtt_tracker_load_checked(&b, &pp, NULL, NULL, sizeof b, (uint32_t)(MTT_CONFIG_ID) ^ 1u));
    keep = pp;
    pp.config_id ^= 1u; /* prepared by a build of another configuration */
    TEST_ASSERT_EQUAL_INT(MTT_ERR_CONFIG, mtt_tracker_load(&b, &pp, NULL, NULL));
    pp = keep;
    pp.mark = 0u; /* not a prepared set */
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_tracker_load(&b, &pp, NULL, NULL));
    for (i = 0; i < sizeof b; ++i) {
        TEST_ASSERT_EQUAL_HEX8(0xa5, bb[i]);
    }
    /* a bad parameter set: the status of mtt_params_check, out unchanged */
    pp = keep;
    p.pd = MTT_P(0.0) - 1;
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_prepare(&p, &pp));
    TEST_ASSERT_EQUAL_MEMORY(&keep, &pp, sizeof pp);
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_params_prepare(NULL, &pp));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_params_prepare(&p, NULL));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_overflow_keeps_strongest);
    RUN_TEST(test_overflow_without_amplitude_keeps_first);
    RUN_TEST(test_bad_data_skipped_and_counted);
    RUN_TEST(test_misuse_changes_nothing);
    RUN_TEST(test_full_table);
    RUN_TEST(test_deterministic);
    RUN_TEST(test_cycle_counter);
    RUN_TEST(test_init_refuses_other_configuration);
    RUN_TEST(test_prepare_and_load);
    return UNITY_END();
}
