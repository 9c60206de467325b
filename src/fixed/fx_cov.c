/* SPDX-License-Identifier: BSD-3-Clause */
/* fx_cov.c - block floating point for the covariances of the fixed-point
 * build (docs/FIXED_POINT.md §2 and its Status, findings 1 and 5): a
 * matrix's values are its int32 mantissas times 2^e, with e in the extra
 * row of mtt_cov (MTT_COV_E).  Renormalisation, the headroom of the
 * prediction, the alignment of two blocks to one exponent, and the process
 * noise Q(dt) of the CV model (ALGORITHMS.md §2) as mantissas and an
 * exponent, and ln sqrt(det S) for the IMM's model weights (§14.2).
 * Compiled only in the fixed-point build. */
#include "mtt_internal.h"

#ifdef MTT_REAL_FIXED

/* Bit length of |v| (0 for 0); |v| <= MTT_FX_MAX. */
static int bitlen(int32_t v)
{
    return 32 - mtt_fx_clz((uint32_t)((v < 0) ? -v : v));
}

/* Bit length of the largest |entry|: that of the OR of all |entries|
 * (one count of leading zeros instead of sixteen). */
static int block_bits(mtt_cov P)
{
    uint32_t u = 0u;
    int i, j;
    for (i = 0; i < MTT_STATE_N; ++i) {
        for (j = 0; j < MTT_STATE_N; ++j) {
            u |= (uint32_t)((P[i][j] < 0) ? -P[i][j] : P[i][j]);
        }
    }
    return 32 - mtt_fx_clz(u);
}

/* v / 2^s rounded to nearest (ties up), 0 < s: a few instructions, no
 * overflow (right shifts of negative values are arithmetic, fixed.h). */
static int32_t shr_round(int32_t v, int s)
{
    if (s > 31) {
        return 0;
    }
    {
        /* t - floor(t / 2) = floor(t / 2) + (t & 1): no constant to load */
        const int32_t t = v >> (s - 1);
        return t - (t >> 1);
    }
}

/* Mantissas times 2^s: exact for s > 0 (the caller keeps them below 2^31),
 * rounded to nearest for s < 0; the exponent takes -s, so the values stay. */
static void shift_block(mtt_cov P, int s)
{
    int i, j;
    /* the direction and shr_round's shift k = -s - 1 chosen once, not per
     * entry; beyond s = -31 every entry rounds to 0 (shr_round), written
     * as a product by 0 with the left moves' loop (a loop of zeros would
     * become a memset call on the stack's deepest path) */
    if (s > 0 || s < -31) {
        const int32_t m = (s > 0) ? (int32_t)1 << s : 0;
        for (i = 0; i < MTT_STATE_N; ++i) {
            for (j = 0; j < MTT_STATE_N; ++j) {
                P[i][j] *= m;
            }
        }
    } else if (s < 0) {
        const int k = -s - 1;
        for (i = 0; i < MTT_STATE_N; ++i) {
            for (j = 0; j < MTT_STATE_N; ++j) {
                const int32_t v = P[i][j] >> k;
                P[i][j] = v - (v >> 1); /* as shr_round */
            }
        }
    }
    MTT_COV_E(P) -= s;
}

void mtt_fx_cov_norm(mtt_cov P, int top)
{
    const int b = block_bits(P);
    if (b > 0) {
        shift_block(P, top - b);
    }
}

/* Largest mantissa bit length before a prediction over dt (Q16 frames):
 * 30 - 2k with 2^k >= 1 + dt, so (1 + dt)^2 |P| + |Q| < 2^31 (finding 1);
 * at least 2, which caps the precision of gaps beyond 2^13 frames. */
static int fit_top(int32_t dt)
{
    const uint32_t frames = ((uint32_t)dt + 131071u) >> 16; /* ceil(1 + dt) */
    const int top = 30 - 2 * (32 - mtt_fx_clz(frames - 1u));
    return (top < 2) ? 2 : top;
}

void mtt_fx_cov_fit(mtt_cov P, int32_t dt)
{
    mtt_fx_cov_norm(P, fit_top(dt));
}

void mtt_fx_cov_align(mtt_cov A, mtt_cov B)
{
    if (MTT_COV_E(A) < MTT_COV_E(B)) {
        shift_block(A, MTT_COV_E(A) - MTT_COV_E(B));
    } else {
        shift_block(B, MTT_COV_E(B) - MTT_COV_E(A));
    }
}

int32_t mtt_fx_unpack(int32_t v, int frac, int *e)
{
    const int l = bitlen(v);
    *e = -frac - (30 - l);
    return (l <= 30) ? v * ((int32_t)1 << (30 - l)) : mtt_fx_mul(v, 1, l - 30);
}

/* round(v / 3) of 0 <= v < 2^31 (no ties: the fraction is 0, 1/3 or 2/3),
 * which is floor((v + 1) / 3): a quotient by shifts and adds (Hacker's
 * Delight, divu3), then the remainder's correction; the result of
 * mtt_fx_div(v, 3, 0) without its 31 restoring steps. */
static int32_t third(int32_t v)
{
    const uint32_t n = (uint32_t)v + 1u;
    uint32_t q = (n >> 2) + (n >> 4), r;
    q += q >> 4;
    q += q >> 8;
    q += q >> 16;
    r = n - q * 3u;
    return (int32_t)(q + ((11u * r) >> 5));
}

void mtt_fx_cov_q(int32_t dt, int32_t sw, mtt_cov Q)
{
    int32_t m[3];
    int e[3], ds, ss, k, eq = -127;
    int i, j;
    for (i = 0; i < MTT_STATE_N; ++i) {
        for (j = 0; j < MTT_STATE_N; ++j) {
            Q[i][j] = 0;
        }
    }
    MTT_COV_E(Q) = -127;
    if (!(dt > 0) || !(sw > 0)) {
        return;
    }
    {
        const int32_t dm = mtt_fx_unpack(dt, MTT_FX_T_FRAC, &ds);
        const int32_t sm = mtt_fx_unpack(sw, MTT_FX_VAR_FRAC, &ss);
        /* q33 = sw dt, q13 = sw dt^2 / 2, q11 = sw dt^3 / 3 */
        m[2] = mtt_fx_mul(sm, dm, 30);
        e[2] = ss + ds + 30;
        m[1] = mtt_fx_mul(m[2], dm, 30);
        e[1] = e[2] + ds + 30;
        m[0] = third(mtt_fx_mul(m[1], dm, 30));
        e[0] = e[1] + ds + 30;
        e[1] -= 1;
    }
    for (k = 0; k < 3; ++k) {
        const int need = e[k] + bitlen(m[k]) - fit_top(dt);
        eq = (need > eq) ? need : eq;
    }
    for (k = 0; k < 3; ++k) {
        const int s = eq - e[k];
        m[k] = (s > 0) ? shr_round(m[k], s) : m[k] * ((int32_t)1 << -s);
    }
    Q[0][0] = m[0];
    Q[1][1] = m[0];
    Q[0][2] = m[1];
    Q[2][0] = m[1];
    Q[1][3] = m[1];
    Q[3][1] = m[1];
    Q[2][2] = m[2];
    Q[3][3] = m[2];
    MTT_COV_E(Q) = eq;
}

int32_t mtt_fx_at(int32_t m, int from, int to)
{
    const int s = to - from;
    if (s > 0) {
        return shr_round(m, s);
    }
    if (s == 0) {
        return m;
    }
    if (m == 0) {
        return 0;
    }
    /* m 2^-s, or MTT_FX_MAX with m's sign beyond it: mtt_fx_mul(m, 2^-s, 0)'s
     * result (m = INT32_MIN saturates) without its 64-bit product */
    if (-s > 30 || m == INT32_MIN || ((m < 0) ? -m : m) > (MTT_FX_MAX >> -s)) {
        return (m > 0) ? MTT_FX_MAX : MTT_FX_MIN;
    }
    return m * ((int32_t)1 << -s);
}

int mtt_fx_s_exp(mtt_cov Pp, const int32_t R[3])
{
    const int b = 32 - mtt_fx_clz(mtt_fx_or_abs(R, 3)); /* the largest bit length */
    int e;
    /* R's values at the exponent where its largest has MTT_FX_COV_TOP bits */
    e = (b > 0) ? -MTT_FX_VAR_FRAC + b - MTT_FX_COV_TOP : -127;
    e = (MTT_COV_E(Pp) > e) ? MTT_COV_E(Pp) : e;
    return e + 1; /* a sum of two terms below 2^28 */
}

int mtt_fx_si_exp(const int32_t S[MTT_SYM_SLOTS], int32_t det)
{
    const int b = 32 - mtt_fx_clz(mtt_fx_or_abs(S, 3)); /* the largest bit length */
    int sh;
    sh = 27 - b + bitlen(det); /* max |S| 2^sh / det < 2^28 */
    sh = (sh < 0) ? 0 : ((sh > 62) ? 62 : sh);
    return -MTT_SYM_E(S) - 28 - sh;
}

void mtt_fx_si_set(int32_t Si[MTT_SYM_SLOTS], const int32_t S[MTT_SYM_SLOTS], int32_t det)
{
    /* S_k 2^sh / det (sh = -e(S) - 28 - e(S^-1), mtt_fx_si_exp) as S_k r
     * 2^(sh - rho) with r = round(2^rho / det) on 30 bits: one quotient
     * instead of three; r's relative error 2^-30 adds |S^-1| 2^-30 (a
     * quarter unit at most) to each product's half unit. */
    const int sh = -MTT_SYM_E(S) - 28 - MTT_SYM_E(Si);
    const int rho = 29 + bitlen(det);
    const int32_t r = mtt_fx_recip(det, rho);
    const int32_t v[3] = {S[2], -S[1], S[0]};
    const int s = rho - sh;
    int k;
    for (k = 0; k < 3; ++k) {
        Si[k] = (s >= 19 && s <= 31) ? mtt_fx_mulq(v[k], r, s) : mtt_fx_mul(v[k], r, (s < 0) ? 0 : s);
    }
}

/* Normalises v (|v| <= MTT_FX_MAX) so that the larger of |a|, |b| has 30
 * bits: returns the shift s (values = mantissas 2^-s of the input's). */
static int norm_pair(int32_t *a, int32_t *b)
{
    const uint32_t u = (uint32_t)((*a < 0) ? -*a : *a) | (uint32_t)((*b < 0) ? -*b : *b);
    const int s = 30 - (32 - mtt_fx_clz(u));
    if (s >= 0) {
        *a *= (int32_t)1 << s;
        *b *= (int32_t)1 << s;
    } else { /* s = -1: |v| <= MTT_FX_MAX has at most 31 bits */
        *a = (*a >> 1) + (*a & 1);
        *b = (*b >> 1) + (*b & 1);
    }
    return s;
}

int32_t mtt_fx_mahal2(const int32_t Si[MTT_SYM_SLOTS], int32_t nx, int32_t ny)
{
    int32_t w0, w1, q;
    int s;
    if (nx == 0 && ny == 0) {
        return 0;
    }
    s = norm_pair(&nx, &ny);
    /* S^-1 nu: mantissas below 2^28 times |nu| <= 2^30, over 2^30: each
     * product below 2^28, each sum below 2^29; then nu' (S^-1 nu) below
     * 2^30: no overflow at any step. */
    w0 = mtt_fx_mulq30(Si[0], nx) + mtt_fx_mulq30(Si[1], ny);
    w1 = mtt_fx_mulq30(Si[1], nx) + mtt_fx_mulq30(Si[2], ny);
    q = mtt_fx_mulq30(nx, w0) + mtt_fx_mulq30(ny, w1);
    if (q < 0) {
        q = 0; /* S^-1 is positive definite: only rounding makes it negative */
    }
    /* d^2 = q 2^(e(S^-1) - 2 (F + s) + 60), returned in Q24 (saturated) */
    return mtt_fx_at(q, MTT_SYM_E(Si) - 2 * (MTT_FX_POS_FRAC + s) + 60, -MTT_FX_D2_FRAC);
}

/* ---- shared by the PDA update and L D L' (kalman.c) ---- */

int32_t mtt_fx_shift(int32_t v, int s)
{
    if (s >= 0) {
        return v * ((int32_t)1 << s);
    }
    if (s < -31) {
        return 0;
    }
    /* shr_round's rounding written out: a call to it here makes GCC stop
     * inlining it into the prediction's exponent moves (+260 instructions
     * per track, as with mtt_fx_mahal2) */
    {
        const int32_t t = v >> (-s - 1);
        return t - (t >> 1); /* floor(t / 2) + (t & 1), as shr_round */
    }
}

uint32_t mtt_fx_or_abs(const int32_t *v, int n)
{
    uint32_t u = 0u;
    int k;
    for (k = 0; k < n; ++k) {
        u |= (uint32_t)((v[k] < 0) ? -v[k] : v[k]);
    }
    return u;
}

int mtt_fx_top_exp(int e, uint32_t u, int top)
{
    return e + (32 - mtt_fx_clz(u)) - top;
}

#if MTT_WITH_IMM
int32_t mtt_fx_half_ln_det(int32_t det, const int32_t S[MTT_SYM_SLOTS])
{
    /* (ln m)/2 from Q25 to Q24, plus e ln(2)/2: |e| < 300 keeps it below 2^31 */
    if (!(det > 0)) {
        return MTT_FX_MAX;
    }
    return mtt_fx_add(MTT_FX_RSHIFT(mtt_fx_ln((uint32_t)det, 0), 2),
                      MTT_DET_E(S) * MTT_FX_CONST(0.34657359027997264, MTT_FX_D2_FRAC));
}
#endif

#endif /* MTT_REAL_FIXED */
