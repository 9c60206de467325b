/* SPDX-License-Identifier: BSD-3-Clause */
/* tv_cov.h - covariances in and out of the tests in every build: from and
 * to doubles, with the block exponent of the fixed-point build (a block of
 * mantissas at 2^e, docs/FIXED_POINT.md §2).  Include after tv_assert.h. */
#ifndef TV_COV_H
#define TV_COV_H

#include <string.h>

#include "mtt_internal.h"

/* A covariance from 16 row-major doubles: mantissas round(v 2^-e) in the
 * fixed build (e ignored otherwise). */
static void tv_cov_set(mtt_cov P, const double *v, int e)
{
    int i, j;
    memset(P, 0, sizeof(mtt_cov));
    for (i = 0; i < 4; ++i) {
        for (j = 0; j < 4; ++j) {
#ifdef MTT_REAL_FIXED
            P[i][j] = (mtt_real)llround(ldexp(v[4 * i + j], -e));
#else
            P[i][j] = (mtt_real)v[4 * i + j];
#endif
        }
    }
#ifdef MTT_REAL_FIXED
    MTT_COV_E(P) = e;
#else
    (void)e;
#endif
}

/* Entry (i, j) as a double. */
static double tv_cov_at(mtt_cov P, int i, int j)
{
#ifdef MTT_REAL_FIXED
    return ldexp((double)P[i][j], MTT_COV_E(P));
#else
    return (double)P[i][j];
#endif
}

#endif /* TV_COV_H */
