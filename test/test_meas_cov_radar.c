/* SPDX-License-Identifier: BSD-3-Clause */
/* test_meas_cov_radar.c - a covariance per detection (ALGORITHMS.md §3.1)
 * at a radar's scale, one text for the float and double builds and the
 * fixed-point build at the radar scale (preset host-fixed-radar,
 * configs/firmware_fixed_radar.h; docs/FIXED_POINT.md §5): a seeded track
 * and one frame of two detections, each with its own R, in the four
 * firmware modes.  The tracks equal the float build's (the table below,
 * from the float build) within the fixed format's tolerance, and differ
 * from the frame with meas_sigma's one R; a detection whose own R is
 * wider than the gate window of the one R is gated; a covariance that
 * does not fit the variance format is counted in meas_out_of_range. */
#include <math.h>
#include <string.h>

#include "mtt_internal.h"
#include "sim.h"
#include "unity.h"

#if defined(MTT_REAL_FIXED) && (MTT_FX_POS_FRAC != 10 || MTT_FX_VAR_FRAC != 4)
#error "test_meas_cov_radar.c in fixed point is the radar scale's test (configs/firmware_fixed_radar.h)"
#endif

static mtt_tracker trk;

void setUp(void) {}
void tearDown(void) {}

#ifdef MTT_REAL_FIXED
static mtt_real fx(double v, int f)
{
    mtt_real r = 0;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_fx_from_double(v, f, &r));
    return r;
}
#define POS(v) fx((v), MTT_FX_POS_FRAC)
#define VAR(v) fx((v), MTT_FX_VAR_FRAC)
#define POS_D(r) mtt_fx_to_double((r), MTT_FX_POS_FRAC)
#define VAR_D(r) mtt_fx_to_double((r), MTT_FX_VAR_FRAC)
/* the fixed build against the float build's table: 2 cm, 1 cm/s, 0.02 %
 * (and 2 LSB of the variance format, below) */
#define TOL_POS 0.02
#define TOL_VEL 0.01
#define TOL_VAR 2e-4
#else
#define POS(v) ((mtt_real)(v))
#define VAR(v) ((mtt_real)(v))
#define POS_D(r) ((double)(r))
#define VAR_D(r) ((double)(r))
/* float's rounding at 100 km (an ulp of 8 mm); double against float's table */
#define TOL_POS 0.02
#define TOL_VEL 0.005
#define TOL_VAR 1e-4
#endif

static void radar_params(mtt_params *p, mtt_assoc mode)
{
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(p));
    p->association = mode;
    p->motion = MTT_MOTION_CV;
    p->process_psd = MTT_VAR(5.0);
    p->meas_sigma[0] = MTT_POS(50.0);
    p->meas_sigma[1] = MTT_POS(50.0);
    p->pd = MTT_P(0.9);
    p->clutter_density = MTT_DENS(1e-7); /* p / lambda well inside Q16 (FIXED_POINT.md §5) */
    p->vmax = MTT_POS(350.0);
}

#if MTT_WITH_MEAS_COV
/* A track seeded at 100 km, 200 m/s, then one frame 4 s later; the view
 * after it.  cov NULL: the one R of meas_sigma. */
static void one_frame(mtt_assoc mode, const mtt_meas *m, const mtt_meas_cov *cov, size_t n, mtt_track_view *v)
{
    mtt_params p;
    mtt_real x[4], P[16];
    size_t cnt = 0;
    memset(P, 0, sizeof P);
    radar_params(&p, mode);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_TIME(0.0), NULL, 0));
    x[0] = POS(100000.0);
    x[1] = POS(50000.0);
    x[2] = POS(200.0);
    x[3] = POS(50.0);
    P[0] = VAR(2500.0);
    P[5] = VAR(2500.0);
    P[10] = VAR(400.0);
    P[15] = VAR(400.0);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&trk, x, P, NULL));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_cov(&trk, MTT_TIME(4.0), m, cov, n));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&trk, &cnt));
    TEST_ASSERT_TRUE(cnt >= 1u);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, 0, v));
}

/* The prediction is at (100800, 50200): detection 0 with a narrow round
 * R (30 m), detection 1 with a wide correlated one. */
static void two_detections(mtt_meas m[2], mtt_meas_cov c[2])
{
    m[0] = sim_meas(POS(100830.0), POS(50180.0), MTT_ZERO, 0);
    m[1] = sim_meas(POS(100700.0), POS(50290.0), MTT_ZERO, 0);
    c[0].r_xx = VAR(900.0);
    c[0].r_xy = VAR(0.0);
    c[0].r_yy = VAR(900.0);
    c[1].r_xx = VAR(10000.0);
    c[1].r_xy = VAR(3000.0);
    c[1].r_yy = VAR(6400.0);
}

/* The float build's track after the frame (x, y, vx, vy, P00, P01, P11,
 * P22, P02) per mode, own R (row 0) and one R (row 1). */
static const mtt_assoc modes[4] = {MTT_ASSOC_LM_IHPDA, MTT_ASSOC_IHPDA, MTT_ASSOC_LM_IPDA, MTT_ASSOC_IPDA};
static const double want[4][2][9] = {
    {{100824.054688, 50183.960938, 204.380661, 47.079559, 1861.289795, -51.588448, 1818.307373, 183.089523, 338.917847},
     {100820.351562, 50186.433594, 203.705566, 47.529625, 2960.732910, -42.485962, 2925.328125, 219.542236, 539.112000}},
    {{100824.054688, 50183.960938, 204.380661, 47.079559, 1861.288696, -51.588402, 1818.306396, 183.089493, 338.917664},
     {100820.351562, 50186.433594, 203.705566, 47.529625, 2960.732910, -42.485962, 2925.328125, 219.542236, 539.112000}},
    {{100806.156250, 50202.242188, 201.121567, 50.408394, 3107.853760, -1085.364868, 2765.897705, 224.417511, 565.893616},
     {100790.398438, 50212.335938, 198.251511, 52.246498, 4231.798828, -1921.540894, 3586.863770, 261.685455, 770.557007}},
    {{100806.156250, 50202.242188, 201.121567, 50.408394, 3107.853760, -1085.364868, 2765.897705, 224.417511, 565.893616},
     {100790.398438, 50212.335938, 198.251511, 52.246498, 4231.798828, -1921.540894, 3586.863770, 261.685455, 770.557007}},
};

static void check(const mtt_track_view *v, const double w[9])
{
    TEST_ASSERT_DOUBLE_WITHIN(TOL_POS, w[0], POS_D(v->x[0]));
    TEST_ASSERT_DOUBLE_WITHIN(TOL_POS, w[1], POS_D(v->x[1]));
    TEST_ASSERT_DOUBLE_WITHIN(TOL_VEL, w[2], POS_D(v->x[2]));
    TEST_ASSERT_DOUBLE_WITHIN(TOL_VEL, w[3], POS_D(v->x[3]));
    TEST_ASSERT_DOUBLE_WITHIN(TOL_VAR * w[4] + 0.125, w[4], VAR_D(v->P[0][0]));
    TEST_ASSERT_DOUBLE_WITHIN(TOL_VAR * w[4] + 0.125, w[5], VAR_D(v->P[0][1]));
    TEST_ASSERT_DOUBLE_WITHIN(TOL_VAR * w[6] + 0.125, w[6], VAR_D(v->P[1][1]));
    TEST_ASSERT_DOUBLE_WITHIN(TOL_VAR * w[7] + 0.125, w[7], VAR_D(v->P[2][2]));
    TEST_ASSERT_DOUBLE_WITHIN(TOL_VAR * w[4] + 0.125, w[8], VAR_D(v->P[0][2]));
}

static void test_own_r_gives_the_float_tracks(void)
{
    mtt_meas m[2];
    mtt_meas_cov c[2];
    mtt_track_view a, b;
    int k;
    two_detections(m, c);
    for (k = 0; k < 4; ++k) {
        one_frame(modes[k], m, c, 2, &a);
        one_frame(modes[k], m, NULL, 2, &b);
        check(&a, want[k][0]);
        check(&b, want[k][1]);
        /* the own R moves the track: detection 0's 30 m pulls it closer */
        TEST_ASSERT_TRUE(fabs(POS_D(a.x[0]) - POS_D(b.x[0])) > 1.0 || fabs(POS_D(a.x[1]) - POS_D(b.x[1])) > 1.0);
        TEST_ASSERT_TRUE(fabs(VAR_D(a.P[0][0]) - VAR_D(b.P[0][0])) > 10.0);
    }
}

/* A detection 1.5 km off in x with an own R of (1 km)^2 is inside its
 * own gate (d^2 about 2.2) but beyond the one R's slice (about 300 m):
 * the window widened by the largest own r_xx finds it. */
static void test_wide_own_r_is_gated(void)
{
    mtt_meas m[1];
    mtt_meas_cov c[1];
    mtt_track_view v;
    mtt_stats st;
    m[0] = sim_meas(POS(102300.0), POS(50200.0), MTT_ZERO, 0);
    c[0].r_xx = VAR(1e6);
    c[0].r_xy = VAR(0.0);
    c[0].r_yy = VAR(2500.0);
    one_frame(MTT_ASSOC_IPDA, m, c, 1, &v);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&trk, &st));
    TEST_ASSERT_EQUAL_UINT32(1u, st.last.pairs);
    TEST_ASSERT_TRUE(POS_D(v.x[0]) > 100800.0);
    one_frame(MTT_ASSOC_IPDA, m, NULL, 1, &v);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&trk, &st));
    TEST_ASSERT_EQUAL_UINT32(0u, st.last.pairs);
}

/* A covariance outside the variance format (saturated, as the host
 * boundary leaves it) is out of range in fixed point, malformed (not
 * finite) in float; one that is not positive definite is malformed;
 * large entries whose products leave 32 bits are kept. */
static void test_covariance_out_of_range_is_counted(void)
{
    mtt_meas m[4];
    mtt_meas_cov c[4];
    mtt_track_view v;
    mtt_stats st;
    int k;
    for (k = 0; k < 4; ++k) {
        m[k] = sim_meas(POS(100800.0 + 10.0 * k), POS(50200.0), MTT_ZERO, 0);
        c[k].r_xx = VAR(900.0);
        c[k].r_xy = VAR(0.0);
        c[k].r_yy = VAR(900.0);
    }
#ifdef MTT_REAL_FIXED
    c[0].r_xx = MTT_FX_MAX;      /* did not fit */
    c[1].r_xy = MTT_FX_MIN;      /* did not fit */
    c[3].r_xx = VAR(1.3e8);      /* (11.4 km)^2: r_xx r_yy beyond 2^31, positive definite */
    c[3].r_xy = VAR(1.2e8);
    c[3].r_yy = VAR(1.3e8);
#else
    c[0].r_xx = (mtt_real)INFINITY;
    c[1].r_xy = (mtt_real)(-INFINITY);
    c[3].r_xx = VAR(1.3e8);
    c[3].r_xy = VAR(1.2e8);
    c[3].r_yy = VAR(1.3e8);
#endif
    c[2].r_xy = VAR(1000.0); /* r_xy^2 > r_xx r_yy */
    one_frame(MTT_ASSOC_LM_IPDA, m, c, 4, &v);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&trk, &st));
#ifdef MTT_REAL_FIXED
    TEST_ASSERT_EQUAL_UINT32(2u, st.last.meas_out_of_range);
    TEST_ASSERT_EQUAL_UINT32(1u, st.last.meas_bad);
#else
    TEST_ASSERT_EQUAL_UINT32(3u, st.last.meas_bad);
#endif
    TEST_ASSERT_EQUAL_UINT32(1u, st.last.pairs); /* the one kept: detection 3 */
}

/* A birth from two detections 4 s apart (ALGORITHMS.md §12.1, §3.1):
 * position Rb, cross Rb/dt, velocity (Ra + Rb)/dt^2, each from that
 * detection's own R (meas_sigma's for one without); the velocity rows and
 * columns scaled by c = vmax / sqrt(max velocity variance) when that
 * exceeds vmax^2. */
static void birth_check(const double Ra[3], const double Rb[3], int own_a, int own_b)
{
    const double dt = 4.0, vmax = 350.0;
    const mtt_meas a = sim_meas(POS(100000.0), POS(50000.0), MTT_ZERO, 0);
    const mtt_meas b = sim_meas(POS(100800.0), POS(50200.0), MTT_ZERO, 0);
    const mtt_meas_cov ca = {VAR(Ra[0]), VAR(Ra[1]), VAR(Ra[2])}, cb = {VAR(Rb[0]), VAR(Rb[1]), VAR(Rb[2])};
    mtt_params p;
    mtt_track_view v;
    size_t n = 0;
    double vv, c = 1.0, w[4][4];
    int i, k;
    radar_params(&p, MTT_ASSOC_IPDA);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_cov(&trk, MTT_TIME(0.0), &a, own_a ? &ca : NULL, 1u));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_cov(&trk, MTT_TIME(dt), &b, own_b ? &cb : NULL, 1u));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&trk, &n));
    TEST_ASSERT_EQUAL_UINT(1, n);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, 0, &v));
    TEST_ASSERT_DOUBLE_WITHIN(TOL_VEL, 200.0, POS_D(v.x[2]));
    TEST_ASSERT_DOUBLE_WITHIN(TOL_VEL, 50.0, POS_D(v.x[3]));
    vv = (Ra[0] + Rb[0]) / (dt * dt);
    vv = ((Ra[2] + Rb[2]) / (dt * dt) > vv) ? (Ra[2] + Rb[2]) / (dt * dt) : vv;
    if (vv > vmax * vmax) {
        c = vmax / sqrt(vv);
    }
    for (i = 0; i < 2; ++i) {
        for (k = 0; k < 2; ++k) {
            w[i][k] = Rb[i + k];
            w[i][k + 2] = c * Rb[i + k] / dt;
            w[i + 2][k] = w[i][k + 2];
            w[i + 2][k + 2] = c * c * (Ra[i + k] + Rb[i + k]) / (dt * dt);
        }
    }
    for (i = 0; i < 4; ++i) {
        for (k = 0; k < 4; ++k) {
            TEST_ASSERT_DOUBLE_WITHIN(TOL_VAR * fabs(w[i][k]) + 0.125, w[i][k], VAR_D(v.P[i][k]));
        }
    }
}

static void test_birth_takes_each_detections_r(void)
{
    const double Ra[3] = {2500.0, 600.0, 1600.0}, Rb[3] = {10000.0, 3000.0, 6400.0};
    const double wide_a[3] = {1.2e6, 0.0, 4e5}, wide_b[3] = {1e6, 1e5, 5e5}; /* velocity capped */
    const double sigma[3] = {2500.0, 0.0, 2500.0};                            /* meas_sigma 50 m */
    birth_check(Ra, Rb, 1, 1);
    birth_check(wide_a, wide_b, 1, 1);
    birth_check(Ra, sigma, 1, 0);
    birth_check(sigma, Rb, 0, 1);
}
#else /* MTT_WITH_MEAS_COV 0 */
static void test_build_without_it_refuses(void)
{
    mtt_params p;
    mtt_meas m = sim_meas(POS(100000.0), POS(50000.0), MTT_ZERO, 0);
    mtt_meas_cov c = {VAR(900.0), VAR(0.0), VAR(900.0)};
    radar_params(&p, MTT_ASSOC_LM_IHPDA);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_UNSUPPORTED, mtt_tracker_step_cov(&trk, MTT_TIME(0.0), &m, &c, 1));
}
#endif

int main(void)
{
    UNITY_BEGIN();
#if MTT_WITH_MEAS_COV
    RUN_TEST(test_own_r_gives_the_float_tracks);
    RUN_TEST(test_wide_own_r_is_gated);
    RUN_TEST(test_covariance_out_of_range_is_counted);
    RUN_TEST(test_birth_takes_each_detections_r);
#else
    RUN_TEST(test_build_without_it_refuses);
#endif
    return UNITY_END();
}
