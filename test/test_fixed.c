/* SPDX-License-Identifier: BSD-3-Clause */
/* test_fixed.c - the integer kernels of the fixed-point build
 * (include/mtt/fixed.h, src/fixed/fx_math.c; docs/FIXED_POINT.md) against exact
 * integer references and double references, densely or exhaustively, with
 * the error bounds that fixed.h states, and saturation (never wrap) at the
 * ends of every range.  The kernels are compiled into this test with
 * MTT_FX_KERNELS (test/CMakeLists.txt), whatever mtt_real is. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>

#include "real_ops.h" /* the kernels: private (src/) */
#include "unity.h"

/* Print a measured worst error beside its bound (ctest -V shows it). */
static void report(const char *fmt, double worst)
{
    char buf[128];
    (void)snprintf(buf, sizeof buf, fmt, worst);
    UnityPrint(buf);
    UNITY_PRINT_EOL();
}

void setUp(void) {}
void tearDown(void) {}

/* xorshift32: a deterministic input stream */
static uint32_t rng = 2463534242u;
static uint32_t rnd(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 17;
    rng ^= rng << 5;
    return rng;
}

/* Random int32 with a random magnitude (all bit lengths equally likely). */
static int32_t rnd_i32(void)
{
    const uint32_t bits = rnd() % 33u;
    uint32_t v = (bits == 0u) ? 0u : (rnd() >> (32u - bits));
    int32_t r = (v > (uint32_t)INT32_MAX) ? INT32_MAX : (int32_t)v;
    return ((rnd() & 1u) != 0u) ? -r : r;
}

static int ref_clz(uint32_t x)
{
    int n = 0;
    if (x == 0u) {
        return 32;
    }
    while ((x & 0x80000000u) == 0u) {
        x <<= 1;
        ++n;
    }
    return n;
}

static void test_clz(void)
{
    int k;
    long i;
    TEST_ASSERT_EQUAL_INT(32, mtt_fx_clz(0u));
    for (k = 0; k < 32; ++k) {
        const uint32_t p = (uint32_t)1u << k;
        TEST_ASSERT_EQUAL_INT(31 - k, mtt_fx_clz(p));
        TEST_ASSERT_EQUAL_INT(31 - k, mtt_fx_clz(p | (p - 1u)));
        if (k > 0) {
            TEST_ASSERT_EQUAL_INT(31 - k, mtt_fx_clz(p + 1u));
        }
    }
    /* Exhaustive below 2^20, random above. */
    for (i = 0; i < (1L << 20); ++i) {
        TEST_ASSERT_EQUAL_INT(ref_clz((uint32_t)i), mtt_fx_clz((uint32_t)i));
    }
    for (i = 0; i < 1000000L; ++i) {
        const uint32_t x = rnd() >> (rnd() % 32u);
        TEST_ASSERT_EQUAL_INT(ref_clz(x), mtt_fx_clz(x));
    }
}

static int32_t clamp64(int64_t v)
{
    if (v > MTT_FX_MAX) {
        return MTT_FX_MAX;
    }
    if (v < MTT_FX_MIN) {
        return MTT_FX_MIN;
    }
    return (int32_t)v;
}

static void test_add_sub_saturate(void)
{
    long i;
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MAX, mtt_fx_add(MTT_FX_MAX, 1));
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MAX, mtt_fx_add(MTT_FX_MAX, MTT_FX_MAX));
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MIN, mtt_fx_add(MTT_FX_MIN, -1));
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MIN, mtt_fx_add(INT32_MIN, INT32_MIN));
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MIN, mtt_fx_add(-1, INT32_MIN + 1));
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MAX, mtt_fx_sub(0, INT32_MIN));
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MIN, mtt_fx_sub(MTT_FX_MIN, 1));
    TEST_ASSERT_EQUAL_INT32(-1, mtt_fx_sub(INT32_MIN + 1, INT32_MIN) - 2);
    for (i = 0; i < 2000000L; ++i) {
        const int32_t a = rnd_i32(), b = rnd_i32();
        TEST_ASSERT_EQUAL_INT32(clamp64((int64_t)a + b), mtt_fx_add(a, b));
        TEST_ASSERT_EQUAL_INT32(clamp64((int64_t)a - b), mtt_fx_sub(a, b));
    }
}

/* Exact reference of mtt_fx_mul: |a b| < 2^62 fits uint64. */
static int32_t ref_mul(int32_t a, int32_t b, int s)
{
    const uint64_t ua = (a < 0) ? (uint64_t)(-(int64_t)a) : (uint64_t)a;
    const uint64_t ub = (b < 0) ? (uint64_t)(-(int64_t)b) : (uint64_t)b;
    const uint64_t p = ua * ub;
    uint64_t r = (s == 0) ? p : ((p + ((uint64_t)1u << (s - 1))) >> s);
    if (r > (uint64_t)MTT_FX_MAX) {
        r = (uint64_t)MTT_FX_MAX;
    }
    return ((a < 0) != (b < 0)) ? -(int32_t)r : (int32_t)r;
}

static void test_mull_exact(void)
{
    long i;
    for (i = 0; i < 2000000L; ++i) {
        const int32_t a = (i < 4) ? ((i & 1) ? INT32_MIN : INT32_MAX) : rnd_i32();
        const int32_t b = (i < 4) ? ((i & 2) ? INT32_MIN : INT32_MAX) : rnd_i32();
        const int64_t p = (int64_t)a * b;
        const uint64_t up = (p < 0) ? (uint64_t)0u - (uint64_t)p : (uint64_t)p;
        uint32_t hi, lo;
        const int sg = mtt_fx_mull(a, b, &hi, &lo);
        TEST_ASSERT_EQUAL_UINT32((uint32_t)(up >> 32), hi);
        TEST_ASSERT_EQUAL_UINT32((uint32_t)up, lo);
        TEST_ASSERT_EQUAL_INT((p > 0) ? 1 : ((p < 0) ? -1 : 0), sg);
    }
}

static void test_mul_rounding_saturation(void)
{
    long i;
    int s;
    /* every shift, random operands: bit-exact (error <= 0.5 ulp) */
    for (s = 0; s <= 62; ++s) {
        for (i = 0; i < 60000L; ++i) {
            const int32_t a = rnd_i32(), b = rnd_i32();
            TEST_ASSERT_EQUAL_INT32(ref_mul(a, b, s), mtt_fx_mul(a, b, s));
        }
    }
    /* ties round away from zero, symmetric in sign */
    TEST_ASSERT_EQUAL_INT32(2, mtt_fx_mul(3, 1, 1));
    TEST_ASSERT_EQUAL_INT32(-2, mtt_fx_mul(-3, 1, 1));
    TEST_ASSERT_EQUAL_INT32(1, mtt_fx_mul(1, 1, 1));
    TEST_ASSERT_EQUAL_INT32(0, mtt_fx_mul(1, 1, 2));
    /* saturation at both ends, never a wrap */
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MAX, mtt_fx_mul(MTT_FX_MAX, MTT_FX_MAX, 30));
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MIN, mtt_fx_mul(MTT_FX_MAX, MTT_FX_MIN, 30));
    TEST_ASSERT_EQUAL_INT32(2, mtt_fx_mul(INT32_MIN, INT32_MIN, 61));
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MAX, mtt_fx_mul(INT32_MIN, INT32_MIN, 31));
    TEST_ASSERT_EQUAL_INT32(1 << 30, mtt_fx_mul(INT32_MIN, INT32_MIN, 32));
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MAX, mtt_fx_mul(65536, 32768, 0));
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MIN, mtt_fx_mul(-65536, 32768, 0));
}

static void test_mulq_fast(void)
{
    long i;
    int s;
    double worst[32] = {0.0};
    for (s = 19; s <= 31; ++s) {
        const double bound = 0.5 + 3.0 * ldexp(1.0, 18 - s);
        for (i = 0; i < 200000L; ++i) {
            const int32_t a = rnd_i32(), b = rnd_i32();
            const long double ex = ldexpl((long double)a * (long double)b, -s); /* exact in 64 bits */
            double e;
            if (fabsl(ex) >= 2147483646.0L) {
                continue; /* outside the precondition */
            }
            e = (double)fabsl((long double)mtt_fx_mulq(a, b, s) - ex);
            worst[s] = (e > worst[s]) ? e : worst[s];
            TEST_ASSERT_TRUE(e <= bound);
            if (s == 30) { /* the Q30 entry: the same result */
                TEST_ASSERT_EQUAL_INT32(mtt_fx_mulq(a, b, 30), mtt_fx_mulq30(a, b));
            }
            if (s == 28) { /* the shift-28 entry (S, K): the same result */
                TEST_ASSERT_EQUAL_INT32(mtt_fx_mulq(a, b, 28), mtt_fx_mulq28(a, b));
            }
        }
    }
    report("mulq: worst error at s = 30: %.4f ulp (bound 0.5007)", worst[30]);
    TEST_ASSERT_EQUAL_INT32(1 << 30, mtt_fx_mulq(1 << 30, 1 << 30, 30));
    TEST_ASSERT_EQUAL_INT32(-(1 << 29), mtt_fx_mulq(-(1 << 30), 1 << 29, 30));
}

/* Exact check of r = mtt_fx_div(a, b, s) for s <= 31: with A = |a| 2^s and
 * B = |b| (both sides < 2^63), 2 |A - r B| <= B, ties away from zero, or
 * r saturated when A / B >= MAX + 1/2. */
static void check_div_exact(int32_t a, int32_t b, int s, int32_t r)
{
    const uint64_t ua = (a < 0) ? (uint64_t)(-(int64_t)a) : (uint64_t)a;
    const uint64_t ub = (b < 0) ? (uint64_t)(-(int64_t)b) : (uint64_t)b;
    const uint64_t A = ua << s;
    const int neg = (a < 0) != (b < 0);
    const uint64_t ur = (r < 0) ? (uint64_t)(-(int64_t)r) : (uint64_t)r;
    if (ua == 0u) {
        TEST_ASSERT_EQUAL_INT32(0, r);
        return;
    }
    TEST_ASSERT_TRUE(neg ? (r <= 0) : (r >= 0));
    if (ur == (uint64_t)MTT_FX_MAX) {
        /* saturated, or exact: A / B >= MAX - 1/2 */
        TEST_ASSERT_TRUE(2u * A >= (2u * (uint64_t)MTT_FX_MAX - 1u) * ub);
        return;
    }
    {
        const uint64_t rb = ur * ub;
        const uint64_t diff2 = (A > rb) ? 2u * (A - rb) : 2u * (rb - A);
        TEST_ASSERT_TRUE(diff2 <= ub);
        if (diff2 == ub) {
            TEST_ASSERT_TRUE(rb > A); /* a tie went away from zero */
        }
    }
}

static void test_div(void)
{
    long i;
    int s;
    for (s = 0; s <= 31; ++s) {
        for (i = 0; i < 40000L; ++i) {
            const int32_t a = rnd_i32();
            int32_t b = rnd_i32();
            if (b == 0) {
                b = 1;
            }
            check_div_exact(a, b, s, mtt_fx_div(a, b, s));
        }
    }
    /* s up to 62 against long double (64-bit significand: the quotient
     * below 2^31 is known to 2^-33, so a 0.5 + 1e-6 ulp band is safe). */
    for (s = 32; s <= 62; ++s) {
        for (i = 0; i < 20000L; ++i) {
            const int32_t a = rnd_i32();
            int32_t b = rnd_i32(), r;
            long double q;
            if (b == 0) {
                b = -1;
            }
            r = mtt_fx_div(a, b, s);
            q = ldexpl((long double)a, s) / (long double)b;
            if (q >= (long double)MTT_FX_MAX) {
                TEST_ASSERT_EQUAL_INT32(MTT_FX_MAX, r);
            } else if (q <= (long double)MTT_FX_MIN) {
                TEST_ASSERT_EQUAL_INT32(MTT_FX_MIN, r);
            } else {
                TEST_ASSERT_TRUE(fabsl(q - (long double)r) <= 0.500001L);
            }
        }
    }
    /* The quotient digits' worst cases (fx_math.c): divisors at both ends
     * of each of the reciprocal table's 64 intervals and with the bits
     * below d >> 15 all set (the Newton step's largest deficit), numerators
     * just below the divisor (the largest digits) and at the edges. */
    for (i = 0; i < 64; ++i) {
        const int64_t lo = (int64_t)(64 + i) << 24; /* 64-bit: the last interval ends at 2^31 */
        const int32_t d[4] = {(int32_t)lo, (int32_t)(lo + (1L << 24) - 1), (int32_t)(lo | 0x7FFF),
                              (int32_t)(lo | 0x00FFFFFF)};
        int k, j;
        for (k = 0; k < 4; ++k) {
            /* d + 1 saturates at MTT_FX_MAX (d = 2^31 - 1 ends the last interval) */
            const int32_t n[5] = {d[k] - 1, d[k], (d[k] < MTT_FX_MAX) ? d[k] + 1 : d[k], 1 << 30, MTT_FX_MAX};
            for (j = 0; j < 5; ++j) {
                for (s = 28; s <= 31; ++s) {
                    check_div_exact(n[j], d[k], s, mtt_fx_div(n[j], d[k], s));
                    check_div_exact(-n[j], d[k] >> 9, s - 9, mtt_fx_div(-n[j], d[k] >> 9, s - 9));
                }
            }
        }
    }
    /* division by zero and overflow saturate */
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MAX, mtt_fx_div(5, 0, 0));
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MIN, mtt_fx_div(-5, 0, 10));
    TEST_ASSERT_EQUAL_INT32(0, mtt_fx_div(0, 0, 10));
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MAX, mtt_fx_div(MTT_FX_MAX, 1, 1));
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MIN, mtt_fx_div(MTT_FX_MAX, -1, 1));
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MAX, mtt_fx_div(INT32_MIN, -1, 0));
    /* ties away from zero */
    TEST_ASSERT_EQUAL_INT32(2, mtt_fx_div(3, 2, 0));
    TEST_ASSERT_EQUAL_INT32(-2, mtt_fx_div(-3, 2, 0));
    TEST_ASSERT_EQUAL_INT32(1 << 30, mtt_fx_div(1, 1, 30));
    /* reciprocal: 2^60 / 3 */
    TEST_ASSERT_EQUAL_INT32(357913941, mtt_fx_recip(3, 30));
    TEST_ASSERT_EQUAL_INT32(715827883, mtt_fx_recip(3 << 29, 60));
}

static void check_sqrt(uint32_t x, int f)
{
    const uint64_t X = (f == 32) ? ((uint64_t)x << 32) : ((uint64_t)x << f);
    const uint32_t r = mtt_fx_sqrt(x, f);
    const uint64_t r64 = r;
    /* round(sqrt(X)) = r  <=>  r^2 - r < X <= r^2 + r (X integer) */
    if (r == 0xFFFFFFFFu) {
        TEST_ASSERT_TRUE(X > r64 * r64 - r64);
        return;
    }
    TEST_ASSERT_TRUE(X <= r64 * r64 + r64);
    if (r > 0u) {
        TEST_ASSERT_TRUE(X > r64 * r64 - r64);
    }
}

static void test_sqrt(void)
{
    long i;
    int f;
    for (i = 0; i < (1L << 20); ++i) {
        check_sqrt((uint32_t)i, 0);
        check_sqrt((uint32_t)i, 30);
    }
    for (f = 0; f <= 32; ++f) {
        for (i = 0; i < 100000L; ++i) {
            check_sqrt(rnd() >> (rnd() % 32u), f);
        }
        check_sqrt(0xFFFFFFFFu, f);
    }
    TEST_ASSERT_EQUAL_UINT32(3u << 15, mtt_fx_sqrt(9u << 15, 15));
    TEST_ASSERT_EQUAL_UINT32(0xFFFFFFFFu, mtt_fx_sqrt(0xFFFFFFFFu, 32)); /* saturates */
    TEST_ASSERT_EQUAL_UINT32(0u, mtt_fx_sqrt(0u, 32));
}

/* the 8-step root of x's top 16 bits X = floor(x / 2^16): r^2 - r < X <=
 * r^2 + r, every X (x = X 2^16 and X 2^16 + 2^16 - 1) and 10^6 random x;
 * and the gate's bound (r + 1) 2^8 > sqrt(x) for every x >= 2^30 tried */
static void check_sqrt8(uint32_t x)
{
    const uint64_t r = mtt_fx_sqrt8(x), X = x >> 16;
    TEST_ASSERT_TRUE(X <= r * r + r);
    if (r > 0u) {
        TEST_ASSERT_TRUE(X > r * r - r);
    }
    if (x >= (1u << 30)) {
        TEST_ASSERT_TRUE((double)((r + 1u) << 8) > sqrt((double)x));
    }
}

static void test_sqrt8(void)
{
    long i;
    for (i = 0; i < (1L << 16); ++i) {
        check_sqrt8((uint32_t)i << 16);
        check_sqrt8(((uint32_t)i << 16) | 0xFFFFu);
    }
    for (i = 0; i < 1000000L; ++i) {
        check_sqrt8(rnd() >> (rnd() % 32u));
    }
    TEST_ASSERT_EQUAL_UINT32(256u, mtt_fx_sqrt8(0xFFFFFFFFu));
}

/* |m 2^-k - 2^30 exp(-y)| in units of the mantissa (2^-30 2^-k). */
static double exp_err(uint32_t yq)
{
    int k;
    const int32_t m = mtt_fx_exp_neg(yq, &k);
    const double y = (double)yq / 16777216.0;
    const double ref = ldexp(exp(-y), 30 + k);
    TEST_ASSERT_TRUE(m >= (1 << 29) && m <= (1 << 30));
    TEST_ASSERT_TRUE(k >= 0);
    return fabs((double)m - ref);
}

static void test_exp(void)
{
    double worst = 0.0, e;
    uint32_t y;
    long i;
    /* the gate range y = d^2 / 2 <= 32 and beyond: every 2^-17, i.e.
     * 2^23 points of [0, 64] */
    for (y = 0u; y <= (64u << 24); y += 128u) {
        e = exp_err(y);
        worst = (e > worst) ? e : worst;
    }
    for (i = 0; i < 2000000L; ++i) {
        e = exp_err(rnd());
        worst = (e > worst) ? e : worst;
    }
    report("exp_neg: worst error %.3f mantissa units (bound 4)", worst);
    TEST_ASSERT_TRUE(worst <= 4.0);
    /* Q30 wrapper: absolute bound 4.5 ulp, and underflow to 0, never wrap */
    for (i = 0; i < 1000000L; ++i) {
        const uint32_t yq = rnd() >> (rnd() % 32u);
        const double ref = ldexp(exp(-(double)yq / 16777216.0), 30);
        TEST_ASSERT_TRUE(fabs((double)mtt_fx_exp_neg_q30(yq) - ref) <= 4.5);
    }
    TEST_ASSERT_EQUAL_INT32(1 << 30, mtt_fx_exp_neg_q30(0u));
    TEST_ASSERT_EQUAL_INT32(0, mtt_fx_exp_neg_q30(0xFFFFFFFFu));
}

static double log2_err(uint32_t x, int f)
{
    const double ref = ldexp(log2((double)x) - (double)f, 25);
    return fabs((double)mtt_fx_log2(x, f) - ref);
}

static void test_log(void)
{
    double worst = 0.0, e;
    long i;
    int f;
    for (i = 1; i < (1L << 20); ++i) {
        e = log2_err((uint32_t)i, 0);
        worst = (e > worst) ? e : worst;
    }
    for (f = 0; f <= 62; ++f) {
        for (i = 0; i < 20000L; ++i) {
            const uint32_t x = rnd() >> (rnd() % 32u);
            if (x != 0u) {
                e = log2_err(x, f);
                worst = (e > worst) ? e : worst;
            }
        }
        e = log2_err(0xFFFFFFFFu, f);
        worst = (e > worst) ? e : worst;
    }
    report("log2: worst error %.3f ulp of Q25 (bound 2)", worst);
    TEST_ASSERT_TRUE(worst <= 2.0);
    worst = 0.0;
    for (i = 0; i < 1000000L; ++i) {
        const uint32_t x = rnd() | 1u;
        const int ff = (int)(rnd() % 63u);
        e = fabs((double)mtt_fx_ln(x, ff) - ldexp(log((double)x) - (double)ff * log(2.0), 25));
        worst = (e > worst) ? e : worst;
    }
    report("ln: worst error %.3f ulp of Q25 (bound 2)", worst);
    TEST_ASSERT_TRUE(worst <= 2.0);
    TEST_ASSERT_EQUAL_INT32(0, mtt_fx_log2(1u << 30, 30));
    TEST_ASSERT_EQUAL_INT32(-62 * 33554432, mtt_fx_log2(1u, 62));
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MIN, mtt_fx_log2(0u, 0));
    /* the gate threshold gamma = -2 ln(1 - PG), PG = 0.99 in Q30 */
    {
        const int32_t one_m_pg = 10737418; /* 0.01 in Q30 */
        const double g = -2.0 * ldexp((double)mtt_fx_ln((uint32_t)one_m_pg, 30), -25);
        TEST_ASSERT_TRUE(fabs(g - 9.21034037) < 2e-7);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_clz);
    RUN_TEST(test_add_sub_saturate);
    RUN_TEST(test_mull_exact);
    RUN_TEST(test_mul_rounding_saturation);
    RUN_TEST(test_mulq_fast);
    RUN_TEST(test_div);
    RUN_TEST(test_sqrt);
    RUN_TEST(test_sqrt8);
    RUN_TEST(test_exp);
    RUN_TEST(test_log);
    return UNITY_END();
}
