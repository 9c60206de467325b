/* mtt/real.h - the one real type and its math layer.
 *
 * mtt_real is float unless MTT_REAL_DOUBLE is defined.  Every literal goes
 * through MTT_R() and every function through the mtt_ macros below, so a
 * float build never promotes to double: on a soft-float or single-precision
 * FPU target a stray double costs a library call per operation.
 */
#ifndef MTT_REAL_H
#define MTT_REAL_H

#include <math.h>

/* MTT_REAL_KIND: 1 float, 2 double (part of the configuration identity). */
#ifdef MTT_REAL_DOUBLE
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

/* Finite test without isfinite(), whose float overloads some freestanding
 * libms lack: NaN fails x == x, and +-Inf fails the magnitude bound. */
#define mtt_isfinite(x) (((x) == (x)) && (mtt_fabs(x) <= MTT_REAL_MAX))

#endif /* MTT_REAL_H */
