# SPDX-License-Identifier: BSD-3-Clause
# cmake/toolchains/cortex-m4f.cmake - Cortex-M4 with the single-precision
# FPU (FPv4-SP-D16), hard-float ABI.  Preset: cortex-m4f (-Os).
set(MTT_CPU_FLAGS "-mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16")
set(MTT_FIRMWARE_CPU cortex-m4f)
include("${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake")
