# SPDX-License-Identifier: BSD-3-Clause
# cmake/toolchains/arm-none-eabi.cmake - bare-metal Arm GNU toolchain
# (Debian: gcc-arm-none-eabi, libnewlib-arm-none-eabi).
#
# Not used directly: cortex-m4f.cmake and cortex-m0plus.cmake set
# MTT_CPU_FLAGS and include this file.  The flags that matter for the
# firmware figures (docs/FIRMWARE.md):
#   -ffunction-sections -fdata-sections + --gc-sections: only what is
#        referenced is linked, so image sizes measure what a caller pays;
#   -fstack-usage -fcallgraph-info=su: per-function frames (.su) and the
#        call graph with frames (.ci) next to each object, for the
#        worst-case stack sum of mtt_tracker_step (tools/fw-measure/fwcheck.py).
# Optimisation comes from the preset (CMAKE_C_FLAGS_RELEASE = -Os).
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

set(_mtt_prefix arm-none-eabi-)
find_program(CMAKE_C_COMPILER NAMES ${_mtt_prefix}gcc REQUIRED)
find_program(CMAKE_AR NAMES ${_mtt_prefix}ar REQUIRED)
find_program(CMAKE_RANLIB NAMES ${_mtt_prefix}ranlib REQUIRED)
find_program(CMAKE_NM NAMES ${_mtt_prefix}nm)
find_program(CMAKE_OBJDUMP NAMES ${_mtt_prefix}objdump)
find_program(CMAKE_OBJCOPY NAMES ${_mtt_prefix}objcopy)
find_program(MTT_SIZE NAMES ${_mtt_prefix}size)

# The compiler check links no program (no startup code yet at that point).
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

if(NOT DEFINED MTT_CPU_FLAGS)
  message(FATAL_ERROR "arm-none-eabi.cmake: include it from a CPU file that sets MTT_CPU_FLAGS")
endif()
# Seen by try_compile too.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES MTT_CPU_FLAGS)

# -Wno-type-limits: AAPCS targets use short enums (arm-none-eabi's default,
# newlib is built so), so an enum whose values are all >= 0 is unsigned and
# the library's "(int)e < 0" half of its enum range checks is always false
# there; the check stays meaningful on hosts, where -Wextra still warns.
set(CMAKE_C_FLAGS_INIT
    "${MTT_CPU_FLAGS} -ffunction-sections -fdata-sections -fstack-usage -fcallgraph-info=su -Wno-type-limits")
set(CMAKE_ASM_FLAGS_INIT "${MTT_CPU_FLAGS}")
# newlib-nano for mem*; the firmware brings its own startup code (-nostartfiles).
set(CMAKE_EXE_LINKER_FLAGS_INIT
    "${MTT_CPU_FLAGS} -specs=nano.specs -nostartfiles -Wl,--gc-sections")

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
