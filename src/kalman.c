/* kalman.c - the Kalman filter steps on the motion model of motion.h
 * (ALGORITHMS.md §3: predict, closed-form S^-1, Joseph-form update,
 * symmetrisation; §6: the PDA combined update, which with one measurement
 * is also §7.4's IHPDA update), and the small dense helpers they and the
 * merge test share (L D L', positive-definite test).  H = [I 0]
 * (motion.h): S and K read the position block of P only. */
#include "mtt_internal.h"

void mtt_sym(mtt_cov P)
{
    int i, j;
    for (i = 0; i < MTT_STATE_N; ++i) {
        for (j = i + 1; j < MTT_STATE_N; ++j) {
            mtt_real s = MTT_MEAN2(P[i][j], P[j][i]);
            P[i][j] = s;
            P[j][i] = s;
        }
    }
}

int mtt_state_finite(const mtt_real *x)
{
    int i;
    for (i = 0; i < MTT_STATE_N; ++i) {
        if (!mtt_isfinite(x[i])) {
            return 0;
        }
    }
    return 1;
}

void mtt_kalman_predict(mtt_real dt, mtt_real sw, const mtt_state x, mtt_cov P, mtt_state xp,
                        mtt_cov Pp)
{
    mtt_motion_predict(dt, sw, x, P, xp, Pp);
    mtt_sym(Pp);
    MTT_COV_NORM(Pp);
}

/* The n-state bodies: one caller with a constant n (MTT_STATE_N) in a
 * build without IMM, so the firmware code is the fixed-size one. */
static int innov_n(int n, mtt_cov Pp, const mtt_real R[3], mtt_real S[MTT_SYM_SLOTS],
                   mtt_real Si[MTT_SYM_SLOTS], mtt_real *det, mtt_real K[][2])
{
    mtt_real d;
    int i;
    if (n < MTT_MEAS_DIM || n > MTT_MAX_STATE) {
        return -1; /* not a model of motion.h (folded away for a constant n) */
    }
    /* Fixed point: Pp and R (Q16) meet at S's exponent (mtt/real.h). */
    MTT_S_EXP(Pp, R, S);
    S[0] = MTT_ADD(MTT_AT(Pp[0][0], MTT_COV_E(Pp), MTT_SYM_E(S)),
                   MTT_AT(R[0], -MTT_FX_VAR_FRAC, MTT_SYM_E(S)));
    S[1] = MTT_ADD(MTT_MEAN2(MTT_AT(Pp[0][1], MTT_COV_E(Pp), MTT_SYM_E(S)),
                             MTT_AT(Pp[1][0], MTT_COV_E(Pp), MTT_SYM_E(S))),
                   MTT_AT(R[1], -MTT_FX_VAR_FRAC, MTT_SYM_E(S)));
    S[2] = MTT_ADD(MTT_AT(Pp[1][1], MTT_COV_E(Pp), MTT_SYM_E(S)),
                   MTT_AT(R[2], -MTT_FX_VAR_FRAC, MTT_SYM_E(S)));
    d = MTT_SUB(MTT_MUL_SS(S[0], S[2]), MTT_MUL_SS(S[1], S[1]));
    if (!(d > MTT_ZERO) || !mtt_isfinite(d)) {
        return -1; /* ALGORITHMS.md §3: the track is numerically invalid */
    }
    *det = d;
    MTT_SI_EXP(Si, S, d);
    Si[0] = MTT_DIV_SI(S[2], d, S, Si);
    Si[1] = MTT_DIV_SI(-S[1], d, S, Si);
    Si[2] = MTT_DIV_SI(S[0], d, S, Si);
    for (i = 0; i < n; ++i) {
        K[i][0] = MTT_ADD(MTT_MUL_K(Pp[i][0], Si[0]), MTT_MUL_K(Pp[i][1], Si[1]));
        K[i][1] = MTT_ADD(MTT_MUL_K(Pp[i][0], Si[1]), MTT_MUL_K(Pp[i][1], Si[2]));
    }
    return 0;
}

int mtt_kalman_innov(mtt_cov Pp, const mtt_real R[3], mtt_real S[MTT_SYM_SLOTS],
                     mtt_real Si[MTT_SYM_SLOTS], mtt_real *det, mtt_real K[][2])
{
    return innov_n(MTT_STATE_N, Pp, R, S, Si, det, K);
}

#if MTT_WITH_IMM
int mtt_kalman_innov_n(int n, mtt_cov Pp, const mtt_real R[3], mtt_real S[MTT_SYM_SLOTS],
                       mtt_real Si[MTT_SYM_SLOTS], mtt_real *det, mtt_real K[][2])
{
    return innov_n(n, Pp, R, S, Si, det, K);
}
#endif

mtt_d2 mtt_mahal2(const mtt_real Si[MTT_SYM_SLOTS], mtt_pos nx, mtt_pos ny)
{
    return MTT_MAHAL2(Si, nx, ny);
}

#ifndef MTT_REAL_FIXED /* not yet converted (docs/FIXED_POINT.md, Status) */

static void pda_n(int n, const mtt_state xp, mtt_cov Pp, mtt_real K[][2], const mtt_real Si[3],
                  const mtt_real R[3], uint16_t m, mtt_real nu[][2], const mtt_real beta[],
                  mtt_real beta0, mtt_state x, mtt_cov P)
{
    mtt_cov AP;
    mtt_real A[MTT_MAX_STATE][2];
    mtt_real cx = MTT_R(0.0), cy = MTT_R(0.0);
    mtt_real sxx = MTT_R(0.0), sxy = MTT_R(0.0), syy = MTT_R(0.0);
    mtt_real w = MTT_R(1.0) - beta0, m11, m12, m22;
    uint16_t j;
    int i, k;
    mtt_real bsum = MTT_R(0.0);
    if (n < MTT_MEAS_DIM || n > MTT_MAX_STATE) {
        return; /* not a model of motion.h (folded away for a constant n) */
    }
    for (j = 0; j < m; ++j) {
        cx += beta[j] * nu[j][0];
        cy += beta[j] * nu[j][1];
        bsum += beta[j];
    }
    /* Spread sum beta nu nu' - nu_c nu_c', written as
     * sum beta (nu - nu_c)(nu - nu_c)' + (1 - sum beta) nu_c nu_c':
     * the same in exact arithmetic, but a sum of positive semi-definite
     * terms (sum beta <= 1), with no cancellation when the innovations are
     * large (a wide prior). */
    for (j = 0; j < m; ++j) {
        const mtt_real dx = nu[j][0] - cx, dy = nu[j][1] - cy;
        sxx += beta[j] * dx * dx;
        sxy += beta[j] * dx * dy;
        syy += beta[j] * dy * dy;
    }
    bsum = MTT_R(1.0) - bsum;
    if (bsum > MTT_R(0.0)) {
        sxx += bsum * cx * cx;
        sxy += bsum * cx * cy;
        syy += bsum * cy * cy;
    }
    for (i = 0; i < n; ++i) {
        x[i] = xp[i] + K[i][0] * cx + K[i][1] * cy;
    }
    /* P = beta0 Pp + (1 - beta0) P_c + K (sum beta nu nu' - nu_c nu_c') K'
     * (ALGORITHMS.md §6, [S1] Table 2 erratum applied), with the Joseph form
     * P_c = A Pp A' + K R K', A = I - K H (ALGORITHMS.md §3).  Both K . K' terms
     * share one 2x2 middle matrix M = (1 - beta0) R + spread. */
    m11 = w * R[0] + sxx;
    m12 = w * R[1] + sxy;
    m22 = w * R[2] + syy;
    /* A = I - K H.  Its position block I - Pp_pos S^-1 equals R S^-1
     * exactly (S = Pp_pos + R); computing it that way avoids the
     * cancellation of 1 - K when the prior is far wider than R (K -> 1,
     * e.g. after a long gap), where the textbook form loses every digit in
     * float.  S^-1 is the one mtt_kalman_innov made K from. */
    A[0][0] = R[0] * Si[0] + R[1] * Si[1];
    A[0][1] = R[0] * Si[1] + R[1] * Si[2];
    A[1][0] = R[1] * Si[0] + R[2] * Si[1];
    A[1][1] = R[1] * Si[1] + R[2] * Si[2];
    for (i = MTT_MEAS_DIM; i < n; ++i) {
        A[i][0] = -K[i][0];
        A[i][1] = -K[i][1];
    }
    /* A Pp: A differs from I only in columns 0 and 1. */
    for (i = 0; i < n; ++i) {
        for (k = 0; k < n; ++k) {
            AP[i][k] = A[i][0] * Pp[0][k] + A[i][1] * Pp[1][k] + ((i >= MTT_MEAS_DIM) ? Pp[i][k] : MTT_R(0.0));
        }
    }
    /* Upper triangle of beta0 Pp + (1 - beta0) A Pp A' + K M K', mirrored:
     * symmetric by construction. */
    for (i = 0; i < n; ++i) {
        const mtt_real a = K[i][0] * m11 + K[i][1] * m12;
        const mtt_real b = K[i][0] * m12 + K[i][1] * m22;
        for (k = i; k < n; ++k) {
            const mtt_real pc = AP[i][0] * A[k][0] + AP[i][1] * A[k][1] + ((k >= MTT_MEAS_DIM) ? AP[i][k] : MTT_R(0.0));
            const mtt_real v = beta0 * Pp[i][k] + w * pc + a * K[k][0] + b * K[k][1];
            P[i][k] = v;
            P[k][i] = v;
        }
    }
}

void mtt_kalman_pda(const mtt_state xp, mtt_cov Pp, mtt_real K[][2], const mtt_real Si[3],
                    const mtt_real R[3], uint16_t m, mtt_real nu[][2], const mtt_real beta[],
                    mtt_real beta0, mtt_state x, mtt_cov P)
{
    pda_n(MTT_STATE_N, xp, Pp, K, Si, R, m, nu, beta, beta0, x, P);
}

#if MTT_WITH_IMM
void mtt_kalman_pda_n(int n, const mtt_state xp, mtt_cov Pp, mtt_real K[][2], const mtt_real Si[3],
                      const mtt_real R[3], uint16_t m, mtt_real nu[][2], const mtt_real beta[],
                      mtt_real beta0, mtt_state x, mtt_cov P)
{
    pda_n(n, xp, Pp, K, Si, R, m, nu, beta, beta0, x, P);
}
#endif

/* A = L D L' (unit lower L, its diagonal not written) of the leading
 * n x n block, without square roots: cheap on soft float.  Returns 0, or
 * -1 when a pivot d_i is not positive and finite. */
static int ldl(int n, mtt_cov A, mtt_cov L, mtt_state d)
{
    int i, j, k;
    for (i = 0; i < n; ++i) {
        mtt_real di = A[i][i];
        for (j = 0; j < i; ++j) {
            mtt_real s = A[i][j];
            for (k = 0; k < j; ++k) {
                s -= L[i][k] * L[j][k] * d[k];
            }
            L[i][j] = s / d[j];
            di -= L[i][j] * s;
        }
        if (!(di > MTT_R(0.0)) || !mtt_isfinite(di)) {
            return -1;
        }
        d[i] = di;
    }
    return 0;
}

/* The hot callers above and below use the static ldl with the constant
 * MTT_STATE_N (the compiler specialises it, as before the split work
 * needed an n); other files call this entry point. */
int mtt_ldl(int n, mtt_cov A, mtt_cov L, mtt_state d)
{
    return ldl(n, A, L, d);
}

int mtt_cov_ok(mtt_cov P, mtt_real rel)
{
    mtt_cov L;
    mtt_state d = {MTT_R(0.0)};
    int i;
    /* d_i / P_ii is the share of state i's variance not explained by the
     * states before it: scale-free (the squared Cholesky pivots of the
     * correlation matrix). */
    if (ldl(MTT_STATE_N, P, L, d) != 0) {
        return 0;
    }
    for (i = 0; i < MTT_STATE_N; ++i) {
        if (!(d[i] > rel * P[i][i])) {
            return 0;
        }
    }
    return 1;
}

int mtt_chol_quad(mtt_cov A, const mtt_state b, mtt_real *d2)
{
    mtt_cov L;
    mtt_state d = {MTT_R(0.0)};
    mtt_state y = {MTT_R(0.0)}; /* zeroed for static analysis */
    mtt_real acc = MTT_R(0.0);
    int i, k;
    if (ldl(MTT_STATE_N, A, L, d) != 0) {
        return -1;
    }
    /* b' A^-1 b = sum y_i^2 / d_i with L y = b: one forward substitution. */
    for (i = 0; i < MTT_STATE_N; ++i) {
        mtt_real s = b[i];
        for (k = 0; k < i; ++k) {
            s -= L[i][k] * y[k];
        }
        y[i] = s;
        acc += s * s / d[i];
    }
    *d2 = acc;
    return 0;
}
#endif /* MTT_REAL_FIXED */
