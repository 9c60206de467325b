/* SPDX-License-Identifier: BSD-3-Clause */
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

void mtt_kalman_predict_q(mtt_real dt, mtt_cov Q, const mtt_state x, mtt_cov P, mtt_state xp,
                          mtt_cov Pp)
{
    mtt_motion_predict(dt, Q, x, P, xp, Pp);
    mtt_sym(Pp);
    MTT_COV_NORM(Pp);
}

void mtt_kalman_predict(mtt_real dt, mtt_real sw, const mtt_state x, mtt_cov P, mtt_state xp,
                        mtt_cov Pp)
{
    mtt_cov Q;
    mtt_motion_q(dt, sw, Q);
    mtt_kalman_predict_q(dt, Q, x, P, xp, Pp);
}

/* S = Pp_pos + R, S^-1 and det S; 0, or -1 when S is not positive definite. */
static int innov_s(mtt_cov Pp, const mtt_real R[3], mtt_real S[MTT_SYM_SLOTS], mtt_real Si[MTT_SYM_SLOTS],
                   mtt_real *det)
{
    mtt_real d;
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
    MTT_SI_SET(Si, S, d); /* adj(S) / det S */
    return 0;
}

/* The n-state bodies: one caller with a constant n (MTT_STATE_N) in a
 * build without IMM, so the firmware code is the fixed-size one. */
static int innov_n(int n, mtt_cov Pp, const mtt_real R[3], mtt_real S[MTT_SYM_SLOTS],
                   mtt_real Si[MTT_SYM_SLOTS], mtt_real *det, mtt_real K[][2])
{
    int i;
    if (n < MTT_MEAS_DIM || n > MTT_MAX_STATE) {
        return -1; /* not a model of motion.h (folded away for a constant n) */
    }
    if (innov_s(Pp, R, S, Si, det) != 0) {
        return -1;
    }
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

#ifdef MTT_REAL_FIXED
/* The fixed-point build (docs/FIXED_POINT.md §2, §3): the float text's
 * update below in block floating point, arranged for fewer products.
 * Every intermediate block is a set of int32 mantissas with one exponent,
 * chosen from the block's inputs so that each product is one mtt_fx_mulq
 * at shift 30 and each sum a plain add (the bounds are noted at each
 * step).  With P_c = (I - K H) Pp (equal to the Joseph form for the gain
 * K = Pp H' S^-1 that mtt_kalman_innov made),
 *   beta0 Pp + (1 - beta0) P_c = G Pp on rows 0, 1 (all columns), with
 *     G = beta0 I + (1 - beta0) R S^-1: I - K H's position block is
 *     R S^-1 exactly (S = Pp_pos + R), so nothing cancels there;
 *   Pp - (1 - beta0) K_v Pp_pos,v on the velocity block (rows and columns
 *     2, 3): at least the Schur complement of Pp's position block, the
 *     conditional velocity variance, so it cancels only as much as velocity
 *     is predicted by position;
 * plus the spread term K sp K' (sp = sum beta nu nu' - nu_c nu_c', no R:
 * the K R K' of the Joseph form is in P_c), which with one measurement is
 * beta (1 - beta) q q', q = K nu.  Each of the two terms is positive
 * semi-definite; they are aligned by their measured sizes, then P is
 * renormalised.  Pp is as mtt_kalman_predict leaves it (largest mantissa
 * below 2^28), K and S^-1 as mtt_kalman_innov leaves them. */

#define or_abs(v, n) mtt_fx_or_abs((v), (n))
#define MULQ(a, b) mtt_fx_mulq30((a), (b))

static void pda_n(int n, const mtt_state xp, mtt_cov Pp, mtt_real K[][2], const mtt_real Si[MTT_SYM_SLOTS],
                  const mtt_real R[3], uint16_t m, mtt_real nu[][2], const mtt_real beta[],
                  mtt_real beta0, mtt_state x, mtt_cov P)
{
    int32_t Kn[MTT_MAX_STATE][2], G[2][2], V[MTT_MAX_STATE][2];
    /* the upper triangles of the two terms */
    int32_t t1[MTT_MAX_STATE * (MTT_MAX_STATE + 1) / 2], t3[MTT_MAX_STATE * (MTT_MAX_STATE + 1) / 2];
    int32_t Rn[3], M[3] = {0, 0, 0}, cx = 0, cy = 0, bsum = 0;
    const int32_t w = MTT_P(1.0) - beta0;
    const int eP = MTT_COV_E(Pp);
    uint32_t u = 0u;
    int s, eK, eR, eG, eV, eM, E1, E2, E3, E, i, k, c;
    uint16_t j;
    if (n < MTT_MEAS_DIM || n > MTT_MAX_STATE) {
        return; /* not a model of motion.h (folded away for a constant n) */
    }
    /* Innovations at 2^-(F + s) with |nu| < 2^28: |nu - nu_c| < 2^29. */
    for (j = 0; j < m; ++j) {
        u |= or_abs(nu[j], 2);
    }
    s = -mtt_fx_top_exp(0, u, 28);
    for (j = 0; j < m && m != 1u; ++j) { /* one measurement: x from q below */
        cx += MULQ(beta[j], mtt_fx_shift(nu[j][0], s));
        cy += MULQ(beta[j], mtt_fx_shift(nu[j][1], s));
        bsum += beta[j];
    }
    /* K to 29 bits (its exponent eK): the state moves by K nu_c. */
    u = 0u;
    for (i = 0; i < n; ++i) {
        u |= or_abs(K[i], 2);
    }
    k = mtt_fx_top_exp(0, u, 29);
    eK = eP + MTT_SYM_E(Si) + 28 + k;
    for (i = 0; i < n; ++i) {
        Kn[i][0] = mtt_fx_shift(K[i][0], -k);
        Kn[i][1] = mtt_fx_shift(K[i][1], -k);
        /* |K| < 2^29, |nu_c| < 2^28 + m: the sum below 2^28 */
        if (m != 1u) {
            x[i] = MTT_ADDS(xp[i], mtt_fx_at(MULQ(Kn[i][0], cx) + MULQ(Kn[i][1], cy),
                                             30 + eK - MTT_FX_POS_FRAC - s, -MTT_FX_POS_FRAC));
        }
    }
    /* The spread term K sp K' at E3, each entry below 2^29. */
    c = 0;
    if (m == 1u) {
        /* beta (1 - beta) q q' with q = K nu (below 2^28, then on 29 bits:
         * exponent eM) and 4 beta (1 - beta) <= 1 in Q30 */
        int32_t q[MTT_MAX_STATE];
        const int32_t b4 = MULQ(beta[0], MTT_P(1.0) - beta[0]) * 4;
        const int32_t nx = mtt_fx_shift(nu[0][0], s), ny = mtt_fx_shift(nu[0][1], s);
        eM = eK - MTT_FX_POS_FRAC - s + 30;
        for (i = 0; i < n; ++i) {
            q[i] = MULQ(Kn[i][0], nx) + MULQ(Kn[i][1], ny);
            /* the state moves by beta q */
            x[i] = MTT_ADDS(xp[i], mtt_fx_at(MULQ(beta[0], q[i]), eM, -MTT_FX_POS_FRAC));
        }
        k = mtt_fx_top_exp(0, or_abs(q, n), 29);
        eM += k;
        for (i = 0; i < n; ++i) {
            q[i] = mtt_fx_shift(q[i], -k);
        }
        for (i = 0; i < n; ++i) {
            const int32_t bq = MULQ(b4, q[i]);
            for (k = i; k < n; ++k) {
                t3[c++] = MULQ(bq, q[k]);
            }
        }
        E3 = 2 * eM + 28;
    } else {
        /* The spread as a sum of PSD terms (see the float text): each term
         * below 2^28, their beta-weighted sum too; exponent 30 - 2 (F + s);
         * then on 29 bits (exponent eM). */
        for (j = 0; j < m; ++j) {
            const int32_t dx = mtt_fx_shift(nu[j][0], s) - cx, dy = mtt_fx_shift(nu[j][1], s) - cy;
            const int32_t bx = MULQ(beta[j], dx);
            M[0] += MULQ(bx, dx);
            M[1] += MULQ(bx, dy);
            M[2] += MULQ(MULQ(beta[j], dy), dy);
        }
        bsum = MTT_P(1.0) - bsum;
        if (bsum > 0) {
            const int32_t bx = MULQ(bsum, cx);
            M[0] += MULQ(bx, cx);
            M[1] += MULQ(bx, cy);
            M[2] += MULQ(MULQ(bsum, cy), cy);
        }
        k = mtt_fx_top_exp(0, or_abs(M, 3), 29);
        eM = 30 - 2 * (MTT_FX_POS_FRAC + s) + k;
        for (c = 0; c < 3; ++c) {
            M[c] = mtt_fx_shift(M[c], -k);
        }
        c = 0;
        for (i = 0; i < n; ++i) {
            const int32_t a = MULQ(Kn[i][0], M[0]) + MULQ(Kn[i][1], M[1]);
            const int32_t b = MULQ(Kn[i][0], M[1]) + MULQ(Kn[i][1], M[2]);
            for (k = i; k < n; ++k) {
                t3[c++] = MULQ(a, Kn[k][0]) + MULQ(b, Kn[k][1]);
            }
        }
        E3 = eK + eM + 30 + eK + 30;
    }
    /* G = beta0 I + (1 - beta0) R S^-1: R on 29 bits (exponent eR), R S^-1
     * below 2^28 at eR + e(S^-1) + 30, then G on 29 bits at eG (at least
     * beta0's: its identity part a right shift). */
    k = mtt_fx_top_exp(0, or_abs(R, 3), 29);
    eR = -MTT_FX_VAR_FRAC + k;
    for (c = 0; c < 3; ++c) {
        Rn[c] = mtt_fx_shift(R[c], -k);
    }
    G[0][0] = MULQ(w, MULQ(Rn[0], Si[0]) + MULQ(Rn[1], Si[1]));
    G[0][1] = MULQ(w, MULQ(Rn[0], Si[1]) + MULQ(Rn[1], Si[2]));
    G[1][0] = MULQ(w, MULQ(Rn[1], Si[0]) + MULQ(Rn[2], Si[1]));
    G[1][1] = MULQ(w, MULQ(Rn[1], Si[1]) + MULQ(Rn[2], Si[2]));
    eR += MTT_SYM_E(Si) + 30;
    eG = mtt_fx_top_exp(eR, or_abs(G[0], 2) | or_abs(G[1], 2), 29);
    k = mtt_fx_top_exp(-MTT_FX_PROB_FRAC, (uint32_t)beta0, 29);
    eG = (k > eG) ? k : eG;
    for (i = 0; i < 2; ++i) {
        for (k = 0; k < 2; ++k) {
            G[i][k] = mtt_fx_shift(G[i][k], eR - eG) + ((i == k) ? mtt_fx_shift(beta0, -MTT_FX_PROB_FRAC - eG) : 0);
        }
    }
    /* (1 - beta0) K_v on 29 bits at eV >= -30, so that Pp's part, 2^-eV
     * times the product's unit, is a right shift. */
    u = 0u;
    for (i = MTT_MEAS_DIM; i < n; ++i) {
        V[i][0] = MULQ(w, Kn[i][0]);
        V[i][1] = MULQ(w, Kn[i][1]);
        u |= or_abs(V[i], 2);
    }
    eV = mtt_fx_top_exp(eK, u, 29);
    eV = (eV < -30) ? -30 : eV;
    for (i = MTT_MEAS_DIM; i < n; ++i) {
        V[i][0] = mtt_fx_shift(V[i][0], eK - eV);
        V[i][1] = mtt_fx_shift(V[i][1], eK - eV);
    }
    /* beta0 Pp + (1 - beta0) P_c: rows 0, 1 at E1 = eG + eP + 30 (|G| <
     * 2^30, |Pp| < 2^28: below 2^29), the velocity block at E2 = eV + eP
     * + 30 (Pp's part below 2^28, the products below 2^27 each). */
    E1 = eG + eP + 30;
    E2 = eV + eP + 30;
    c = 0;
    u = 0u; /* rows 0, 1 */
    for (i = 0; i < MTT_MEAS_DIM; ++i) {
        for (k = i; k < n; ++k) {
            t1[c] = MULQ(G[i][0], Pp[0][k]) + MULQ(G[i][1], Pp[1][k]);
            u |= (uint32_t)((t1[c] < 0) ? -t1[c] : t1[c]);
            ++c;
        }
    }
    /* One exponent for the sum: each term below 2^29 there. */
    E = mtt_fx_top_exp(E1, u, 29);
    u = 0u; /* the velocity block */
    for (; i < n; ++i) {
        for (k = i; k < n; ++k) {
            t1[c] = mtt_fx_shift(Pp[i][k], -(eV + 30)) - MULQ(V[i][0], Pp[0][k]) - MULQ(V[i][1], Pp[1][k]);
            u |= (uint32_t)((t1[c] < 0) ? -t1[c] : t1[c]);
            ++c;
        }
    }
    k = mtt_fx_top_exp(E2, u, 29);
    E = (k > E) ? k : E;
    k = mtt_fx_top_exp(E3, or_abs(t3, c), 29);
    E = (k > E) ? k : E;
    c = 0;
    for (i = 0; i < n; ++i) {
        for (k = i; k < n; ++k) {
            const int32_t v = mtt_fx_shift(t1[c], ((i < MTT_MEAS_DIM) ? E1 : E2) - E) + mtt_fx_shift(t3[c], E3 - E);
            P[i][k] = v;
            P[k][i] = v;
            ++c;
        }
    }
    MTT_COV_E(P) = E;
    MTT_COV_NORM(P);
}

/* Fraction-free elimination (no division, no L): the positive-definiteness
 * test and the quadratic form b' A^-1 b.  A is first scaled D A D, D =
 * diag(2^t_i), so that every diagonal entry has 29 or 30 bits: the pivot
 * ratios d_i / a_ii do not change, and a block whose variances span many
 * bits keeps the precision of its small ones, as float's per-value
 * exponent does; then |a_ij| <= sqrt(a_ii a_jj) < 2^30 unless A is not
 * positive semi-definite, which fails at once.  Step k turns the block B =
 * mu_k S_k (S_k the Schur complement left after k pivots, mu_k > 0 a known
 * factor, mm 2^em) into p B_ij - B_ik B_jk = mu_k p S_k+1,ij (p = B_kk =
 * mu_k d_k), renormalised to 30 bits.  Each product has both factors below
 * 2^30, each difference stays below 2^31; every rounding is 2^-30 of the
 * block.  Row MTT_STATE_N (the quadratic form's) borders A with D b. */
struct ff {
    int32_t a[MTT_MAX_STATE + 1][MTT_MAX_STATE + 1]; /* lower triangle */
    int32_t mm;                                      /* mu = mm 2^em */
    int em;
    int t[MTT_MAX_STATE];
};

static int ff_scale(mtt_cov A, struct ff *f)
{
    int i, j;
    for (i = 0; i < MTT_STATE_N; ++i) {
        if (!(A[i][i] > 0)) {
            return -1;
        }
        f->t[i] = (30 - (32 - mtt_fx_clz((uint32_t)A[i][i]))) >> 1; /* arithmetic: -1 for 31 bits */
    }
    for (i = 0; i < MTT_STATE_N; ++i) {
        for (j = 0; j <= i; ++j) {
            const int32_t v = A[i][j];
            const int tt = f->t[i] + f->t[j];
            int32_t m;
            if (tt >= 0) {
                m = (tt > 0 && ((v < 0) ? -v : v) >> (30 - tt) != 0) ? MTT_FX_MAX : v * ((int32_t)1 << tt);
            } else {
                const int32_t h = v >> (-tt - 1); /* tt >= -2: mtt_fx_shift's rounding inline */
                m = h - (h >> 1);
            }
            if (!(((m < 0) ? -m : m) < ((int32_t)1 << 30))) {
                return -1;
            }
            f->a[i][j] = m;
        }
    }
    f->mm = (int32_t)1 << 29;
    f->em = -29;
    return 0;
}

/* Step k on rows and columns k + 1 .. n - 1 (pivot f->a[k][k] > 0). */
static void ff_step(struct ff *f, int k, int n)
{
    const int32_t p = f->a[k][k];
    uint32_t u = 0u;
    int i, j, sh;
    for (i = k + 1; i < n; ++i) {
        for (j = k + 1; j <= i; ++j) {
            const int32_t v = MULQ(p, f->a[i][j]) - MULQ(f->a[i][k], f->a[j][k]);
            f->a[i][j] = v;
            u |= (uint32_t)((v < 0) ? -v : v);
        }
    }
    sh = mtt_fx_top_exp(0, u, 30);
    for (i = k + 1; i < n; ++i) {
        for (j = k + 1; j <= i; ++j) {
            f->a[i][j] = mtt_fx_shift(f->a[i][j], -sh);
        }
    }
    /* mu_k+1 = mu_k p 2^(-30 - sh), its mantissa back on 30 bits */
    f->mm = MULQ(f->mm, p);
    f->em -= sh;
    sh = mtt_fx_top_exp(0, (uint32_t)f->mm, 30);
    f->mm = mtt_fx_shift(f->mm, -sh);
    f->em += sh;
}

/* d_k > rel a_kk is p > rel a_kk mu_k: two products. */
int mtt_cov_ok(mtt_cov P, mtt_real rel)
{
    struct ff f;
    int32_t ad[MTT_MAX_STATE];
    const int z = -mtt_fx_top_exp(0, (uint32_t)rel, 30); /* rel on 30 bits */
    const int32_t reln = mtt_fx_shift(rel, z);
    int i, k;
    /* d_i / P_ii is scale-free (see the float text); rel in Q30. */
    if (!(rel > 0) || ff_scale(P, &f) != 0) {
        return 0;
    }
    for (i = 0; i < MTT_STATE_N; ++i) {
        ad[i] = f.a[i][i];
    }
#if MTT_STATE_N == 4
    {
        /* A sufficient test first (the common case): with the states in
         * the order (x, vx) (y, vy), D P D = blockdiag(Cx, Cy) plus the
         * cross-axis part E, so lambda_min >= min(det Cx / tr Cx, det Cy /
         * tr Cy) - sum |E_ij| (a 2 x 2 block's smaller eigenvalue is at
         * least det / tr; Weyl's inequality with ||E|| <= sum |E_ij|), and
         * every pivot d_k >= lambda_min.  So when both blocks' det exceeds
         * (sum |E_ij| + 4 rel + 8 units) times their trace, every d_k >
         * rel a_kk (a_kk < 1 in Q30): the 8 units cover the roundings of
         * the scaling and of these products.  Otherwise the elimination
         * decides. */
        int32_t(*a)[MTT_MAX_STATE + 1] = f.a;
        const uint32_t e = (uint32_t)MTT_ABS(a[1][0]) + (uint32_t)MTT_ABS(a[3][0]) + (uint32_t)MTT_ABS(a[2][1]) +
                           (uint32_t)MTT_ABS(a[3][2]);
        if (e < ((uint32_t)1 << 29) && rel < ((int32_t)1 << 26)) {
            const int32_t b = (int32_t)e + 4 * rel + 8;
            if (MULQ(a[0][0], a[2][2]) - MULQ(a[2][0], a[2][0]) > MULQ(b, a[0][0] + a[2][2]) &&
                MULQ(a[1][1], a[3][3]) - MULQ(a[3][1], a[3][1]) > MULQ(b, a[1][1] + a[3][3])) {
                return 1;
            }
        }
    }
#endif
    for (k = 0; k < MTT_STATE_N; ++k) {
        const int32_t p = f.a[k][k];
        if (!(p > 0)) {
            return 0;
        }
        if (k > 0) {
            /* rel a_kk mu = X 2^(30 + em - z) */
            const int32_t X = MULQ(MULQ(reln, ad[k]), f.mm);
            if (!(p > mtt_fx_at(X, 30 + f.em - z, 0))) {
                return 0;
            }
        }
        if (k + 1 < MTT_STATE_N) {
            ff_step(&f, k, MTT_STATE_N);
        }
    }
    return 1;
}

/* b' A^-1 b: A bordered with D b 2^-eb (its largest entry on 29 bits);
 * after the four steps the corner is mu (0 - (D b)' (D A D)^-1 (D b))
 * 2^(-2 eb), so with A = its mantissas 2^e(A) and b in the position
 * format, d2 = -corner / mu 2^(2 eb - e(A) - 2 F): one quotient. */
int mtt_chol_quad(mtt_cov A, const mtt_state b, mtt_real *d2)
{
    struct ff f;
    int32_t x;
    int i, k, eb = -127;
    if (ff_scale(A, &f) != 0) {
        return -1;
    }
    for (i = 0; i < MTT_STATE_N; ++i) {
        k = mtt_fx_top_exp(f.t[i], (uint32_t)((b[i] < 0) ? -b[i] : b[i]), 29);
        eb = (k > eb) ? k : eb;
    }
    for (i = 0; i < MTT_STATE_N; ++i) {
        f.a[MTT_STATE_N][i] = mtt_fx_shift(b[i], f.t[i] - eb);
    }
    f.a[MTT_STATE_N][MTT_STATE_N] = 0;
    for (k = 0; k < MTT_STATE_N; ++k) {
        if (!(f.a[k][k] > 0)) {
            return -1;
        }
        ff_step(&f, k, MTT_STATE_N + 1);
    }
    x = -f.a[MTT_STATE_N][MTT_STATE_N];
    if (!(x > 0)) {
        *d2 = 0; /* b = 0, or rounding */
        return 0;
    }
    /* x / mm on 29 or 30 bits (x < 2^31, mm in [2^29, 2^30)), then in Q24 (saturated) */
    *d2 = mtt_fx_at(mtt_fx_div(x, f.mm, 28), 2 * eb - MTT_COV_E(A) - 2 * MTT_FX_POS_FRAC - f.em - 28,
                    -MTT_FX_D2_FRAC);
    return 0;
}
#undef MULQ
#undef or_abs

#else /* float, double */

static void pda_n(int n, const mtt_state xp, mtt_cov Pp, mtt_real K[][2], const mtt_real Si[MTT_SYM_SLOTS],
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

#endif /* MTT_REAL_FIXED */

void mtt_kalman_pda(const mtt_state xp, mtt_cov Pp, mtt_real K[][2], const mtt_real Si[MTT_SYM_SLOTS],
                    const mtt_real R[3], uint16_t m, mtt_real nu[][2], const mtt_real beta[],
                    mtt_real beta0, mtt_state x, mtt_cov P)
{
    pda_n(MTT_STATE_N, xp, Pp, K, Si, R, m, nu, beta, beta0, x, P);
}

#if MTT_WITH_IMM
void mtt_kalman_pda_n(int n, const mtt_state xp, mtt_cov Pp, mtt_real K[][2], const mtt_real Si[MTT_SYM_SLOTS],
                      const mtt_real R[3], uint16_t m, mtt_real nu[][2], const mtt_real beta[],
                      mtt_real beta0, mtt_state x, mtt_cov P)
{
    pda_n(n, xp, Pp, K, Si, R, m, nu, beta, beta0, x, P);
}
#endif

#if MTT_WITH_MEAS_COV && defined(MTT_REAL_FIXED)
int mtt_meas_gauss_fx(mtt_cov Pp, const mtt_real R[3], const int32_t *gc, mtt_pos nx, mtt_pos ny, mtt_d2 *d2,
                      mtt_ratio *p, int32_t *hl)
{
    mtt_real S[MTT_SYM_SLOTS], Si[MTT_SYM_SLOTS], det;
    mtt_ratio peak;
    if (innov_s(Pp, R, S, Si, &det) != 0) {
        return -1;
    }
    *d2 = MTT_MAHAL2(Si, nx, ny);
#if MTT_WITH_IMM
    if (hl != NULL) {
        *hl = mtt_fx_half_ln_det(det, S);
    }
#else
    (void)hl;
#endif
    if (gc != NULL) {
        (void)mtt_fx_gate_area_peak_c(gc, det, S, &peak); /* the track's own area stays its tf->vg */
        *p = MTT_GATE_LIK(peak, *d2);
    }
    return 0;
}

#define MULQ(a, b) mtt_fx_mulq30((a), (b))

/* round(v / 2^s) of an int64 (s >= 0; 0 beyond 62 bits). */
static int64_t shr64(int64_t v, int s)
{
    if (s <= 0) {
        return v;
    }
    return (s > 62) ? 0 : ((v + ((int64_t)1 << (s - 1))) >> s);
}

/* The float text's mixture below (ALGORITHMS.md §3.1) in block floating
 * point: each single-detection update is pda_n's with its own R_j (its P_j
 * a block with its own exponent); beta0 Pp + sum beta_j P_j accumulates in
 * int64 at 28 bits below the largest block's exponent seen so far (each
 * term below 2^56, the beta-weighted sum below 2^57), the spread of the d_j
 * at the exponent of the d_j normalised to 28 bits (each product below
 * 2^56, the weighted sum below 2^57), and the two meet one bit above the
 * larger exponent before P is rounded back to 28-bit mantissas.  Fixed
 * point has no polar detections, so rr and sensor are unused (NULL). */
void mtt_kalman_pda_each(int n, const mtt_state xp, mtt_cov Pp, const mtt_real *const Rj[],
                         const mtt_real *const rr[], const mtt_real sensor[2], uint16_t m,
                         mtt_real nu[][2], const mtt_real beta[], mtt_real beta0, mtt_real d[][MTT_MAX_STATE],
                         mtt_state x, mtt_cov P)
{
    mtt_cov Pj;
    mtt_state xj;
    mtt_real S[MTT_SYM_SLOTS], Si[MTT_SYM_SLOTS], det, K[MTT_MAX_STATE][2], c[MTT_MAX_STATE];
    int64_t acc[MTT_MAX_STATE][MTT_MAX_STATE], sp[MTT_MAX_STATE][MTT_MAX_STATE];
    mtt_prob bsum = 0, b0 = beta0;
    const mtt_real one[1] = {MTT_P(1.0)};
    uint32_t u = 0u;
    uint16_t j;
    int i, k, ea, es, e, sh;
    (void)rr;
    (void)sensor;
    if (n < MTT_MEAS_DIM || n > MTT_MAX_STATE) {
        return;
    }
    for (i = 0; i < n; ++i) {
        c[i] = 0;
    }
    for (j = 0; j < m; ++j) {
        if (innov_n(n, Pp, Rj[j], S, Si, &det, K) != 0) {
            b0 += beta[j]; /* as the float text: its weight goes to the prediction */
        }
        bsum += beta[j];
    }
    /* beta0' Pp first: its mantissas below 2^28 at eP, so at ea = eP - 28 below 2^56 */
    ea = MTT_COV_E(Pp) - 28;
    for (i = 0; i < n; ++i) {
        for (k = i; k < n; ++k) {
            acc[i][k] = (int64_t)MULQ(b0, Pp[i][k]) << 28;
        }
    }
    for (j = 0; j < m; ++j) {
        int ej;
        for (i = 0; i < n; ++i) {
            d[j][i] = 0;
        }
        if (innov_n(n, Pp, Rj[j], S, Si, &det, K) != 0) {
            continue;
        }
        pda_n(n, xp, Pp, K, Si, Rj[j], 1, &nu[j], one, 0, xj, Pj);
        ej = MTT_COV_E(Pj) - 28;
        if (ej > ea) { /* a larger block: the sum moves to its exponent */
            for (i = 0; i < n; ++i) {
                for (k = i; k < n; ++k) {
                    acc[i][k] = shr64(acc[i][k], ej - ea);
                }
            }
            ea = ej;
        }
        for (i = 0; i < n; ++i) {
            d[j][i] = MTT_SUBS(xj[i], xp[i]);
            c[i] = MTT_ADDS(c[i], MULQ(beta[j], d[j][i]));
            for (k = i; k < n; ++k) {
                const int64_t t = MULQ(beta[j], Pj[i][k]);
                acc[i][k] += (ej - ea + 28 >= 0) ? (t * ((int64_t)1 << (ej - ea + 28))) : shr64(t, ea - ej - 28);
            }
        }
    }
    bsum = MTT_P(1.0) - bsum + (b0 - beta0); /* the weight of c c' (float: 1 - sum of the valid betas) */
    /* the spread: d_j - c and c (bsum's term) on 28 bits, exponent es */
    for (i = 0; i < n; ++i) {
        x[i] = MTT_ADDS(xp[i], c[i]);
        u |= (uint32_t)((c[i] < 0) ? -c[i] : c[i]);
        for (j = 0; j < m; ++j) {
            const int32_t v = MTT_SUBS(d[j][i], c[i]);
            u |= (uint32_t)((v < 0) ? -v : v);
        }
    }
    sh = 28 - (32 - mtt_fx_clz(u)); /* u = 0: no spread */
    es = -2 * (MTT_FX_POS_FRAC + sh);
    for (i = 0; i < n; ++i) {
        for (k = i; k < n; ++k) {
            sp[i][k] = 0;
        }
    }
    for (j = 0; j <= m && u != 0u; ++j) {
        int32_t vn[MTT_MAX_STATE];
        const mtt_prob b = (j < m) ? beta[j] : bsum;
        if (!(b > 0)) {
            continue;
        }
        for (i = 0; i < n; ++i) {
            vn[i] = mtt_fx_shift((j < m) ? MTT_SUBS(d[j][i], c[i]) : c[i], sh);
        }
        for (i = 0; i < n; ++i) {
            const int64_t bv = MULQ(b, vn[i]);
            for (k = i; k < n; ++k) {
                sp[i][k] += bv * vn[k];
            }
        }
    }
    /* the two sums at one exponent e, one bit above the larger (below
     * 2^58), then 28-bit mantissas */
    e = ((ea > es) ? ea : es) + 1;
    for (i = 0; i < n; ++i) {
        for (k = i; k < n; ++k) {
            acc[i][k] = shr64(acc[i][k], e - ea) + shr64(sp[i][k], e - es);
        }
    }
    sh = 0;
    for (i = 0; i < n; ++i) {
        for (k = i; k < n; ++k) {
            const int64_t a = (acc[i][k] < 0) ? -acc[i][k] : acc[i][k];
            int b = 0;
            while (b < 63 && (a >> b) != 0) {
                ++b;
            }
            sh = (b - 28 > sh) ? b - 28 : sh;
        }
    }
    for (i = 0; i < n; ++i) {
        for (k = i; k < n; ++k) {
            const int32_t v = (int32_t)shr64(acc[i][k], sh);
            P[i][k] = v;
            P[k][i] = v;
        }
    }
    MTT_COV_E(P) = e + sh;
    MTT_COV_NORM(P);
}
#undef MULQ
#elif MTT_WITH_MEAS_COV
int mtt_meas_gauss(const mtt_real *p0, const mtt_real *p1, const mtt_real R[3], mtt_real pg, mtt_real nx,
                   mtt_real ny, mtt_real *d2, mtt_real *p, mtt_real S[3])
{
    /* S = Pp_pos + R as innov_n forms it */
    const mtt_real s0 = p0[0] + R[0], s1 = MTT_R(0.5) * (p0[1] + p1[0]) + R[1], s2 = p1[1] + R[2];
    const mtt_real det = s0 * s2 - s1 * s1;
    mtt_real Si[MTT_SYM_SLOTS];
    S[0] = s0;
    S[1] = s1;
    S[2] = s2;
    if (!(det > MTT_R(0.0)) || !mtt_isfinite(det)) {
        return -1;
    }
    Si[0] = s2 / det;
    Si[1] = -s1 / det;
    Si[2] = s0 / det;
    *d2 = MTT_MAHAL2(Si, nx, ny);
    *p = mtt_gate_likelihood(*d2, det, pg);
    return 0;
}

/* [CHOICE] ALGORITHMS.md §3.1: with a covariance per detection the PDA
 * update is the mixture of the m single-detection updates (each the Joseph
 * form with its own R_j and gain K_j) and of the prediction, weights beta_j
 * and beta0: x = xp + sum beta_j d_j (d_j = K_j nu_j), P = beta0 Pp + sum
 * beta_j P_j + the spread of the d_j, written as the sum of positive
 * semi-definite terms as pda_n writes it.  With every R_j equal it is
 * pda_n's update (the same in exact arithmetic). */
void mtt_kalman_pda_each(int n, const mtt_state xp, mtt_cov Pp, const mtt_real *const Rj[],
                         const mtt_real *const rr[], const mtt_real sensor[2], uint16_t m,
                         mtt_real nu[][2], const mtt_real beta[], mtt_real beta0, mtt_real d[][MTT_MAX_STATE],
                         mtt_state x, mtt_cov P)
{
    mtt_cov Pj, acc;
    mtt_state xj;
    mtt_real S[MTT_SYM_SLOTS], Si[MTT_SYM_SLOTS], det, K[MTT_MAX_STATE][2], c[MTT_MAX_STATE];
    mtt_real bsum = MTT_R(0.0), b0 = beta0;
    const mtt_real one[1] = {MTT_R(1.0)};
    uint16_t j;
    int i, k;
    if (n < MTT_MEAS_DIM || n > MTT_MAX_STATE) {
        return;
    }
    for (i = 0; i < n; ++i) {
        c[i] = MTT_R(0.0);
        for (k = 0; k < n; ++k) {
            acc[i][k] = MTT_R(0.0);
        }
    }
    for (j = 0; j < m; ++j) {
        if (innov_n(n, Pp, Rj[j], S, Si, &det, K) != 0) {
            /* not positive definite (R_j was checked, Pp is): its weight
             * goes to the prediction */
            b0 += beta[j];
            for (i = 0; i < n; ++i) {
                d[j][i] = MTT_R(0.0);
            }
            continue;
        }
        pda_n(n, xp, Pp, K, Si, Rj[j], 1, &nu[j], one, MTT_R(0.0), xj, Pj);
        if (rr != NULL && rr[j] != NULL) {
            mtt_polar_rdot_update(n, sensor, rr[j], xj, Pj); /* its range rate (§3.2) */
        }
        for (i = 0; i < n; ++i) {
            d[j][i] = xj[i] - xp[i];
            c[i] += beta[j] * d[j][i];
            for (k = i; k < n; ++k) {
                acc[i][k] += beta[j] * Pj[i][k];
            }
        }
        bsum += beta[j];
    }
    bsum = MTT_R(1.0) - bsum;
    for (i = 0; i < n; ++i) {
        x[i] = xp[i] + c[i];
        for (k = i; k < n; ++k) {
            mtt_real v = b0 * Pp[i][k] + acc[i][k];
            for (j = 0; j < m; ++j) {
                v += beta[j] * (d[j][i] - c[i]) * (d[j][k] - c[k]);
            }
            if (bsum > MTT_R(0.0)) {
                v += bsum * c[i] * c[k];
            }
            P[i][k] = v;
            P[k][i] = v;
        }
    }
}
#endif

#ifndef MTT_REAL_FIXED /* the fixed L D L' is above */

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
