/* SPDX-License-Identifier: BSD-3-Clause */
/* motion_ct.c - coordinated-turn (CT) model with unknown turn rate: the
 * state transition, its Jacobian (extended Kalman prediction) and Q.
 *
 * ALGORITHMS.md §14.1 (a mode of the IMM; X. R. Li and V. Jilkov, "Survey
 * of maneuvering target tracking, Part I", 2003, §V.B).  State
 * [x y vx vy w], w the turn rate in rad/time (positive counter-clockwise).
 * With s = sin(wT), c = cos(wT):
 *   x'  = x + vx s/w - vy (1 - c)/w      vx' = c vx - s vy
 *   y'  = y + vx (1 - c)/w + vy s/w      vy' = s vx + c vy,   w' = w
 * The speed is kept; the velocity turns by wT.  w = 0 is the CV model.
 * Q: the CV model's white-noise acceleration (ALGORITHMS.md §2, PSD sw per
 * axis) on [x y vx vy] plus white noise of PSD sw_turn (rad^2/time^3) on
 * w, Q_ww = sw_turn T -- the usual approximation (the exact Q of a turning
 * target rotates with the velocity; its trace is the same).
 * mtt_ct_predict is the extended Kalman prediction with them:
 * xp = f(x), Pp = F P F' + Q with F the Jacobian at x. */
#include "mtt_internal.h"

#if MTT_WITH_IMM_CACT

/* Below this |wT| the four turn coefficients come from their Taylor
 * series: the closed forms of the w-derivatives cancel (float keeps
 * 2e-5 relative at 0.1), the series' first omitted term is at most
 * 2e-10 relative there. */
#define MTT_CT_SMALL MTT_R(0.1)

/* a = s/w, b = (1 - c)/w and their derivatives da, db with respect to w. */
static void ct_coef(mtt_real dt, mtt_real w, mtt_real *a, mtt_real *b, mtt_real *da, mtt_real *db,
                    mtt_real *s, mtt_real *c)
{
    const mtt_real th = w * dt;
    *s = mtt_sin(th);
    *c = mtt_cos(th);
    if (mtt_fabs(th) < MTT_CT_SMALL) {
        const mtt_real t2 = th * th;
        *a = dt * (MTT_R(1.0) - t2 / MTT_R(6.0) * (MTT_R(1.0) - t2 / MTT_R(20.0)));
        *b = dt * th * (MTT_R(0.5) - t2 / MTT_R(24.0) * (MTT_R(1.0) - t2 / MTT_R(30.0)));
        *da = dt * dt * th * (-MTT_R(1.0) / MTT_R(3.0) + t2 / MTT_R(30.0) * (MTT_R(1.0) - t2 / MTT_R(28.0)));
        *db = dt * dt * (MTT_R(0.5) - t2 / MTT_R(8.0) * (MTT_R(1.0) - t2 / MTT_R(18.0)));
    } else {
        /* 1 - c = 2 sin^2(th/2): no cancellation for small th. */
        const mtt_real h = mtt_sin(MTT_R(0.5) * th);
        const mtt_real omc = MTT_R(2.0) * h * h;
        *a = *s / w;
        *b = omc / w;
        *da = (th * *c - *s) / (w * w);
        *db = (th * *s - omc) / (w * w);
    }
}

void mtt_ct_f(mtt_real dt, const mtt_real x[MTT_CT_N], mtt_real xp[MTT_CT_N], mtt_real F[][MTT_MAX_STATE])
{
    mtt_real a, b, da, db, s, c;
    const mtt_real vx = x[2], vy = x[3];
    int i, j;
    ct_coef(dt, x[4], &a, &b, &da, &db, &s, &c);
    xp[0] = x[0] + a * vx - b * vy;
    xp[1] = x[1] + b * vx + a * vy;
    xp[2] = c * vx - s * vy;
    xp[3] = s * vx + c * vy;
    xp[4] = x[4];
    for (i = 0; i < MTT_CT_N; ++i) {
        for (j = 0; j < MTT_CT_N; ++j) {
            F[i][j] = (i == j) ? MTT_R(1.0) : MTT_R(0.0);
        }
    }
    F[0][2] = a;  F[0][3] = -b; F[0][4] = da * vx - db * vy;
    F[1][2] = b;  F[1][3] = a;  F[1][4] = db * vx + da * vy;
    F[2][2] = c;  F[2][3] = -s; F[2][4] = -dt * (s * vx + c * vy);
    F[3][2] = s;  F[3][3] = c;  F[3][4] = dt * (c * vx - s * vy);
}

void mtt_ct_q(mtt_real dt, mtt_real sw, mtt_real sw_turn, mtt_real Q[][MTT_MAX_STATE])
{
    mtt_cov q4;
    int i, j;
    mtt_motion_q(dt, sw, q4);
    for (i = 0; i < MTT_CT_N; ++i) {
        for (j = 0; j < MTT_CT_N; ++j) {
            Q[i][j] = (i < 4 && j < 4) ? q4[i][j] : MTT_R(0.0);
        }
    }
    Q[4][4] = sw_turn * dt;
}

void mtt_ct_predict(mtt_real dt, mtt_real sw, mtt_real sw_turn, const mtt_real x[], mtt_real P[][MTT_MAX_STATE],
                    mtt_real xp[], mtt_real Pp[][MTT_MAX_STATE])
{
    mtt_real F[MTT_MAX_STATE][MTT_MAX_STATE], Q[MTT_MAX_STATE][MTT_MAX_STATE];
    mtt_real FP[MTT_CT_N][MTT_CT_N], xn[MTT_CT_N];
    int i, j, k;
    mtt_ct_f(dt, x, xn, F);
    mtt_ct_q(dt, sw, sw_turn, Q);
    /* F P: F is I except rows 0 to 3, which reach columns 2 to 4 only */
    for (i = 0; i < MTT_CT_N; ++i) {
        for (j = 0; j < MTT_CT_N; ++j) {
            mtt_real v = (i < 2) ? P[i][j] : MTT_R(0.0);
            for (k = 2; k < MTT_CT_N; ++k) {
                v += F[i][k] * P[k][j];
            }
            FP[i][j] = (i == 4) ? P[4][j] : v;
        }
    }
    /* (F P) F' + Q, upper triangle mirrored (so that Pp may be P, after
     * F P is formed) */
    for (i = 0; i < MTT_CT_N; ++i) {
        for (j = i; j < MTT_CT_N; ++j) {
            mtt_real v = (j < 2) ? FP[i][j] : MTT_R(0.0);
            for (k = 2; k < MTT_CT_N; ++k) {
                v += FP[i][k] * F[j][k];
            }
            v = ((j == 4) ? FP[i][4] : v) + Q[i][j];
            Pp[i][j] = v;
            Pp[j][i] = v;
        }
    }
    for (i = 0; i < MTT_CT_N; ++i) {
        xp[i] = xn[i];
    }
}

#endif /* MTT_WITH_IMM_CACT */
