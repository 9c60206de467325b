/* SPDX-License-Identifier: BSD-3-Clause */
/* configs/firmware.h - the firmware configuration: the bounds and switches of
 * the small builds (presets host-float-small, host-fixed, cortex-m0plus-fixed;
 * with configs/firmware_small.h the cortex-m*-small presets), of the firmware
 * coverage run and of the fixed-point measurement scripts.
 *
 * Named in MTT_USER_CONFIG (CMake: -DMTT_CONFIG_HEADER=configs/firmware.h),
 * so every build of the configuration reads the one list.  Each value is a
 * default: a -D on the command line still overrides it (the consumer
 * mismatch tests rely on that).  MTT_CONFIG_ID (mtt/mtt.h) follows from the
 * values, so this configuration's id differs from the default build's. */
#ifndef MTT_CONFIGS_FIRMWARE_H
#define MTT_CONFIGS_FIRMWARE_H

/* sizeof(mtt_tracker) within a few KiB of RAM (docs/FIRMWARE.md) */
#ifndef MTT_MAX_TRACKS
#define MTT_MAX_TRACKS 16
#endif
#ifndef MTT_MAX_MEAS
#define MTT_MAX_MEAS 64
#endif
#ifndef MTT_MAX_PAIRS
#define MTT_MAX_PAIRS 256
#endif

/* The firmware modes only: lm-ihpda, ihpda, lm-ipda, ipda with CV motion. */
#ifndef MTT_WITH_BASELINES
#define MTT_WITH_BASELINES 0
#endif
#ifndef MTT_WITH_IMM
#define MTT_WITH_IMM 0
#endif
#ifndef MTT_WITH_CONTEST
#define MTT_WITH_CONTEST 0
#endif
#ifndef MTT_WITH_MEAS_COV
#define MTT_WITH_MEAS_COV 0 /* one R (meas_sigma) for every detection */
#endif

#endif /* MTT_CONFIGS_FIRMWARE_H */
