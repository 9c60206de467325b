/* SPDX-License-Identifier: BSD-3-Clause */
/* motion_ca.c - nearly constant acceleration (CA) model: F and Q.
 *
 * ALGORITHMS.md §14.1 (a mode of the IMM; [S3] model 4): state
 * [x y vx vy ax ay], continuous white-noise jerk of power spectral density q
 * per axis (q in length^2/time^5), the third-order analogue of the CV
 * model of ALGORITHMS.md §2 (Bar-Shalom and Li, "Estimation and Tracking").
 * Per axis, state [p v a]:
 *   F = [[1, T, T^2/2], [0, 1, T], [0, 0, 1]]
 *   Q = q [[T^5/20, T^4/8, T^3/6], [T^4/8, T^3/3, T^2/2], [T^3/6, T^2/2, T]]
 * The axes are independent; the 6x6 matrices interleave them.
 * mtt_ca_predict applies them without forming the 6x6 products: F acts
 * per axis on 3x3 blocks (three terms per element at most), Q only on the
 * two diagonal blocks, and the x-y block gives its transpose: symmetric by
 * construction. */
#include "mtt_internal.h"

#if MTT_WITH_IMM_CACT

void mtt_ca_axis(mtt_real dt, mtt_real q, mtt_real F[3][3], mtt_real Q[3][3])
{
    const mtt_real t2 = dt * dt, t3 = t2 * dt;
    F[0][0] = MTT_R(1.0); F[0][1] = dt;         F[0][2] = MTT_R(0.5) * t2;
    F[1][0] = MTT_R(0.0); F[1][1] = MTT_R(1.0); F[1][2] = dt;
    F[2][0] = MTT_R(0.0); F[2][1] = MTT_R(0.0); F[2][2] = MTT_R(1.0);
    Q[0][0] = q * t3 * t2 / MTT_R(20.0);
    Q[0][1] = q * t2 * t2 / MTT_R(8.0);
    Q[0][2] = q * t3 / MTT_R(6.0);
    Q[1][1] = q * t3 / MTT_R(3.0);
    Q[1][2] = q * t2 / MTT_R(2.0);
    Q[2][2] = q * dt;
    Q[1][0] = Q[0][1];
    Q[2][0] = Q[0][2];
    Q[2][1] = Q[1][2];
}

/* F B F' of one 3x3 axis block B (rows axis a, columns axis b), written
 * out: F B adds T row 1 and T^2/2 row 2 to row 0, T row 2 to row 1; the
 * product with F' does the same to the columns. */
static void ca_block(mtt_real t, mtt_real h, mtt_real P[][MTT_MAX_STATE], int a, int b, mtt_real M[3][3])
{
    const mtt_real *p0 = P[a], *p1 = P[2 + a], *p2 = P[4 + a];
    /* F B, column by column (columns b, 2 + b, 4 + b of P) */
    const mtt_real r00 = p0[b] + t * p1[b] + h * p2[b], r10 = p1[b] + t * p2[b], r20 = p2[b];
    const mtt_real r01 = p0[2 + b] + t * p1[2 + b] + h * p2[2 + b], r11 = p1[2 + b] + t * p2[2 + b], r21 = p2[2 + b];
    const mtt_real r02 = p0[4 + b] + t * p1[4 + b] + h * p2[4 + b], r12 = p1[4 + b] + t * p2[4 + b], r22 = p2[4 + b];
    /* (F B) F', row by row */
    M[0][0] = r00 + t * r01 + h * r02;
    M[0][1] = r01 + t * r02;
    M[0][2] = r02;
    M[1][0] = r10 + t * r11 + h * r12;
    M[1][1] = r11 + t * r12;
    M[1][2] = r12;
    M[2][0] = r20 + t * r21 + h * r22;
    M[2][1] = r21 + t * r22;
    M[2][2] = r22;
}

void mtt_ca_predict(mtt_real dt, mtt_real q, const mtt_real x[], mtt_real P[][MTT_MAX_STATE],
                    mtt_real xp[], mtt_real Pp[][MTT_MAX_STATE])
{
    mtt_real f[3][3], qa[3][3], M[3][3][3];
    const mtt_real h = MTT_R(0.5) * dt * dt;
    int a, i;
    mtt_ca_axis(dt, q, f, qa);
    for (a = 0; a < 2; ++a) {
        xp[a] = x[a] + dt * x[2 + a] + h * x[4 + a];
        xp[2 + a] = x[2 + a] + dt * x[4 + a];
        xp[4 + a] = x[4 + a];
    }
    /* the three distinct axis blocks first (so that Pp may be P): x-x,
     * y-y, x-y */
    ca_block(dt, h, P, 0, 0, M[0]);
    ca_block(dt, h, P, 1, 1, M[1]);
    ca_block(dt, h, P, 0, 1, M[2]);
    /* the diagonal blocks' upper triangles plus Q, mirrored (Q is
     * symmetric: M + Q's lower triangle is its upper one's mirror) */
    for (a = 0; a < 2; ++a) {
        mtt_real(*m)[3] = M[a];
        Pp[a][a] = m[0][0] + qa[0][0];
        Pp[2 + a][2 + a] = m[1][1] + qa[1][1];
        Pp[4 + a][4 + a] = m[2][2] + qa[2][2];
        Pp[a][2 + a] = Pp[2 + a][a] = m[0][1] + qa[0][1];
        Pp[a][4 + a] = Pp[4 + a][a] = m[0][2] + qa[0][2];
        Pp[2 + a][4 + a] = Pp[4 + a][2 + a] = m[1][2] + qa[1][2];
    }
    /* the x-y block and its transpose */
    for (i = 0; i < 6; i += 2) {
        const mtt_real *m = M[2][i / 2];
        Pp[i][1] = Pp[1][i] = m[0];
        Pp[i][3] = Pp[3][i] = m[1];
        Pp[i][5] = Pp[5][i] = m[2];
    }
}

#endif /* MTT_WITH_IMM_CACT */
