/* SPDX-License-Identifier: BSD-3-Clause */
/* fx_double.c - the host boundary of the fixed-point build: the user's
 * doubles (settings JSON, detections CSV) into the Q formats of
 * docs/FIXED_POINT.md §3 and back (the tracks CSV, mtt_params_get).
 *
 * Host only: double arithmetic.  The tools (io/) and params_info.c call it;
 * nothing in the tracker does, so a firmware image does not link it
 * (tools/ci/ci-firmware.sh checks the fixed image for float and double
 * helpers).  Out of range saturates, never wraps: the saturated value is
 * what measure.c skips and counts as a bad detection and what
 * mtt_params_check refuses (ALGORITHMS.md §16). */
#include "real_ops.h"
#include "mtt/mtt.h"

#if defined(MTT_REAL_FIXED)

/* 2^f, exactly (no libm). */
static double pow2(int f)
{
    double s = 1.0;
    int i;
    for (i = 0; i < f; ++i) {
        s *= 2.0;
    }
    return s;
}

int mtt_fx_from_double(double v, int f, int32_t *out)
{
    /* Inside (MIN, MAX) after rounding: |v 2^f| < 2^31 - 1.5.  NaN fails
     * both comparisons and saturates high. */
    const double lim = (double)MTT_FX_MAX - 0.5;
    double s;
    if (out == NULL) {
        return MTT_ERR_NULL;
    }
    if (f < 0 || f > 62) {
        return MTT_ERR_RANGE;
    }
    s = v * pow2(f);
    if (!(s < lim)) {
        *out = (s < 0.0) ? MTT_FX_MIN : MTT_FX_MAX;
        return MTT_ERR_RANGE;
    }
    if (!(s > -lim)) {
        *out = MTT_FX_MIN;
        return MTT_ERR_RANGE;
    }
    /* round half away from zero; the conversion truncates toward zero */
    *out = (s >= 0.0) ? (int32_t)(s + 0.5) : -(int32_t)(0.5 - s);
    return MTT_OK;
}

double mtt_fx_to_double(int32_t m, int f)
{
    return (f >= 0 && f <= 62) ? (double)m / pow2(f) : 0.0;
}

#else
/* ISO C wants at least one declaration in a translation unit. */
typedef int mtt_fx_double_unused;
#endif
