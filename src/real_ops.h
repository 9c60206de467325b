/* SPDX-License-Identifier: BSD-3-Clause */
/* real_ops.h - the arithmetic of mtt_real: private to the library.
 *
 * Every literal goes through a constant macro of mtt/real.h and every
 * function through the mtt_ macros below, so a float build never promotes
 * to double: on a soft-float or single-precision FPU target a stray double
 * costs a library call per operation.
 *
 * The fixed-point build (MTT_REAL_FIXED, docs/FIXED_POINT.md) writes the
 * converted stages with the quantity types and operation macros of the
 * second half of this file.  In the float and double builds those types are
 * mtt_real and every macro expands to exactly the expression it replaces
 * (same operands, same order), so converting a stage does not change one
 * bit of their results.  mtt_sqrt, mtt_exp and mtt_log do not exist in the
 * fixed build: a stage that still uses them does not compile there.
 *
 * Not installed: the library's sources get it through mtt_internal.h; a
 * host tool or test that needs an operation includes it itself (with src/
 * on its include path).  Public callers see only mtt/real.h's constants. */
#ifndef MTT_REAL_OPS_H
#define MTT_REAL_OPS_H

#include <stdint.h>

#include "mtt/fixed.h" /* MTT_FX_MAX, MTT_FX_MIN: the kernels saturate to them in every build */
#include "mtt/mtt.h"

#if !defined(MTT_REAL_FIXED)
#include <math.h>
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------------
 * Integer kernels of the fixed-point build (docs/FIXED_POINT.md).
 *
 * Pure integer arithmetic for targets without an FPU (Cortex-M0/M0+/M3):
 * no float, no double, no 64 x 64 multiply (__aeabi_lmul), no divide
 * instruction or helper (__aeabi_idiv), no count-leading-zeros instruction.
 * Every kernel rounds to nearest (ties away from zero) and saturates to
 * [MTT_FX_MIN, MTT_FX_MAX] instead of wrapping; the error bounds below are
 * checked by test/test_fixed.c against double references.
 *
 * The definitions in src/fixed/fx_math.c are compiled only when MTT_REAL_FIXED
 * (the fixed-point build) or MTT_FX_KERNELS (the kernel unit test) is
 * defined, so a float or double library carries none of them.
 *
 * Notation: a "Qf" value v stands for v * 2^-f.  "ulp" is 2^-f of the
 * result's format.  MTT_FX_MAX / MTT_FX_MIN: mtt/fixed.h.
 * --------------------------------------------------------------------- */
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

/* ---- the host boundary (src/fixed/fx_double.c) ----------------------------
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


/* ---------------------------------------------------------------------
 * Functions of mtt_real (float and double: <math.h> in mtt_real's precision).
 * --------------------------------------------------------------------- */
#if defined(MTT_REAL_DOUBLE)
#define mtt_sqrt(x) sqrt(x)
#define mtt_exp(x) exp(x)
#define mtt_expm1(x) expm1(x)
#define mtt_log(x) log(x)
#define mtt_fabs(x) fabs(x)
#define mtt_sin(x) sin(x)
#define mtt_cos(x) cos(x)
#elif !defined(MTT_REAL_FIXED)
#define mtt_sqrt(x) sqrtf(x)
#define mtt_exp(x) expf(x)
#define mtt_expm1(x) expm1f(x)
#define mtt_log(x) logf(x)
#define mtt_fabs(x) fabsf(x)
#define mtt_sin(x) sinf(x)
#define mtt_cos(x) cosf(x)
#endif

/* ---------------------------------------------------------------------
 * Quantity types and operations (docs/FIXED_POINT.md §3, §4).
 *
 *   mtt_prob   probabilities, existence, betas         Q30, [0, 2)
 *   mtt_ratio  likelihood ratios p/lambda, L, Lambda    Q16, [0, 32768)
 *   mtt_d2     squared Mahalanobis distances, gamma     Q24, [0, 128)
 *   mtt_pos    positions, velocities, measurements      Q MTT_FX_POS_FRAC
 *   counts     m, ranks and sums of them (MTT_CNT)      Q24, [0, 128)
 * Densities are held relative to the clutter density (p_j / lambda,
 * lambda~ / lambda: ratios) and the gate area times it (MTT_REL_DENS).
 *
 * Operation macros name their result format: MTT_MUL_PP is prob x prob ->
 * prob, MTT_MUL_RP ratio x prob -> ratio, MTT_DIV_P a quotient of two
 * values of one format as a prob, MTT_DIV_R the same as a ratio,
 * MTT_DIV_PR prob / ratio -> prob, MTT_DIV_RP ratio / prob -> ratio; the
 * count format has MTT_MUL_PC (prob x count -> count), MTT_MUL_CR (count x
 * ratio -> ratio), MTT_DIV_CR (count / ratio -> ratio).  MTT_ADD/MTT_SUB are plain adds (the
 * formats prove the headroom); MTT_ADDS/MTT_SUBS saturate.  Comparisons of
 * two values of one format stay <, <=, ==.  The constants of each format
 * (MTT_P(), MTT_RATIO(), MTT_D2(), MTT_POS(), ...) are public: mtt/real.h.
 * --------------------------------------------------------------------- */
#if defined(MTT_REAL_FIXED)

typedef int32_t mtt_prob;
typedef int32_t mtt_ratio;
typedef int32_t mtt_d2;
typedef int32_t mtt_pos;


/* MTT_FX_CONST (mtt/real.h) saturated to [MTT_FX_MIN, MTT_FX_MAX] (parameter bounds): the
 * double is clamped before the conversion, which is then always defined. */
#define MTT_FX_CLAMPD_(v) (((v) > 2147483647.0) ? 2147483647.0 : (((v) < -2147483647.0) ? -2147483647.0 : (v)))
#define MTT_FX_CONST_SAT(x, f)                                                                     \
    ((int32_t)MTT_FX_CLAMPD_((x) * (double)((uint64_t)1 << (f)) + (((x) < 0) ? -0.5 : 0.5)))
#define MTT_CNT(n) ((int32_t)(n) * ((int32_t)1 << MTT_FX_CNT_FRAC))
/* The declared density relative to itself: 1.  mtt_params_check refuses
 * a density that is not positive in this build (the estimated density of
 * ALGORITHMS.md §5.2 has no reference), so the estimate is not compiled. */
#define MTT_REL_DENS(d) MTT_RATIO(1.0)
/* Existence floor of ALGORITHMS.md §16 (1e-30 in float): one Q30 unit. */
#define MTT_P_FLOOR 0

#define MTT_ADD(a, b) ((a) + (b))
#define MTT_SUB(a, b) ((a) - (b))
#define MTT_ADDS(a, b) mtt_fx_add((a), (b))
#define MTT_SUBS(a, b) mtt_fx_sub((a), (b))
#define MTT_MUL_PP(a, b) mtt_fx_mulq30((a), (b)) /* MTT_FX_PROB_FRAC 30 */
#define MTT_MUL_RP(a, b) mtt_fx_mul((a), (b), MTT_FX_PROB_FRAC)
#define MTT_MUL_RR(a, b) mtt_fx_mul((a), (b), MTT_FX_RATIO_FRAC)
#define MTT_DIV_P(a, b) mtt_fx_div((a), (b), MTT_FX_PROB_FRAC)
#define MTT_DIV_R(a, b) mtt_fx_div((a), (b), MTT_FX_RATIO_FRAC)
#define MTT_DIV_PR(a, b) mtt_fx_div((a), (b), MTT_FX_RATIO_FRAC)
#define MTT_DIV_RP(a, b) mtt_fx_div((a), (b), MTT_FX_PROB_FRAC)
#define MTT_MUL_PC(a, b) mtt_fx_mul((a), (b), MTT_FX_PROB_FRAC)
#define MTT_MUL_CR(a, b) mtt_fx_mul((a), (b), MTT_FX_CNT_FRAC)
#define MTT_DIV_CR(a, b) mtt_fx_div((a), (b), MTT_FX_RATIO_FRAC + MTT_FX_RATIO_FRAC - MTT_FX_CNT_FRAC)
/* count / lambda V_G (Q MTT_FX_GATE_FRAC) -> ratio; MTT_GATE: a constant of lambda V_G */
#define MTT_DIV_CG(a, b) mtt_fx_div((a), (b), MTT_FX_RATIO_FRAC + MTT_FX_GATE_FRAC - MTT_FX_CNT_FRAC)
#define MTT_GATE(x) MTT_FX_CONST(x, MTT_FX_GATE_FRAC)
/* round(x / 2^s), 0 < s < 32, ties away from zero: mtt_fx_mul(x, 1, s)'s
 * result by a shift (x is evaluated twice: a side-effect-free operand) */
#define MTT_FX_RSHIFT(x, s)                                                                        \
    (((x) < 0) ? -(int32_t)(((uint32_t) - (x) + ((uint32_t)1 << ((s) - 1))) >> (s))                \
               : (int32_t)(((uint32_t)(x) + ((uint32_t)1 << ((s) - 1))) >> (s)))
#define MTT_CVT_P_C(x) MTT_FX_RSHIFT((x), MTT_FX_PROB_FRAC - MTT_FX_CNT_FRAC)
#define MTT_CVT_P_R(x) MTT_FX_RSHIFT((x), MTT_FX_PROB_FRAC - MTT_FX_RATIO_FRAC)
#define MTT_CVT_R_P(x) mtt_fx_mul((x), (int32_t)1 << (MTT_FX_PROB_FRAC - MTT_FX_RATIO_FRAC), 0)

/* Covariances in block floating point (docs/FIXED_POINT.md §2, Status
 * findings 1 and 5): mtt_cov has one more row, whose first element is the
 * block exponent e (values = mantissas 2^e); between stages the largest
 * mantissa has MTT_FX_COV_TOP bits.  dt is in Q16 frames (T0). */
#define MTT_FX_COV_TOP 28
#define MTT_COV_E(P) ((P)[MTT_MAX_STATE][0])
/* dt = 1 frame (the common case) multiplies by nothing. */
#define MTT_MUL_T(dt, v) (((dt) == ((int32_t)1 << MTT_FX_T_FRAC)) ? (v) : mtt_fx_mul((dt), (v), MTT_FX_T_FRAC))
/* v / dt (a position difference over Q16 frames: a velocity), saturated. */
#define MTT_DIV_T(v, dt) mtt_fx_div((v), (dt), MTT_FX_T_FRAC)
/* (a + b) / 2 without forming a + b (no headroom needed), rounded down. */
#define MTT_MEAN2(a, b) (((a) >> 1) + ((b) >> 1) + ((a) & (b) & 1))
#define MTT_COV_FIT(P, dt) mtt_fx_cov_fit((P), (dt))
#define MTT_COV_ALIGN(A, B) mtt_fx_cov_align((A), (B))
#define MTT_COV_COPY_E(D, S) (MTT_COV_E(D) = MTT_COV_E(S))
#define MTT_COV_NORM(P) mtt_fx_cov_norm((P), MTT_FX_COV_TOP)
/* S, S^-1 (3 values of a symmetric 2 x 2) carry their exponent in a fourth
 * slot; det S is a mantissa at 2 e(S) + 28, K = Pp S^-1 one at
 * e(Pp) + e(S^-1) + 28 (implied, not stored).  MTT_AT re-expresses a
 * mantissa given at exponent `from` at exponent `to`. */
#define MTT_SYM_E(S) ((S)[3])
#define MTT_DET_E(S) (2 * MTT_SYM_E(S) + 28)
#define MTT_AT(m, from, to) mtt_fx_at((m), (from), (to))
#define MTT_S_EXP(Pp, R, S) (MTT_SYM_E(S) = mtt_fx_s_exp((Pp), (R)))
#define MTT_SI_EXP(Si, S, d) (MTT_SYM_E(Si) = mtt_fx_si_exp((S), (d)))
#define MTT_MUL_SS(a, b) mtt_fx_mulq28((a), (b))
/* S^-1 = adj(S) / det S at e(S^-1): one reciprocal of det S, three products */
#define MTT_SI_SET(Si, S, d) mtt_fx_si_set((Si), (S), (d))
#define MTT_MUL_K(a, b) mtt_fx_mulq28((a), (b))
/* d^2 = nu' S^-1 nu (Q24, saturated: a distance beyond 128 is outside
 * every gate): fx_cov.c. */
#define MTT_MAHAL2(Si, nx, ny) mtt_fx_mahal2((Si), (nx), (ny))
/* The gate (gate.c, docs/FIXED_POINT.md §4): lambda V_G and p / lambda as
 * Q16 ratios of the declared clutter density, the slice half-width as an
 * upper bound in the position format. */
#define MTT_ABS(x) (((x) < 0) ? -(x) : (x))
#define MTT_GATE_AREA(gamma, det, S, dens) mtt_fx_gate_area((gamma), (det), (S), (dens))
#define MTT_GATE_WIDTH(gamma, S, k) mtt_fx_gate_width((gamma), (S), (k))
#define MTT_GATE_PEAK(det, S, pg, dens) mtt_fx_gate_peak((det), (S), (pg), (dens))
#define MTT_GATE_LIK(peak, d2) mtt_fx_gate_lik((peak), (d2))
/* lambda V_G and the peak p / lambda of one track from one sqrt(det S) */
#define MTT_GATE_AREA_PEAK(vg, peak, gamma, det, S, pg, dens) \
    ((vg) = mtt_fx_gate_area_peak((gamma), (det), (S), (pg), (dens), &(peak)))

/* "Finite" in a fixed format: not a saturated value (every kernel
 * saturates to MTT_FX_MIN / MTT_FX_MAX instead of wrapping). */
#define mtt_isfinite(x) (((x) > MTT_FX_MIN) && ((x) < MTT_FX_MAX))
/* A coordinate inside the declared range (docs/FIXED_POINT.md §3); a
 * detection outside it is counted apart from malformed ones. */
#define MTT_POS_OK(x) (((x) >= -MTT_FX_POS_LIMIT) && ((x) <= MTT_FX_POS_LIMIT))
#define MTT_MEAS_RANGE(c) (&(c)->meas_out_of_range)

/* The tracker's boundary (tracker.c, track_table.c, initiate.c, merge.c;
 * docs/FIXED_POINT.md §3).  Time is a Q16 count of frames (T0) modulo
 * 2^32: a step is later than the last when the difference, taken modulo
 * 2^32, lies in (0, 2^31), so a long run never overflows.  A variance
 * crossing the API (mtt_track_view.P, mtt_tracker_add_track,
 * mtt_init_two_point_cov) is Q MTT_FX_VAR_FRAC (unit^2; per T0 or T0^2
 * for the velocity rows), saturated; inside, covariances are BFP.
 * MTT_VAR_OF squares a standard deviation of the position format into a
 * variance. */
#define MTT_TIME_OK(t) 1
#define MTT_TIME_AFTER(t, t0) (((uint32_t)(t) - (uint32_t)(t0) - 1u) < 0x7FFFFFFFu)
#define MTT_TIME_SUB(t, t0) ((int32_t)((uint32_t)(t) - (uint32_t)(t0)))
#define MTT_VAR_OF(s)                                                                              \
    ((2 * MTT_FX_POS_FRAC >= MTT_FX_VAR_FRAC)                                                      \
         ? mtt_fx_mul((s), (s), (2 * MTT_FX_POS_FRAC >= MTT_FX_VAR_FRAC) ? 2 * MTT_FX_POS_FRAC - MTT_FX_VAR_FRAC : 0) \
         : mtt_fx_at(mtt_fx_mul((s), (s), 0), -2 * MTT_FX_POS_FRAC, -MTT_FX_VAR_FRAC))
#define MTT_COV_VIEW(P, i, j) mtt_fx_at((P)[i][j], MTT_COV_E(P), -MTT_FX_VAR_FRAC)
#define MTT_COV_SET_E(P, e) (MTT_COV_E(P) = (e))
#define MTT_COV_EMAX(A, B) ((MTT_COV_E(A) > MTT_COV_E(B)) ? MTT_COV_E(A) : MTT_COV_E(B))

#else /* float, double: every macro is the expression it stands for */

typedef mtt_real mtt_prob;
typedef mtt_real mtt_ratio;
typedef mtt_real mtt_d2;
typedef mtt_real mtt_pos;

#define MTT_CNT(n) ((mtt_real)(n))
#define MTT_REL_DENS(d) (d)
#define MTT_P_FLOOR MTT_R(1e-30)

#define MTT_ADD(a, b) ((a) + (b))
#define MTT_SUB(a, b) ((a) - (b))
#define MTT_ADDS(a, b) ((a) + (b))
#define MTT_SUBS(a, b) ((a) - (b))
#define MTT_MUL_PP(a, b) ((a) * (b))
#define MTT_MUL_RP(a, b) ((a) * (b))
#define MTT_MUL_RR(a, b) ((a) * (b))
#define MTT_DIV_P(a, b) ((a) / (b))
#define MTT_DIV_R(a, b) ((a) / (b))
#define MTT_DIV_PR(a, b) ((a) / (b))
#define MTT_DIV_RP(a, b) ((a) / (b))
#define MTT_MUL_PC(a, b) ((a) * (b))
#define MTT_MUL_CR(a, b) ((a) * (b))
#define MTT_DIV_CR(a, b) ((a) / (b))
#define MTT_DIV_CG(a, b) ((a) / (b))
#define MTT_GATE(x) MTT_R(x)
#define MTT_CVT_P_C(x) (x)
#define MTT_CVT_P_R(x) (x)
#define MTT_CVT_R_P(x) (x)

#define MTT_MUL_T(dt, v) ((dt) * (v))
#define MTT_DIV_T(v, dt) ((v) / (dt))
#define MTT_MEAN2(a, b) (MTT_R(0.5) * ((a) + (b)))
#define MTT_COV_FIT(P, dt) ((void)0)
#define MTT_COV_ALIGN(A, B) ((void)0)
#define MTT_COV_COPY_E(D, S) ((void)0)
#define MTT_COV_NORM(P) ((void)0)
#define MTT_AT(m, from, to) (m)
#define MTT_S_EXP(Pp, R, S) ((void)0)
#define MTT_SI_EXP(Si, S, d) ((void)0)
#define MTT_MUL_SS(a, b) ((a) * (b))
#define MTT_SI_SET(Si, S, d) ((Si)[0] = (S)[2] / (d), (Si)[1] = (-(S)[1]) / (d), (Si)[2] = (S)[0] / (d))
#define MTT_MUL_K(a, b) ((a) * (b))
#define MTT_MAHAL2(Si, nx, ny) ((Si)[0] * (nx) * (nx) + MTT_R(2.0) * (Si)[1] * (nx) * (ny) + (Si)[2] * (ny) * (ny))
#define MTT_ABS(x) mtt_fabs(x)
#define MTT_GATE_AREA(gamma, det, S, dens) mtt_gate_volume((gamma), (det))
#define MTT_GATE_WIDTH(gamma, S, k) mtt_sqrt((gamma) * (S)[k])
#define MTT_GATE_PEAK(det, S, pg, dens) mtt_gate_likelihood(MTT_R(0.0), (det), (pg))
#define MTT_GATE_LIK(peak, d2) ((peak) * mtt_exp(MTT_R(-0.5) * (d2)))
#define MTT_GATE_AREA_PEAK(vg, peak, gamma, det, S, pg, dens) \
    ((vg) = MTT_GATE_AREA((gamma), (det), (S), (dens)), (peak) = MTT_GATE_PEAK((det), (S), (pg), (dens)))

/* Finite test without isfinite(), whose float overloads some freestanding
 * libms lack: NaN fails x == x, and +-Inf fails the magnitude bound. */
#define mtt_isfinite(x) (((x) == (x)) && (mtt_fabs(x) <= MTT_REAL_MAX))
#define MTT_POS_OK(x) mtt_isfinite(x)
#define MTT_MEAS_RANGE(c) (&(c)->meas_bad) /* NaN/Inf: malformed; nothing is out of range */

#define MTT_TIME_OK(t) mtt_isfinite(t)
#define MTT_TIME_AFTER(t, t0) ((t) > (t0))
#define MTT_TIME_SUB(t, t0) ((t) - (t0))
#define MTT_VAR_OF(s) ((s) * (s))
#define MTT_COV_VIEW(P, i, j) ((P)[i][j])
#define MTT_COV_SET_E(P, e) ((void)0)
#define MTT_COV_EMAX(A, B) 0

#endif /* MTT_REAL_FIXED */

#ifdef __cplusplus
}
#endif

#endif /* MTT_REAL_OPS_H */
