/* SPDX-License-Identifier: BSD-3-Clause */
/* mtt/fixed.h - the saturation limits of the fixed-point build
 * (docs/FIXED_POINT.md).
 *
 * Every fixed-point value saturates to [MTT_FX_MIN, MTT_FX_MAX] instead of
 * wrapping: a saturated value is the build's "not finite" (a position or a
 * variance of mtt_track_view, a parameter).  The integer kernels that do
 * the arithmetic are private to the library (src/real_ops.h). */
#ifndef MTT_FIXED_H
#define MTT_FIXED_H

#include <stdint.h>

/* Symmetric saturation: -MTT_FX_MIN never overflows, so negating a
 * saturated value stays saturated. */
#define MTT_FX_MAX INT32_MAX
#define MTT_FX_MIN (-INT32_MAX)

#endif /* MTT_FIXED_H */
