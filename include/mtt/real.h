/* SPDX-License-Identifier: BSD-3-Clause */
/* mtt/real.h - the one real type and its constants.
 *
 * mtt_real is float unless MTT_REAL_DOUBLE is defined; MTT_REAL_FIXED
 * selects the fixed-point build (docs/FIXED_POINT.md), where every real is
 * an int32_t in the Q format of its quantity.  A caller writes values with
 * the constant macros below: MTT_R() in float and double, the format's
 * constant (MTT_P() for a probability, MTT_POS() for a position, ...) in
 * any build.  Each folds at compile time, so no double reaches a float or
 * fixed image.
 *
 * Only the type, its constants and the two layout macros of mtt/state.h
 * are here.  The library's arithmetic (the quantity types and operation
 * macros that a stage is written with) is private: src/real_ops.h.
 */
#ifndef MTT_REAL_H
#define MTT_REAL_H

#if defined(MTT_REAL_FIXED) && defined(MTT_REAL_DOUBLE)
#error "MTT_REAL_FIXED and MTT_REAL_DOUBLE exclude each other"
#endif

/* MTT_REAL_KIND: 1 float, 2 double, 3 fixed point with the declared
 * position, amplitude, variance and density formats folded in (below):
 * part of the configuration identity, so a caller compiled with other
 * declared units is refused like one with other bounds. */
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

/* Variance LSB 2^-MTT_FX_VAR_FRAC unit^2 at the API (R's sigma^2,
 * process_psd, views, seeds; inside, covariances are block floating
 * point), clutter density LSB 2^-MTT_FX_DENS_FRAC per unit^2: declared
 * with the length unit (configs/firmware_fixed_radar.h). */
#ifndef MTT_FX_VAR_FRAC
#define MTT_FX_VAR_FRAC 16
#endif
#if MTT_FX_VAR_FRAC < 0 || MTT_FX_VAR_FRAC > 30
#error "MTT_FX_VAR_FRAC must lie in 0..30"
#endif
#ifndef MTT_FX_DENS_FRAC
#define MTT_FX_DENS_FRAC 30
#endif
#if MTT_FX_DENS_FRAC < 16 || MTT_FX_DENS_FRAC > 60
#error "MTT_FX_DENS_FRAC must lie in 16..60"
#endif

/* lambda V_G, the expected clutter count of a gate (ALGORITHMS.md §4),
 * LSB 2^-MTT_FX_GATE_FRAC: a track state's format, declared with the
 * density (a radar's 1e-4 needs more than Q16's 16 bits). */
#ifndef MTT_FX_GATE_FRAC
#define MTT_FX_GATE_FRAC 16
#endif
#if MTT_FX_GATE_FRAC < 16 || MTT_FX_GATE_FRAC > 28
#error "MTT_FX_GATE_FRAC must lie in 16..28"
#endif

/* The units folded in: 0 for the variance, density and gate terms at
 * their defaults, so the default build's identity does not move. */
#define MTT_REAL_KIND                                                                              \
    (3 + 4 * (MTT_FX_POS_FRAC + 32 * MTT_FX_AMP_FRAC) +                                            \
     4096 * ((MTT_FX_VAR_FRAC - 16) + 32 * (MTT_FX_DENS_FRAC - 30)) +                               \
     8388608 * (MTT_FX_GATE_FRAC - 16))

/* The formats of the quantities (docs/FIXED_POINT.md §3):
 *   probabilities, existence            Q30, [0, 2)
 *   likelihood ratios                   Q16, [0, 32768)
 *   squared Mahalanobis distances       Q24, [0, 128)
 *   counts                              Q24
 *   variances and their rates           MTT_FX_VAR_FRAC (16: unit^2, per T0^3)
 *   clutter density per unit^2          MTT_FX_DENS_FRAC (30)
 *   time                                Q16 frames (T0)
 *   positions, amplitudes               MTT_FX_POS_FRAC, MTT_FX_AMP_FRAC */
#define MTT_FX_PROB_FRAC 30
#define MTT_FX_RATIO_FRAC 16
#define MTT_FX_D2_FRAC 24
#define MTT_FX_CNT_FRAC 24
#define MTT_FX_T_FRAC 16

/* round(x 2^f) of a constant x: an arithmetic constant expression that the
 * compiler folds, so no double arithmetic reaches the image. */
#define MTT_FX_CONST(x, f)                                                                         \
    ((int32_t)((x) * (double)((uint64_t)1 << (f)) + (((x) < 0) ? -0.5 : 0.5)))
/* "No bound" of the parameter table (mtt_param_info): saturates. */
#define MTT_REAL_MAX 3.4028235e38
#define MTT_P(x) MTT_FX_CONST(x, MTT_FX_PROB_FRAC)
#define MTT_RATIO(x) MTT_FX_CONST(x, MTT_FX_RATIO_FRAC)
#define MTT_D2(x) MTT_FX_CONST(x, MTT_FX_D2_FRAC)
#define MTT_POS(x) MTT_FX_CONST(x, MTT_FX_POS_FRAC)
#define MTT_AMP(x) MTT_FX_CONST(x, MTT_FX_AMP_FRAC)
#define MTT_DENS(x) MTT_FX_CONST(x, MTT_FX_DENS_FRAC)
#define MTT_TIME(x) MTT_FX_CONST(x, MTT_FX_T_FRAC)
#define MTT_VAR(x) MTT_FX_CONST(x, MTT_FX_VAR_FRAC)
#define MTT_ZERO 0

/* Layout (mtt/state.h): a covariance in block floating point has one more
 * row, holding its exponent; a symmetric 2 x 2 a fourth slot for it. */
#define MTT_COV_ROWS(n) ((n) + 1)
#define MTT_SYM_SLOTS 4

#else /* float, double */

#if defined(MTT_REAL_DOUBLE)
typedef double mtt_real;
#define MTT_REAL_KIND 2
#define MTT_R(x) (x)
#define MTT_REAL_EPS 2.220446049250313e-16
#define MTT_REAL_MAX 1.7976931348623157e308
#else
typedef float mtt_real;
#define MTT_REAL_KIND 1
#define MTT_R(x) ((float)(x)) /* a constant expression: folded at compile time */
#define MTT_REAL_EPS 1.1920929e-7f
#define MTT_REAL_MAX 3.4028235e38f
#endif

/* The format constants of the fixed build are plain reals here, so that
 * one source serves every build. */
#define MTT_P(x) MTT_R(x)
#define MTT_RATIO(x) MTT_R(x)
#define MTT_D2(x) MTT_R(x)
#define MTT_POS(x) MTT_R(x)
#define MTT_AMP(x) MTT_R(x)
#define MTT_DENS(x) MTT_R(x)
#define MTT_TIME(x) MTT_R(x)
#define MTT_VAR(x) MTT_R(x)
#define MTT_ZERO MTT_R(0.0)

#define MTT_COV_ROWS(n) (n)
#define MTT_SYM_SLOTS 3

#endif /* MTT_REAL_FIXED */

#endif /* MTT_REAL_H */
