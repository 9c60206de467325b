/* SPDX-License-Identifier: BSD-3-Clause */
/* test_fixed_radar.c - the fixed-point build at a radar's scale
 * (configs/firmware_fixed_radar.h, preset host-fixed-radar;
 * docs/FIXED_POINT.md §3, "Scales"): metres to +-500 km, variances from
 * (1 m)^2 to (10 km)^2, a clutter density of 1.1e-9 per m^2, and the host's
 * default bounds (a scan of 250 detections and 100 targets).  Built only
 * with MTT_FIXED_SCALE radar: the vectors are in metres and seconds. */
#include <math.h>
#include <string.h>

#include "mtt_internal.h"
#include "sim.h"
#include "unity.h"

#if !defined(MTT_REAL_FIXED) || MTT_FX_POS_FRAC != 10 || MTT_FX_VAR_FRAC != 4 ||                  \
    MTT_FX_DENS_FRAC != 42 || MTT_FX_GATE_FRAC != 24
#error "test_fixed_radar.c is the radar scale's test (configs/firmware_fixed_radar.h)"
#endif

#define T_SCAN 4.0     /* s: the time unit T0 is the file's, 1 s */
#define SIGMA 50.0     /* m */
#define DENSITY 1.111111111111111e-9 /* per m^2: 100 false detections over 300 x 300 km */

static mtt_tracker trk;

void setUp(void) {}
void tearDown(void) {}

/* A deterministic standard normal (Box-Muller on a 64-bit LCG). */
static uint64_t rng = 12345u;
static double unif(void)
{
    rng = rng * 6364136223846793005ull + 1442695040888963407ull;
    return ((double)(rng >> 11) + 0.5) / 9007199254740992.0;
}
static double gauss(void)
{
    return sqrt(-2.0 * log(unif())) * cos(6.283185307179586 * unif());
}

static mtt_real pos(double v)
{
    mtt_real r = 0;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_fx_from_double(v, MTT_FX_POS_FRAC, &r));
    return r;
}
static double pos_d(mtt_real r)
{
    return mtt_fx_to_double(r, MTT_FX_POS_FRAC);
}

static void radar_params(mtt_params *p, mtt_assoc mode)
{
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(p));
    p->association = mode;
    p->motion = MTT_MOTION_CV;
    p->process_psd = MTT_VAR(5.0);
    p->meas_sigma[0] = MTT_POS(SIGMA);
    p->meas_sigma[1] = MTT_POS(SIGMA);
    p->pd = MTT_P(0.9);
    p->clutter_density = MTT_DENS(DENSITY);
    p->vmax = MTT_POS(350.0);
}

/* The declared ranges (mtt/real.h): +-1048576 m on a 1/1024 m LSB. */
static void test_ranges_hold_the_radar(void)
{
    double v;
    mtt_real r;
    TEST_ASSERT_TRUE(MTT_POS(500000.0) < MTT_FX_POS_LIMIT && -MTT_POS(500000.0) > -MTT_FX_POS_LIMIT);
    TEST_ASSERT_EQUAL_DOUBLE(1048576.0, pos_d(MTT_FX_POS_LIMIT));
    TEST_ASSERT_EQUAL_DOUBLE(499999.9990234375, pos_d(pos(499999.999)));
    /* velocity per frame: 1000 m/s in one 4-s frame */
    TEST_ASSERT_TRUE(MTT_POS(4000.0) < MTT_FX_POS_LIMIT);
    /* variances at the API: (1 m)^2 is 16 units, (10 km)^2 round-trips exactly */
    TEST_ASSERT_EQUAL_INT32(16, MTT_VAR(1.0));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_fx_from_double(1e8, MTT_FX_VAR_FRAC, &r));
    TEST_ASSERT_EQUAL_DOUBLE(1e8, mtt_fx_to_double(r, MTT_FX_VAR_FRAC));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_fx_from_double(1.3e8, MTT_FX_VAR_FRAC, &r));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_RANGE, mtt_fx_from_double(1.4e8, MTT_FX_VAR_FRAC, &r));
    /* sigma 50 m squared by the tracker: 2500 m^2 exactly */
    TEST_ASSERT_EQUAL_INT32(MTT_VAR(2500.0), MTT_VAR_OF(MTT_POS(SIGMA)));
    /* the clutter density: 1.1e-9 per m^2 on 12 bits, within 2^-13 relative */
    TEST_ASSERT_TRUE(MTT_DENS(DENSITY) >= 4096);
    v = mtt_fx_to_double(MTT_DENS(DENSITY), MTT_FX_DENS_FRAC);
    TEST_ASSERT_DOUBLE_WITHIN(DENSITY * ldexp(1.0, -13), DENSITY, v);
    /* and 1e-12 .. 4e-4 per m^2 fit */
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_fx_from_double(4e-4, MTT_FX_DENS_FRAC, &r));
    TEST_ASSERT_TRUE(MTT_DENS(1e-12) >= 4);
    /* bounds: a scan of 250 detections and 100 targets */
    TEST_ASSERT_TRUE(MTT_MAX_MEAS >= 250 && MTT_MAX_TRACKS >= 100);
}

/* lambda V_G of a radar gate (sigma 50 m, gamma 9.21: about 1.3e-4
 * expected false detections) on more than 11 bits of its format, where
 * the default Q16 would leave it 9 units. */
static void test_gate_area_resolved(void)
{
    int32_t S[MTT_SYM_SLOTS], det;
    double want, got;
    const mtt_d2 gamma = MTT_D2(9.21034);
    /* S = diag(5000, 5000) m^2 as a block: mantissas 5000 2^16 at exponent -16 */
    S[0] = 5000 * 65536;
    S[1] = 0;
    S[2] = 5000 * 65536;
    MTT_SYM_E(S) = -16;
    /* det S = 2.5e7 m^4 as a mantissa at 2 e(S) + 28 */
    det = (int32_t)llround(ldexp(2.5e7, -(2 * MTT_SYM_E(S) + 28)));
    want = 9.21034 * 3.141592653589793 * 5000.0 * mtt_fx_to_double(MTT_DENS(DENSITY), MTT_FX_DENS_FRAC);
    got = mtt_fx_to_double(mtt_fx_gate_area(gamma, det, S, MTT_DENS(DENSITY)), MTT_FX_GATE_FRAC);
    TEST_ASSERT_TRUE(want * ldexp(1.0, MTT_FX_GATE_FRAC) > 2048.0);
    TEST_ASSERT_DOUBLE_WITHIN(want * 1e-3, want, got);
}

/* A seeded track holds (10 km)^2 and (1 m)^2 through the block exponent:
 * the view gives both back (the view's variance format). */
static void test_seed_variances_round_trip(void)
{
    mtt_params p;
    mtt_track_view v;
    mtt_real x[4], P[16];
    uint32_t id;
    memset(P, 0, sizeof P);
    radar_params(&p, MTT_ASSOC_LM_IHPDA);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    x[0] = pos(400000.0);
    x[1] = pos(-300000.0);
    x[2] = pos(800.0); /* 200 m/s in one 4-s frame */
    x[3] = pos(0.0);
    P[0] = MTT_VAR(1e8); /* row-major: the diagonal at 0, 5, 10, 15 */
    P[5] = MTT_VAR(1e8);
    P[10] = MTT_VAR(1.0);
    P[15] = MTT_VAR(1.0);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&trk, x, P, &id));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, 0, &v));
    TEST_ASSERT_EQUAL_DOUBLE(400000.0, pos_d(v.x[0]));
    TEST_ASSERT_EQUAL_DOUBLE(-300000.0, pos_d(v.x[1]));
    TEST_ASSERT_DOUBLE_WITHIN(1e8 * ldexp(1.0, -26), 1e8, mtt_fx_to_double(v.P[0][0], MTT_FX_VAR_FRAC));
    /* (1 m)^2 beside (10 km)^2 in one block: 2^27 / 1e8 of a unit below the top, a few LSB */
    TEST_ASSERT_DOUBLE_WITHIN(0.5, 1.0, mtt_fx_to_double(v.P[2][2], MTT_FX_VAR_FRAC));
}

/* One target at 400 km, 200 m/s, sigma 50 m, PD 1, one frame per 4 s:
 * confirmed and tracked to a few sigma; nothing skipped or out of range.
 * With a detection at 1100 km in every scan: counted out of range. */
static void test_target_at_400_km_tracked(void)
{
    mtt_params p;
    mtt_stats st;
    mtt_track_view v;
    mtt_meas m[2];
    size_t n = 0;
    int k;
    double tx = 400000.0, ty = -300000.0;
    radar_params(&p, MTT_ASSOC_LM_IHPDA);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    for (k = 0; k < 30; ++k) {
        tx += 200.0 * T_SCAN;
        ty += 50.0 * T_SCAN;
        m[0] = sim_meas(pos(tx + SIGMA * gauss()), pos(ty + SIGMA * gauss()), MTT_ZERO, 0);
        m[1] = sim_meas(MTT_FX_POS_LIMIT + MTT_POS(51200.0), pos(0.0), MTT_ZERO, 0);
        TEST_ASSERT_EQUAL_INT(MTT_OK,
                              mtt_tracker_step(&trk, MTT_TIME((double)k * T_SCAN), m, 2));
    }
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&trk, &st));
    TEST_ASSERT_EQUAL_UINT32(0u, st.total.meas_bad);
    TEST_ASSERT_EQUAL_UINT32(30u, st.total.meas_out_of_range);
    TEST_ASSERT_EQUAL_UINT32(0u, st.total.numeric_deletions);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&trk, &n));
    TEST_ASSERT_EQUAL_UINT(1u, n);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, 0, &v));
    TEST_ASSERT_TRUE(v.confirmed);
    TEST_ASSERT_DOUBLE_WITHIN(3.0 * SIGMA, tx, pos_d(v.x[0]));
    TEST_ASSERT_DOUBLE_WITHIN(3.0 * SIGMA, ty, pos_d(v.x[1]));
    TEST_ASSERT_DOUBLE_WITHIN(20.0, 200.0, pos_d(v.x[2]));
    TEST_ASSERT_DOUBLE_WITHIN(20.0, 50.0, pos_d(v.x[3]));
    /* the view's position variance: between (1 m)^2 and sigma^2 */
    TEST_ASSERT_TRUE(v.P[0][0] > MTT_VAR(1.0) && v.P[0][0] < MTT_VAR(SIGMA * SIGMA));
}

/* 100 targets on a 20-km grid out to +-495 km, plus 150 false detections
 * over the +-500 km box (density 1.5e-10 per m^2): a scan of 250, all
 * kept, all 100 confirmed after 12 frames. */
static void test_full_scan_fits(void)
{
    static mtt_meas m[250];
    mtt_params p;
    mtt_stats st;
    size_t n = 0, i, conf = 0;
    int k, t;
    radar_params(&p, MTT_ASSOC_LM_IHPDA);
    p.pd = MTT_P(0.95);
    p.clutter_density = MTT_DENS(1.5e-10);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    for (k = 0; k < 12; ++k) {
        for (t = 0; t < 100; ++t) {
            const double x0 = -495000.0 + 110000.0 * (double)(t % 10);
            const double y0 = -495000.0 + 110000.0 * (double)(t / 10);
            m[t] = sim_meas(pos(x0 + 150.0 * T_SCAN * k + SIGMA * gauss()),
                            pos(y0 - 100.0 * T_SCAN * k + SIGMA * gauss()), MTT_ZERO, 0);
        }
        for (t = 100; t < 250; ++t) {
            m[t] = sim_meas(pos(-500000.0 + 1e6 * unif()), pos(-500000.0 + 1e6 * unif()), MTT_ZERO, 0);
        }
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_TIME((double)k * T_SCAN), m, 250));
    }
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&trk, &st));
    TEST_ASSERT_EQUAL_UINT32(3000u, st.total.meas_in);
    TEST_ASSERT_EQUAL_UINT32(0u, st.total.meas_dropped + st.total.meas_bad + st.total.meas_out_of_range);
    TEST_ASSERT_EQUAL_UINT32(0u, st.total.pairs_dropped + st.total.births_dropped);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&trk, &n));
    for (i = 0; i < n; ++i) {
        mtt_track_view v;
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, i, &v));
        conf += v.confirmed ? 1u : 0u;
    }
    TEST_ASSERT_EQUAL_UINT(100u, conf);
}

/* The motion from max_accel (ALGORITHMS.md §2.2) at this scale: a in
 * Q10 m/s^2, a^2 in the variance format Q4 m^2/s^3 (MTT_VAR_OF), q = a^2 dT
 * per frame (dT in Q16 s).  Against the double a^2 dT, the tolerance from
 * the formats: a's rounding (2^-11) times 2a, a^2's rounding (2^-5), both
 * times dT, plus dT's rounding (2^-17) times a^2 and q's rounding (2^-5).
 * An a whose square leaves [2^-5, 2^27) m^2/s^3 is refused, naming it. */
static void test_motion_from_max_accel(void)
{
    const double a = 9.81, dt = 4.7;
    const double tol1 = 2.0 * a * 0x1p-11 + 0x1p-5;
    mtt_params p, r;
    mtt_meas m;
    const char *bad = NULL;
    radar_params(&p, MTT_ASSOC_LM_IHPDA);
    p.process_psd = 0;
    p.max_accel = pos(a);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_resolve(&p, &r));
    TEST_ASSERT_EQUAL_INT(MTT_MOTION_CV, r.motion);
    TEST_ASSERT_DOUBLE_WITHIN(tol1, a * a, mtt_fx_to_double(r.process_psd, MTT_FX_VAR_FRAC));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    m = sim_meas(pos(1000.0), pos(2000.0), MTT_ZERO, 0);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_TIME(100.0), &m, 1));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_TIME(100.0 + dt), &m, 1));
    TEST_ASSERT_DOUBLE_WITHIN(dt * tol1 + a * a * 0x1p-17 + 0x1p-5, a * a * dt,
                              mtt_fx_to_double(trk.par.process_psd, MTT_FX_VAR_FRAC));
    p.max_accel = pos(12000.0); /* a^2 = 1.44e8 > 1.34e8 */
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_check(&p, &bad));
    TEST_ASSERT_EQUAL_STRING("max_accel", bad);
    p.max_accel = pos(0.1); /* a^2 = 0.01: 0.16 units, rounds to 0 */
    bad = NULL;
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_check(&p, &bad));
    TEST_ASSERT_EQUAL_STRING("max_accel", bad);
    p.max_accel = pos(11000.0); /* a^2 = 1.21e8 fits */
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_check(&p, &bad));
}

#if MTT_WITH_IMM
/* The derived IMM (ALGORITHMS.md §2.2) in fixed point against its formulas
 * in double, for a as the position format holds it: a steady cv model with
 * (a/10)^2 dT and a manoeuvring one with a^2 dT (one rounding each: 1/2
 * unit of Q4, plus a/10's rounding, 2^-10 relative at most), rates 1/tau = a / vmax out of the manoeuvre and a
 * tenth of it in, Pi(dT) = the two-state chain's closed form (exp within
 * 8 units of Q30, the quotient 1/2 unit). */
static void pi_expect(double a, double vmax, double dt, double Pi[2][2])
{
    const double l10 = a / vmax, l01 = 0.1 * l10, sr = l01 + l10, g = 1.0 - exp(-sr * dt);
    Pi[0][1] = l01 / sr * g;
    Pi[0][0] = 1.0 - Pi[0][1];
    Pi[1][0] = l10 / sr * g;
    Pi[1][1] = 1.0 - Pi[1][0];
}

static void test_imm_from_max_accel(void)
{
    const double a = pos_d(pos(9.81)), dt = 4.7, ulp = 0x1p-30 * 16.0; /* a as the build holds it */
    const double lv[2] = {0.01 * a * a, a * a};
    double Pi[2][2];
    mtt_params p, r;
    mtt_meas m;
    int i, j;
    radar_params(&p, MTT_ASSOC_LM_IHPDA);
    p.process_psd = 0;
    p.motion = MTT_MOTION_AUTO;
    p.max_accel = pos(a);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_resolve(&p, &r));
    TEST_ASSERT_EQUAL_INT(MTT_MOTION_IMM, r.motion);
    TEST_ASSERT_EQUAL_UINT8(2u, r.imm_n_models);
    pi_expect(a, 350.0, 1.0, Pi);
    for (j = 0; j < 2; ++j) {
        TEST_ASSERT_EQUAL_INT(MTT_MODEL_CV, r.imm_model[j]);
        TEST_ASSERT_DOUBLE_WITHIN(lv[j] * 0x1p-10 + 0x1p-5, lv[j], mtt_fx_to_double(r.imm_psd[j], MTT_FX_VAR_FRAC));
        for (i = 0; i < 2; ++i) {
            TEST_ASSERT_DOUBLE_WITHIN(1e-6 + ulp, Pi[i][j], mtt_fx_to_double(r.imm_transition[i][j], MTT_FX_PROB_FRAC));
        }
    }
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    m = sim_meas(pos(1000.0), pos(2000.0), MTT_ZERO, 0);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_TIME(100.0), &m, 1));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_TIME(100.0 + dt), &m, 1));
    pi_expect(a, 350.0, mtt_fx_to_double(MTT_TIME(dt), MTT_FX_T_FRAC), Pi);
    for (j = 0; j < 2; ++j) {
        TEST_ASSERT_DOUBLE_WITHIN(lv[j] * dt * 0x1p-10 + 0x1p-4, lv[j] * dt,
                                  mtt_fx_to_double(trk.par.imm_psd[j], MTT_FX_VAR_FRAC));
        for (i = 0; i < 2; ++i) {
            TEST_ASSERT_DOUBLE_WITHIN(1e-6 + ulp, Pi[i][j],
                                      mtt_fx_to_double(trk.par.imm_transition[i][j], MTT_FX_PROB_FRAC));
        }
    }
    /* a steady level below the format's unit is one unit ((0.25/10)^2 = 6.25e-4 m^2: 0.01 units) */
    p.max_accel = pos(0.25);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_resolve(&p, &r));
    TEST_ASSERT_EQUAL_INT32(1, r.imm_psd[0]);
    /* ca and ct are float only */
    radar_params(&p, MTT_ASSOC_LM_IHPDA);
    p.motion = MTT_MOTION_IMM;
    p.imm_model[1] = MTT_MODEL_CA;
    {
        const char *bad = NULL;
        TEST_ASSERT_EQUAL_INT(MTT_ERR_UNSUPPORTED, mtt_params_check(&p, &bad));
        TEST_ASSERT_EQUAL_STRING("imm_models", bad);
    }
}

/* The IMM that max_accel derives, end to end: a target at 250 km flies
 * straight at 200 m/s, turns at 3 g (30 m/s², max_accel) through 90 degrees,
 * then straight again; one track from start to end, confirmed, within 3
 * sigma of the truth and 20 m/s after the turn, the manoeuvring model's
 * probability above its steady value during the turn and the steady
 * model's back above 1/2 at the end. */
static void test_imm_tracks_a_turn(void)
{
    const double v0 = 200.0, w = 30.0 / v0; /* rad/s: 30 m/s² at 200 m/s */
    mtt_params p;
    mtt_track_view v;
    mtt_meas m;
    size_t n = 0;
    double tx = 250000.0, ty = 0.0, vx = v0, vy = 0.0, mu_turn = 0.0, mu_before = 1.0;
    uint32_t id = 0u;
    int k;
    radar_params(&p, MTT_ASSOC_LM_IHPDA);
    p.motion = MTT_MOTION_AUTO;
    p.process_psd = 0;
    p.max_accel = pos(30.0);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    for (k = 0; k < 60; ++k) {
        const int turning = k >= 20 && (double)(k - 20) * T_SCAN * w < 1.5707963267948966;
        if (turning) { /* the exact turn over one scan */
            const double c = cos(w * T_SCAN), sn = sin(w * T_SCAN);
            const double nvx = c * vx - sn * vy, nvy = sn * vx + c * vy;
            tx += (sn * vx - (1.0 - c) * vy) / w;
            ty += ((1.0 - c) * vx + sn * vy) / w;
            vx = nvx;
            vy = nvy;
        } else {
            tx += vx * T_SCAN;
            ty += vy * T_SCAN;
        }
        m = sim_meas(pos(tx + SIGMA * gauss()), pos(ty + SIGMA * gauss()), MTT_ZERO, 0);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_TIME((double)k * T_SCAN), &m, 1));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&trk, &n));
        TEST_ASSERT_EQUAL_UINT((k == 0) ? 0u : 1u, n); /* born from two detections */
        if (k == 0) {
            continue;
        }
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, 0, &v));
        TEST_ASSERT_EQUAL_UINT8(2u, v.n_models);
        id = (k == 1) ? v.id : id;
        TEST_ASSERT_EQUAL_UINT32(id, v.id);
        if (k == 19) {
            mu_before = mtt_fx_to_double(v.mu[1], MTT_FX_PROB_FRAC);
        }
        if (turning) {
            const double mt = mtt_fx_to_double(v.mu[1], MTT_FX_PROB_FRAC);
            mu_turn = (mt > mu_turn) ? mt : mu_turn;
        }
    }
    TEST_ASSERT_TRUE(v.confirmed);
    TEST_ASSERT_DOUBLE_WITHIN(3.0 * SIGMA, tx, pos_d(v.x[0]));
    TEST_ASSERT_DOUBLE_WITHIN(3.0 * SIGMA, ty, pos_d(v.x[1]));
    TEST_ASSERT_DOUBLE_WITHIN(20.0, vx, pos_d(v.x[2]));
    TEST_ASSERT_DOUBLE_WITHIN(20.0, vy, pos_d(v.x[3]));
    TEST_ASSERT_TRUE(mu_turn > mu_before);
    TEST_ASSERT_TRUE(mtt_fx_to_double(v.mu[0], MTT_FX_PROB_FRAC) > 0.5);
}

/* A block P = v 2^e from doubles (largest mantissa below 2^28) and back. */
static void cov_set(mtt_cov P, const double v[4][4])
{
    double mx = 0.0;
    int i, j, e;
    for (i = 0; i < 4; ++i) {
        mx = (fabs(v[i][i]) > mx) ? fabs(v[i][i]) : mx;
    }
    e = (int)ceil(log2(mx)) - 27;
    for (i = 0; i < 4; ++i) {
        for (j = 0; j < 4; ++j) {
            P[i][j] = (mtt_real)llround(ldexp(v[i][j], -e));
        }
    }
    MTT_COV_E(P) = e;
}
static double cov_at(mtt_cov P, int i, int j)
{
    return ldexp((double)P[i][j], MTT_COV_E(P));
}

/* The IMM's mixing and combination (ALGORITHMS.md §14.1) in fixed point
 * against the moment-matched mixture in double: x̄ = Σ w_i x_i, P̄ = Σ w_i
 * (P_i + d_i d_i'), two models 300 m and 40 m/s apart at 120 km, within 2^-23
 * of the largest variance (block rounding) and 2^-8 m; the apportionment
 * against its formulas within 1e-7. */
static void test_imm_mixing_matches_double(void)
{
    static const double P0[4][4] = {{2500, 300, 400, 0}, {300, 2000, 0, 350}, {400, 0, 900, 20}, {0, 350, 20, 800}};
    static const double P1[4][4] = {{9000, -500, 2500, 0}, {-500, 8000, 0, 2100}, {2500, 0, 4000, 100},
                                    {0, 2100, 100, 3500}};
    static const double x0[4] = {120000.0, -35000.0, 150.0, -20.0}, x1[4] = {120300.0, -35100.0, 110.0, 5.0};
    const double mu[2] = {0.8, 0.2}, Pi[2][2] = {{0.95, 0.05}, {0.3, 0.7}};
    mtt_real Pf[MTT_MAX_MODELS][MTT_MAX_MODELS] = {{0}}, muf[MTT_MAX_MODELS] = {0}, cb[MTT_MAX_MODELS],
             mix[MTT_MAX_MODELS][MTT_MAX_MODELS], x[MTT_MAX_MODELS][MTT_MAX_STATE], xo[MTT_MAX_MODELS][MTT_MAX_STATE],
             xc[MTT_MAX_STATE];
    mtt_cov P[MTT_MAX_MODELS], Po[MTT_MAX_MODELS], Pc;
    const uint8_t n[MTT_MAX_MODELS] = {4, 4};
    const double *xs[2] = {x0, x1};
    double w[2][2], c[2];
    int i, j, a, b;
    for (i = 0; i < 2; ++i) {
        muf[i] = MTT_FX_CONST(mu[i], MTT_FX_PROB_FRAC);
        for (j = 0; j < 2; ++j) {
            Pf[i][j] = MTT_FX_CONST(Pi[i][j], MTT_FX_PROB_FRAC);
        }
        for (a = 0; a < 4; ++a) {
            x[i][a] = pos(xs[i][a]);
        }
    }
    cov_set(P[0], P0);
    cov_set(P[1], P1);
    TEST_ASSERT_EQUAL_INT(0, mtt_imm_mix_weights(2, Pf, muf, cb, mix));
    for (j = 0; j < 2; ++j) {
        c[j] = Pi[0][j] * mu[0] + Pi[1][j] * mu[1];
        TEST_ASSERT_DOUBLE_WITHIN(4e-9, c[j], mtt_fx_to_double(cb[j], MTT_FX_PROB_FRAC));
        for (i = 0; i < 2; ++i) {
            w[i][j] = Pi[i][j] * mu[i] / c[j];
            TEST_ASSERT_DOUBLE_WITHIN(1e-8, w[i][j], mtt_fx_to_double(mix[i][j], MTT_FX_PROB_FRAC));
        }
    }
    TEST_ASSERT_EQUAL_INT(0, mtt_imm_mix(2, n, mix, x, P, xo, Po));
    TEST_ASSERT_EQUAL_INT(0, mtt_imm_combine(2, muf, x, P, xc, Pc));
    for (j = 0; j < 3; ++j) { /* j = 2: the combination with mu */
        const double wt[2] = {(j < 2) ? w[0][j] : mu[0], (j < 2) ? w[1][j] : mu[1]};
        double xm[4], mx = 0.0;
        for (a = 0; a < 4; ++a) {
            xm[a] = wt[0] * pos_d(x[0][a]) + wt[1] * pos_d(x[1][a]);
            TEST_ASSERT_DOUBLE_WITHIN(0x1p-8, xm[a], pos_d((j < 2) ? xo[j][a] : xc[a]));
        }
        /* the blocks meet at one exponent 2^E <= 2^-26 of the largest
         * input or spread variance; a few roundings there and one in the
         * renormalisation: 2^-23 of it */
        for (a = 0; a < 4; ++a) {
            for (i = 0; i < 2; ++i) {
                const double d = pos_d(x[i][a]) - xm[a];
                mx = (cov_at(P[i], a, a) > mx) ? cov_at(P[i], a, a) : mx;
                mx = (d * d > mx) ? d * d : mx;
            }
        }
        for (a = 0; a < 4; ++a) {
            for (b = 0; b < 4; ++b) {
                double v = 0.0;
                for (i = 0; i < 2; ++i) {
                    v += wt[i] * (cov_at(P[i], a, b) + (pos_d(x[i][a]) - xm[a]) * (pos_d(x[i][b]) - xm[b]));
                }
                TEST_ASSERT_DOUBLE_WITHIN(mx * 0x1p-23, v, cov_at((j < 2) ? Po[j] : Pc, a, b));
            }
        }
    }
    {
        /* two measurements, model weights 1 and 0.25, 0.5 and 1; beta0 0.1 */
        const double e[2][2] = {{1.0, 0.25}, {0.5, 1.0}}, be[2] = {0.6, 0.3}, b0 = 0.1;
        mtt_real ef[MTT_MAX_GATED][MTT_MAX_MODELS] = {{0}}, e0[MTT_MAX_MODELS] = {MTT_P(1.0), MTT_P(1.0)},
                 bf[MTT_MAX_GATED] = {0}, muo[MTT_MAX_MODELS], b0j[MTT_MAX_MODELS], bj[MTT_MAX_MODELS][MTT_MAX_GATED];
        double mj[2] = {0.0, 0.0}, jt[3][2];
        for (i = 0; i < 2; ++i) {
            bf[i] = MTT_FX_CONST(be[i], MTT_FX_PROB_FRAC);
            for (j = 0; j < 2; ++j) {
                ef[i][j] = MTT_FX_CONST(e[i][j], MTT_FX_PROB_FRAC);
            }
        }
        TEST_ASSERT_EQUAL_INT(0, mtt_imm_apportion(2, cb, 2, MTT_P(0.1), bf, e0, ef, muo, b0j, bj));
        for (j = 0; j < 2; ++j) {
            jt[0][j] = b0 * c[j] / (c[0] + c[1]);
            for (i = 0; i < 2; ++i) {
                jt[i + 1][j] = be[i] * c[j] * e[i][j] / (c[0] * e[i][0] + c[1] * e[i][1]);
            }
            mj[j] = jt[0][j] + jt[1][j] + jt[2][j];
        }
        for (j = 0; j < 2; ++j) {
            TEST_ASSERT_DOUBLE_WITHIN(1e-7, mj[j] / (mj[0] + mj[1]), mtt_fx_to_double(muo[j], MTT_FX_PROB_FRAC));
            TEST_ASSERT_DOUBLE_WITHIN(1e-7, jt[0][j] / mj[j], mtt_fx_to_double(b0j[j], MTT_FX_PROB_FRAC));
            for (i = 0; i < 2; ++i) {
                TEST_ASSERT_DOUBLE_WITHIN(1e-7, jt[i + 1][j] / mj[j], mtt_fx_to_double(bj[j][i], MTT_FX_PROB_FRAC));
            }
        }
    }
}
#endif

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_ranges_hold_the_radar);
    RUN_TEST(test_gate_area_resolved);
    RUN_TEST(test_seed_variances_round_trip);
    RUN_TEST(test_target_at_400_km_tracked);
    RUN_TEST(test_full_scan_fits);
    RUN_TEST(test_motion_from_max_accel);
#if MTT_WITH_IMM
    RUN_TEST(test_imm_from_max_accel);
    RUN_TEST(test_imm_mixing_matches_double);
    RUN_TEST(test_imm_tracks_a_turn);
#endif
    return UNITY_END();
}
