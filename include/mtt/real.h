/* mtt/real.h - the one real type and its math layer.
 *
 * mtt_real is float unless MTT_REAL_DOUBLE is defined.  Every literal goes
 * through MTT_R() and every function through the mtt_ macros below, so a
 * float build never promotes to double: on a soft-float or single-precision
 * FPU target a stray double costs a library call per operation.
 *
 * MTT_REAL_FIXED selects the fixed-point build (docs/FIXED_POINT.md): every
 * real is an int32_t in the Q format of its quantity, and the converted
 * stages are written with the quantity types and operation macros of the
 * second half of this file.  In the float and double builds those types are
 * mtt_real and every macro expands to exactly the expression it replaces
 * (same operands, same order), so converting a stage does not change one
 * bit of their results.  MTT_R, mtt_sqrt, mtt_exp and mtt_log do not exist
 * in the fixed build: a stage that still uses them does not compile there.
 */
#ifndef MTT_REAL_H
#define MTT_REAL_H

#if defined(MTT_REAL_FIXED) && defined(MTT_REAL_DOUBLE)
#error "MTT_REAL_FIXED and MTT_REAL_DOUBLE exclude each other"
#endif

/* MTT_REAL_KIND: 1 float, 2 double, 3 fixed point with the declared
 * position and amplitude formats folded in (3 + 4 (MTT_FX_POS_FRAC + 32
 * MTT_FX_AMP_FRAC)): part of the configuration identity, so a caller
 * compiled with other declared units is refused like one with other bounds. */
#if defined(MTT_REAL_FIXED)
#include <stdint.h>

#include "mtt/fixed.h"
typedef int32_t mtt_real; /* a Q-format integer; its format is its quantity's */

/* Position LSB 2^-MTT_FX_POS_FRAC of the user's length unit; positions and
 * measurements must lie in +-MTT_FX_POS_LIMIT (one bit is kept so that an
 * innovation z - x^ never overflows).  Declared at compile time
 * (docs/FIXED_POINT.md §3). */
#ifndef MTT_FX_POS_FRAC
#define MTT_FX_POS_FRAC 16
#endif
#if MTT_FX_POS_FRAC < 0 || MTT_FX_POS_FRAC > 24
#error "MTT_FX_POS_FRAC must lie in 0..24"
#endif
#define MTT_FX_POS_LIMIT ((int32_t)1 << 30)

/* Amplitude LSB 2^-MTT_FX_AMP_FRAC (amplitudes are only ranked and fed to
 * the amplitude likelihood ratio). */
#ifndef MTT_FX_AMP_FRAC
#define MTT_FX_AMP_FRAC 16
#endif
#if MTT_FX_AMP_FRAC < 0 || MTT_FX_AMP_FRAC > 30
#error "MTT_FX_AMP_FRAC must lie in 0..30"
#endif

#define MTT_REAL_KIND (3 + 4 * (MTT_FX_POS_FRAC + 32 * MTT_FX_AMP_FRAC))
#elif defined(MTT_REAL_DOUBLE)
#include <math.h>
typedef double mtt_real;
#define MTT_REAL_KIND 2
#define MTT_R(x) (x)
#define mtt_sqrt(x) sqrt(x)
#define mtt_exp(x) exp(x)
#define mtt_log(x) log(x)
#define mtt_fabs(x) fabs(x)
#define mtt_sin(x) sin(x)
#define mtt_cos(x) cos(x)
#define MTT_REAL_EPS 2.220446049250313e-16
#define MTT_REAL_MAX 1.7976931348623157e308
#else
#include <math.h>
typedef float mtt_real;
#define MTT_REAL_KIND 1
#define MTT_R(x) ((float)(x)) /* a constant expression: folded at compile time */
#define mtt_sqrt(x) sqrtf(x)
#define mtt_exp(x) expf(x)
#define mtt_log(x) logf(x)
#define mtt_fabs(x) fabsf(x)
#define mtt_sin(x) sinf(x)
#define mtt_cos(x) cosf(x)
#define MTT_REAL_EPS 1.1920929e-7f
#define MTT_REAL_MAX 3.4028235e38f
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
 * two values of one format stay <, <=, ==.  MTT_P(), MTT_RATIO(), MTT_D2(),
 * MTT_POS() are constants of each format (folded at compile time).
 * --------------------------------------------------------------------- */
#if defined(MTT_REAL_FIXED)

typedef int32_t mtt_prob;
typedef int32_t mtt_ratio;
typedef int32_t mtt_d2;
typedef int32_t mtt_pos;

#define MTT_FX_PROB_FRAC 30
#define MTT_FX_RATIO_FRAC 16
#define MTT_FX_D2_FRAC 24
#define MTT_FX_CNT_FRAC 24
/* Variances and their rates (R's sigma^2, the process noise density):
 * unit^2 (per T0^3), Q16. */
#define MTT_FX_VAR_FRAC 16

/* round(x 2^f) of a constant x: an arithmetic constant expression that the
 * compiler folds, so no double arithmetic reaches the image. */
#define MTT_FX_CONST(x, f)                                                                         \
    ((int32_t)((x) * (double)((int32_t)1 << (f)) + (((x) < 0) ? -0.5 : 0.5)))
/* The same, saturated to [MTT_FX_MIN, MTT_FX_MAX] (parameter bounds): the
 * double is clamped before the conversion, which is then always defined. */
#define MTT_FX_CLAMPD_(v) (((v) > 2147483647.0) ? 2147483647.0 : (((v) < -2147483647.0) ? -2147483647.0 : (v)))
#define MTT_FX_CONST_SAT(x, f)                                                                     \
    ((int32_t)MTT_FX_CLAMPD_((x) * (double)((int32_t)1 << (f)) + (((x) < 0) ? -0.5 : 0.5)))
/* "No bound" of the parameter table (params_table.h): saturates. */
#define MTT_REAL_MAX 3.4028235e38
#define MTT_P(x) MTT_FX_CONST(x, MTT_FX_PROB_FRAC)
#define MTT_RATIO(x) MTT_FX_CONST(x, MTT_FX_RATIO_FRAC)
#define MTT_D2(x) MTT_FX_CONST(x, MTT_FX_D2_FRAC)
#define MTT_POS(x) MTT_FX_CONST(x, MTT_FX_POS_FRAC)
#define MTT_AMP(x) MTT_FX_CONST(x, MTT_FX_AMP_FRAC)
/* Clutter density per unit^2 (a parameter; provisional format Q30). */
#define MTT_FX_DENS_FRAC 30
#define MTT_DENS(x) MTT_FX_CONST(x, MTT_FX_DENS_FRAC)
#define MTT_ZERO 0
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
#define MTT_FX_T_FRAC 16
#define MTT_COV_ROWS(n) ((n) + 1)
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
#define MTT_SYM_SLOTS 4
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
/* A coordinate inside the declared range (docs/FIXED_POINT.md §3). */
#define MTT_POS_OK(x) (((x) >= -MTT_FX_POS_LIMIT) && ((x) <= MTT_FX_POS_LIMIT))

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
/* Constants of time (Q16 frames) and of the variance format. */
#define MTT_TIME(x) MTT_FX_CONST(x, MTT_FX_T_FRAC)
#define MTT_VAR(x) MTT_FX_CONST(x, MTT_FX_VAR_FRAC)

#else /* float, double: every macro is the expression it stands for */

typedef mtt_real mtt_prob;
typedef mtt_real mtt_ratio;
typedef mtt_real mtt_d2;
typedef mtt_real mtt_pos;

#define MTT_P(x) MTT_R(x)
#define MTT_RATIO(x) MTT_R(x)
#define MTT_D2(x) MTT_R(x)
#define MTT_POS(x) MTT_R(x)
#define MTT_AMP(x) MTT_R(x)
#define MTT_DENS(x) MTT_R(x)
#define MTT_ZERO MTT_R(0.0)
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
#define MTT_CVT_P_C(x) (x)
#define MTT_CVT_P_R(x) (x)
#define MTT_CVT_R_P(x) (x)

#define MTT_COV_ROWS(n) (n)
#define MTT_MUL_T(dt, v) ((dt) * (v))
#define MTT_DIV_T(v, dt) ((v) / (dt))
#define MTT_MEAN2(a, b) (MTT_R(0.5) * ((a) + (b)))
#define MTT_COV_FIT(P, dt) ((void)0)
#define MTT_COV_ALIGN(A, B) ((void)0)
#define MTT_COV_COPY_E(D, S) ((void)0)
#define MTT_COV_NORM(P) ((void)0)
#define MTT_SYM_SLOTS 3
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

#define MTT_TIME_OK(t) mtt_isfinite(t)
#define MTT_TIME_AFTER(t, t0) ((t) > (t0))
#define MTT_TIME_SUB(t, t0) ((t) - (t0))
#define MTT_VAR_OF(s) ((s) * (s))
#define MTT_COV_VIEW(P, i, j) ((P)[i][j])
#define MTT_COV_SET_E(P, e) ((void)0)
#define MTT_COV_EMAX(A, B) 0
#define MTT_TIME(x) MTT_R(x)
#define MTT_VAR(x) MTT_R(x)

#endif /* MTT_REAL_FIXED */

#endif /* MTT_REAL_H */
