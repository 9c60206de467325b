/* SPDX-License-Identifier: BSD-3-Clause */
/* test_polar.c - polar detections (mtt_tracker_step_polar, ALGORITHMS.md
 * §3.2): the unbiased conversion against the paper's closed form in double
 * and a Monte Carlo of its bias and covariance; the clutter Jacobian
 * lambda / r; a target tracked from polar detections across ranges, in any
 * order; bad detections counted; the range rate: its extended Kalman
 * update against a double computation with a numerical Jacobian, its gate
 * and likelihood, the birth's radial velocity, a scene where it lowers the
 * velocity error; the split modes with range rates; the refusals (Cartesian settings, polar settings with a
 * Cartesian step, a range rate without range_rate_sigma (split too), a build
 * without MTT_WITH_MEAS_COV). */
#include <math.h>
#include <string.h>

#include "mtt_internal.h"
#include "tv_assert.h"
#include "unity.h"

static mtt_tracker ta;
#if MTT_WITH_MEAS_COV
static mtt_tracker tb;
#endif

void setUp(void) {}
void tearDown(void) {}

#if MTT_WITH_MEAS_COV

/* A deterministic N(0, 1): an LCG and Box-Muller, in double. */
static uint64_t rng_state;
static double unif(void)
{
    rng_state = rng_state * 6364136223846793005ull + 1442695040888963407ull;
    return ((double)(rng_state >> 11) + 0.5) / 9007199254740992.0;
}
static double gauss01(void)
{
    return sqrt(-2.0 * log(unif())) * cos(6.283185307179586 * unif());
}

static mtt_polar pol(double r, double b)
{
    mtt_polar d;
    memset(&d, 0, sizeof d);
    d.range = (mtt_real)r;
    d.bearing = (mtt_real)b;
    return d;
}

/* Mo et al. 1998, the paper's form, in double: x = e^{u/2} r cos b and
 * R_xx = (e^u - 2) r^2 c^2 + (r^2 + sr^2)(1 + e^{-2u} cos 2b)/2, ... */
static void mo_closed_form(double sr, double sb, double r, double b, double out[5])
{
    const double u = sb * sb, l2 = exp(-2.0 * u), k = exp(u) - 2.0, c = cos(b), s = sin(b);
    out[0] = exp(0.5 * u) * r * c;
    out[1] = exp(0.5 * u) * r * s;
    out[2] = k * r * r * c * c + 0.5 * (r * r + sr * sr) * (1.0 + l2 * cos(2.0 * b));
    out[3] = k * r * r * c * s + 0.5 * (r * r + sr * sr) * l2 * sin(2.0 * b);
    out[4] = k * r * r * s * s + 0.5 * (r * r + sr * sr) * (1.0 - l2 * cos(2.0 * b));
}

static void test_conversion_is_the_closed_form(void)
{
    static const double cases[][4] = {/* sr, sb, r, b */
                                      {10.0, 0.01, 5000.0, 0.3}, {1.0, 0.05, 200.0, -2.0},
                                      {25.0, 0.002, 20000.0, 1.5}, {5.0, 0.2, 50.0, 3.0}};
    const mtt_real sensor[2] = {MTT_R(100.0), MTT_R(-50.0)};
    size_t i;
    for (i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        const mtt_real sig[2] = {(mtt_real)cases[i][0], (mtt_real)cases[i][1]};
        const mtt_polar d = pol(cases[i][2], cases[i][3]);
        mtt_meas m;
        mtt_meas_cov c;
        double ref[5], scale;
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_polar_to_cartesian(sig, sensor, &d, &m, &c));
        mo_closed_form(cases[i][0], cases[i][1], (double)d.range, (double)d.bearing, ref);
        TEST_ASSERT_DOUBLE_WITHIN(1e-5 * cases[i][2], ref[0] + 100.0, (double)m.x);
        TEST_ASSERT_DOUBLE_WITHIN(1e-5 * cases[i][2], ref[1] - 50.0, (double)m.y);
        /* the regrouped form against the paper's: to 1e-3 of the larger axis
         * (the paper's own form in double loses r^2 1e-16) */
        scale = ref[2] > ref[4] ? ref[2] : ref[4];
        TEST_ASSERT_DOUBLE_WITHIN(1e-3 * scale, ref[2], (double)c.r_xx);
        TEST_ASSERT_DOUBLE_WITHIN(1e-3 * scale, ref[3], (double)c.r_xy);
        TEST_ASSERT_DOUBLE_WITHIN(1e-3 * scale, ref[4], (double)c.r_yy);
        TEST_ASSERT_TRUE((double)c.r_xx * (double)c.r_yy > (double)c.r_xy * (double)c.r_xy);
    }
}

/* The conversion is unbiased and its covariance the spread, where the
 * plain r (cos b, sin b) is biased by r (e^{-sb^2/2} - 1): a Monte Carlo
 * of 200000 detections of one point, range 1000, bearing 0.7, sr 5,
 * sb 0.05 (the plain bias is -0.96 in x, about 13 standard errors). */
static void test_monte_carlo_bias_and_covariance(void)
{
    const double r0 = 1000.0, b0 = 0.7, x0 = r0 * cos(b0), y0 = r0 * sin(b0);
    const mtt_real sig[2] = {MTT_R(5.0), MTT_R(0.05)}, sensor[2] = {MTT_R(0.0), MTT_R(0.0)};
    const int N = 200000;
    double sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0, rx = 0, rxy = 0, ry = 0, plain = 0, se;
    int k;
    rng_state = 12345u;
    for (k = 0; k < N; ++k) {
        const double r = r0 + 5.0 * gauss01(), b = b0 + 0.05 * gauss01();
        const mtt_polar d = pol(r, b);
        mtt_meas m;
        mtt_meas_cov c;
        double ex, ey;
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_polar_to_cartesian(sig, sensor, &d, &m, &c));
        ex = (double)m.x - x0;
        ey = (double)m.y - y0;
        sx += ex;
        sy += ey;
        sxx += ex * ex;
        sxy += ex * ey;
        syy += ey * ey;
        rx += (double)c.r_xx;
        rxy += (double)c.r_xy;
        ry += (double)c.r_yy;
        plain += r * cos(b) - x0;
    }
    sx /= N;
    sy /= N;
    se = sqrt(sxx / N / N);
    TEST_ASSERT_DOUBLE_WITHIN(4.0 * se, 0.0, sx);
    TEST_ASSERT_DOUBLE_WITHIN(4.0 * sqrt(syy / N / N), 0.0, sy);
    TEST_ASSERT_TRUE(plain / N < -8.0 * se); /* the plain conversion's bias, seen */
    TEST_ASSERT_DOUBLE_WITHIN(3.0 * se, x0 * (exp(-0.00125) - 1.0), plain / N);
    /* the mean R is the spread of the converted detections, to 3 % */
    TEST_ASSERT_DOUBLE_WITHIN(0.03 * sxx / N, sxx / N, rx / N);
    TEST_ASSERT_DOUBLE_WITHIN(0.03 * syy / N, syy / N, ry / N);
    TEST_ASSERT_DOUBLE_WITHIN(0.03 * sqrt(sxx * syy) / N, sxy / N, rxy / N);
}

static void polar_params(mtt_params *p)
{
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(p));
    p->association = MTT_ASSOC_LM_IHPDA;
    p->measurement = MTT_MEASUREMENT_POLAR;
    p->sensor_xy[0] = MTT_R(-1000.0);
    p->sensor_xy[1] = MTT_R(500.0);
    p->meas_sigma[0] = MTT_R(10.0);
    p->meas_sigma[1] = MTT_R(0.005);
    p->process_psd = MTT_R(1.0);
    p->motion = MTT_MOTION_CV;
    p->pd = MTT_R(0.9);
    p->pg = MTT_R(0.99);
    p->clutter_density = MTT_R(1e-4); /* per metre radian */
    p->vmax = MTT_R(300.0);
}

/* pair.lam = lambda / r_j and the track's lambda at its predicted range. */
static void test_clutter_density_has_the_jacobian(void)
{
    mtt_params p;
    const mtt_real x[4] = {MTT_R(3000.0), MTT_R(500.0), MTT_R(0.0), MTT_R(0.0)}; /* range 4000 */
    mtt_real P[16];
    mtt_polar d[2];
    uint16_t k;
    polar_params(&p);
    p.initiate = 0;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&ta, &p));
    memset(P, 0, sizeof P);
    P[0] = P[5] = MTT_R(400.0);
    P[10] = P[15] = MTT_R(1.0);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&ta, x, P, NULL));
    d[0] = pol(4010.0, 0.002);
    d[1] = pol(3985.0, -0.003);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_polar(&ta, MTT_R(0.0), d, 2u));
    TEST_ASSERT_EQUAL_UINT16(2u, ta.tf[0].pair_count);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f * 2.5e-8f, (float)(1e-4 / 4000.0), (float)ta.tf[0].lambda);
    for (k = 0; k < 2u; ++k) {
        const mtt_pair *pp = &ta.pairs[ta.tf[0].pair_first + k];
        const double r = (double)ta.meas[pp->meas].rng;
        TEST_ASSERT_TRUE(r == 4010.0 || r == 3985.0);
        TEST_ASSERT_FLOAT_WITHIN((float)(1e-6 * 1e-4 / r), (float)(1e-4 / r), (float)pp->lam);
    }
}

/* A target from range 2 km out to 9 km past the sensor (cross-range noise
 * 10 m to 45 m), PD 0.9, 3 clutter detections a scan: one confirmed track,
 * one identity, its position error below the measurements'. */
#define SCANS 60
static mtt_polar scene[SCANS][8];
static int scene_n[SCANS];
static double truth[SCANS][2];

static void make_scene(void)
{
    int k;
    rng_state = 777u;
    for (k = 0; k < SCANS; ++k) {
        const double tx = 500.0 + 120.0 * k, ty = 1500.0 - 20.0 * k; /* 122 m/s */
        const double dx = tx + 1000.0, dy = ty - 500.0;
        int n = 0, c;
        truth[k][0] = tx;
        truth[k][1] = ty;
        if (unif() < 0.9) {
            scene[k][n++] = pol(sqrt(dx * dx + dy * dy) + 10.0 * gauss01(), atan2(dy, dx) + 0.005 * gauss01());
        }
        for (c = 0; c < 3; ++c) {
            scene[k][n++] = pol(500.0 + 9500.0 * unif(), -1.0 + 2.0 * unif());
        }
        scene_n[k] = n;
    }
}

static void run_scene(mtt_tracker *t, int reverse, double *rms, uint32_t *ids, size_t *n_confirmed_end)
{
    mtt_params p;
    double se = 0.0;
    int k, counted = 0;
    uint32_t id = 0xFFFFFFFFu;
    *ids = 0;
    polar_params(&p);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(t, &p));
    for (k = 0; k < SCANS; ++k) {
        mtt_polar in[8];
        size_t i, n = (size_t)scene_n[k], cnt;
        for (i = 0; i < n; ++i) {
            in[i] = scene[k][reverse ? n - 1u - i : i];
        }
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_polar(t, (mtt_real)k, in, n));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(t, &cnt));
        *n_confirmed_end = 0;
        for (i = 0; i < cnt; ++i) {
            mtt_track_view v;
            TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(t, i, &v));
            if (!v.confirmed) {
                continue;
            }
            ++*n_confirmed_end;
            if (fabs((double)v.x[0] - truth[k][0]) < 300.0 && fabs((double)v.x[1] - truth[k][1]) < 300.0) {
                const double ex = (double)v.x[0] - truth[k][0], ey = (double)v.x[1] - truth[k][1];
                if (v.id != id) {
                    id = v.id;
                    ++*ids;
                }
                if (k >= 10) {
                    se += ex * ex + ey * ey;
                    ++counted;
                }
            }
        }
    }
    TEST_ASSERT_TRUE(counted >= SCANS - 12);
    *rms = sqrt(se / counted);
}

static void test_tracks_a_target_across_ranges_in_any_order(void)
{
    double rms_a, rms_b;
    uint32_t ids_a, ids_b;
    size_t ca, cb;
    mtt_stats st;
    make_scene();
    run_scene(&ta, 0, &rms_a, &ids_a, &ca);
    run_scene(&tb, 1, &rms_b, &ids_b, &cb);
    TEST_ASSERT_EQUAL_UINT32(1u, ids_a); /* one identity from confirmation to the end */
    TEST_ASSERT_EQUAL_UINT32(1u, (uint32_t)ca); /* and no false track at the end */
    /* the measurements' error at the far end is 10 m x 45 m: the track's
     * RMS over the run is below the mean of the two */
    TEST_ASSERT_TRUE(rms_a < 25.0);
    TEST_ASSERT_TRUE(rms_a > 2.0); /* (the noise is there: a real error) */
    TEST_ASSERT_EQUAL_DOUBLE(rms_a, rms_b); /* bit for bit in reversed order */
    TEST_ASSERT_EQUAL_UINT32(ids_a, ids_b);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&ta, &st));
    TEST_ASSERT_EQUAL_UINT32(0u, st.total.meas_bad);
}

static void test_bad_polar_detections_are_counted(void)
{
    mtt_params p;
    mtt_polar d[5];
    mtt_stats st;
    mtt_meas m;
    mtt_meas_cov c;
    const mtt_real sig[2] = {MTT_R(1.0), MTT_R(0.01)}, sensor[2] = {MTT_R(0.0), MTT_R(0.0)};
    polar_params(&p);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&ta, &p));
    d[0] = pol(0.0, 0.1);
    d[1] = pol(-5.0, 0.1);
    d[2] = pol(100.0, (double)NAN);
    d[3] = pol((double)INFINITY, 0.0);
    d[4] = pol(100.0, 0.2);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_polar(&ta, MTT_R(0.0), d, 5u));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&ta, &st));
    TEST_ASSERT_EQUAL_UINT32(4u, st.last.meas_bad);
    TEST_ASSERT_EQUAL_UINT16(1u, ta.n_meas);
    TEST_ASSERT_EQUAL_INT(MTT_ERR_VALUE, mtt_polar_to_cartesian(sig, sensor, &d[0], &m, &c));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_polar_to_cartesian(sig, sensor, NULL, &m, &c));
}

static void test_refusals(void)
{
    mtt_params p;
    const char *bad = NULL;
    const mtt_polar d = pol(100.0, 0.1);
    mtt_meas z;
    mtt_stats st;
    memset(&z, 0, sizeof z);
    /* Cartesian settings refuse polar detections, polar settings Cartesian ones */
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&ta, &p));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_UNSUPPORTED, mtt_tracker_step_polar(&ta, (mtt_real)0, &d, 1u));
    polar_params(&p);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&ta, &p));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_UNSUPPORTED, mtt_tracker_step(&ta, MTT_R(0.0), &z, 1u));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&ta, &st));
    TEST_ASSERT_EQUAL_UINT32(0u, st.total.frames); /* nothing changed */
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_tracker_step_polar(&ta, MTT_R(0.0), NULL, 1u));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_polar(&ta, MTT_R(0.0), NULL, 0u));
#if MTT_WITH_SPLIT
    /* split takes polar detections and their range rates (§14.3); a range
     * rate without range_rate_sigma stays refused */
    p.motion = MTT_MOTION_IMM;
    p.split = 1;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_check(&p, &bad));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&ta, &p));
    {
        mtt_polar dr[2];
        dr[0] = d;
        dr[1] = pol(200.0, 0.3);
        dr[1].has_range_rate = 1;
        dr[1].range_rate = MTT_R(3.0);
        TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_tracker_step_polar(&ta, MTT_R(0.0), dr, 2u));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&ta, &st));
        TEST_ASSERT_EQUAL_UINT32(0u, st.total.frames); /* nothing changed */
        p.range_rate_sigma = MTT_R(0.5);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&ta, &p));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_polar(&ta, MTT_R(0.0), dr, 2u));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&ta, &st));
        TEST_ASSERT_EQUAL_UINT32(1u, st.total.frames);
    }
#else
    (void)bad;
#endif
}

/* mtt_polar_rdot_step on a stacked state (the split modes', §14.3): a
 * target block at offset 4 with no cross covariance gets the update of the
 * block alone (mtt_polar_rdot_update) and the other block is untouched; M
 * is I - K H; out of range, at the sensor or with a variance that leaves
 * s <= 0 nothing is done. */
#define ST (2 * MTT_MAX_STATE)
static void test_range_rate_step_on_a_block(void)
{
    const mtt_real sr[2] = {MTT_R(-100.0), MTT_R(300.0)}, rrv[2] = {MTT_R(4.5), MTT_R(0.25)};
    const mtt_real bad[2] = {MTT_R(4.5), MTT_R(-1e9)};
    const double x0[4] = {900.0, 1200.0, 12.0, -7.0};
    const double P0[4][4] = {{40, 5, 2, 0.5}, {5, 60, -1, 3}, {2, -1, 9, 0.4}, {0.5, 3, 0.4, 7}};
    mtt_real xs[ST], Ps[ST * ST], M[ST * ST], T[ST * ST], x[MTT_MAX_STATE], xk[ST];
    mtt_cov P;
    int i, k;
    memset(xs, 0, sizeof xs);
    memset(Ps, 0, sizeof Ps);
    memset(x, 0, sizeof x);
    memset(P, 0, sizeof P);
    for (i = 0; i < 4; ++i) {
        xs[i] = (mtt_real)(100.0 * (i + 1));
        x[i] = xs[4 + i] = (mtt_real)x0[i];
        Ps[i * ST + i] = MTT_R(3.0);
        for (k = 0; k < 4; ++k) {
            P[i][k] = Ps[(4 + i) * ST + 4 + k] = (mtt_real)P0[i][k];
        }
    }
    TEST_ASSERT_EQUAL_INT(0, mtt_polar_rdot_step(8, 4, ST, sr, rrv, xs, Ps, M, T));
    mtt_polar_rdot_update(4, sr, rrv, x, P);
    for (i = 0; i < 4; ++i) {
        TV_ASSERT_REAL((double)(100.0 * (i + 1)), xs[i]);
        TV_ASSERT_REAL((double)x[i], xs[4 + i]);
        TV_ASSERT_REAL(3.0, Ps[i * ST + i]);
        TV_ASSERT_REAL(1.0, M[i * ST + i]);
        for (k = 0; k < 4; ++k) {
            TV_ASSERT_REAL((double)P[i][k], Ps[(4 + i) * ST + 4 + k]);
            TEST_ASSERT_TRUE(Ps[i * ST + 4 + k] == MTT_R(0.0) && M[i * ST + 4 + k] == MTT_R(0.0));
        }
    }
    memcpy(xk, xs, sizeof xk);
    TEST_ASSERT_EQUAL_INT(-1, mtt_polar_rdot_step(8, 5, ST, sr, rrv, xs, Ps, M, T)); /* block beyond n */
    TEST_ASSERT_EQUAL_INT(-1, mtt_polar_rdot_step(ST + 1, 0, ST + 1, sr, rrv, xs, Ps, M, T));
    TEST_ASSERT_EQUAL_INT(-1, mtt_polar_rdot_step(8, 0, 4, sr, rrv, xs, Ps, M, T)); /* rows shorter than n */
    TEST_ASSERT_EQUAL_INT(-1, mtt_polar_rdot_step(8, 4, ST, sr, bad, xs, Ps, M, T)); /* s <= 0 */
    xs[4] = sr[0];
    xs[5] = sr[1];
    xk[4] = sr[0];
    xk[5] = sr[1];
    TEST_ASSERT_EQUAL_INT(-1, mtt_polar_rdot_step(8, 4, ST, sr, rrv, xs, Ps, M, T)); /* at the sensor */
    TEST_ASSERT_EQUAL_MEMORY(xk, xs, sizeof xs);
    x[0] = MTT_R(7.0);
    mtt_polar_rdot_update(3, sr, rrv, x, P); /* fewer than x y vx vy: nothing */
    TV_ASSERT_REAL(7.0, x[0]);
}
#undef ST

/* h(x) = u . v of a state in double. */
static double rdot_of(const double *x, const double *s)
{
    const double dx = x[0] - s[0], dy = x[1] - s[1], r = sqrt(dx * dx + dy * dy);
    return (dx * x[2] + dy * x[3]) / r;
}

static void test_range_rate_update_is_the_ekf(void)
{
    const double s[2] = {-100.0, 300.0}, x0[4] = {900.0, 1200.0, 12.0, -7.0}, rr = 4.5, var = 0.25;
    const double P0[4][4] = {{40, 5, 2, 0.5}, {5, 60, -1, 3}, {2, -1, 9, 0.4}, {0.5, 3, 0.4, 7}};
    const mtt_real sr[2] = {(mtt_real)s[0], (mtt_real)s[1]}, rrv[2] = {(mtt_real)rr, (mtt_real)var};
    mtt_real x[MTT_MAX_STATE];
    mtt_cov P;
    double H[4], A[4], S = var, K[4], xe[4], Pe[4][4];
    int i, k;
    memset(x, 0, sizeof x);
    memset(P, 0, sizeof P);
    for (i = 0; i < 4; ++i) {
        x[i] = (mtt_real)x0[i];
        for (k = 0; k < 4; ++k) {
            P[i][k] = (mtt_real)P0[i][k];
        }
    }
    /* the reference: a central-difference Jacobian and the standard form */
    for (i = 0; i < 4; ++i) {
        double xp[4], xm[4];
        memcpy(xp, x0, sizeof xp);
        memcpy(xm, x0, sizeof xm);
        xp[i] += 1e-4;
        xm[i] -= 1e-4;
        H[i] = (rdot_of(xp, s) - rdot_of(xm, s)) / 2e-4;
    }
    for (i = 0; i < 4; ++i) {
        A[i] = 0.0;
        for (k = 0; k < 4; ++k) {
            A[i] += P0[i][k] * H[k];
        }
        S += H[i] * A[i];
    }
    for (i = 0; i < 4; ++i) {
        K[i] = A[i] / S;
        xe[i] = x0[i] + K[i] * (rr - rdot_of(x0, s));
    }
    for (i = 0; i < 4; ++i) {
        for (k = 0; k < 4; ++k) {
            Pe[i][k] = P0[i][k] - A[i] * A[k] / S;
        }
    }
    mtt_polar_rdot_update(4, sr, rrv, x, P);
    for (i = 0; i < 4; ++i) {
        TEST_ASSERT_DOUBLE_WITHIN(1e-4 * (1.0 + fabs(xe[i])), xe[i], (double)x[i]);
        for (k = 0; k < 4; ++k) {
            TEST_ASSERT_DOUBLE_WITHIN(1e-4 * (1.0 + fabs(P0[i][k])), Pe[i][k], (double)P[i][k]);
        }
    }
    /* the radial velocity is pulled to the measurement: nearer than before */
    TEST_ASSERT_TRUE(fabs(rdot_of(xe, s) - rr) < 0.5 * fabs(rdot_of(x0, s) - rr));
}

static mtt_polar pol_rr(double r, double b, double rr)
{
    mtt_polar d = pol(r, b);
    d.range_rate = (mtt_real)rr;
    d.has_range_rate = 1;
    return d;
}

/* The seeded track of the range-rate tests: at (3000, 500), moving
 * radially at 20 from the sensor at (-1000, 500). */
static void seed_radial(mtt_tracker *t)
{
    const mtt_real x[4] = {MTT_R(3000.0), MTT_R(500.0), MTT_R(20.0), MTT_R(0.0)};
    mtt_real P[16];
    memset(P, 0, sizeof P);
    P[0] = P[5] = MTT_R(400.0);
    P[10] = P[15] = MTT_R(4.0);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(t, x, P, NULL));
}

/* A seeded track moving radially at 20 from the sensor at (-1000, 500):
 * a detection on it with range rate 20 is gated with a likelihood ratio
 * above its position's alone; with range rate -20 it is not gated. */
static void test_range_rate_gates_and_weighs(void)
{
    mtt_params p;
    mtt_polar d[1];
    double p_pos;
    int k;
    for (k = 0; k < 3; ++k) {
        polar_params(&p);
        p.initiate = 0;
        p.range_rate_sigma = MTT_R(0.5);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&ta, &p));
        seed_radial(&ta);
        d[0] = (k == 0) ? pol(4005.0, 0.001) : pol_rr(4005.0, 0.001, (k == 1) ? 20.0 : -20.0);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_polar(&ta, MTT_R(0.0), d, 1u));
        if (k == 0) {
            TEST_ASSERT_EQUAL_UINT16(1u, ta.tf[0].pair_count);
            p_pos = (double)ta.pairs[0].p;
        } else if (k == 1) {
            /* times 2 vmax N(0; 0, s), s = 4 + 0.25 (the velocity's along u): 300 / sqrt(2 pi 4.25) */
            TEST_ASSERT_EQUAL_UINT16(1u, ta.tf[0].pair_count);
            TEST_ASSERT_DOUBLE_WITHIN(0.01 * p_pos * 600.0 / sqrt(2.0 * 3.14159265358979 * 4.25),
                                      p_pos * 600.0 / sqrt(2.0 * 3.14159265358979 * 4.25), (double)ta.pairs[0].p);
        } else {
            TEST_ASSERT_EQUAL_UINT16(0u, ta.tf[0].pair_count);
        }
    }
}

/* A birth from two detections whose second has a range rate takes its
 * radial velocity from it: the two points say 10 along the bearing, the
 * range rate 14 with sigma 0.1. */
static void test_birth_takes_the_radial_velocity(void)
{
    mtt_params p;
    mtt_polar a = pol(4000.0, 0.0), b = pol_rr(4010.0, 0.0, 14.0);
    mtt_track_view v;
    size_t n;
    polar_params(&p);
    p.sensor_xy[0] = MTT_R(0.0);
    p.sensor_xy[1] = MTT_R(0.0);
    p.range_rate_sigma = MTT_R(0.1);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&ta, &p));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_polar(&ta, MTT_R(0.0), &a, 1u));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_polar(&ta, MTT_R(1.0), &b, 1u));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&ta, &n));
    TEST_ASSERT_EQUAL_UINT(1u, (unsigned)n);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&ta, 0u, &v));
    /* the two-point velocity variance (100 + 100 + ...) against 0.01: the range rate's */
    TEST_ASSERT_DOUBLE_WITHIN(0.05, 14.0, (double)v.x[2]);
    TEST_ASSERT_DOUBLE_WITHIN(0.5, 0.0, (double)v.x[3]);
    TEST_ASSERT_TRUE((double)v.P[2][2] < 0.02);
}

/* Scan k of the scene of test_tracks_a_target_across_ranges into in, with
 * (with_rr) the target's range rate (sigma 0.5) on its detection and an
 * arbitrary one on clutter; e the unit vector from the sensor to the
 * target.  Returns the count. */
static size_t rr_frame(int k, int with_rr, mtt_polar in[8], double e[2])
{
    size_t i, n = (size_t)scene_n[k];
    const double dx = truth[k][0] + 1000.0, dy = truth[k][1] - 500.0, r = sqrt(dx * dx + dy * dy);
    e[0] = dx / r;
    e[1] = dy / r;
    for (i = 0; i < n; ++i) {
        in[i] = scene[k][i];
        if (with_rr) {
            const int target = i == 0 && fabs((double)in[i].range - r) < 60.0;
            in[i].range_rate = (mtt_real)(target ? (dx * 120.0 - dy * 20.0) / r + 0.5 * gauss01()
                                                 : -150.0 + 300.0 * unif());
            in[i].has_range_rate = 1;
        }
    }
    return n;
}

/* That scene: the radial component of the track's velocity error is
 * smaller with the range rates than without; imm: the IMM from max_accel,
 * whose models each weigh the range rate against their own prediction. */
static double velocity_rms(int with_rr, int imm)
{
    mtt_params p;
    double se = 0.0;
    int k, counted = 0;
    polar_params(&p);
    p.range_rate_sigma = MTT_R(0.5);
    if (imm) {
        p.process_psd = MTT_R(0.0);
        p.max_accel = MTT_R(5.0);
        p.motion = MTT_MOTION_IMM;
    }
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&ta, &p));
    rng_state = 4242u;
    for (k = 0; k < SCANS; ++k) {
        mtt_polar in[8];
        double e[2];
        size_t i, n = rr_frame(k, with_rr, in, e), cnt;
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_polar(&ta, (mtt_real)k, in, n));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&ta, &cnt));
        for (i = 0; i < cnt && k >= 10; ++i) {
            mtt_track_view v;
            TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&ta, i, &v));
            if (v.confirmed && fabs((double)v.x[0] - truth[k][0]) < 300.0) {
                /* the radial component of the velocity error */
                se += pow(((double)v.x[2] - 120.0) * e[0] + ((double)v.x[3] + 20.0) * e[1], 2);
                ++counted;
            }
        }
    }
    TEST_ASSERT_TRUE(counted >= SCANS - 12);
    return sqrt(se / counted);
}

static void test_range_rate_lowers_the_velocity_error(void)
{
    double without, with_rr;
    make_scene();
    without = velocity_rms(0, 0);
    with_rr = velocity_rms(1, 0);
    TEST_ASSERT_TRUE(with_rr > 0.05);        /* a real error */
    TEST_ASSERT_TRUE(with_rr < 0.5 * without); /* 0.21 against 0.52 m/s in float */
#if MTT_WITH_IMM
    without = velocity_rms(0, 1);
    with_rr = velocity_rms(1, 1);
    TEST_ASSERT_TRUE(with_rr > 0.05);
    TEST_ASSERT_TRUE(with_rr < 0.5 * without);
#endif
}

/* The IMM (motion imm) takes polar detections
 * with range rates: the target of the range-rate scene is tracked with one
 * identity by an IMM track in lm-ihpda, ihpda, lm-ipda and ipda. */
static void test_imm_takes_polar_detections(void)
{
#if MTT_WITH_IMM
    static const mtt_assoc modes[] = {MTT_ASSOC_LM_IHPDA, MTT_ASSOC_IHPDA, MTT_ASSOC_LM_IPDA, MTT_ASSOC_IPDA};
    size_t m;
    make_scene();
    for (m = 0; m < sizeof modes / sizeof modes[0]; ++m) {
        mtt_params p;
        int k;
        uint32_t id = 0xFFFFFFFFu, ids = 0;
        uint8_t models = 0;
        polar_params(&p);
        p.association = modes[m];
        p.process_psd = MTT_R(0.0);
        p.max_accel = MTT_R(5.0); /* the IMM from max_accel (ALGORITHMS.md 2.2) */
        p.motion = MTT_MOTION_IMM;
        p.range_rate_sigma = MTT_R(0.5);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&ta, &p));
        rng_state = 4242u;
        for (k = 0; k < SCANS; ++k) {
            mtt_polar in[8];
            double e[2];
            size_t i, n = rr_frame(k, 1, in, e), cnt;
            TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_polar(&ta, (mtt_real)k, in, n));
            TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&ta, &cnt));
            for (i = 0; i < cnt; ++i) {
                mtt_track_view v;
                TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&ta, i, &v));
                if (v.confirmed && fabs((double)v.x[0] - truth[k][0]) < 100.0 &&
                    fabs((double)v.x[1] - truth[k][1]) < 100.0) {
                    models = v.n_models;
                    ids += v.id != id;
                    id = v.id;
                }
            }
        }
        TEST_ASSERT_EQUAL_UINT32(1u, ids);
        TEST_ASSERT_TRUE(models >= 2u); /* an IMM track */
    }
#else
    TEST_IGNORE_MESSAGE("no IMM in this build");
#endif
}

#if MTT_WITH_SPLIT
/* tools/track/tests/polar_split.json's settings, range_rate_sigma 0.1,
 * split on or off. */
static void split_polar_params(mtt_params *p, int split)
{
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(p));
    p->association = MTT_ASSOC_LM_IHPDA;
    p->measurement = MTT_MEASUREMENT_POLAR;
    p->sensor_xy[0] = MTT_R(0.0);
    p->sensor_xy[1] = MTT_R(0.0);
    p->meas_sigma[0] = MTT_R(0.3);
    p->meas_sigma[1] = MTT_R(0.003);
    p->clutter_density = MTT_R(0.01);
    p->vmax = MTT_R(5.0);
    p->motion = MTT_MOTION_IMM;
    p->imm_n_models = 2u;
    p->imm_model[0] = MTT_MODEL_CV;
    p->imm_model[1] = MTT_MODEL_CA;
    p->imm_psd[0] = MTT_R(1.0);
    p->imm_psd[1] = MTT_R(400.0);
    p->imm_transition[0][0] = MTT_R(0.95);
    p->imm_transition[0][1] = MTT_R(0.05);
    p->imm_transition[1][0] = MTT_R(0.1);
    p->imm_transition[1][1] = MTT_R(0.9);
    p->imm_initial[0] = MTT_R(0.9);
    p->imm_initial[1] = MTT_R(0.1);
    p->split = split;
    p->split_dv = MTT_R(1.0);
    p->range_rate_sigma = MTT_R(0.1);
}
#endif

/* The split modes take polar detections with range rates (ALGORITHMS.md
 * §3.2, §14.3): polar_split.det.csv's scene (tools/track/tests), a target
 * at (100 + k, 50) seen from (0, 0) that splits from scan 13, its child at
 * (100 + k, 50 + (k - 12)), here with each detection's range rate u . v
 * (sigma 0.1): every scan is taken, one child splits off its parent, and
 * at the end each is within 2 of its target's position and 1 of its
 * velocity ((1, 0) and (1, 1): the last scan's estimates are about 0.5
 * off, the noise of sigma 0.3 in range and 0.33 across at 110). */
#define SPLIT_SCANS 30
static void test_split_takes_range_rates(void)
{
#if MTT_WITH_SPLIT
    mtt_params p;
    mtt_stats st;
    size_t cnt, i;
    int k, children = 0, parents = 0;
    split_polar_params(&p, 1);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&ta, &p));
    rng_state = 3u;
    for (k = 0; k < SPLIT_SCANS; ++k) {
        mtt_polar in[2];
        size_t n = 0;
        int t;
        for (t = 0; t < 2; ++t) {
            const double x = 100.0 + k, y = 50.0 + ((t == 1) ? (double)(k - 12) : 0.0), vy = (t == 1) ? 1.0 : 0.0;
            const double r = hypot(x, y);
            if (t == 1 && k < 13) {
                continue;
            }
            in[n] = pol(r + 0.3 * gauss01(), atan2(y, x) + 0.003 * gauss01());
            in[n].has_range_rate = 1;
            in[n].range_rate = (mtt_real)((x * 1.0 + y * vy) / r + 0.1 * gauss01());
            ++n;
        }
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_polar(&ta, (mtt_real)k, in, n));
    }
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&ta, &st));
    TEST_ASSERT_EQUAL_UINT32(1u, st.total.splits);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&ta, &cnt));
    for (i = 0; i < cnt; ++i) {
        mtt_track_view v;
        const double kx = 100.0 + (SPLIT_SCANS - 1);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&ta, i, &v));
        if (!v.confirmed) {
            continue;
        }
        if (v.parent != MTT_NO_PARENT) {
            ++children;
            TEST_ASSERT_TRUE(hypot((double)v.x[0] - kx, (double)v.x[1] - (50.0 + SPLIT_SCANS - 13)) < 2.0);
            TEST_ASSERT_TRUE(hypot((double)v.x[2] - 1.0, (double)v.x[3] - 1.0) < 1.0);
        } else {
            ++parents;
            TEST_ASSERT_TRUE(hypot((double)v.x[0] - kx, (double)v.x[1] - 50.0) < 2.0);
            TEST_ASSERT_TRUE(hypot((double)v.x[2] - 1.0, (double)v.x[3]) < 1.0);
        }
    }
    TEST_ASSERT_EQUAL_INT(1, children);
    TEST_ASSERT_EQUAL_INT(1, parents);
#else
    TEST_IGNORE_MESSAGE("no split in this build");
#endif
}

/* Under split a detection with a range rate in a confirmed track's
 * position gate is left to its split modes even where its range rate is
 * outside the track's range-rate gate (ALGORITHMS.md §14.3): a seeded
 * track at (100, 50) moving (1, 0), each scan its detection and one 0.7
 * from it whose range rate is 10 (100 sigma) off: without split those
 * start a track (two-point initiation), with split none starts. */
static void test_split_holds_a_gated_position_with_another_range_rate(void)
{
#if MTT_WITH_SPLIT
    const mtt_real x0[4] = {MTT_R(100.0), MTT_R(50.0), MTT_R(1.0), MTT_R(0.0)};
    const mtt_real P0[16] = {MTT_R(0.1), 0, 0, 0, 0, MTT_R(0.1), 0, 0, 0, 0, MTT_R(0.01), 0, 0, 0, 0, MTT_R(0.01)};
    int split;
    for (split = 0; split <= 1; ++split) {
        mtt_params p;
        mtt_stats st;
        uint32_t id;
        int k;
        split_polar_params(&p, split);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&ta, &p));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&ta, x0, P0, &id));
        for (k = 0; k < 6; ++k) {
            const double x = 100.0 + k, y = 50.0, r = hypot(x, y);
            const double x2 = x + 0.5, y2 = y + 0.5, r2 = hypot(x2, y2);
            mtt_polar in[2];
            in[0] = pol(r, atan2(y, x));
            in[0].has_range_rate = 1;
            in[0].range_rate = (mtt_real)(x / r);
            in[1] = pol(r2, atan2(y2, x2));
            in[1].has_range_rate = 1;
            in[1].range_rate = (mtt_real)(x2 / r2 + 10.0);
            TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_polar(&ta, (mtt_real)k, in, 2u));
        }
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&ta, &st));
        TEST_ASSERT_EQUAL_UINT32(0u, st.total.splits);
        if (split) {
            TEST_ASSERT_EQUAL_UINT32(0u, st.total.births);
        } else {
            TEST_ASSERT_TRUE(st.total.births >= 1u);
        }
    }
#else
    TEST_IGNORE_MESSAGE("no split in this build");
#endif
}

/* Under the IMM each model weighs the range rate against its own
 * prediction (ALGORITHMS.md §3.2, §14.2): a seeded track moving radially
 * at 20 from the sensor, one frame later a detection on its predicted
 * position whose range rate is 5 off (2.4 sigma of the steady model's
 * predicted range rate, 0.9 of the manoeuvring one's) raises the
 * manoeuvring model's probability above what a matching range rate
 * leaves.  (Before 834da07 the models' likelihoods left the range rate out
 * and both gave the same probabilities.) */
static double imm_mu_after(double rr)
{
#if MTT_WITH_IMM
    mtt_params p;
    mtt_polar d[1];
    mtt_track_view v;
    size_t cnt;
    polar_params(&p);
    p.association = MTT_ASSOC_LM_IPDA;
    p.initiate = 0;
    p.process_psd = MTT_R(0.0);
    p.max_accel = MTT_R(5.0); /* models (0.5)^2 and 5^2 per unit time */
    p.motion = MTT_MOTION_IMM;
    p.range_rate_sigma = MTT_R(0.5);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&ta, &p));
    seed_radial(&ta);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_polar(&ta, MTT_R(0.0), d, 0u));
    d[0] = pol_rr(4020.0, 0.0, rr); /* the predicted position (3020, 500) */
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_polar(&ta, MTT_R(1.0), d, 1u));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&ta, &cnt));
    TEST_ASSERT_EQUAL_UINT32(1u, (uint32_t)cnt);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&ta, 0, &v));
    TEST_ASSERT_EQUAL_UINT8(2u, v.n_models);
    return (double)v.mu[1];
#else
    (void)rr;
    return 0.0;
#endif
}

static void test_imm_models_weigh_the_range_rate(void)
{
#if MTT_WITH_IMM
    const double match = imm_mu_after(20.0), off = imm_mu_after(25.0);
    TEST_ASSERT_TRUE(match > 0.0 && off < 1.0);
    TEST_ASSERT_TRUE(off > 5.0 * match); /* 0.0068 against 0.0006 in float and double */
    /* range rate -20: outside every model's gate, so not gated at all */
    (void)imm_mu_after(-20.0);
    TEST_ASSERT_EQUAL_UINT16(0u, ta.tf[0].pair_count);
#else
    TEST_IGNORE_MESSAGE("no IMM in this build");
#endif
}

/* Detections on one position that differ only in their range rate (none,
 * 1, 2 m/s), and beyond MTT_MAX_MEAS a frame's weakest dropped: any input
 * order gives the same tracks and identities (the canonical order takes
 * the range rate after the position; the cap ranks polar detections by
 * amplitude). */
static void polar_order_run(mtt_tracker *t, int reverse, mtt_track_view *out, size_t *n_out, uint32_t *dropped)
{
    static mtt_polar in[MTT_MAX_MEAS + 10];
    mtt_params p;
    mtt_stats st;
    const size_t n = sizeof in / sizeof in[0];
    size_t i, cnt;
    int k;
    polar_params(&p);
    p.range_rate_sigma = MTT_R(0.5);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(t, &p));
    for (k = 0; k < 6; ++k) {
        for (i = 0; i < n; ++i) {
            const size_t s = reverse ? n - 1u - i : i;
            in[s] = pol(2000.0 + 30.0 * (double)k + (double)(i / 3u) * 40.0, 0.1 + 0.001 * (double)(i / 3u));
            in[s].amplitude = (mtt_real)((i / 3u) % 7u); /* one per position: the range rate breaks the tie */
            in[s].has_amplitude = 1;
            in[s].has_range_rate = (i % 3u) != 0u;
            in[s].range_rate = (mtt_real)(i % 3u);
        }
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_polar(t, (mtt_real)k, in, n));
    }
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(t, &st));
    *dropped = st.total.meas_dropped;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(t, &cnt));
    TEST_ASSERT_TRUE(cnt > 0u && cnt <= MTT_MAX_TRACKS);
    for (i = 0; i < cnt && i < 16u; ++i) {
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(t, i, &out[i]));
    }
    *n_out = cnt;
}

static void test_polar_order_and_cap(void)
{
    static mtt_track_view a[16], b[16];
    size_t na = 0, nb = 0, i;
    uint32_t da = 0, db = 0;
    polar_order_run(&ta, 0, a, &na, &da);
    polar_order_run(&tb, 1, b, &nb, &db);
    TEST_ASSERT_EQUAL_UINT32(6u * 10u, da); /* 10 a frame beyond MTT_MAX_MEAS */
    TEST_ASSERT_EQUAL_UINT32(da, db);
    TEST_ASSERT_EQUAL_UINT32((uint32_t)na, (uint32_t)nb);
    for (i = 0; i < na && i < 16u; ++i) {
        TEST_ASSERT_EQUAL_UINT32(a[i].id, b[i].id);
        TEST_ASSERT_EQUAL_MEMORY(a[i].x, b[i].x, sizeof a[i].x);
    }
}

static void test_range_rate_needs_its_sigma(void)
{
    mtt_params p;
    const mtt_polar d = pol_rr(100.0, 0.1, 3.0);
    mtt_polar bad = pol_rr(100.0, 0.1, 0.0);
    mtt_stats st;
    polar_params(&p);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&ta, &p));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_tracker_step_polar(&ta, (mtt_real)0, &d, 1u));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&ta, &st));
    TEST_ASSERT_EQUAL_UINT32(0u, st.total.frames); /* nothing changed */
    p.range_rate_sigma = MTT_R(1.0);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&ta, &p));
    bad.range_rate = (mtt_real)NAN;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_polar(&ta, MTT_R(0.0), &bad, 1u));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&ta, &st));
    TEST_ASSERT_EQUAL_UINT32(1u, st.last.meas_bad);
}

#else /* MTT_WITH_MEAS_COV 0 */

static void test_build_without_meas_cov_refuses_polar(void)
{
    mtt_params p;
    const char *bad = NULL;
    mtt_polar d;
    mtt_meas m;
    mtt_meas_cov c;
    mtt_real sig[2], sensor[2];
    memset(&d, 0, sizeof d);
    memset(sig, 0, sizeof sig);
    memset(sensor, 0, sizeof sensor);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.measurement = MTT_MEASUREMENT_POLAR;
    TEST_ASSERT_EQUAL_INT(MTT_ERR_UNSUPPORTED, mtt_params_check(&p, &bad));
    TEST_ASSERT_EQUAL_STRING("measurement", bad);
    TEST_ASSERT_EQUAL_INT(MTT_ERR_UNSUPPORTED, mtt_tracker_init(&ta, &p));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_UNSUPPORTED, mtt_polar_to_cartesian(sig, sensor, &d, &m, &c));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_polar_to_cartesian(NULL, sensor, &d, &m, &c));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_tracker_step_polar(NULL, (mtt_real)0, &d, 1u));
#ifndef MTT_REAL_FIXED
    /* a Cartesian tracker of this build refuses polar detections (the
     * fixed build's defaults need a declared clutter density first) */
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&ta, &p));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_UNSUPPORTED, mtt_tracker_step_polar(&ta, (mtt_real)0, &d, 1u));
#endif
}

#endif

int main(void)
{
    UNITY_BEGIN();
#if MTT_WITH_MEAS_COV
    RUN_TEST(test_conversion_is_the_closed_form);
    RUN_TEST(test_monte_carlo_bias_and_covariance);
    RUN_TEST(test_clutter_density_has_the_jacobian);
    RUN_TEST(test_tracks_a_target_across_ranges_in_any_order);
    RUN_TEST(test_bad_polar_detections_are_counted);
    RUN_TEST(test_refusals);
    RUN_TEST(test_range_rate_update_is_the_ekf);
    RUN_TEST(test_range_rate_step_on_a_block);
    RUN_TEST(test_range_rate_gates_and_weighs);
    RUN_TEST(test_birth_takes_the_radial_velocity);
    RUN_TEST(test_range_rate_lowers_the_velocity_error);
    RUN_TEST(test_imm_takes_polar_detections);
    RUN_TEST(test_imm_models_weigh_the_range_rate);
    RUN_TEST(test_split_takes_range_rates);
    RUN_TEST(test_split_holds_a_gated_position_with_another_range_rate);
    RUN_TEST(test_polar_order_and_cap);
    RUN_TEST(test_range_rate_needs_its_sigma);
#else
    RUN_TEST(test_build_without_meas_cov_refuses_polar);
#endif
    return UNITY_END();
}
