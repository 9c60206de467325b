/* SPDX-License-Identifier: BSD-3-Clause */
/* configs/firmware_small.h - the firmware configuration with the library's
 * logarithm by a short series instead of libm's (MTT_SMALL_LOG, about 500
 * bytes less .text): presets cortex-m4f-small and cortex-m0plus-small. */
#ifndef MTT_CONFIGS_FIRMWARE_SMALL_H
#define MTT_CONFIGS_FIRMWARE_SMALL_H

#include "firmware.h"

#ifndef MTT_SMALL_LOG
#define MTT_SMALL_LOG 1
#endif

#endif /* MTT_CONFIGS_FIRMWARE_SMALL_H */
