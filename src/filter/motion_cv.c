/* SPDX-License-Identifier: BSD-3-Clause */
/* motion_cv.c - the constant-velocity motion model behind the seam of
 * motion.h (ALGORITHMS.md §2; its two-point start §12.1).
 *
 * State [x, y, vx, vy]; continuous white-noise acceleration of power
 * spectral density Sw:
 *   F = [[I, dt I], [0, I]],
 *   Q = Sw [[dt^3/3 I, dt^2/2 I], [dt^2/2 I, dt I]];
 * two points z_a (time k-1) and z_b (k), dt apart:
 *   x = [z_b, (z_b - z_a)/dt], P = [[R, R/dt], [R/dt, 2R/dt^2]]. */
#include <string.h>

#include "mtt_internal.h"

void mtt_motion_q(mtt_real dt, mtt_real sw, mtt_cov Q)
{
#ifdef MTT_REAL_FIXED
    mtt_fx_cov_q(dt, sw, Q); /* mantissas and one exponent (fx_cov.c) */
#else
    mtt_real q11 = sw * dt * dt * dt / MTT_R(3.0);
    mtt_real q13 = sw * dt * dt / MTT_R(2.0);
    mtt_real q33 = sw * dt;
    int i, j;
    for (i = 0; i < MTT_STATE_N; ++i) {
        for (j = 0; j < MTT_STATE_N; ++j) {
            Q[i][j] = MTT_R(0.0);
        }
    }
    Q[0][0] = q11; Q[1][1] = q11;
    Q[0][2] = q13; Q[2][0] = q13; Q[1][3] = q13; Q[3][1] = q13;
    Q[2][2] = q33; Q[3][3] = q33;
#endif
}

void mtt_motion_predict(mtt_real dt, mtt_cov Q0, const mtt_state x, mtt_cov P, mtt_state xp,
                        mtt_cov Pp)
{
    mtt_cov FP;
#ifdef MTT_REAL_FIXED
    mtt_cov Q; /* the caller's Q serves every track: aligned below in a copy */
    memcpy(Q, Q0, sizeof Q);
#else
    mtt_real(*const Q)[MTT_MAX_STATE] = Q0; /* read only (no alignment in float) */
#endif
    int i, j;
    xp[0] = MTT_ADDS(x[0], MTT_MUL_T(dt, x[2]));
    xp[1] = MTT_ADDS(x[1], MTT_MUL_T(dt, x[3]));
    xp[2] = x[2];
    xp[3] = x[3];
    /* Fixed point: P rescaled so the sums below cannot overflow. */
    MTT_COV_FIT(P, dt);
    /* F P: rows 0,1 gain dt times rows 2,3 (F is sparse; no 4x4 product). */
    for (j = 0; j < 4; ++j) {
        FP[0][j] = MTT_ADD(P[0][j], MTT_MUL_T(dt, P[2][j]));
        FP[1][j] = MTT_ADD(P[1][j], MTT_MUL_T(dt, P[3][j]));
        FP[2][j] = P[2][j];
        FP[3][j] = P[3][j];
    }
    MTT_COV_COPY_E(FP, P);
    MTT_COV_ALIGN(FP, Q);
    /* (F P) F': columns 0,1 gain dt times columns 2,3. */
    for (i = 0; i < 4; ++i) {
        Pp[i][0] = MTT_ADD(MTT_ADD(FP[i][0], MTT_MUL_T(dt, FP[i][2])), Q[i][0]);
        Pp[i][1] = MTT_ADD(MTT_ADD(FP[i][1], MTT_MUL_T(dt, FP[i][3])), Q[i][1]);
        Pp[i][2] = MTT_ADD(FP[i][2], Q[i][2]);
        Pp[i][3] = MTT_ADD(FP[i][3], Q[i][3]);
    }
    MTT_COV_COPY_E(Pp, FP);
}

#ifdef MTT_REAL_FIXED
/* The velocity cap of the float text below, on the two-point blocks before
 * they meet at one exponent (so a capped P keeps the position block's
 * precision): c^2 = vmax^2 / max(2R/dt^2) when that is below 1, as the
 * mantissa cm (Q30, at least 29 bits) of c = cm 2^-30 2^-z; returns 1 and
 * sets *z, or 0 for no cap.  v: the 2R/dt^2 block at exponent e3. */
static int cap_factor(const int32_t v[3], int e3, mtt_real vmax, int32_t *cm, int *z)
{
    const int32_t vv = (v[0] > v[2]) ? v[0] : v[2];
    int32_t vm, cap, q;
    int a, g, t;
    if (!(vv > 0) || !(vmax > 0)) {
        return 0;
    }
    a = -mtt_fx_top_exp(0, (uint32_t)vmax, 30);
    vm = mtt_fx_shift(vmax, a);
    cap = mtt_fx_mulq(vm, vm, 30); /* vmax^2 at 2^ec, ec = 30 - 2 (F + a) */
    /* q = cap 2^g / vv on 28 or 29 bits; cap / vv = q 2^-t with t even */
    g = 28 + mtt_fx_top_exp(0, (uint32_t)vv, 0) - mtt_fx_top_exp(0, (uint32_t)cap, 0);
    t = g - (30 - 2 * (MTT_FX_POS_FRAC + a)) + e3;
    if (t & 1) {
        ++g;
        ++t;
    }
    if (t <= 0 || g < 0 || g > 62) {
        return 0; /* cap / vv >= q >= 2^27, or far outside the formats */
    }
    q = mtt_fx_div(cap, vv, g);
    if (t < 31 && !(q < ((int32_t)1 << t))) {
        return 0; /* vv <= vmax^2: nothing to cap */
    }
    *cm = (int32_t)mtt_fx_sqrt((uint32_t)q, 30); /* sqrt(q 2^-30): c = cm 2^-30 2^(15 - t/2) */
    *z = t / 2 - 15;
    return 1;
}

/* Fixed point (docs/FIXED_POINT.md §2): Ra, Rb (Q16) on 29 bits, 1/dt from
 * dt's mantissa dm in [2^29, 2^30] (dt = dm 2^de): Rb/dt and (Ra + Rb)/dt^2
 * are quotients by dm at their own exponents, scaled by c and c^2 when vmax
 * > 0 caps them; the three blocks meet at the largest exponent, then P is
 * renormalised.  Ra == Rb (one R): 2R/dt^2 is R/dt^2 at the next exponent,
 * the text every one-R birth has taken. */
static void two_point_fx(const mtt_real Ra[3], const mtt_real Rb[3], mtt_real dt, mtt_real vmax, mtt_cov P)
{
    int32_t r[3], q[3], v[3], cm = 0;
    int de, k, i, j, e1, e2, e3, E, z = 0;
    const int32_t dm = mtt_fx_unpack(dt, MTT_FX_T_FRAC, &de);
    const int sh = mtt_fx_top_exp(0, mtt_fx_or_abs(Ra, 3) | mtt_fx_or_abs(Rb, 3), 29);
    e1 = -MTT_FX_VAR_FRAC + sh;
    e2 = e1 - de - 29;
    e3 = e2 - de - 29 + ((Ra == Rb) ? 1 : 0); /* the factor 2 of one R */
    for (k = 0; k < 3; ++k) {
        r[k] = mtt_fx_shift(Rb[k], -sh);
        q[k] = mtt_fx_div(r[k], dm, 29);
        /* Ra + Rb below 2^30: its quotients too */
        v[k] = (Ra == Rb) ? mtt_fx_div(q[k], dm, 29)
                          : mtt_fx_div(mtt_fx_div(r[k] + mtt_fx_shift(Ra[k], -sh), dm, 29), dm, 29);
    }
    if (cap_factor(v, e3, vmax, &cm, &z)) {
        for (k = 0; k < 3; ++k) {
            q[k] = mtt_fx_mulq(q[k], cm, 30);
            v[k] = mtt_fx_mulq(mtt_fx_mulq(v[k], cm, 30), cm, 30);
        }
        e2 -= z;
        e3 -= 2 * z;
    }
    E = (e2 > e1) ? e2 : e1;
    E = (e3 > E) ? e3 : E;
    for (i = 0; i < 2; ++i) {
        for (j = 0; j < 2; ++j) {
            k = i + j; /* r11, r12, r22 */
            P[i][j] = mtt_fx_shift(r[k], e1 - E);
            P[i][j + 2] = mtt_fx_shift(q[k], e2 - E);
            P[i + 2][j] = P[i][j + 2];
            P[i + 2][j + 2] = mtt_fx_shift(v[k], e3 - E);
        }
    }
    MTT_COV_E(P) = E;
    MTT_COV_NORM(P);
}

void mtt_motion_two_point_cov(const mtt_real R[3], mtt_real dt, mtt_cov P)
{
    two_point_fx(R, R, dt, 0, P);
}

/* the two-point P with its velocity capped at vmax^2 (the float text's
 * [CHOICE] below), of one R and of two */
#define TWO_POINT_CAPPED(R, dt, vmax, P) two_point_fx((R), (R), (dt), (vmax), (P))
#define TWO_POINT_OWN(Ra, Rb, dt, vmax, P) two_point_fx((Ra), (Rb), (dt), (vmax), (P))

#else /* float, double */

/* The two-point P of detections with covariances Ra (at k-1) and Rb (at
 * k): position Rb, velocity (Ra + Rb)/dT^2, their covariance Rb/dT
 * (ALGORITHMS.md §12.1, §3.1). */
static void two_point_cov2(const mtt_real Ra[3], const mtt_real Rb[3], mtt_real dt, mtt_cov P)
{
    const mtt_real a[2][2] = {{Ra[0], Ra[1]}, {Ra[1], Ra[2]}};
    const mtt_real b[2][2] = {{Rb[0], Rb[1]}, {Rb[1], Rb[2]}};
    int i, j;
    for (i = 0; i < 2; ++i) {
        for (j = 0; j < 2; ++j) {
            P[i][j] = b[i][j];
            P[i][j + 2] = b[i][j] / dt;
            P[i + 2][j] = b[i][j] / dt;
            P[i + 2][j + 2] = (a[i][j] + b[i][j]) / (dt * dt); /* 2R when Ra = Rb: exactly R + R */
        }
    }
}

void mtt_motion_two_point_cov(const mtt_real R[3], mtt_real dt, mtt_cov P)
{
    two_point_cov2(R, R, dt, P);
}

/* [CHOICE] The velocity gate says |v| <= vmax, but the two-point velocity
 * variance 2R/dT^2 exceeds vmax^2 when dT < sqrt(2) sigma / vmax, i.e. when
 * the two detections are closer in time than the noise can resolve.  Then
 * the velocity rows and columns are scaled (P <- D P D, D = diag(1, 1, c,
 * c)) so that the larger velocity variance is vmax^2: still positive
 * definite, same correlations as ALGORITHMS.md §12.1.  Unscaled, a float
 * track turns singular at its first prediction (fuzz finding F6: sigma 32,
 * dT 1e-6).  With ordinary frame intervals (dT >= sqrt(2) sigma / vmax)
 * this does nothing. */
static void cap_velocity(mtt_cov P, mtt_real vmax)
{
    const mtt_real vv = (P[2][2] > P[3][3]) ? P[2][2] : P[3][3];
    const mtt_real cap = vmax * vmax;
    mtt_real c;
    int i;
    if (!(vv > cap)) {
        return;
    }
    c = mtt_sqrt(cap / vv);
    for (i = 0; i < 4; ++i) {
        P[i][2] *= c;
        P[i][3] *= c;
    }
    for (i = 0; i < 4; ++i) {
        P[2][i] *= c;
        P[3][i] *= c;
    }
}

#define TWO_POINT_CAPPED(R, dt, vmax, P) (mtt_motion_two_point_cov((R), (dt), (P)), cap_velocity((P), (vmax)))
#define TWO_POINT_OWN(Ra, Rb, dt, vmax, P) (two_point_cov2((Ra), (Rb), (dt), (P)), cap_velocity((P), (vmax)))
#endif /* MTT_REAL_FIXED */

void mtt_motion_birth(const mtt_mstore *a, const mtt_mstore *b, mtt_real dt, const mtt_real R[3],
                      mtt_real vmax, mtt_state x, mtt_cov P)
{
    x[0] = b->x;
    x[1] = b->y;
    x[2] = MTT_DIV_T(MTT_SUBS(b->x, a->x), dt);
    x[3] = MTT_DIV_T(MTT_SUBS(b->y, a->y), dt);
#if MTT_WITH_MEAS_COV
    if (a->has_R || b->has_R) {
        TWO_POINT_OWN(a->has_R ? a->R : R, b->has_R ? b->R : R, dt, vmax, P);
        return;
    }
#endif
    TWO_POINT_CAPPED(R, dt, vmax, P);
}
