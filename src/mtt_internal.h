/* SPDX-License-Identifier: BSD-3-Clause */
/* mtt_internal.h - the library's common internal header: the constants
 * every layer shares and the internal header of each src/ directory (its
 * stage functions, shared by the source files and the unit tests).  Not
 * installed; not part of the API.  Sections "§N" are those of
 * docs/ALGORITHMS.md. */
#ifndef MTT_INTERNAL_H
#define MTT_INTERNAL_H

#include "mtt/mtt.h"
#include "real_ops.h" /* the operation macros and kernels: private */
#include "filter/motion.h"

#define MTT_MAGIC 0x4d54545fu /* "MTT_" : set by mtt_tracker_init */
#define MTT_NONE16 ((uint16_t)0xffffu)
#define MTT_PI MTT_R(3.14159265358979323846)

/* The layers, lowest first (a layer's header may use the ones above it). */
#include "fixed/fx.h"
#include "core/core.h"
#include "filter/filter.h"
#include "contest/contest.h"
#include "assoc/assoc.h"
#include "baselines/baselines.h"
#include "imm/imm.h"
#include "split/split.h"

#endif /* MTT_INTERNAL_H */
