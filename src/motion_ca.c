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

#if MTT_WITH_IMM

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

void mtt_ca_model(mtt_real dt, mtt_real q, mtt_real F[][MTT_MAX_STATE], mtt_real Q[][MTT_MAX_STATE])
{
    mtt_real f[3][3], qa[3][3];
    int ax, i, j;
    mtt_ca_axis(dt, q, f, qa);
    for (i = 0; i < MTT_CA_N; ++i) {
        for (j = 0; j < MTT_CA_N; ++j) {
            F[i][j] = MTT_R(0.0);
            Q[i][j] = MTT_R(0.0);
        }
    }
    /* Axis ax occupies components ax (position), 2 + ax, 4 + ax. */
    for (ax = 0; ax < 2; ++ax) {
        for (i = 0; i < 3; ++i) {
            for (j = 0; j < 3; ++j) {
                F[2 * i + ax][2 * j + ax] = f[i][j];
                Q[2 * i + ax][2 * j + ax] = qa[i][j];
            }
        }
    }
}

/* F B F' of one 3x3 axis block B (rows axis a, columns axis b), written
 * out: F B adds T row 1 and T^2/2 row 2 to row 0, T row 2 to row 1; the
 * product with F' does the same to the columns. */
static void ca_block(mtt_real t, mtt_real h, mtt_real P[][MTT_MAX_STATE], int a, int b, mtt_real M[3][3])
{
    mtt_real r[3][3];
    int k;
    for (k = 0; k < 3; ++k) {
        const mtt_real b0 = P[a][2 * k + b], b1 = P[2 + a][2 * k + b], b2 = P[4 + a][2 * k + b];
        r[0][k] = b0 + t * b1 + h * b2;
        r[1][k] = b1 + t * b2;
        r[2][k] = b2;
    }
    for (k = 0; k < 3; ++k) {
        M[k][0] = r[k][0] + t * r[k][1] + h * r[k][2];
        M[k][1] = r[k][1] + t * r[k][2];
        M[k][2] = r[k][2];
    }
}

void mtt_ca_predict(mtt_real dt, mtt_real q, const mtt_real x[], mtt_real P[][MTT_MAX_STATE],
                    mtt_real xp[], mtt_real Pp[][MTT_MAX_STATE])
{
    mtt_real f[3][3], qa[3][3], M[3][3][3];
    const mtt_real h = MTT_R(0.5) * dt * dt;
    int a, i, j;
    mtt_ca_axis(dt, q, f, qa);
    for (a = 0; a < 2; ++a) {
        xp[a] = x[a] + dt * x[2 + a] + h * x[4 + a];
        xp[2 + a] = x[2 + a] + dt * x[4 + a];
        xp[4 + a] = x[4 + a];
    }
    /* the three distinct axis blocks first (so that Pp may be P), then the
     * diagonal blocks' upper triangles plus Q, and the x-y block, mirrored */
    for (a = 0; a < 3; ++a) {
        ca_block(dt, h, P, (a == 2) ? 0 : a, (a == 2) ? 1 : a, M[a]);
    }
    for (a = 0; a < 2; ++a) {
        for (i = 0; i < 3; ++i) {
            for (j = i; j < 3; ++j) {
                const mtt_real v = M[a][i][j] + qa[i][j];
                Pp[2 * i + a][2 * j + a] = v;
                Pp[2 * j + a][2 * i + a] = v;
            }
        }
    }
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j) {
            Pp[2 * i][2 * j + 1] = M[2][i][j];
            Pp[2 * j + 1][2 * i] = M[2][i][j];
        }
    }
}

#endif /* MTT_WITH_IMM */
