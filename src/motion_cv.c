/* motion_cv.c - the constant-velocity motion model behind the seam of
 * motion.h (ALGORITHMS.md §2; its two-point start §12.1).
 *
 * State [x, y, vx, vy]; continuous white-noise acceleration of power
 * spectral density Sw:
 *   F = [[I, dt I], [0, I]],
 *   Q = Sw [[dt^3/3 I, dt^2/2 I], [dt^2/2 I, dt I]];
 * two points z_a (time k-1) and z_b (k), dt apart:
 *   x = [z_b, (z_b - z_a)/dt], P = [[R, R/dt], [R/dt, 2R/dt^2]]. */
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

void mtt_motion_predict(mtt_real dt, mtt_real sw, const mtt_state x, mtt_cov P, mtt_state xp,
                        mtt_cov Pp)
{
    mtt_cov FP, Q;
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
    mtt_motion_q(dt, sw, Q);
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

#ifndef MTT_REAL_FIXED /* not yet converted (docs/FIXED_POINT.md, Status) */

void mtt_motion_two_point_cov(const mtt_real R[3], mtt_real dt, mtt_cov P)
{
    const mtt_real r[2][2] = {{R[0], R[1]}, {R[1], R[2]}};
    int i, j;
    for (i = 0; i < 2; ++i) {
        for (j = 0; j < 2; ++j) {
            P[i][j] = r[i][j];
            P[i][j + 2] = r[i][j] / dt;
            P[i + 2][j] = r[i][j] / dt;
            P[i + 2][j + 2] = MTT_R(2.0) * r[i][j] / (dt * dt);
        }
    }
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

void mtt_motion_birth(const mtt_mstore *a, const mtt_mstore *b, mtt_real dt, const mtt_real R[3],
                      mtt_real vmax, mtt_state x, mtt_cov P)
{
    x[0] = b->x;
    x[1] = b->y;
    x[2] = (b->x - a->x) / dt;
    x[3] = (b->y - a->y) / dt;
    mtt_motion_two_point_cov(R, dt, P);
    cap_velocity(P, vmax);
}
#endif /* MTT_REAL_FIXED */
