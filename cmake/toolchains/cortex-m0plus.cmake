# SPDX-License-Identifier: BSD-3-Clause
# cmake/toolchains/cortex-m0plus.cmake - Cortex-M0+ (ARMv6-M), no FPU,
# soft-float ABI.  Preset: cortex-m0plus (-Os).
set(MTT_CPU_FLAGS "-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft")
set(MTT_FIRMWARE_CPU cortex-m0plus)
include("${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake")
