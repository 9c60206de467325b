/* SPDX-License-Identifier: BSD-3-Clause */
/* tv_assert.h - the one tolerance rule of the unit tests (ALGORITHMS.md §16,
 * docs/TEST_VECTORS.md header): double builds 1e-6 relative with a 1e-9 absolute
 * floor; float builds 1e-4 relative with a 1e-6 absolute floor.
 *
 *   TV_ASSERT_REAL(expected, actual)          expected: a test-vector number
 *   TV_ASSERT_REAL_MSG(expected, actual, s)   s names the quantity on failure
 *
 * Both print the expected and the actual value when they fail.  The
 * expected value is taken as double (test-vector literals stay exact); the
 * actual value is converted explicitly, so no implicit promotion happens. */
#ifndef TV_ASSERT_H
#define TV_ASSERT_H

#include <math.h>
#include <stdio.h>

#include "mtt/mtt.h"
#include "mtt/real.h"
#include "unity.h"

#ifdef MTT_REAL_DOUBLE
#define TV_REL 1e-6
#define TV_ABS 1e-9
#else
#define TV_REL 1e-4
#define TV_ABS 1e-6
#endif

/* 1 when actual is within the build's tolerance of expected. */
static inline int tv_close(double expected, double actual)
{
    double tol = TV_REL * fabs(expected);
    if (tol < TV_ABS) {
        tol = TV_ABS;
    }
    return fabs(actual - expected) <= tol; /* NaN fails */
}

static inline void tv_assert_real(double expected, double actual, const char *what, int line)
{
    char msg[256];
    if (!tv_close(expected, actual)) {
        double tol = TV_REL * fabs(expected);
        if (tol < TV_ABS) {
            tol = TV_ABS;
        }
        snprintf(msg, sizeof msg, "%s: expected %.10g, actual %.10g (|diff| %.3g > tol %.3g)",
                 what, expected, actual, fabs(actual - expected), tol);
        UNITY_TEST_FAIL((UNITY_LINE_TYPE)line, msg);
    }
}

#define TV_ASSERT_REAL(expected, actual) \
    tv_assert_real((double)(expected), (double)(actual), #actual, __LINE__)
#define TV_ASSERT_REAL_MSG(expected, actual, what) \
    tv_assert_real((double)(expected), (double)(actual), (what), __LINE__)

/* A value of Q format f against its double reference.  Fixed-point build
 * (docs/FIXED_POINT.md §7): |actual 2^-f - expected| <= tol_fx, a tolerance
 * the test derives from the formats (roundings on the way plus the
 * quantisation of the inputs times their condition factor).  Float and
 * double builds: TV_ASSERT_REAL (tol_fx unused). */
#ifdef MTT_REAL_FIXED
static inline void tv_assert_q(double expected, double actual, double tol, const char *what,
                               int line)
{
    char msg[512];
    if (!(fabs(actual - expected) <= tol)) {
        snprintf(msg, sizeof msg, "%.300s: expected %.10g, actual %.10g (|diff| %.3g > fixed tol %.3g)",
                 what, expected, actual, fabs(actual - expected), tol);
        UNITY_TEST_FAIL((UNITY_LINE_TYPE)line, msg);
    }
}
#define TV_Q(x, f) ((double)(x) / (double)((int64_t)1 << (f)))
#define TV_ASSERT_Q(expected, actual, f, tol_fx) \
    tv_assert_q((double)(expected), TV_Q(actual, f), (tol_fx), #actual, __LINE__)
#else
#define TV_Q(x, f) ((double)(x))
#define TV_ASSERT_Q(expected, actual, f, tol_fx) \
    do {                                          \
        (void)(tol_fx);                           \
        TV_ASSERT_REAL(expected, actual);         \
    } while (0)
#endif
/* Probabilities (Q30) and ratios (Q16). */
#define TV_ASSERT_PROB(expected, actual, tol_fx) TV_ASSERT_Q(expected, actual, 30, tol_fx)
#define TV_ASSERT_RATIO(expected, actual, tol_fx) TV_ASSERT_Q(expected, actual, 16, tol_fx)

/* Element-wise over a 4x4 matrix given as 16 row-major doubles. */
#define TV_ASSERT_MAT4(expected16, M)                                          \
    do {                                                                       \
        int tv_i_, tv_j_;                                                      \
        char tv_w_[64];                                                        \
        for (tv_i_ = 0; tv_i_ < 4; ++tv_i_) {                                  \
            for (tv_j_ = 0; tv_j_ < 4; ++tv_j_) {                              \
                snprintf(tv_w_, sizeof tv_w_, "%s[%d][%d]", #M, tv_i_, tv_j_); \
                tv_assert_real((expected16)[4 * tv_i_ + tv_j_],                \
                               (double)(M)[tv_i_][tv_j_], tv_w_, __LINE__);    \
            }                                                                  \
        }                                                                      \
    } while (0)

#define TV_ASSERT_VEC(expected, v, n)                                          \
    do {                                                                       \
        int tv_i_;                                                             \
        char tv_w_[64];                                                        \
        for (tv_i_ = 0; tv_i_ < (int)(n); ++tv_i_) {                           \
            snprintf(tv_w_, sizeof tv_w_, "%s[%d]", #v, tv_i_);                \
            tv_assert_real((expected)[tv_i_], (double)(v)[tv_i_], tv_w_, __LINE__); \
        }                                                                      \
    } while (0)

/* Exact symmetry (the library symmetrises every covariance it outputs). */
#define TV_ASSERT_SYM4(M)                                                      \
    do {                                                                       \
        int tv_i_, tv_j_;                                                      \
        for (tv_i_ = 0; tv_i_ < 4; ++tv_i_) {                                  \
            for (tv_j_ = tv_i_ + 1; tv_j_ < 4; ++tv_j_) {                      \
                TEST_ASSERT_TRUE_MESSAGE((M)[tv_i_][tv_j_] == (M)[tv_j_][tv_i_], \
                                         #M " is not symmetric");              \
            }                                                                  \
        }                                                                      \
    } while (0)

/* How a build refuses a mode it does not run: MTT_ERR_UNSUPPORTED, except
 * that without the baselines the modes from MTT_ASSOC_LM_IPDA_ALL on are
 * not values of the build at all: MTT_ERR_PARAM (so that such a build
 * keeps its mode tables and code). */
#define TV_REFUSED(m)                                                            \
    ((MTT_WITH_BASELINES || (int)(m) < (int)MTT_ASSOC_LM_IPDA_ALL) ? MTT_ERR_UNSUPPORTED : MTT_ERR_PARAM)

/* Built without the baselines (MTT_WITH_BASELINES 0): mode m must be
 * refused by mtt_params_check, with the field named, not half-run. */
static inline void tv_assert_mode_refused(mtt_assoc m)
{
    mtt_params p;
    const char *field = NULL;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.association = m;
    TEST_ASSERT_EQUAL_INT(TV_REFUSED(m), mtt_params_check(&p, &field));
    TEST_ASSERT_EQUAL_STRING("association", field);
}

#endif /* TV_ASSERT_H */
