/* SPDX-License-Identifier: BSD-3-Clause */
/* test_tracker_q.c - the tracker through its public API in every build,
 * written for the fixed-point build (docs/FIXED_POINT.md §3, §7): the
 * settings keys from and to the user's units, the refusals, time as Q16
 * frames modulo 2^32, a seed and its view, and a single target tracked
 * from its two-point birth (ALGORITHMS.md §12.1) through 40 frames in the
 * four firmware modes against a double reference of ALGORITHMS.md §2, §3,
 * §4, §6, §11 evaluated on the parameters and detections the tracker
 * itself holds (read back through mtt_params_get and the measurement
 * formats), so that only the arithmetic differs.
 *
 * One isolated target detected every frame has m = 1: IHPDA's row (§7.3,
 * P_r(1|1) = 1) and the LM density (§8, no other track) reduce to IPDA's
 * (§6), so one reference serves the four modes.
 *
 * Tolerance (derived, not chosen).  Let u be the unit of a rounding: in
 * the fixed build 2^-28 relative to a covariance block (BFP mantissas on
 * 28 bits) and 2^-F (F = MTT_FX_POS_FRAC) absolute on a position; in
 * float and double the type's epsilon relative.  Per frame the update adds
 * at most e_P = (88 + 8) u T to each entry of P (test_update_q.c counts 88
 * for the PDA update in units of T, the largest of its three terms; the
 * prediction's alignment, Q, symmetrisation and renormalisation 8 more, in
 * units of the largest entry of P^, taken as T too), and to the state
 * e_x = 1/2 unit of the position format + 3 u (|K_i0 nu_x| + |K_i1 nu_y|)
 * (test_update_q.c; float: 4 u |x_i| more, the state's own roundings),
 * plus the gain's error from P^'s, times |nu|: |dK_i| <= (|dP^_i0| +
 * |dP^_i1| + 2 (|K_i0| + |K_i1|) max |dS|) ||S^-1||_inf.  Errors carried from the frame
 * before go through Phi_k = (I - beta K H + beta (1 - beta) K nu nu' S^-1 H) F
 * (beta's own dependence on nu: d beta / d nu = -beta (1 - beta) S^-1 nu):
 * an error e made at frame h reaches frame k as M e with M = Phi_k ...
 * Phi_h+1, the product of the signed matrices (the filter contracts it,
 * the product of their magnitudes would not), so |dx_k| <= sum_h |M| e_h
 * and |dP_k| <= sum_h |M| E_h |M|' (the Joseph form is first order
 * insensitive to the gain, and so is the fixed build's P^ - K H P^ form
 * as a function of P^ when K is made from that P^, as the tracker does;
 * the gain's own roundings are in the 88; beta0 P^'s share, carried by F instead, is
 * injected again each frame).  The existence: the L of the tracker is
 * a Q16 ratio (three roundings of 2^-17) plus L's change with d^2 (from
 * dx) and d^2's own error (2e-6, docs/FIXED_POINT.md §7), through dP/dL;
 * the prediction's 2.51 Q30 units and the update's own (num = L P^ and
 * den = 1 - P^ + num in Q16: test_existence.c's upd_tol) each frame; the
 * error carried from the frame before through dP/dP^ (p11 - p21).  The
 * view adds half a unit of its format.  The test fails when any
 * component leaves its bound, and also when the bound itself exceeds
 * 10^-3 of the measurement sigma (10^-2 in float: it would no longer
 * test anything). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mtt/mtt.h"
#include "sim.h"
#include "unity.h"

static mtt_tracker trk;

void setUp(void) {}
void tearDown(void) {}

/* ---- the build's formats, as the user sees them ---- */
#ifdef MTT_REAL_FIXED
#define F_POS MTT_FX_POS_FRAC
#define F_VAR MTT_FX_VAR_FRAC
#define F_PROB MTT_FX_PROB_FRAC
#define F_TIME MTT_FX_T_FRAC
#define UNIT_REL ldexp(1.0, -28)
#define UNIT_POS ldexp(1.0, -F_POS)
#define VACUOUS 1e-3 /* a bound above this share of sigma tests nothing */
static mtt_real to_q(double v, int f)
{
    return (mtt_real)llround(ldexp(v, f));
}
static double from_q(mtt_real v, int f)
{
    return ldexp((double)v, -f);
}
#else
#define F_POS 0
#define F_VAR 0
#define F_PROB 0
#define F_TIME 0
#ifdef MTT_REAL_DOUBLE
#define UNIT_REL 2.220446049250313e-16
#else
#define UNIT_REL 1.1920929e-7
#endif
#define UNIT_POS 0.0 /* float: relative only */
#define VACUOUS 1e-2
static mtt_real to_q(double v, int f)
{
    (void)f;
    return (mtt_real)v;
}
static double from_q(mtt_real v, int f)
{
    (void)f;
    return (double)v;
}
#endif

static void set1(mtt_params *p, const char *key, double v)
{
    TEST_ASSERT_EQUAL_INT_MESSAGE(MTT_OK, mtt_params_set(p, key, &v, 1), key);
}

static double get1(const mtt_params *p, const char *key)
{
    double v = 0.0;
    TEST_ASSERT_EQUAL_INT_MESSAGE(MTT_OK, mtt_params_get(p, key, &v, 1), key);
    return v;
}

/* The scene's settings, through the settings keys. */
static void scene_params(mtt_params *p, mtt_assoc mode)
{
    const double sigma[2] = {1.0, 1.0};
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(p));
    p->association = mode;
    p->lm_ihpda_variant = MTT_LM_IHPDA_S0;
    set1(p, "pd", 0.9);
    set1(p, "pg", 0.99);
    set1(p, "clutter_density", 1e-4);
    set1(p, "process_psd", 0.05);
    set1(p, "vmax", 10.0);
    set1(p, "snr_rho", 0.0);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_set(p, "meas_sigma", sigma, 2));
}

/* ---- settings keys in the user's units ---- */

void test_settings_round_trip_in_user_units(void)
{
    mtt_params p;
    double v = 0.0, big = 1e12;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    set1(&p, "pd", 0.7);
    /* the stored value is the nearest of its format: within half a unit */
    TEST_ASSERT_TRUE(fabs(get1(&p, "pd") - 0.7) <= ((F_PROB > 0) ? ldexp(0.5, -F_PROB) : 1e-7));
    TEST_ASSERT_TRUE(fabs(from_q(p.pd, F_PROB) - 0.7) <= ((F_PROB > 0) ? ldexp(0.5, -F_PROB) : 1e-7));
    set1(&p, "vmax", 12.25); /* exact in every format */
    TEST_ASSERT_EQUAL_DOUBLE(12.25, get1(&p, "vmax"));
    TEST_ASSERT_TRUE(p.vmax == to_q(12.25, F_POS));
    /* outside the format (fixed: 2^(31 - F) units) or NaN: refused, nothing written */
    v = p.vmax;
#ifdef MTT_REAL_FIXED
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_set(&p, "vmax", &big, 1));
#else
    (void)big;
#endif
    big = nan("");
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_set(&p, "vmax", &big, 1));
    TEST_ASSERT_TRUE(p.vmax == (mtt_real)v);
}

/* ---- what the fixed build refuses ---- */

void test_fixed_build_refusals(void)
{
    mtt_params p;
    const char *field = NULL;
    scene_params(&p, MTT_ASSOC_LM_IHPDA);
    set1(&p, "clutter_density", 0.0);
#ifdef MTT_REAL_FIXED
    TEST_ASSERT_EQUAL_INT(MTT_ERR_UNSUPPORTED, mtt_tracker_init(&trk, &p));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_UNSUPPORTED, mtt_params_check(&p, &field));
    TEST_ASSERT_EQUAL_STRING("clutter_density", field);
#else
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p)); /* the estimated density */
    (void)field;
#endif
    scene_params(&p, MTT_ASSOC_IPDA);
    p.init_gate = MTT_INIT_GATE_INTENSITY;
#ifdef MTT_REAL_FIXED
    TEST_ASSERT_EQUAL_INT(MTT_ERR_UNSUPPORTED, mtt_params_check(&p, &field));
    TEST_ASSERT_EQUAL_STRING("init_gate", field);
    TEST_ASSERT_EQUAL_INT(MTT_ERR_UNSUPPORTED, mtt_tracker_init(&trk, &p));
#else
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
#endif
#ifdef MTT_REAL_FIXED
    {
        /* R = sigma^2 outside the variance format (0, 32768) unit^2 */
        const double small[2] = {1.0, 0.001}, large[2] = {200.0, 1.0};
        scene_params(&p, MTT_ASSOC_IPDA);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_set(&p, "meas_sigma", small, 2));
        TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_check(&p, &field));
        TEST_ASSERT_EQUAL_STRING("meas_sigma", field);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_set(&p, "meas_sigma", large, 2));
        TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_tracker_init(&trk, &p));
    }
#endif
    scene_params(&p, MTT_ASSOC_IPDA);
    p.motion = MTT_MOTION_IMM;
    TEST_ASSERT_EQUAL_INT(MTT_WITH_IMM ? MTT_OK : MTT_ERR_UNSUPPORTED, mtt_tracker_init(&trk, &p));
    scene_params(&p, MTT_ASSOC_JIPDA);
    TEST_ASSERT_EQUAL_INT(MTT_WITH_BASELINES ? MTT_OK : MTT_ERR_UNSUPPORTED, mtt_tracker_init(&trk, &p));
}

/* ---- time ---- */

/* A seeded track with velocity (2, -1) and no detection: each step
 * predicts by dt exactly (dt = 1 frame: F x is exact in every format). */
static void seed_one(void)
{
    mtt_real x[4], P[16];
    int i;
    uint32_t id = 0;
    x[0] = to_q(100.0, F_POS);
    x[1] = to_q(200.0, F_POS);
    x[2] = to_q(2.0, F_POS);
    x[3] = to_q(-1.0, F_POS);
    for (i = 0; i < 16; ++i) {
        P[i] = to_q((i % 5 == 0) ? 4.0 : 0.0, F_VAR);
    }
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&trk, x, P, &id));
}

static void assert_x(double x, double y)
{
    mtt_track_view v;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, 0, &v));
    TEST_ASSERT_EQUAL_DOUBLE(x, from_q(v.x[0], F_POS));
    TEST_ASSERT_EQUAL_DOUBLE(y, from_q(v.x[1], F_POS));
}

void test_time_steps_and_wrap(void)
{
    mtt_params p;
    mtt_real t0;
    scene_params(&p, MTT_ASSOC_IPDA);
    set1(&p, "terminate_threshold", 0.0); /* a coasting track stays */
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    seed_one();
#ifdef MTT_REAL_FIXED
    /* half a frame before the int32 wrap: the next frame is negative */
    t0 = (mtt_real)(INT32_MAX - 32767);
#else
    t0 = to_q(1000.0, F_TIME);
#endif
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, t0, NULL, 0));
    assert_x(100.0, 200.0); /* first frame: no prediction */
#ifdef MTT_REAL_FIXED
    {
        const mtt_real t1 = (mtt_real)((int64_t)t0 + 65536 - 4294967296LL); /* wrapped */
        TEST_ASSERT_TRUE(t1 < 0);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, t1, NULL, 0));
        assert_x(102.0, 199.0);
        TEST_ASSERT_EQUAL_INT(MTT_ERR_TIME, mtt_tracker_step(&trk, t1, NULL, 0));
        TEST_ASSERT_EQUAL_INT(MTT_ERR_TIME, mtt_tracker_step(&trk, t0, NULL, 0)); /* earlier */
        /* 2^31 Q16 units ahead (32768 frames) is "earlier" modulo 2^32 */
        TEST_ASSERT_EQUAL_INT(MTT_ERR_TIME,
                              mtt_tracker_step(&trk, (mtt_real)((int64_t)t1 + 2147483647LL + 1 - 4294967296LL), NULL, 0));
        /* two frames on: dt = 2 */
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, t1 + 2 * 65536, NULL, 0));
        assert_x(106.0, 197.0);
    }
#else
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, t0 + 1, NULL, 0));
    assert_x(102.0, 199.0);
    TEST_ASSERT_EQUAL_INT(MTT_ERR_TIME, mtt_tracker_step(&trk, t0 + 1, NULL, 0));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_TIME, mtt_tracker_step(&trk, t0, NULL, 0));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, t0 + 3, NULL, 0));
    assert_x(106.0, 197.0);
#endif
}

/* ---- a seed and its view ---- */

void test_seed_view_round_trip(void)
{
    /* Entries below 2^28 units of the variance format go into the block
     * exactly (left shifts) and come back exactly; a larger block (the
     * 20000 unit^2 velocity variance, 2^30.3 units in Q16) is shifted
     * right by s = 3 bits: each entry within 2^(s-1) units. */
    static const double P0[16] = {2.5,  0.25, 1.0,     0.0,   0.25, 3.0, 0.0,   -0.5,
                                  1.0,  0.0,  20000.0, 7.125, 0.0,  -0.5, 7.125, 9.0};
    mtt_params p;
    mtt_real x[4], P[16];
    mtt_track_view v;
    uint32_t id = 0;
    int i, j;
    const double tol_big = (F_VAR > 0) ? 4.0 * ldexp(1.0, -F_VAR) : 0.0;
    scene_params(&p, MTT_ASSOC_LM_IHPDA);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    x[0] = to_q(-50.5, F_POS);
    x[1] = to_q(1234.0, F_POS);
    x[2] = to_q(0.75, F_POS);
    x[3] = to_q(-3.0, F_POS);
    for (i = 0; i < 16; ++i) {
        P[i] = to_q(P0[i], F_VAR);
    }
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&trk, x, P, &id));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, 0, &v));
    TEST_ASSERT_EQUAL_UINT32(id, v.id);
    TEST_ASSERT_EQUAL_INT(1, v.confirmed);
    TEST_ASSERT_EQUAL_DOUBLE(1.0, from_q(v.existence, F_PROB));
    for (i = 0; i < 4; ++i) {
        TEST_ASSERT_TRUE(v.x[i] == x[i]);
        for (j = 0; j < 4; ++j) {
            TEST_ASSERT_DOUBLE_WITHIN(tol_big, P0[4 * i + j], from_q(v.P[i][j], F_VAR));
        }
    }
    /* not symmetric (beyond the rounding of its format): refused */
    P[1] = to_q(0.5, F_VAR);
    TEST_ASSERT_EQUAL_INT(MTT_ERR_VALUE, mtt_tracker_add_track(&trk, x, P, &id));
    /* not positive definite: refused */
    P[1] = to_q(0.25, F_VAR);
    P[0] = to_q(-1.0, F_VAR);
    TEST_ASSERT_EQUAL_INT(MTT_ERR_VALUE, mtt_tracker_add_track(&trk, x, P, &id));
}

/* ---- one target from its birth, against the double reference ---- */

#define N_FRAMES 40

typedef struct ref {
    double x[4], P[4][4], ex;
    double bx[4], bP[4][4], bex; /* the derived bounds */
    /* the errors made at each frame h so far (state, P) and the product of
     * the transitions since then */
    int nh;
    double M[N_FRAMES][4][4], ex_[N_FRAMES][4], eP_[N_FRAMES][4][4];
} ref;

static void mat_eye(double A[4][4])
{
    int i;
    memset(A, 0, 16 * sizeof A[0][0]);
    for (i = 0; i < 4; ++i) {
        A[i][i] = 1.0;
    }
}

/* B <- A B */
static void mat_mul(double A[4][4], double B[4][4])
{
    double C[4][4];
    int i, j, k;
    for (i = 0; i < 4; ++i) {
        for (j = 0; j < 4; ++j) {
            double s = 0.0;
            for (k = 0; k < 4; ++k) {
                s += A[i][k] * B[k][j];
            }
            C[i][j] = s;
        }
    }
    memcpy(B, C, sizeof C);
}

/* bx = sum_h |M_h| e_h, bP = sum_h |M_h| E_h |M_h|' */
static void bounds(ref *r)
{
    int h, i, j, a, b;
    memset(r->bx, 0, sizeof r->bx);
    memset(r->bP, 0, sizeof r->bP);
    for (h = 0; h < r->nh; ++h) {
        for (i = 0; i < 4; ++i) {
            for (a = 0; a < 4; ++a) {
                r->bx[i] += fabs(r->M[h][i][a]) * r->ex_[h][a];
            }
            for (j = 0; j < 4; ++j) {
                for (a = 0; a < 4; ++a) {
                    for (b = 0; b < 4; ++b) {
                        r->bP[i][j] += fabs(r->M[h][i][a]) * r->eP_[h][a][b] * fabs(r->M[h][j][b]);
                    }
                }
            }
        }
    }
}

static double max_abs(double A[4][4])
{
    double m = 0.0;
    int i, j;
    for (i = 0; i < 4; ++i) {
        for (j = 0; j < 4; ++j) {
            m = (fabs(A[i][j]) > m) ? fabs(A[i][j]) : m;
        }
    }
    return m;
}

/* One frame of the reference with the measurement z (dt = 1 frame). */
static void ref_step(ref *r, const mtt_params *p, const double z[2])
{
    const double sw = get1(p, "process_psd"), pd = get1(p, "pd"), pg = get1(p, "pg");
    const double lam = get1(p, "clutter_density"), p11 = get1(p, "markov_p11");
    const double p21 = get1(p, "markov_p21");
    double sg[2], R[2];
    double xp[4], Pp[4][4], S[3], Si[3], det, K[4][2], nu[2], d2, lik, L, beta, beta0;
    double A[4][4], Pc[4][4], Phi[4][4], F[4][4], exp_, dL, dd2;
    double T, eP, Bp[4][4];
    int i, j, k;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_get(p, "meas_sigma", sg, 2));
#ifdef MTT_REAL_FIXED
    /* R as the tracker forms it: sigma^2 rounded to the variance format */
    R[0] = ldexp(nearbyint(ldexp(sg[0] * sg[0], F_VAR)), -F_VAR);
    R[1] = ldexp(nearbyint(ldexp(sg[1] * sg[1], F_VAR)), -F_VAR);
#else
    R[0] = sg[0] * sg[0];
    R[1] = sg[1] * sg[1];
#endif
    memset(F, 0, sizeof F);
    for (i = 0; i < 4; ++i) {
        F[i][i] = 1.0;
    }
    F[0][2] = F[1][3] = 1.0;
    /* §2, §3 predict */
    xp[0] = r->x[0] + r->x[2];
    xp[1] = r->x[1] + r->x[3];
    xp[2] = r->x[2];
    xp[3] = r->x[3];
    for (i = 0; i < 4; ++i) {
        for (j = 0; j < 4; ++j) {
            double s = 0.0;
            int a, b;
            for (a = 0; a < 4; ++a) {
                for (b = 0; b < 4; ++b) {
                    s += F[i][a] * r->P[a][b] * F[j][b];
                }
            }
            Pp[i][j] = s;
        }
    }
    for (i = 0; i < 2; ++i) {
        Pp[i][i] += sw / 3.0;
        Pp[i][i + 2] += sw / 2.0;
        Pp[i + 2][i] += sw / 2.0;
        Pp[i + 2][i + 2] += sw;
    }
    S[0] = Pp[0][0] + R[0];
    S[1] = Pp[0][1];
    S[2] = Pp[1][1] + R[1];
    det = S[0] * S[2] - S[1] * S[1];
    Si[0] = S[2] / det;
    Si[1] = -S[1] / det;
    Si[2] = S[0] / det;
    for (i = 0; i < 4; ++i) {
        K[i][0] = Pp[i][0] * Si[0] + Pp[i][1] * Si[1];
        K[i][1] = Pp[i][0] * Si[1] + Pp[i][1] * Si[2];
    }
    nu[0] = z[0] - xp[0];
    nu[1] = z[1] - xp[1];
    /* §4 gate and likelihood, §6 with m = 1 */
    d2 = Si[0] * nu[0] * nu[0] + 2.0 * Si[1] * nu[0] * nu[1] + Si[2] * nu[1] * nu[1];
    TEST_ASSERT_TRUE(d2 <= -2.0 * log(1.0 - pg)); /* the scene keeps the target gated */
    lik = exp(-0.5 * d2) / (2.0 * 3.141592653589793 * sqrt(det) * pg);
    L = 1.0 - pd * pg + pd * pg * lik / lam;
    beta = pd * pg * lik / lam / L;
    beta0 = (1.0 - pd * pg) / L;
    for (i = 0; i < 4; ++i) {
        r->x[i] = xp[i] + beta * (K[i][0] * nu[0] + K[i][1] * nu[1]);
    }
    /* Joseph P_c with A = I - K H */
    memset(A, 0, sizeof A);
    for (i = 0; i < 4; ++i) {
        A[i][i] = 1.0;
        A[i][0] -= K[i][0];
        A[i][1] -= K[i][1];
    }
    for (i = 0; i < 4; ++i) {
        for (j = 0; j < 4; ++j) {
            double s = K[i][0] * R[0] * K[j][0] + K[i][1] * R[1] * K[j][1];
            int a, b;
            for (a = 0; a < 4; ++a) {
                for (b = 0; b < 4; ++b) {
                    s += A[i][a] * Pp[a][b] * A[j][b];
                }
            }
            Pc[i][j] = s;
        }
    }
    for (i = 0; i < 4; ++i) {
        for (j = 0; j < 4; ++j) {
            const double kn_i = K[i][0] * nu[0] + K[i][1] * nu[1];
            const double kn_j = K[j][0] * nu[0] + K[j][1] * nu[1];
            r->P[i][j] = beta0 * Pp[i][j] + beta * Pc[i][j] + beta * beta0 * kn_i * kn_j;
        }
    }
    /* §11, §6 existence */
    exp_ = p11 * r->ex + p21 * (1.0 - r->ex);
    /* ---- the bounds ---- */
    /* Phi = dx/dx_prev = (I - beta K H + beta (1 - beta) K nu nu' S^-1 H) F
     * (beta's own dependence on nu: d beta / d nu = -beta (1 - beta) S^-1 nu) */
    for (i = 0; i < 4; ++i) {
        const double kn = K[i][0] * nu[0] + K[i][1] * nu[1];
        const double g0 = beta * (1.0 - beta) * (Si[0] * nu[0] + Si[1] * nu[1]);
        const double g1 = beta * (1.0 - beta) * (Si[1] * nu[0] + Si[2] * nu[1]);
        for (j = 0; j < 4; ++j) {
            double s = 0.0;
            for (k = 0; k < 4; ++k) {
                double ikh = ((i == k) ? 1.0 : 0.0) - ((k < 2) ? beta * K[i][k] : 0.0);
                ikh += (k == 0) ? kn * g0 : ((k == 1) ? kn * g1 : 0.0);
                s += ikh * F[k][j];
            }
            Phi[i][j] = s;
        }
    }
    T = max_abs(Pp);
    {
        double t2 = beta * max_abs(Pc), t3 = 0.0;
        for (i = 0; i < 4; ++i) {
            const double kn = fabs(K[i][0] * nu[0] + K[i][1] * nu[1]);
            t3 = (beta * beta0 * kn * kn > t3) ? beta * beta0 * kn * kn : t3;
        }
        T = (t2 > T) ? t2 : T;
        T = (t3 > T) ? t3 : T;
    }
    eP = (88.0 + 8.0) * UNIT_REL * T;
    {
        const double siinf = fmax(fabs(Si[0]) + fabs(Si[1]), fabs(Si[1]) + fabs(Si[2]));
        double dS, ex[4], eM[4][4];
        int h;
        /* P^'s carried error: |F| B |F|' (B the bound of P) */
        for (i = 0; i < 4; ++i) {
            for (j = 0; j < 4; ++j) {
                double sp = 0.0, sn = 0.0;
                int a, b;
                for (a = 0; a < 4; ++a) {
                    for (b = 0; b < 4; ++b) {
                        sp += fabs(F[i][a]) * r->bP[a][b] * fabs(F[j][b]);
                        sn += fabs(Phi[i][a]) * r->bP[a][b] * fabs(Phi[j][b]);
                    }
                }
                Bp[i][j] = sp;
                /* injected this frame: the roundings, and beta0 P^'s part,
                 * which is carried by F rather than Phi (both counted) */
                eM[i][j] = eP + beta0 * (sp + sn);
            }
        }
        dS = fmax(Bp[0][0], fmax(Bp[0][1], Bp[1][1]));
        for (i = 0; i < 4; ++i) {
            /* K = P^ H' S^-1: |dK_i| <= (|dP^_i0| + |dP^_i1| + (|K_i0| + |K_i1|) 2 |dS|) ||S^-1|| */
            const double dK = (Bp[i][0] + Bp[i][1] + (fabs(K[i][0]) + fabs(K[i][1])) * 2.0 * dS) * siinf;
            ex[i] = 0.5 * UNIT_POS + 3.0 * UNIT_REL * (fabs(K[i][0] * nu[0]) + fabs(K[i][1] * nu[1])) +
                    beta * dK * (fabs(nu[0]) + fabs(nu[1]));
            if (UNIT_POS == 0.0) {
                ex[i] += 4.0 * UNIT_REL * fabs(r->x[i]); /* float: the state's own roundings */
            }
        }
        /* Every error made at frame i reaches frame k through the product
         * of the signed Phi between them (the filter contracts it; the
         * product of the magnitudes would not). */
        for (h = 0; h < r->nh; ++h) {
            mat_mul(Phi, r->M[h]);
        }
        TEST_ASSERT_TRUE(r->nh < N_FRAMES);
        mat_eye(r->M[r->nh]);
        memcpy(r->ex_[r->nh], ex, sizeof ex);
        memcpy(r->eP_[r->nh], eM, sizeof eM);
        r->nh++;
        bounds(r);
    }
    /* existence: L's error (three Q16 roundings, or float's relative),
     * d^2's from the state and its own, carried with dP/dP^ */
    dd2 = 2.0 * (fabs(Si[0] * nu[0] + Si[1] * nu[1]) * 2.0 * r->bx[0] +
                 fabs(Si[1] * nu[0] + Si[2] * nu[1]) * 2.0 * r->bx[1]) +
          ((F_PROB > 0) ? 2e-6 : 8.0 * UNIT_REL * d2);
    dL = ((F_PROB > 0) ? 3.0 * ldexp(1.0, -17) : 8.0 * UNIT_REL * L) + 0.5 * pd * pg * lik / lam * dd2;
    {
        const double den = 1.0 - exp_ + L * exp_;
        /* the prediction's own error (test_existence.c: 2.51 Q30 units)
         * and the update's (test_existence.c's upd_tol: num = L P^ and
         * den = 1 - P^ + num in Q16, the quotient in Q30) */
        const double q = ldexp(1.0, -17), post = L * exp_ / den;
        const double dnum = q * (1.0 + exp_) + L * ldexp(1.0, -31);
        const double e_pred = (F_PROB > 0) ? 2.51 * ldexp(1.0, -30) : 4.0 * UNIT_REL;
        const double e_upd = (F_PROB > 0) ? (dnum + post * (q + dnum)) / den + ldexp(1.0, -31) : 4.0 * UNIT_REL;
        r->bex = L / (den * den) * fabs(p11 - p21) * (r->bex + e_pred) + exp_ * (1.0 - exp_) / (den * den) * dL +
                 e_upd;
        r->ex = L * exp_ / den;
    }
}

static void run_single_target(mtt_assoc mode, double *worst)
{
    mtt_params p;
    sim_rng rng = {20261130u};
    ref r;
    double zq[N_FRAMES][2];
    const double sigma = 1.0;
    size_t n;
    int k, i, j;
    char msg[160];
    scene_params(&p, mode);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    memset(&r, 0, sizeof r);
    for (k = 0; k < N_FRAMES; ++k) {
        mtt_meas m;
        const double tx = 100.0 + 2.0 * k, ty = 200.0 - 1.0 * k;
        m.x = to_q(tx + sigma * sim_gauss(&rng), F_POS);
        m.y = to_q(ty + sigma * sim_gauss(&rng), F_POS);
        m.amplitude = to_q(0.0, F_POS);
        m.has_amplitude = 0;
        zq[k][0] = from_q(m.x, F_POS); /* what the tracker sees */
        zq[k][1] = from_q(m.y, F_POS);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, to_q((double)k, F_TIME), &m, 1));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&trk, &n));
        TEST_ASSERT_EQUAL_UINT((k == 0) ? 0u : 1u, (unsigned)n);
        if (k == 1) {
            /* §12.1: the two-point birth, exact in the reference */
            double sg[2], R0, R1;
            mtt_track_view v;
            TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_get(&p, "meas_sigma", sg, 2));
            R0 = sg[0] * sg[0];
            R1 = sg[1] * sg[1];
            r.x[0] = zq[1][0];
            r.x[1] = zq[1][1];
            r.x[2] = zq[1][0] - zq[0][0];
            r.x[3] = zq[1][1] - zq[0][1];
            r.P[0][0] = R0;
            r.P[1][1] = R1;
            r.P[0][2] = r.P[2][0] = R0;
            r.P[1][3] = r.P[3][1] = R1;
            r.P[2][2] = 2.0 * R0;
            r.P[3][3] = 2.0 * R1;
            r.ex = get1(&p, "existence_init");
            /* the birth's own roundings: R to its format, the block */
            mat_eye(r.M[0]);
            for (i = 0; i < 4; ++i) {
                r.ex_[0][i] = UNIT_POS + 2.0 * UNIT_REL * fabs(r.x[i]);
                for (j = 0; j < 4; ++j) {
                    r.eP_[0][i][j] = ((F_VAR > 0) ? ldexp(1.0, -F_VAR) : 0.0) + 8.0 * UNIT_REL * 2.0 * R0;
                }
            }
            r.nh = 1;
            bounds(&r);
            r.bex = (F_PROB > 0) ? ldexp(1.0, -31) : UNIT_REL;
            TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, 0, &v));
            TEST_ASSERT_EQUAL_INT(0, v.confirmed);
            continue;
        }
        if (k == 0) {
            continue;
        }
        ref_step(&r, &p, zq[k]);
        {
            mtt_track_view v;
            const double vq = (F_VAR > 0) ? ldexp(0.5, -F_VAR) : 0.0;
            TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, 0, &v));
            for (i = 0; i < 4; ++i) {
                const double e = fabs(from_q(v.x[i], F_POS) - r.x[i]);
                snprintf(msg, sizeof msg, "mode %d frame %d x[%d]: %.9g vs %.9g, bound %.3g", (int)mode, k, i,
                         from_q(v.x[i], F_POS), r.x[i], r.bx[i]);
                TEST_ASSERT_TRUE_MESSAGE(e <= r.bx[i], msg);
                TEST_ASSERT_TRUE_MESSAGE(r.bx[i] <= VACUOUS * sigma, msg);
                worst[0] = fmax(worst[0], e / r.bx[i]);
                worst[3] = fmax(worst[3], r.bx[i] / sigma);
                for (j = 0; j < 4; ++j) {
                    const double ep = fabs(from_q(v.P[i][j], F_VAR) - r.P[i][j]);
                    snprintf(msg, sizeof msg, "mode %d frame %d P[%d][%d]: %.9g vs %.9g, bound %.3g", (int)mode,
                             k, i, j, from_q(v.P[i][j], F_VAR), r.P[i][j], r.bP[i][j] + vq);
                    TEST_ASSERT_TRUE_MESSAGE(ep <= r.bP[i][j] + vq, msg);
                    TEST_ASSERT_TRUE_MESSAGE(r.bP[i][j] <= VACUOUS * r.P[i][i], msg);
                    worst[1] = fmax(worst[1], ep / (r.bP[i][j] + vq));
                }
            }
            {
                const double e = fabs(from_q(v.existence, F_PROB) - r.ex);
                snprintf(msg, sizeof msg, "mode %d frame %d existence: %.12g vs %.12g, bound %.3g", (int)mode, k,
                         from_q(v.existence, F_PROB), r.ex, r.bex);
                TEST_ASSERT_TRUE_MESSAGE(e <= r.bex, msg);
                TEST_ASSERT_TRUE_MESSAGE(r.bex <= VACUOUS, msg);
                worst[2] = fmax(worst[2], e / r.bex);
            }
            TEST_ASSERT_EQUAL_INT(r.ex >= get1(&p, "confirm_threshold"), v.confirmed);
        }
    }
}

void test_single_target_against_reference(void)
{
    const mtt_assoc modes[4] = {MTT_ASSOC_LM_IHPDA, MTT_ASSOC_IHPDA, MTT_ASSOC_LM_IPDA, MTT_ASSOC_IPDA};
    double worst[4] = {0.0, 0.0, 0.0, 0.0};
    int i;
    for (i = 0; i < 4; ++i) {
        run_single_target(modes[i], worst);
    }
    /* the share of the derived bound used (reported; < 1 asserted above) */
    printf("single target, 4 modes x %d frames: worst |error| / bound: x %.3f, P %.3f, existence %.3f; "
           "largest bound of x %.3g sigma\n",
           N_FRAMES, worst[0], worst[1], worst[2], worst[3]);
}

/* ---- merging (ALGORITHMS.md §12.3) at two block exponents ---- */

/* Two seeded tracks, covariances 16 times apart (their blocks' exponents
 * differ by 4), both gating one detection (one cluster), updated by ipda
 * (each alone: the reference of ref_step); merge d^2 of the updated pair
 * in double, and its bound from the states' and covariances' bounds:
 * |d(d^2)| <= 2 sum |w_i| (bx_a + bx_b)_i + sum |w_i w_j| (bP_a + bP_b)_ij
 * with w = (P_a + P_b)^-1 (x_a - x_b), plus the L D L' quadratic form's
 * own 2^-20 relative (test_update_q.c).  A threshold above d^2 + bound
 * merges, one below d^2 - bound does not. */
static void seed_ref(ref *r, double x0, double y0, double vx, double vy, double var)
{
    mtt_real x[4], P[16];
    uint32_t id = 0;
    int i;
    memset(r, 0, sizeof *r);
    r->x[0] = x0;
    r->x[1] = y0;
    r->x[2] = vx;
    r->x[3] = vy;
    for (i = 0; i < 4; ++i) {
        r->P[i][i] = var;
        x[i] = to_q(r->x[i], F_POS);
    }
    for (i = 0; i < 16; ++i) {
        P[i] = to_q((i % 5 == 0) ? var : 0.0, F_VAR);
    }
    r->ex = 1.0;
    mat_eye(r->M[0]);
    r->nh = 1; /* the seed is exact in every format: no error yet */
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&trk, x, P, &id));
}

static double merge_d2(const ref *a, const ref *b, double *bound)
{
    double A[4][4], w[4], d[4], s = 0.0, e = 0.0;
    int i, j, k;
    for (i = 0; i < 4; ++i) {
        d[i] = a->x[i] - b->x[i];
        for (j = 0; j < 4; ++j) {
            A[i][j] = a->P[i][j] + b->P[i][j];
        }
    }
    /* w = A^-1 d by Gaussian elimination (A is positive definite: no
     * pivoting), on copies */
    {
        double G[4][4], g[4];
        memcpy(G, A, sizeof G);
        memcpy(g, d, sizeof g);
        for (k = 0; k < 4; ++k) {
            for (i = k + 1; i < 4; ++i) {
                const double f = G[i][k] / G[k][k];
                for (j = k; j < 4; ++j) {
                    G[i][j] -= f * G[k][j];
                }
                g[i] -= f * g[k];
            }
        }
        for (i = 3; i >= 0; --i) {
            w[i] = g[i];
            for (j = i + 1; j < 4; ++j) {
                w[i] -= G[i][j] * w[j];
            }
            w[i] /= G[i][i];
        }
    }
    for (i = 0; i < 4; ++i) {
        s += d[i] * w[i];
        e += 2.0 * fabs(w[i]) * (a->bx[i] + b->bx[i]);
        for (j = 0; j < 4; ++j) {
            e += fabs(w[i] * w[j]) * (a->bP[i][j] + b->bP[i][j] + ((F_VAR > 0) ? ldexp(1.0, -F_VAR) : 0.0));
        }
    }
    *bound = e + ldexp(s, -20) + ((F_VAR > 0) ? ldexp(1.0, -24) : 0.0);
    return s;
}

void test_merge_at_two_exponents(void)
{
    int pass;
    for (pass = 0; pass < 2; ++pass) {
        mtt_params p;
        mtt_stats st;
        mtt_track_view v;
        ref ra, rb;
        size_t n;
        double d2, bound;
        double z[2] = {101.3, 100.9};
        mtt_meas m;
        scene_params(&p, MTT_ASSOC_IPDA);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
        seed_ref(&ra, 100.0, 100.0, 1.0, 0.5, 0.25);
        seed_ref(&rb, 100.5, 100.25, 2.0, -0.5, 4.0);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, to_q(0.0, F_TIME), NULL, 0));
        m = sim_meas(to_q(z[0], F_POS), to_q(z[1], F_POS), to_q(0.0, F_POS), 0);
        z[0] = from_q(m.x, F_POS);
        z[1] = from_q(m.y, F_POS);
        ref_step(&ra, &p, z);
        ref_step(&rb, &p, z);
        d2 = merge_d2(&ra, &rb, &bound);
        TEST_ASSERT_TRUE_MESSAGE(bound <= 1e-3 * d2, "the bound of d^2 tests nothing");
        set1(&p, "merge_threshold", (pass == 0) ? d2 + bound : d2 - bound);
        /* the threshold is read at init: a second tracker, same seeds */
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
        seed_ref(&ra, 100.0, 100.0, 1.0, 0.5, 0.25);
        seed_ref(&rb, 100.5, 100.25, 2.0, -0.5, 4.0);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, to_q(0.0, F_TIME), NULL, 0));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, to_q(1.0, F_TIME), &m, 1));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&trk, &st));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&trk, &n));
        if (pass == 0) {
            TEST_ASSERT_EQUAL_UINT32(1u, st.last.merges);
            TEST_ASSERT_EQUAL_UINT(1u, (unsigned)n);
            /* the survivor: the smaller position trace, the first seed */
            TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, 0, &v));
            TEST_ASSERT_EQUAL_UINT32(0u, v.id);
        } else {
            TEST_ASSERT_EQUAL_UINT32(0u, st.last.merges);
            TEST_ASSERT_EQUAL_UINT(2u, (unsigned)n);
        }
    }
}

/* ---- a saturated IPDA row (ALGORITHMS.md §6) ---- */

/* 32 exact duplicates at a confident track: each p_j / lambda is about
 * 8000, so Lambda = sum p_j / lambda saturates its Q16 ratio (32768) in
 * the fixed build.  The betas must still add up to 1 - beta0 (ipda.c
 * scales the row), or the PDA spread term turns P indefinite and the
 * track is deleted as numerically invalid.  32 equal innovations are one
 * measurement with beta = 1 - beta0: x = x^ + (1 - beta0) K nu with
 * 0 <= beta0 <= (1 - PD PG) / 32768 (L saturated; exactly (1 - PD PG) / L
 * in float), so |x - (x^ + K nu)| <= ((1 - PD PG) / 32768 + 2^-24) |K nu|
 * plus one unit of the position format (float: 4 epsilons of |x|). */
void test_saturated_ipda_row(void)
{
    const mtt_assoc modes[2] = {MTT_ASSOC_LM_IPDA, MTT_ASSOC_IPDA};
    int mi;
    for (mi = 0; mi < 2; ++mi) {
        mtt_params p;
        mtt_stats st;
        mtt_track_view v;
        mtt_meas m[32];
        mtt_real x[4], P[16];
        uint32_t id = 0;
        size_t n;
        int i;
        double sw, pd, pg, sg[2], z[2], c[3], det;
        const double vp = 1.0, vv = 0.5;
        scene_params(&p, modes[mi]);
        set1(&p, "clutter_density", 1e-5);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
        x[0] = to_q(100.0, F_POS);
        x[1] = to_q(100.0, F_POS);
        x[2] = to_q(1.0, F_POS);
        x[3] = to_q(0.5, F_POS);
        for (i = 0; i < 16; ++i) {
            P[i] = to_q((i == 0 || i == 5) ? vp : ((i == 10 || i == 15) ? vv : 0.0), F_VAR);
        }
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&trk, x, P, &id));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, to_q(0.0, F_TIME), NULL, 0));
        for (i = 0; i < 32; ++i) {
            m[i] = sim_meas(to_q(101.25, F_POS), to_q(100.625, F_POS), to_q(0.0, F_POS), 0);
        }
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, to_q(1.0, F_TIME), m, 32));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&trk, &st));
        TEST_ASSERT_EQUAL_UINT32(0u, st.last.numeric_deletions);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&trk, &n));
        TEST_ASSERT_EQUAL_UINT(1u, (unsigned)n);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, 0, &v));
        /* the reference: one Kalman update per axis (P diagonal per axis) */
        sw = get1(&p, "process_psd");
        pd = get1(&p, "pd");
        pg = get1(&p, "pg");
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_get(&p, "meas_sigma", sg, 2));
        z[0] = 101.25 - 101.0;
        z[1] = 100.625 - 100.5;
        for (i = 0; i < 2; ++i) {
            const double ppx = vp + vv + sw / 3.0, ppv = vv + sw / 2.0;
            const double S = ppx + sg[i] * sg[i];
            const double kx = ppx / S * z[i], kv = ppv / S * z[i];
            const double tol = (1.0 - pd * pg) / 32768.0 + ldexp(1.0, -24);
            /* float: the state's own roundings, 4 epsilons of |x| */
            const double ux = (UNIT_POS > 0.0) ? UNIT_POS : 4.0 * UNIT_REL * 101.0;
            TEST_ASSERT_DOUBLE_WITHIN(tol * fabs(kx) + ux, (i == 0 ? 101.0 : 100.5) + kx, from_q(v.x[i], F_POS));
            TEST_ASSERT_DOUBLE_WITHIN(tol * fabs(kv) + ux, (i == 0 ? 1.0 : 0.5) + kv, from_q(v.x[i + 2], F_POS));
        }
        /* positive definite: the position block and each axis's block */
        c[0] = from_q(v.P[0][0], F_VAR);
        c[1] = from_q(v.P[0][1], F_VAR);
        c[2] = from_q(v.P[1][1], F_VAR);
        det = c[0] * c[2] - c[1] * c[1];
        TEST_ASSERT_TRUE(c[0] > 0.0 && det > 0.0);
        TEST_ASSERT_TRUE(from_q(v.P[0][0], F_VAR) * from_q(v.P[2][2], F_VAR) >
                         from_q(v.P[0][2], F_VAR) * from_q(v.P[0][2], F_VAR));
        TEST_ASSERT_TRUE(from_q(v.existence, F_PROB) >= 1.0 - ldexp(1.0, -15));
    }
}

/* ---- two targets in clutter: the pipeline as a whole ---- */

void test_two_targets_in_clutter(void)
{
    const mtt_assoc modes[4] = {MTT_ASSOC_LM_IHPDA, MTT_ASSOC_IHPDA, MTT_ASSOC_LM_IPDA, MTT_ASSOC_IPDA};
    int mi;
    for (mi = 0; mi < 4; ++mi) {
        mtt_params p;
        sim_rng rng = {777u + (uint64_t)mi};
        mtt_stats st;
        size_t n, i;
        int k, near[2] = {0, 0}, confirmed = 0;
        scene_params(&p, modes[mi]);
        set1(&p, "clutter_density", 5e-5);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
        for (k = 0; k < 50; ++k) {
            mtt_meas m[40];
            size_t nm = 0;
            int c, nc = sim_poisson(&rng, 5e-5 * 400.0 * 400.0);
            const double tx[2] = {50.0 + 3.0 * k, 50.0 + 3.0 * k};
            const double ty[2] = {60.0 + 2.0 * k, 300.0 - 2.0 * k};
            for (i = 0; i < 2; ++i) {
                if (sim_unif(&rng) < 0.9) {
                    m[nm++] = sim_meas(to_q(tx[i] + sim_gauss(&rng), F_POS), to_q(ty[i] + sim_gauss(&rng), F_POS),
                                       to_q(0.0, F_POS), 0);
                }
            }
            for (c = 0; c < nc && nm < 40u; ++c) {
                m[nm++] = sim_meas(to_q(400.0 * sim_unif(&rng), F_POS), to_q(400.0 * sim_unif(&rng), F_POS),
                                   to_q(0.0, F_POS), 0);
            }
            TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, to_q((double)k, F_TIME), m, nm));
        }
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&trk, &n));
        for (i = 0; i < n; ++i) {
            mtt_track_view v;
            int t;
            TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, i, &v));
            if (!v.confirmed) {
                continue;
            }
            ++confirmed;
            for (t = 0; t < 2; ++t) {
                const double ex = 50.0 + 3.0 * 49 - from_q(v.x[0], F_POS);
                const double ey = ((t == 0) ? 60.0 + 2.0 * 49 : 300.0 - 2.0 * 49) - from_q(v.x[1], F_POS);
                if (ex * ex + ey * ey < 9.0) { /* within 3 sigma */
                    near[t]++;
                }
            }
        }
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&trk, &st));
        TEST_ASSERT_EQUAL_UINT32(50u, st.total.frames);
        TEST_ASSERT_EQUAL_UINT32(0u, st.total.numeric_deletions);
        TEST_ASSERT_EQUAL_INT_MESSAGE(1, near[0], "target 1: one confirmed track within 3 sigma");
        TEST_ASSERT_EQUAL_INT_MESSAGE(1, near[1], "target 2: one confirmed track within 3 sigma");
        TEST_ASSERT_EQUAL_INT_MESSAGE(2, confirmed, "no confirmed false track");
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_settings_round_trip_in_user_units);
    RUN_TEST(test_fixed_build_refusals);
    RUN_TEST(test_time_steps_and_wrap);
    RUN_TEST(test_seed_view_round_trip);
    RUN_TEST(test_single_target_against_reference);
    RUN_TEST(test_merge_at_two_exponents);
    RUN_TEST(test_saturated_ipda_row);
    RUN_TEST(test_two_targets_in_clutter);
    return UNITY_END();
}
