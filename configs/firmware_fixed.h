/* SPDX-License-Identifier: BSD-3-Clause */
/* configs/firmware_fixed.h - the fixed-point build's configuration (presets
 * host-fixed and cortex-m0plus-fixed; docs/FIXED_POINT.md).
 *
 * The same bounds and switches as configs/firmware.h: the fixed-point build
 * covers exactly the firmware configuration.  MTT_REAL_FIXED itself is not
 * set here: it is the CMake option of that name, which also chooses the
 * src/ files of the library (MTT_FIXED_STAGES). */
#ifndef MTT_CONFIGS_FIRMWARE_FIXED_H
#define MTT_CONFIGS_FIRMWARE_FIXED_H

#include "firmware.h"

#endif /* MTT_CONFIGS_FIRMWARE_FIXED_H */
