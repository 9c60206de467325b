/* SPDX-License-Identifier: BSD-3-Clause */
/* fx_math.c - the integer kernels of the fixed-point build: saturating
 * add, exact product, rounded multiply and divide, square root, exp(-y)
 * and log2 (docs/FIXED_POINT.md; the numerics of ALGORITHMS.md §16).
 *
 * Integer only, and only what ARMv6-M does in one instruction: 32-bit
 * add, shift, compare and a 32 x 32 -> 32 multiply (MULS).  So no 64-bit
 * multiply (__aeabi_lmul), no divide (__aeabi_idiv), no variable 64-bit
 * shift (__aeabi_llsr), no CLZ.  Compiled only in the fixed-point build
 * (MTT_REAL_FIXED) and for its unit test (MTT_FX_KERNELS): a float or
 * double library carries none of it. */
#include "real_ops.h"

#if defined(MTT_REAL_FIXED) || defined(MTT_FX_KERNELS)

/* leading zeros of a 4-bit value (4 for 0) */
static const uint8_t clz4_tab[16] = {4u, 3u, 2u, 2u, 1u, 1u, 1u, 1u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u};

int mtt_fx_clz(uint32_t x)
{
    /* the leading bit brought into the top nibble by shifts of 16, 8 and
     * 4 (no 32-bit constants to load on Thumb-1), the nibble by a table;
     * 0 gives 28 + 4 = 32 */
    int n = 0;
    if ((x >> 16) == 0u) {
        n = 16;
        x <<= 16;
    }
    if ((x >> 24) == 0u) {
        n += 8;
        x <<= 8;
    }
    if ((x >> 28) == 0u) {
        n += 4;
        x <<= 4;
    }
    return n + (int)clz4_tab[x >> 28];
}

int32_t mtt_fx_add(int32_t a, int32_t b)
{
    /* Overflow only when both have the same sign: test before adding
     * (signed overflow is undefined in C). */
    if (b > 0 && a > MTT_FX_MAX - b) {
        return MTT_FX_MAX;
    }
    if (b < 0 && a < MTT_FX_MIN - b) {
        return MTT_FX_MIN;
    }
    {
        const int32_t s = a + b;
        return (s < MTT_FX_MIN) ? MTT_FX_MIN : s; /* a + b = INT32_MIN */
    }
}

int32_t mtt_fx_sub(int32_t a, int32_t b)
{
    /* -b saturates: b = INT32_MIN becomes MAX, one below the exact 2^31. */
    if (b == INT32_MIN) {
        return (a >= 0) ? MTT_FX_MAX : mtt_fx_add(a + 1, MTT_FX_MAX);
    }
    return mtt_fx_add(a, -b);
}

/* |v| as uint32 (2^31 for INT32_MIN). */
static uint32_t mag(int32_t v)
{
    return (v < 0) ? (uint32_t)0u - (uint32_t)v : (uint32_t)v;
}

/* Exact ua * ub = hi:lo from four 16 x 16 -> 32 products (a macro: the
 * hot mtt_fx_mul keeps hi and lo in registers). */
#define FX_UMULL(ua, ub, hi, lo)                                                                    \
    do {                                                                                           \
        const uint32_t al_ = (ua) & 0xFFFFu, ah_ = (ua) >> 16, bl_ = (ub) & 0xFFFFu, bh_ = (ub) >> 16; \
        const uint32_t ll_ = al_ * bl_, hh_ = ah_ * bh_, m1_ = al_ * bh_, m2_ = ah_ * bl_;          \
        /* mid = m1 + m2 may carry out of 32 bits: that carry is worth 2^48. */                    \
        const uint32_t mid_ = m1_ + m2_;                                                           \
        const uint32_t carry_ = (mid_ < m1_) ? 0x10000u : 0u;                                      \
        const uint32_t l_ = ll_ + (mid_ << 16);                                                    \
        (hi) = hh_ + (mid_ >> 16) + carry_ + ((l_ < ll_) ? 1u : 0u);                               \
        (lo) = l_;                                                                                 \
    } while (0)

static void umull(uint32_t ua, uint32_t ub, uint32_t *hi, uint32_t *lo)
{
    FX_UMULL(ua, ub, *hi, *lo);
}

int mtt_fx_mull(int32_t a, int32_t b, uint32_t *hi, uint32_t *lo)
{
    const uint32_t ua = mag(a), ub = mag(b);
    umull(ua, ub, hi, lo);
    if (ua == 0u || ub == 0u) {
        return 0;
    }
    return ((a < 0) != (b < 0)) ? -1 : 1;
}

/* round((hi:lo) / 2^s) (ties up), saturated to MTT_FX_MAX; 0 <= s <= 62,
 * hi:lo < 2^62.  floor((x + 2^(s-1)) / 2^s) = t - floor(t / 2) with t =
 * floor(x / 2^(s-1)): no 64-bit add; t >= 2^32 saturates. */
static uint32_t shr_round(uint32_t hi, uint32_t lo, int s)
{
    const int k = s - 1;
    uint32_t r;
    if (s == 0) {
        return (hi != 0u || lo > (uint32_t)MTT_FX_MAX) ? (uint32_t)MTT_FX_MAX : lo;
    }
    if (k >= 32) {
        lo = hi >> (k - 32);
    } else if (k > 0) {
        if ((hi >> k) != 0u) {
            return (uint32_t)MTT_FX_MAX;
        }
        lo = (lo >> k) | (hi << (32 - k));
    } else if (hi != 0u) {
        return (uint32_t)MTT_FX_MAX;
    }
    r = lo - (lo >> 1);
    return (r > (uint32_t)MTT_FX_MAX) ? (uint32_t)MTT_FX_MAX : r;
}

int32_t mtt_fx_mul(int32_t a, int32_t b, int s)
{
    /* mtt_fx_mull's steps without its call (a hot kernel on Cortex-M0+) */
    const uint32_t ua = mag(a), ub = mag(b);
    uint32_t hi, lo, r;
    if (ua == 0u || ub == 0u) {
        return 0;
    }
    FX_UMULL(ua, ub, hi, lo);
    r = shr_round(hi, lo, s);
    return ((a < 0) != (b < 0)) ? -(int32_t)r : (int32_t)r;
}

/* The body of mtt_fx_mulq, one text for its two entries (the Q30 one
 * with the shift folded: the hot products of the PDA update and L D L').
 * a = ah 2^16 + al with ah signed, al in [0, 2^16): every partial product
 * fits int32, so no sign juggling.  The two middle products and the low
 * one are summed at 2^-18 of the product (each floored: an error in
 * [0, 3) there), the high one added exactly.  The high part is exact only
 * modulo 2^32 (its top bits leave the word); the sum is formed in
 * uint32_t, where wrapping is defined, and the exact result fits int32_t. */
#define FX_MULQ_RETURN(a, b, s)                                                                     \
    do {                                                                                           \
        const int32_t ah = (a) >> 16, bh = (b) >> 16;                                              \
        const int32_t al = (int32_t)((uint32_t)(a) & 0xFFFFu), bl = (int32_t)((uint32_t)(b) & 0xFFFFu); \
        const int32_t mid = ((al * bh) >> 2) + ((ah * bl) >> 2) +                                  \
                            (int32_t)(((uint32_t)al * (uint32_t)bl) >> 18);                        \
        const int k = (s) - 18;                                                                    \
        const uint32_t high = (uint32_t)(ah * bh) << (32 - (s));                                   \
        const int32_t t = mid >> (k - 1); /* (mid + 2^(k-1)) >> k = t - (t >> 1): no constant */ \
        const uint32_t low = (uint32_t)(t - (t >> 1));                                             \
        return (int32_t)(high + low);                                                              \
    } while (0)

int32_t mtt_fx_mulq(int32_t a, int32_t b, int s)
{
    FX_MULQ_RETURN(a, b, s);
}

int32_t mtt_fx_mulq30(int32_t a, int32_t b)
{
    FX_MULQ_RETURN(a, b, 30);
}

int32_t mtt_fx_mulq28(int32_t a, int32_t b)
{
    FX_MULQ_RETURN(a, b, 28);
}

/* round(2^46 / m) at the midpoint m of each interval [(64 + i) 2^24,
 * (65 + i) 2^24) of a divisor in [2^30, 2^31): 7 bits of 2^46 / d. */
static const uint16_t recip_tab[64] = {
    65028u, 64035u, 63072u, 62138u, 61231u, 60350u, 59494u, 58662u,
    57852u, 57065u, 56299u, 55554u, 54828u, 54120u, 53431u, 52759u,
    52103u, 51464u, 50840u, 50231u, 49637u, 49056u, 48489u, 47935u,
    47393u, 46864u, 46346u, 45839u, 45344u, 44859u, 44384u, 43919u,
    43464u, 43019u, 42582u, 42154u, 41734u, 41323u, 40920u, 40525u,
    40137u, 39756u, 39383u, 39017u, 38657u, 38304u, 37958u, 37617u,
    37283u, 36954u, 36631u, 36314u, 36003u, 35696u, 35395u, 35099u,
    34808u, 34521u, 34239u, 33962u, 33689u, 33421u, 33157u, 32897u};

/* One quotient digit of b bits (b <= 11): q = floor(r 2^b / d) with
 * r < d, d in [2^30, 2^31), and r becomes r 2^b - q d.  The estimate
 * (r >> 15) v >> (31 - b) (below 2^31: v <= 2^46 / d) is never above q
 * and at most 1 below it: the truncated r costs under 2^(b-15), v's
 * deficit (< 7.1, fx_div_core) 7.1 2^(b-15), the floor 1, together
 * < 1.5 for b = 11.  So the remainder, formed modulo 2^32, is in
 * [0, 2d) and exact, and one comparison corrects the digit. */
#define FX_DIV_DIGIT(q, b)                                   \
    do {                                                     \
        (q) = ((r >> 15) * v) >> (31 - (b));                 \
        r = (r << (b)) - (q) * d;                            \
        if (r >= d) {                                        \
            r -= d;                                          \
            ++(q);                                           \
        }                                                    \
    } while (0)

/* floor(n 2^31 / d) for n, d in [2^30, 2^31) (below 2^32), and the
 * remainder n 2^31 - q d in *rem: the restoring division's result, by
 * three digits of 11, 10 and 10 bits after the integer bit.  v: 2^46 / d
 * from the table and one Newton step on d1 = d >> 15, v1 = x0 + x0 e /
 * 2^31 with e = 2^31 - d1 x0 (|e| < 2^31 / 128: x0 (e >> 10) fits).
 * Newton from x0 of relative error < 2^-7 lands below 2^31 / d1 by at
 * most 2^16 2^-14 = 4, the floors add < 1.04; 2^31 / d1 exceeds 2^46 / d
 * by < 2 (d1 2^15 > d - 2^15), so v = v1 - 2 <= 2^46 / d, at most 7.1 below. */
static uint32_t fx_div_core(uint32_t n, uint32_t d, uint32_t *rem)
{
    const uint32_t d1 = d >> 15;
    const uint32_t x0 = recip_tab[(d >> 24) - 64u];
    const int32_t e = (int32_t)(0x80000000u - d1 * x0);
    const uint32_t v = (uint32_t)((int32_t)x0 + (((int32_t)x0 * (e >> 10)) >> 21)) - 2u;
    uint32_t r = n, q0 = 0u, q1, q2, q3;
    if (r >= d) {
        q0 = 0x80000000u;
        r -= d;
    }
    FX_DIV_DIGIT(q1, 11);
    FX_DIV_DIGIT(q2, 10);
    FX_DIV_DIGIT(q3, 10);
    *rem = r;
    return q0 | (q1 << 20) | (q2 << 10) | q3;
}
#undef FX_DIV_DIGIT

int32_t mtt_fx_div(int32_t a, int32_t b, int s)
{
    const uint32_t ua = mag(a), ub = mag(b);
    const int neg = (a < 0) != (b < 0);
    uint32_t n, d, q, r;
    int na, nb, sh;
    if (ub == 0u) {
        return (a > 0) ? MTT_FX_MAX : ((a < 0) ? MTT_FX_MIN : 0);
    }
    if (ua == 0u) {
        return 0;
    }
    na = mtt_fx_clz(ua);
    nb = mtt_fx_clz(ub);
    /* Both in [2^30, 2^31): n / d in (1/2, 2).  The shift drops no bit: a
     * magnitude is at most 2^31, so na = 0 only for 2^31 itself. */
    n = (ua << na) >> 1;
    d = (ub << nb) >> 1;
    /* q = floor(n / d 2^31) < 2^32, n the remainder */
    q = fx_div_core(n, d, &n);
    /* |a| 2^s / |b| = (n0 / d) 2^(s - na + nb) = q 2^-sh (+ the remainder). */
    sh = 31 + na - nb - s;
    if (sh < 0) {
        r = (uint32_t)MTT_FX_MAX; /* q >= 2^30: the result is >= 2^31 */
    } else if (sh == 0) {
        /* round with the next quotient bit: 2 rem >= d */
        const uint32_t up = ((n << 1) >= d) ? 1u : 0u;
        r = (q > (uint32_t)MTT_FX_MAX - up) ? (uint32_t)MTT_FX_MAX : q + up;
    } else if (sh > 32) {
        r = 0u;
    } else if (sh == 32) {
        r = (q >= 0x80000000u) ? 1u : 0u;
    } else {
        /* floor(floor(x) + c) / 2^sh = floor((x + c) / 2^sh): rounding the
         * floored quotient is rounding the exact one.  shr_round(0, q, sh)
         * in one word: floor((q + 2^(sh-1)) / 2^sh) = t - floor(t / 2) with
         * t = floor(q / 2^(sh-1)), at most 2^31 (saturated) */
        const uint32_t t = q >> (sh - 1);
        r = t - (t >> 1);
        r = (r > (uint32_t)MTT_FX_MAX) ? (uint32_t)MTT_FX_MAX : r;
    }
    return neg ? -(int32_t)r : (int32_t)r;
}

int32_t mtt_fx_recip(int32_t x, int s)
{
    return mtt_fx_div(1, x, s);
}

/* One step of the digit-by-digit root in one word: the next two radicand
 * bits from the top of w, one root bit (rem <= 2 root before and after). */
#define FX_SQRT_STEP(w)                       \
    do {                                      \
        const uint32_t trial = (root << 2) | 1u; \
        rem = (rem << 2) | ((w) >> 30);       \
        (w) <<= 2;                            \
        root <<= 1;                           \
        if (rem >= trial) {                   \
            rem -= trial;                     \
            root |= 1u;                       \
        }                                     \
    } while (0)

/* round(sqrt(hi:lo)) (32 root bits), two radicand bits per step. */
static uint32_t sqrt_digits(uint32_t hi, uint32_t lo)
{
    uint32_t root = 0u, rem = 0u, remc = 0u;
    int i;
    /* The first 28 steps: root < 2^i and rem <= 2 root < 2^(i+1) after i
     * steps, so 4 rem + 3 and 4 root + 1 stay below 2^31: one word each.
     * The first 16 take their bits from hi, the next 12 from lo (no
     * 64-bit shift per step). */
    for (i = 0; i < 16; ++i) {
        FX_SQRT_STEP(hi);
    }
    for (i = 0; i < 12; ++i) {
        FX_SQRT_STEP(lo);
    }
    hi = lo; /* the last 8 bits, now at the top of lo */
    /* The last steps of a 32-bit root: root < 2^32 and rem <= 2 root, so
     * rem needs 33 bits: kept as rem (low 32) and remc (bit 32). */
    for (i = 0; i < 4; ++i) {
        /* rem = rem * 4 + next two bits; trial = 4 root + 1 (both up to 35 bits:
         * the high parts are tracked in remc / trc). */
        const uint32_t bits = hi >> 30;
        uint32_t trial, trc;
        hi <<= 2;
        remc = (remc << 2) | (rem >> 30);
        rem = (rem << 2) | bits;
        trc = root >> 30;
        trial = (root << 2) | 1u;
        root <<= 1;
        if (remc > trc || (remc == trc && rem >= trial)) {
            remc = remc - trc - ((rem < trial) ? 1u : 0u);
            rem -= trial;
            root |= 1u;
        }
    }
    /* Round to nearest: (root + 1/2)^2 = root^2 + root + 1/4, so round up
     * when rem = x - root^2 > root. */
    if ((remc != 0u || rem > root) && root != 0xFFFFFFFFu) {
        ++root;
    }
    return root;
}

uint32_t mtt_fx_sqrt(uint32_t x, int f)
{
    /* Radicand x 2^f = hi:lo (64 bits), 32 steps. */
    if (f == 0) {
        return sqrt_digits(0u, x);
    }
    if (f < 32) {
        return sqrt_digits(x >> (32 - f), x << f);
    }
    return sqrt_digits(x, 0u);
}

uint32_t mtt_fx_sqrt8(uint32_t x)
{
    /* sqrt_digits(x, 0, 8) in one word: the radicand's top 16 bits, root
     * < 2^8 and rem <= 2 root; the same steps and rounding */
    uint32_t root = 0u, rem = 0u;
    int i;
    for (i = 0; i < 8; ++i) {
        FX_SQRT_STEP(x);
    }
    return (rem > root) ? root + 1u : root;
}
#undef FX_SQRT_STEP

/* 2^-(i/16) in Q30, i = 0..15, rounded. */
static const int32_t exp2_tab[16] = {
    1073741824, 1028218693, 984625594, 942880699, 902905651, 864625413, 827968132, 792865000,
    759250125,  727060411,  696235434, 666717336, 638450708, 611382493, 585461881, 560640218};

int32_t mtt_fx_exp_neg(uint32_t y, int *k)
{
    /* log2(e) = LE_HI 2^-30 + LE_LO 2^-62 (64 bits of it). */
    const uint32_t le_hi = 1549082004u, le_lo = 2920020061u;
    const int32_t ln2 = 744261118; /* ln 2 in Q30 */
    uint32_t th, tl, ch, cl, f, r;
    int32_t u, h;
    int i;
    /* t = y log2(e) in Q54: y le_hi + (y le_lo) / 2^32 (truncated). */
    FX_UMULL(y, le_hi, th, tl);
    FX_UMULL(y, le_lo, ch, cl);
    (void)cl;
    {
        const uint32_t l = tl + ch;
        th += (l < tl) ? 1u : 0u;
        tl = l;
    }
    /* t = th:tl in Q54: k = t >> 54, fraction f in Q30 = (t >> 24) & (2^30 - 1). */
    *k = (int)(th >> 22);
    f = ((th << 8) | (tl >> 24)) & 0x3FFFFFFFu;
    i = (int)(f >> 26);
    r = f & 0x03FFFFFFu;                  /* r < 1/16 in Q30 */
    u = mtt_fx_mulq30((int32_t)r, ln2); /* u = r ln 2 < 0.0434 */
    /* exp(-u) = 1 - u (1 - u (1/2 - u (1/6 - u/24))) */
    h = 178956971 - mtt_fx_mulq30(u, 44739243); /* 1/6 - u/24 */
    h = 536870912 - mtt_fx_mulq30(u, h);        /* 1/2 - u h */
    h = MTT_FX_Q30_ONE - mtt_fx_mulq30(u, h);   /* 1 - u h */
    h = MTT_FX_Q30_ONE - mtt_fx_mulq30(u, h);   /* exp(-u) */
    return mtt_fx_mulq30(exp2_tab[i], h);
}

int32_t mtt_fx_exp_neg_q30(uint32_t y)
{
    int k;
    const int32_t m = mtt_fx_exp_neg(y, &k);
    if (k > 31) {
        return 0;
    }
    if (k == 0) {
        return m;
    }
    return (int32_t)(((uint32_t)m + ((uint32_t)1u << (k - 1))) >> k);
}

/* log2(1 + 2^-i) in Q30, i = 1..30, rounded. */
static const int32_t log2_tab[30] = {
    628098702, 345667660, 182455581, 93912511, 47667823, 24017256, 12055174, 6039314,
    3022600,   1512037,   756203,    378148,   189085,   94546,    47274,    23637,
    11819,     5909,      2955,      1477,     739,      369,      185,      92,
    46,        23,        12,        6,        3,        1};

int32_t mtt_fx_log2(uint32_t x, int f)
{
    /* x = 2^(31 - nz) * (xn / 2^31), xn in [2^31, 2^32): work in Q31 on
     * z = xn / 2 in [2^30, 2^31) (Q30, [1, 2)) so z + z 2^-i cannot wrap. */
    uint32_t z;
    int32_t acc = 0; /* sum of log2(1 + 2^-i) chosen, Q30 */
    int nz, i;
    int32_t e;
    if (x == 0u) {
        return MTT_FX_MIN;
    }
    nz = mtt_fx_clz(x);
    z = (x << nz) >> 1;
    /* Multiply z by (1 + 2^-i) while it stays below 2: z prod -> 2. */
    for (i = 1; i <= 30; ++i) {
        const uint32_t t = z + (z >> i);
        if (t < 0x80000000u) {
            z = t;
            acc += log2_tab[i - 1];
        }
    }
    /* log2(z0) = 1 - acc - log2(z / 2^31); z / 2^31 = 1 - d with d = (2^31 - z) / 2^31
     * < 2^-29: log2(1 - d) = -d log2(e) (+ O(d^2) < 2^-58).  d log2(e) in Q30:
     * (2^31 - z) * log2(e) / 2. */
    {
        const int32_t dz = (int32_t)(0x80000000u - z);
        acc += mtt_fx_mul(dz, 1549082005, 31); /* log2(e) in Q30, / 2 */
    }
    /* x 2^-f = z0 2^(31 - nz - f) with z0 = z / 2^30 in [1, 2). */
    e = (int32_t)(31 - nz - f);
    {
        /* frac = 1 - acc in Q30 is log2(z0) in [0, 1]; total in Q25 rounded. */
        const int32_t frac = MTT_FX_Q30_ONE - acc;
        const int32_t fr25 = (frac + 16) >> 5;
        return e * (int32_t)33554432 + fr25;
    }
}

int32_t mtt_fx_ln(uint32_t x, int f)
{
    /* ln 2 in Q31 = 1488522236; Q25 times Q31 >> 31 stays Q25. */
    return mtt_fx_mul(mtt_fx_log2(x, f), 1488522236, 31);
}

#else
/* ISO C wants at least one declaration in a translation unit. */
typedef int mtt_fx_math_unused;
#endif
