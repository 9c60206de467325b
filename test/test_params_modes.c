/* SPDX-License-Identifier: BSD-3-Clause */
/* test_params_modes.c - what mtt_params_check accepts in this build, the
 * fixed-point one included (docs/FIXED_POINT.md: the firmware
 * configuration; every value in its Q format): the four core modes with
 * CV motion, MTT_ERR_UNSUPPORTED for what the build leaves out, and
 * MTT_ERR_PARAM naming a value outside its range. */
#include <string.h>

#include "mtt_internal.h"
#include "unity.h"

static mtt_params p;
static const char *bad;

void setUp(void)
{
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.clutter_density = MTT_DENS(3.5e-5); /* a declared density (the fixed build needs one) */
    bad = "unset";
}
void tearDown(void) {}

static void test_core_modes_accepted(void)
{
    static const mtt_assoc core[4] = {MTT_ASSOC_LM_IHPDA, MTT_ASSOC_IHPDA, MTT_ASSOC_LM_IPDA,
                                      MTT_ASSOC_IPDA};
    int i;
    for (i = 0; i < 4; ++i) {
        p.association = core[i];
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_check(&p, &bad));
        TEST_ASSERT_NULL(bad);
    }
}

static void test_left_out_refused(void)
{
    int a;
    for (a = (int)MTT_ASSOC_IHPDA_2D; a < (int)MTT_ASSOC_COUNT; ++a) {
        /* lm-ipda-all, the last, is out of range without the baselines */
        const mtt_status off = a < (int)MTT_ASSOC_LM_IPDA_ALL ? MTT_ERR_UNSUPPORTED : MTT_ERR_PARAM;
        p.association = (mtt_assoc)a;
        TEST_ASSERT_EQUAL_INT(MTT_WITH_BASELINES ? MTT_OK : off, mtt_params_check(&p, &bad));
        if (!MTT_WITH_BASELINES) {
            TEST_ASSERT_EQUAL_STRING("association", bad);
        }
    }
    p.association = MTT_ASSOC_LM_IHPDA;
    p.lm_ihpda_variant = MTT_LM_IHPDA_CONTEST;
    TEST_ASSERT_EQUAL_INT(MTT_WITH_CONTEST ? MTT_OK : MTT_ERR_UNSUPPORTED, mtt_params_check(&p, &bad));
    p.lm_ihpda_variant = MTT_LM_IHPDA_S0;
    if (!MTT_WITH_IMM) {
        p.motion = MTT_MOTION_IMM;
        TEST_ASSERT_EQUAL_INT(MTT_ERR_UNSUPPORTED, mtt_params_check(&p, &bad));
        TEST_ASSERT_EQUAL_STRING("motion", bad);
    }
}

static void test_ranges_in_the_format(void)
{
    p.pd = MTT_P(0.0); /* PD in (0, 1] */
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_check(&p, &bad));
    TEST_ASSERT_EQUAL_STRING("pd", bad);
    p.pd = MTT_P(1.0);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_check(&p, &bad));
    p.pg = MTT_P(1.0); /* PG in (0, 1) */
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_check(&p, &bad));
    TEST_ASSERT_EQUAL_STRING("pg", bad);
    p.pg = MTT_P(0.99);
    p.meas_sigma[1] = MTT_POS(0.0); /* sigma >= 1e-9: positive, also where 1e-9 rounds to 0 */
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_check(&p, &bad));
    TEST_ASSERT_EQUAL_STRING("meas_sigma", bad);
    p.meas_sigma[1] = MTT_POS(0.5);
    p.terminate_threshold = p.confirm_threshold; /* cross rule: below confirm */
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_check(&p, &bad));
    TEST_ASSERT_EQUAL_STRING("terminate_threshold", bad);
}

static void test_estimated_density(void)
{
    p.clutter_density = MTT_DENS(0.0);
#ifdef MTT_REAL_FIXED
    TEST_ASSERT_EQUAL_INT(MTT_ERR_UNSUPPORTED, mtt_params_check(&p, &bad));
    TEST_ASSERT_EQUAL_STRING("clutter_density", bad);
#else
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_check(&p, &bad)); /* ALGORITHMS.md §5.2 */
#endif
}

/* max_accel with process_psd left out (ALGORITHMS.md §2.2): with motion cv
 * the tracker predicts with q = a² ΔT, frame for frame the tracker with
 * process_psd = a² ΔT given (ΔT = 2: the level follows the interval).  In
 * fixed point a² and a² ΔT are exact here (a = 2: 4 and 8 on their bits). */
static mtt_tracker ta, tb;
static void test_motion_from_max_accel_cv(void)
{
    mtt_params pe, r;
    int k;
    p.max_accel = MTT_POS(2.0);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_resolve(&p, &r));
    TEST_ASSERT_EQUAL_INT(MTT_WITH_IMM ? MTT_MOTION_IMM : MTT_MOTION_CV, r.motion);
#ifdef MTT_REAL_FIXED
    TEST_ASSERT_EQUAL_INT32(4 << MTT_FX_VAR_FRAC, r.process_psd); /* a² at ΔT = 1 */
#else
    TEST_ASSERT_TRUE(r.process_psd == MTT_R(4.0)); /* a² at ΔT = 1 */
#endif
    p.motion = MTT_MOTION_CV;
    pe = p;
    pe.process_psd = MTT_VAR(8.0);
#if MTT_WITH_CONTEST
    p.adapt_s_max = pe.adapt_s_max = MTT_R(1.0); /* the derived motion's rise resolves to 100 */
#endif
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&ta, &p));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&tb, &pe));
    for (k = 0; k < 8; ++k) {
        const mtt_meas m = {MTT_POS(10.0) * (mtt_real)k, MTT_POS(0.5) * (mtt_real)(k * k), MTT_AMP(0.0), 0};
        mtt_track_view va, vb;
        size_t n;
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&ta, MTT_TIME(2.0) * (mtt_real)k, &m, 1));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&tb, MTT_TIME(2.0) * (mtt_real)k, &m, 1));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&ta, &n));
        if (k >= 1) {
            TEST_ASSERT_EQUAL_UINT64(1u, (uint64_t)n);
            TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&ta, 0, &va));
            TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&tb, 0, &vb));
            TEST_ASSERT_TRUE(va.x[0] == vb.x[0] && va.x[3] == vb.x[3] && va.P[2][2] == vb.P[2][2]);
        }
    }
#ifdef MTT_REAL_FIXED
    p.max_accel = MTT_POS(182.0); /* a² = 33124 px²: beyond the variance format's 32768 */
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_check(&p, &bad));
    TEST_ASSERT_EQUAL_STRING("max_accel", bad);
#endif
}

#ifdef MTT_REAL_FIXED
/* The defaults in their formats: PD 0.9 (Q30), process_psd 0 resolved to 5 (Q16), vmax 60 px per frame. */
static void test_defaults_in_formats(void)
{
    TEST_ASSERT_EQUAL_INT32(966367642, p.pd);
    TEST_ASSERT_EQUAL_INT32(0, p.process_psd); /* not given: 5 as resolved (ALGORITHMS.md §2.2) */
    {
        mtt_params r;
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_resolve(&p, &r));
        TEST_ASSERT_EQUAL_INT32(5 * 65536, r.process_psd);
        TEST_ASSERT_EQUAL_INT(MTT_MOTION_CV, r.motion);
    }
    TEST_ASSERT_EQUAL_INT32(60 * (1 << MTT_FX_POS_FRAC), p.vmax);
}
#endif

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_core_modes_accepted);
    RUN_TEST(test_left_out_refused);
    RUN_TEST(test_ranges_in_the_format);
    RUN_TEST(test_estimated_density);
    RUN_TEST(test_motion_from_max_accel_cv);
#ifdef MTT_REAL_FIXED
    RUN_TEST(test_defaults_in_formats);
#endif
    return UNITY_END();
}
