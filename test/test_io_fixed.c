/* SPDX-License-Identifier: BSD-3-Clause */
/* test_io_fixed.c - the host boundary of tools/io/ (libmtt_io): the one
 * conversion of the files' doubles into mtt_real (mtt_io_to_real) and back
 * (mtt_io_from_real), as the detections, settings and initial tracks use
 * it (docs/FIXED_POINT.md §3).
 *
 * Fixed point: every value is rounded to nearest in its format, so the
 * round trip is within half a unit of the format, 2^-(f+1) (the derived
 * tolerance: one correctly rounded conversion, nothing else); a value
 * outside the format takes the saturation value of its sign, which
 * measure.c skips and counts (never a wrapped value); settings keys take
 * their row's format (pd in Q30, meas_sigma in the position format, ...).
 * Float and double: the conversion is the cast (half an ulp, 2^-24 or
 * 2^-53 relative) and a value that overflows mtt_real is refused. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mtt_internal.h"
#include "mtt_io.h"
#include "sim.h"
#include "tv_fixture.h"
#include "unity.h"

static mtt_tracker trk; /* measure.c reads no parameter: zeroed is enough */

void setUp(void)
{
    memset(&trk, 0, sizeof trk);
}
void tearDown(void) {}

#ifdef MTT_REAL_FIXED
/* Half a unit of a Qf format. */
static double half_unit(int f)
{
    return ldexp(0.5, -f);
}
#endif

/* Write text to a file under the build directory; returns its path. */
static const char *put_file(const char *name, const char *text)
{
    static char path[4][512];
    static int next;
    char *p = path[next++ % 4];
    FILE *fp;
    snprintf(p, 512, "%s/test_io_fixed_%s", MTT_BINARY_DIR, name);
    fp = fopen(p, "w");
    TEST_ASSERT_NOT_NULL(fp);
    fputs(text, fp);
    TEST_ASSERT_EQUAL_INT(0, fclose(fp));
    return p;
}

/* Round trip of 10^5 values of the position range and of probabilities. */
static void test_round_trip_within_half_unit(void)
{
    sim_rng r = {12345u};
    int i, k;
    const int fmts[3] = {MTT_IO_POS, MTT_IO_PROB, MTT_IO_TIME};
    const double span[3] = {16000.0, 1.0, 30000.0};
    double worst = 0.0;
    for (k = 0; k < 3; ++k) {
        for (i = 0; i < 100000; ++i) {
            double v = (2.0 * sim_unif(&r) - 1.0) * span[k], back, err;
            mtt_real q;
            if (fmts[k] == MTT_IO_PROB)
                v = fabs(v);
            TEST_ASSERT_TRUE(mtt_io_to_real(v, fmts[k], &q));
            back = mtt_io_from_real(q, fmts[k]);
            err = fabs(back - v);
#ifdef MTT_REAL_FIXED
            TEST_ASSERT_TRUE(err <= half_unit(fmts[k]));
            /* exact: the value of the mantissa, and back to the same mantissa */
            {
                mtt_real q2;
                TEST_ASSERT_TRUE(mtt_io_to_real(back, fmts[k], &q2));
                TEST_ASSERT_EQUAL_INT32(q, q2);
                TEST_ASSERT_TRUE(back == ldexp((double)q, -fmts[k]));
            }
            err /= half_unit(fmts[k]);
#elif defined(MTT_REAL_DOUBLE)
            TEST_ASSERT_TRUE(err == 0.0); /* the identity */
            err = 1.0;
#else
            TEST_ASSERT_TRUE(err <= fabs(v) * (double)MTT_REAL_EPS * 0.5);
            err /= fabs(v) * (double)MTT_REAL_EPS * 0.5 + 1e-300;
#endif
            if (err > worst)
                worst = err;
        }
    }
    /* the bound is reached, not loose: the worst case uses most of it */
    TEST_ASSERT_TRUE(worst > 0.9);
}

/* Ties round away from zero, as the compile-time constants (MTT_FX_CONST). */
static void test_rounding_and_constants(void)
{
#ifdef MTT_REAL_FIXED
    mtt_real q;
    TEST_ASSERT_TRUE(mtt_io_to_real(ldexp(1.0, -MTT_IO_POS - 1), MTT_IO_POS, &q));
    TEST_ASSERT_EQUAL_INT32(1, q);
    TEST_ASSERT_TRUE(mtt_io_to_real(-ldexp(1.0, -MTT_IO_POS - 1), MTT_IO_POS, &q));
    TEST_ASSERT_EQUAL_INT32(-1, q);
    TEST_ASSERT_TRUE(mtt_io_to_real(ldexp(0.999, -MTT_IO_POS - 1), MTT_IO_POS, &q));
    TEST_ASSERT_EQUAL_INT32(0, q);
    TEST_ASSERT_TRUE(mtt_io_to_real(0.9, MTT_IO_PROB, &q));
    TEST_ASSERT_EQUAL_INT32(MTT_P(0.9), q);
    TEST_ASSERT_TRUE(mtt_io_to_real(-123.456, MTT_IO_POS, &q));
    TEST_ASSERT_EQUAL_INT32(MTT_POS(-123.456), q);
    TEST_ASSERT_TRUE(mtt_io_to_real(1.0, MTT_IO_TIME, &q));
    TEST_ASSERT_EQUAL_INT32(65536, q);
#else
    mtt_real q;
    TEST_ASSERT_TRUE(mtt_io_to_real(0.9, MTT_IO_PROB, &q));
    TEST_ASSERT_TRUE(q == MTT_R(0.9));
#endif
}

/* Outside the format: the saturation value of the sign, never wrapped. */
static void test_out_of_range_saturates(void)
{
#ifdef MTT_REAL_FIXED
    const double top = ldexp(1.0, 31 - MTT_IO_POS); /* 2^31 units of 2^-f */
    mtt_real q = 0;
    TEST_ASSERT_FALSE(mtt_io_to_real(top, MTT_IO_POS, &q));
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MAX, q);
    TEST_ASSERT_FALSE(mtt_io_to_real(-top, MTT_IO_POS, &q));
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MIN, q);
    TEST_ASSERT_FALSE(mtt_io_to_real(1e300, MTT_IO_POS, &q));
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MAX, q);
    TEST_ASSERT_FALSE(mtt_io_to_real(-1e300, MTT_IO_AMP, &q));
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MIN, q);
    TEST_ASSERT_FALSE(mtt_io_to_real(NAN, MTT_IO_POS, &q));
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MAX, q);
    /* the edge: a value that rounds to MAX - 1 fits, one rounding to MAX not */
    TEST_ASSERT_TRUE(mtt_io_to_real(ldexp(2147483646.49, -MTT_IO_POS), MTT_IO_POS, &q));
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MAX - 1, q);
    TEST_ASSERT_FALSE(mtt_io_to_real(ldexp(2147483646.5, -MTT_IO_POS), MTT_IO_POS, &q));
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MAX, q);
    TEST_ASSERT_TRUE(mtt_io_to_real(ldexp(-2147483646.49, -MTT_IO_POS), MTT_IO_POS, &q));
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MIN + 1, q);
    /* the saturated values are not finite in the fixed build */
    TEST_ASSERT_FALSE(mtt_isfinite(MTT_FX_MAX) || mtt_isfinite(MTT_FX_MIN));
#else
    mtt_real q = MTT_R(7.0);
    TEST_ASSERT_FALSE(mtt_io_to_real((double)INFINITY, MTT_IO_POS, &q));
    TEST_ASSERT_TRUE(q == MTT_R(7.0)); /* unchanged */
#ifndef MTT_REAL_DOUBLE
    TEST_ASSERT_FALSE(mtt_io_to_real(1e300, MTT_IO_POS, &q)); /* beyond float */
    TEST_ASSERT_TRUE(q == MTT_R(7.0));
#endif
#endif
}

/* A detections file whose coordinates leave the declared range: refused
 * at its first such line (fixed), or with MTT_IO_SKIP_OUT_OF_RANGE read,
 * saturated, counted, and then skipped and counted apart from malformed
 * detections by measure.c. */
static void test_detections_out_of_range_counted(void)
{
    mtt_io_detections d;
    const char *path = put_file("range.det.csv",
                                "scan,time,x,y,amplitude\n"
                                "1,100.0,10.5,-20.25,3.5\n"
                                "1,100.0,20000,5,\n"     /* beyond +-16384: in Q16 but not POS_OK */
                                "1,100.0,1e6,5,2\n"      /* beyond the format: saturated */
                                "1,100.0,7,-1e6,\n"
                                "1,100.0,1,2,1e9\n"      /* amplitude beyond its format */
                                "2,101.0,,,\n"
                                "3,102.5,3,4,\n");
    mtt_io_progname = "test_io_fixed";
#ifdef MTT_REAL_FIXED
    TEST_ASSERT_EQUAL_INT(MTT_IO_EINPUT, mtt_io_read_detections(path, &d));
#else
    TEST_ASSERT_EQUAL_INT(MTT_IO_OK, mtt_io_read_detections(path, &d));
    TEST_ASSERT_EQUAL_UINT(0u, d.out_of_range);
    mtt_io_free_detections(&d);
#endif
    TEST_ASSERT_EQUAL_INT(MTT_IO_OK, mtt_io_read_detections_opt(path, &d, MTT_IO_SKIP_OUT_OF_RANGE));
    TEST_ASSERT_EQUAL_UINT(6u, d.n_meas);
    TEST_ASSERT_EQUAL_UINT(3u, d.n_scans);
    TEST_ASSERT_TRUE(d.meas[0].x == MTT_POS(10.5) && d.meas[0].y == MTT_POS(-20.25));
    TEST_ASSERT_TRUE(d.meas[0].has_amplitude && d.meas[0].amplitude == MTT_AMP(3.5));
#ifdef MTT_REAL_FIXED
    TEST_ASSERT_EQUAL_INT32(20000 * 65536, d.meas[1].x);
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MAX, d.meas[2].x);
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MIN, d.meas[3].y);
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MAX, d.meas[4].amplitude);
    /* time in Q16 of the file's unit, counted from the first scan */
    TEST_ASSERT_EQUAL_INT32(0, d.scans[0].rtime);
    TEST_ASSERT_EQUAL_INT32(65536, d.scans[1].rtime);
    TEST_ASSERT_EQUAL_INT32(163840, d.scans[2].rtime);
    mtt_measure_select(&trk, d.meas, NULL, NULL, d.scans[0].count);
    TEST_ASSERT_EQUAL_UINT(1u, tv_meas_count(&trk));
    TEST_ASSERT_EQUAL_UINT(4u, d.out_of_range);
    TEST_ASSERT_EQUAL_UINT32(4u, TV_STATS(&trk).last.meas_out_of_range);
    TEST_ASSERT_EQUAL_UINT32(0u, TV_STATS(&trk).last.meas_bad);
#else
    TEST_ASSERT_TRUE(d.meas[2].x == MTT_R(1e6));
    TEST_ASSERT_TRUE(d.scans[2].rtime == MTT_R(2.5));
    mtt_measure_select(&trk, d.meas, NULL, NULL, d.scans[0].count);
    TEST_ASSERT_EQUAL_UINT(5u, tv_meas_count(&trk));
    TEST_ASSERT_EQUAL_UINT(0u, d.out_of_range);
    TEST_ASSERT_EQUAL_UINT32(0u, TV_STATS(&trk).last.meas_bad);
#endif
    mtt_io_free_detections(&d);
}

/* Time steps must fit the format: a step of 32768 time units or more is
 * refused by the fixed build (the float build takes it); a long file of
 * shorter steps is read, its times counted modulo 2^32 in Q16 as the
 * tracker compares them (MTT_TIME_AFTER). */
static void test_detections_time_range(void)
{
    mtt_io_detections d;
    const char *gap = put_file("time.det.csv",
                               "scan,time,x,y,amplitude\n"
                               "1,5.0,1,2,\n"
                               "2,40000.0,1,2,\n");
    const char *longf = put_file("long.det.csv",
                                 "scan,time,x,y,amplitude\n"
                                 "1,0,1,2,\n"
                                 "2,30000,1,2,\n"
                                 "3,60000,1,2,\n"
                                 "4,90000.5,1,2,\n");
    size_t k;
    mtt_io_progname = "test_io_fixed";
#ifdef MTT_REAL_FIXED
    TEST_ASSERT_EQUAL_INT(MTT_IO_EINPUT, mtt_io_read_detections(gap, &d));
#else
    TEST_ASSERT_EQUAL_INT(MTT_IO_OK, mtt_io_read_detections(gap, &d));
    mtt_io_free_detections(&d);
#endif
    TEST_ASSERT_EQUAL_INT(MTT_IO_OK, mtt_io_read_detections(longf, &d));
    TEST_ASSERT_EQUAL_UINT(4u, d.n_scans);
    for (k = 1; k < 4; ++k)
        TEST_ASSERT_TRUE(MTT_TIME_AFTER(d.scans[k].rtime, d.scans[k - 1].rtime));
#ifdef MTT_REAL_FIXED
    /* 90000.5 * 2^16 modulo 2^32, as a signed word */
    TEST_ASSERT_EQUAL_INT32((int32_t)(5898272768ll - 4294967296ll), d.scans[3].rtime);
    TEST_ASSERT_EQUAL_INT32((int32_t)(30000 * 65536), MTT_TIME_SUB(d.scans[3].rtime, d.scans[2].rtime) - 32768);
#else
    TEST_ASSERT_TRUE(d.scans[3].rtime == MTT_R(90000.5));
#endif
    mtt_io_free_detections(&d);
}

/* Settings: each key in its row's format, read back through mtt_params_get
 * within half a unit. */
static void test_settings_formats(void)
{
    mtt_io_settings s;
    double v[3];
    const char *path = put_file("ok.json",
                                "{\"pd\": 0.9, \"meas_sigma\": [2.5, 0.75], \"clutter_density\": 1e-4,"
                                " \"process_psd\": 0.5, \"vmax\": 30, \"association\": \"ipda\","
                                " \"initial_tracks\": [{\"x\": 1.25, \"y\": -2, \"vx\": 0.5, \"vy\": -0.5}]}");
    mtt_io_progname = "test_io_fixed";
    TEST_ASSERT_EQUAL_INT(MTT_IO_OK, mtt_io_read_settings(path, &s));
    TEST_ASSERT_TRUE(s.params.pd == MTT_P(0.9));
    TEST_ASSERT_TRUE(s.params.meas_sigma[0] == MTT_POS(2.5) && s.params.meas_sigma[1] == MTT_POS(0.75));
    TEST_ASSERT_TRUE(s.params.clutter_density == MTT_DENS(1e-4));
    TEST_ASSERT_TRUE(s.params.vmax == MTT_POS(30.0));
    TEST_ASSERT_EQUAL_UINT(1u, s.n_seeds);
    TEST_ASSERT_TRUE(s.seeds[0].x[0] == MTT_POS(1.25) && s.seeds[0].x[3] == MTT_POS(-0.5));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_get(&s.params, "pd", v, 1));
#ifdef MTT_REAL_FIXED
    TEST_ASSERT_TRUE(s.params.process_psd == MTT_FX_CONST(0.5, MTT_FX_VAR_FRAC));
    TEST_ASSERT_DOUBLE_WITHIN(half_unit(MTT_FX_PROB_FRAC), 0.9, v[0]);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_get(&s.params, "clutter_density", v, 1));
    TEST_ASSERT_DOUBLE_WITHIN(half_unit(MTT_FX_DENS_FRAC), 1e-4, v[0]);
#else
    TEST_ASSERT_TRUE(v[0] == (double)MTT_R(0.9));
#endif
    mtt_io_free_settings(&s);
}

/* A settings value outside its format is refused (never wrapped): vmax
 * beyond the position format, a process noise that rounds to 0 in Q16,
 * an initial track beyond it. */
static void test_settings_out_of_format(void)
{
    mtt_io_settings s;
    const char *vmax = put_file("vmax.json", "{\"clutter_density\": 1e-4, \"vmax\": 1e6}");
    const char *psd = put_file("psd.json", "{\"clutter_density\": 1e-4, \"process_psd\": 1e-7}");
    const char *seed = put_file("seed.json", "{\"clutter_density\": 1e-4, \"initial_tracks\": "
                                             "[{\"x\": 1e5, \"y\": 0, \"vx\": 0, \"vy\": 0}]}");
    mtt_params p;
    double big = 1e6;
    mtt_io_progname = "test_io_fixed";
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
#ifdef MTT_REAL_FIXED
    TEST_ASSERT_EQUAL_INT(MTT_IO_EINPUT, mtt_io_read_settings(vmax, &s));
    TEST_ASSERT_EQUAL_INT(MTT_IO_EINPUT, mtt_io_read_settings(psd, &s));
    TEST_ASSERT_EQUAL_INT(MTT_IO_EINPUT, mtt_io_read_settings(seed, &s));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_set(&p, "vmax", &big, 1));
    TEST_ASSERT_TRUE(p.vmax == MTT_POS(60.0)); /* unchanged */
#else
    TEST_ASSERT_EQUAL_INT(MTT_IO_OK, mtt_io_read_settings(vmax, &s));
    mtt_io_free_settings(&s);
    TEST_ASSERT_EQUAL_INT(MTT_IO_OK, mtt_io_read_settings(psd, &s));
    mtt_io_free_settings(&s);
    TEST_ASSERT_EQUAL_INT(MTT_IO_OK, mtt_io_read_settings(seed, &s));
    mtt_io_free_settings(&s);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_set(&p, "vmax", &big, 1));
#endif
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_round_trip_within_half_unit);
    RUN_TEST(test_rounding_and_constants);
    RUN_TEST(test_out_of_range_saturates);
    RUN_TEST(test_detections_out_of_range_counted);
    RUN_TEST(test_detections_time_range);
    RUN_TEST(test_settings_formats);
    RUN_TEST(test_settings_out_of_format);
    return UNITY_END();
}
