/* motion_ca.c - nearly constant acceleration (CA) model: F and Q.
 *
 * ALGORITHMS.md §14.1 (a mode of the IMM; [S3] model 4): state
 * [x y vx vy ax ay], continuous white-noise jerk of power spectral density q
 * per axis (q in length^2/time^5), the third-order analogue of the CV
 * model of ALGORITHMS.md §2 (Bar-Shalom and Li, "Estimation and Tracking").
 * Per axis, state [p v a]:
 *   F = [[1, T, T^2/2], [0, 1, T], [0, 0, 1]]
 *   Q = q [[T^5/20, T^4/8, T^3/6], [T^4/8, T^3/3, T^2/2], [T^3/6, T^2/2, T]]
 * The axes are independent; the 6x6 matrices interleave them. */
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

#endif /* MTT_WITH_IMM */
