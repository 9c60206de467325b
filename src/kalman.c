/* kalman.c - constant-velocity model and Kalman filter steps.
 *
 * spec 2 (F, Q of continuous white-noise acceleration), spec 3 (predict,
 * closed-form S^-1, Joseph-form update, symmetrisation), spec 6 (the PDA
 * combined update, which with one measurement is also spec 7.4's IHPDA
 * update).  State [x, y, vx, vy], measurement [x, y], H = [I 0]. */
#include "mtt_internal.h"

void mtt_sym4(mtt_real P[4][4])
{
    int i, j;
    for (i = 0; i < 4; ++i) {
        for (j = i + 1; j < 4; ++j) {
            mtt_real s = MTT_R(0.5) * (P[i][j] + P[j][i]);
            P[i][j] = s;
            P[j][i] = s;
        }
    }
}

void mtt_cv_q(mtt_real dt, mtt_real sw, mtt_real Q[4][4])
{
    mtt_real q11 = sw * dt * dt * dt / MTT_R(3.0);
    mtt_real q13 = sw * dt * dt / MTT_R(2.0);
    mtt_real q33 = sw * dt;
    int i, j;
    for (i = 0; i < 4; ++i) {
        for (j = 0; j < 4; ++j) {
            Q[i][j] = MTT_R(0.0);
        }
    }
    Q[0][0] = q11; Q[1][1] = q11;
    Q[0][2] = q13; Q[2][0] = q13; Q[1][3] = q13; Q[3][1] = q13;
    Q[2][2] = q33; Q[3][3] = q33;
}

void mtt_kalman_predict(mtt_real dt, mtt_real sw, const mtt_real x[4], mtt_real P[4][4],
                        mtt_real xp[4], mtt_real Pp[4][4])
{
    mtt_real FP[4][4], Q[4][4];
    int i, j;
    xp[0] = x[0] + dt * x[2];
    xp[1] = x[1] + dt * x[3];
    xp[2] = x[2];
    xp[3] = x[3];
    /* F P: rows 0,1 gain dt times rows 2,3 (F is sparse; no 4x4 product). */
    for (j = 0; j < 4; ++j) {
        FP[0][j] = P[0][j] + dt * P[2][j];
        FP[1][j] = P[1][j] + dt * P[3][j];
        FP[2][j] = P[2][j];
        FP[3][j] = P[3][j];
    }
    mtt_cv_q(dt, sw, Q);
    /* (F P) F': columns 0,1 gain dt times columns 2,3. */
    for (i = 0; i < 4; ++i) {
        Pp[i][0] = FP[i][0] + dt * FP[i][2] + Q[i][0];
        Pp[i][1] = FP[i][1] + dt * FP[i][3] + Q[i][1];
        Pp[i][2] = FP[i][2] + Q[i][2];
        Pp[i][3] = FP[i][3] + Q[i][3];
    }
    mtt_sym4(Pp);
}

int mtt_kalman_innov(mtt_real Pp[4][4], const mtt_real R[3], mtt_real S[3],
                     mtt_real Si[3], mtt_real *det, mtt_real K[4][2])
{
    mtt_real d;
    int i;
    S[0] = Pp[0][0] + R[0];
    S[1] = MTT_R(0.5) * (Pp[0][1] + Pp[1][0]) + R[1];
    S[2] = Pp[1][1] + R[2];
    d = S[0] * S[2] - S[1] * S[1];
    if (!(d > MTT_R(0.0)) || !mtt_isfinite(d)) {
        return -1; /* spec 3: the track is numerically invalid */
    }
    *det = d;
    Si[0] = S[2] / d;
    Si[1] = -S[1] / d;
    Si[2] = S[0] / d;
    for (i = 0; i < 4; ++i) {
        K[i][0] = Pp[i][0] * Si[0] + Pp[i][1] * Si[1];
        K[i][1] = Pp[i][0] * Si[1] + Pp[i][1] * Si[2];
    }
    return 0;
}

mtt_real mtt_mahal2(const mtt_real Si[3], mtt_real nx, mtt_real ny)
{
    return Si[0] * nx * nx + MTT_R(2.0) * Si[1] * nx * ny + Si[2] * ny * ny;
}

/* Out = K M K' for a symmetric 2x2 M (m11, m12, m22), added with weight w. */
static void add_kmk(mtt_real K[4][2], mtt_real m11, mtt_real m12, mtt_real m22,
                    mtt_real w, mtt_real Out[4][4])
{
    int i, j;
    for (i = 0; i < 4; ++i) {
        mtt_real a = K[i][0] * m11 + K[i][1] * m12;
        mtt_real b = K[i][0] * m12 + K[i][1] * m22;
        for (j = 0; j < 4; ++j) {
            Out[i][j] += w * (a * K[j][0] + b * K[j][1]);
        }
    }
}

void mtt_kalman_joseph(mtt_real Pp[4][4], mtt_real K[4][2], const mtt_real R[3],
                       mtt_real Pc[4][4])
{
    mtt_real AP[4][4];
    int i, j;
    /* A = I - K H; A Pp = Pp - K (rows 0,1 of Pp). */
    for (i = 0; i < 4; ++i) {
        for (j = 0; j < 4; ++j) {
            AP[i][j] = Pp[i][j] - K[i][0] * Pp[0][j] - K[i][1] * Pp[1][j];
        }
    }
    /* (A Pp) A' = AP - (columns 0,1 of AP) K'. */
    for (i = 0; i < 4; ++i) {
        for (j = 0; j < 4; ++j) {
            Pc[i][j] = AP[i][j] - AP[i][0] * K[j][0] - AP[i][1] * K[j][1];
        }
    }
    add_kmk(K, R[0], R[1], R[2], MTT_R(1.0), Pc);
    mtt_sym4(Pc);
}

void mtt_kalman_pda(const mtt_real xp[4], mtt_real Pp[4][4], mtt_real K[4][2],
                    const mtt_real R[3], uint16_t m, mtt_real nu[][2],
                    const mtt_real beta[], mtt_real beta0, mtt_real x[4], mtt_real P[4][4])
{
    mtt_real Pc[4][4];
    mtt_real cx = MTT_R(0.0), cy = MTT_R(0.0);
    mtt_real sxx = MTT_R(0.0), sxy = MTT_R(0.0), syy = MTT_R(0.0);
    uint16_t j;
    int i, k;
    for (j = 0; j < m; ++j) {
        cx += beta[j] * nu[j][0];
        cy += beta[j] * nu[j][1];
        sxx += beta[j] * nu[j][0] * nu[j][0];
        sxy += beta[j] * nu[j][0] * nu[j][1];
        syy += beta[j] * nu[j][1] * nu[j][1];
    }
    for (i = 0; i < 4; ++i) {
        x[i] = xp[i] + K[i][0] * cx + K[i][1] * cy;
    }
    mtt_kalman_joseph(Pp, K, R, Pc);
    for (i = 0; i < 4; ++i) {
        for (k = 0; k < 4; ++k) {
            P[i][k] = beta0 * Pp[i][k] + (MTT_R(1.0) - beta0) * Pc[i][k];
        }
    }
    /* Spread of the innovations: sum beta nu nu' - nu_c nu_c' (spec 6, with
     * the S1 Table 2 erratum applied). */
    add_kmk(K, sxx - cx * cx, sxy - cx * cy, syy - cy * cy, MTT_R(1.0), P);
    mtt_sym4(P);
}

int mtt_chol4_quad(mtt_real A[4][4], const mtt_real b[4], mtt_real *d2)
{
    mtt_real L[4][4], y[4] = {MTT_R(0.0), MTT_R(0.0), MTT_R(0.0), MTT_R(0.0)}; /* zeroed for static analysis: each y[k] is written before it is read */
    mtt_real acc = MTT_R(0.0);
    int i, j, k;
    for (i = 0; i < 4; ++i) {
        for (j = 0; j <= i; ++j) {
            mtt_real s = A[i][j];
            for (k = 0; k < j; ++k) {
                s -= L[i][k] * L[j][k];
            }
            if (i == j) {
                if (!(s > MTT_R(0.0)) || !mtt_isfinite(s)) {
                    return -1;
                }
                L[i][i] = mtt_sqrt(s);
            } else {
                L[i][j] = s / L[j][j];
            }
        }
    }
    /* b' A^-1 b = |L^-1 b|^2: one forward substitution. */
    for (i = 0; i < 4; ++i) {
        mtt_real s = b[i];
        for (k = 0; k < i; ++k) {
            s -= L[i][k] * y[k];
        }
        y[i] = s / L[i][i];
        acc += y[i] * y[i];
    }
    *d2 = acc;
    return 0;
}
