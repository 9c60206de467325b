/* mtt/fixed.h - integer kernels of the fixed-point build (docs/FIXED_POINT.md).
 *
 * Pure integer arithmetic for targets without an FPU (Cortex-M0/M0+/M3):
 * no float, no double, no 64 x 64 multiply (__aeabi_lmul), no divide
 * instruction or helper (__aeabi_idiv), no count-leading-zeros instruction.
 * Every kernel rounds to nearest (ties away from zero) and saturates to
 * [MTT_FX_MIN, MTT_FX_MAX] instead of wrapping; the error bounds below are
 * checked by test/test_fixed.c against double references.
 *
 * The definitions in src/fx_math.c are compiled only when MTT_REAL_FIXED
 * (the fixed-point build) or MTT_FX_KERNELS (the kernel unit test) is
 * defined, so a float or double library carries none of them.
 *
 * Notation: a "Qf" value v stands for v * 2^-f.  "ulp" is 2^-f of the
 * result's format. */
#ifndef MTT_FIXED_H
#define MTT_FIXED_H

#include <stdint.h>

/* Symmetric saturation: -MTT_FX_MIN never overflows, so negating a
 * saturated value stays saturated. */
#define MTT_FX_MAX INT32_MAX
#define MTT_FX_MIN (-INT32_MAX)

/* Common formats of docs/FIXED_POINT.md. */
#define MTT_FX_Q30_ONE ((int32_t)1 << 30) /* probabilities: Q30, [0, 2) */
#define MTT_FX_Q24_ONE ((int32_t)1 << 24) /* d^2, gamma, logarithms: Q24, [0, 128) */

/* Number of leading zero bits of x: 32 for x = 0, 0 for x >= 2^31.
 * A branchy binary search (ARMv6-M has no CLZ): about 15 instructions. */
int mtt_fx_clz(uint32_t x);

/* Saturating add and subtract: the exact sum clamped to [MIN, MAX]. */
int32_t mtt_fx_add(int32_t a, int32_t b);
int32_t mtt_fx_sub(int32_t a, int32_t b);

/* Exact 64-bit product |a| * |b| as two words (hi:lo), built from four
 * 16 x 16 -> 32 multiplies (one MULS each on ARMv6-M).  Returns the sign
 * of the product: 1 or -1 (0 when a or b is 0). */
int mtt_fx_mull(int32_t a, int32_t b, uint32_t *hi, uint32_t *lo);

/* round(a * b / 2^s), saturated; 0 <= s <= 62.
 * Error <= 0.5 ulp (correctly rounded), exact saturation. */
int32_t mtt_fx_mul(int32_t a, int32_t b, int s);

/* a * b / 2^s for 19 <= s <= 31, the fast multiply of the hot loops:
 * four 16 x 16 products, no saturation (the caller's formats keep
 * |a b / 2^s| < 2^31 - 1; docs/FIXED_POINT.md).  Rounds to nearest with
 * error <= 0.5 + 3 * 2^(18-s) ulp (0.5007 ulp at s = 30).  Right shifts
 * of negative values are arithmetic (GCC, Clang, every Arm compiler). */
int32_t mtt_fx_mulq(int32_t a, int32_t b, int s);
/* mtt_fx_mulq(a, b, 30) with the shift folded (the same result) */
int32_t mtt_fx_mulq30(int32_t a, int32_t b);
/* mtt_fx_mulq(a, b, 28) with the shift folded (S, det S and K) */
int32_t mtt_fx_mulq28(int32_t a, int32_t b);

/* round(a * 2^s / b), saturated; 0 <= s <= 62.  b = 0 saturates with
 * the sign of a (0 / 0 = 0).  The normalised operands' 32 quotient bits
 * (three digits from a table-and-Newton reciprocal, each corrected by its
 * exact remainder: the restoring division's bits) + a rounding bit:
 * correctly rounded, error <= 0.5 ulp. */
int32_t mtt_fx_div(int32_t a, int32_t b, int s);

/* round(2^s / x), saturated; 0 <= s <= 62 (mtt_fx_div(1, x, s)). */
int32_t mtt_fx_recip(int32_t x, int s);

/* round(sqrt(x * 2^f)), saturated to UINT32_MAX; 0 <= f <= 32: the square
 * root of a Qf value in Qf.  Digit-by-digit (two radicand bits per step,
 * 32 steps, no multiply): correctly rounded, error <= 0.5 ulp. */
uint32_t mtt_fx_sqrt(uint32_t x, int f);

/* round(sqrt(floor(x / 2^16))) of a 32-bit x: the same digits, 8 steps on
 * x's top 16 bits (an 8-bit root, error <= 0.5; the gate's slice bounds,
 * gate.c, where (root + 1) 2^8 > sqrt(x) for x >= 2^30). */
uint32_t mtt_fx_sqrt8(uint32_t x);

/* exp(-y) for y >= 0 given in Q24 (0 <= y < 256), as a mantissa m in
 * [2^29, 2^30] (Q30, (0.5, 1]) and a shift *k >= 0:
 *   exp(-y) ~= m * 2^-30 * 2^-k.
 * y log2(e) = k + f; 2^-f = T[i] * exp(-r ln 2) with a 16-entry table T
 * and a degree-4 Taylor polynomial on r < 1/16.
 * Error: |m - 2^(30+k) exp(-y)| <= 4 (units of m), i.e. relative error
 * <= 8 * 2^-30 = 7.5e-9, for every y (checked exhaustively on a 2^-17 grid
 * of [0, 64] and at random points of [0, 256) by test/test_fixed.c). */
int32_t mtt_fx_exp_neg(uint32_t y, int *k);

/* exp(-y) in Q30 (absolute): round(m * 2^-k); 0 when it rounds to 0.
 * Error <= 4.5 ulp of Q30 (4.2e-9 absolute). */
int32_t mtt_fx_exp_neg_q30(uint32_t y);

/* log2(x * 2^-f) in Q25 for x > 0 (x = 0 saturates to MTT_FX_MIN);
 * 0 <= f <= 62.  Normalisation by mtt_fx_clz, then shift-and-add
 * (multiplicative normalisation by (1 + 2^-i), i = 1..30, with a table of
 * log2(1 + 2^-i)) and a first-order residual term.
 * Error <= 2 ulp of Q25 (6.0e-8 absolute). */
int32_t mtt_fx_log2(uint32_t x, int f);

/* ln(x * 2^-f) in Q25: mtt_fx_log2 times ln 2.
 * Error <= 2 ulp of Q25 (6.0e-8 absolute). */
int32_t mtt_fx_ln(uint32_t x, int f);

/* ---- the host boundary (src/fx_double.c) ----------------------------
 * The user's numbers (doubles read from the settings JSON and the CSV
 * files, docs/FIXED_POINT.md §3) into a Qf format and back, for the host
 * tools and params_info.c: double arithmetic, so nothing in the tracker
 * calls them and no firmware image links them.  0 <= f <= 62.
 *
 * mtt_fx_from_double: round(v 2^f), ties away from zero, in *out and
 * MTT_OK when it lies strictly inside (MTT_FX_MIN, MTT_FX_MAX); otherwise
 * MTT_ERR_RANGE with *out the saturation value of v's sign (MTT_FX_MAX for
 * NaN), never a wrapped value: the value measure.c skips and counts
 * (mtt_isfinite fails on it).  mtt_fx_to_double: m 2^-f, exact. */
int mtt_fx_from_double(double v, int f, int32_t *out);
double mtt_fx_to_double(int32_t m, int f);

#endif /* MTT_FIXED_H */
