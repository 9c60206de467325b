# SPDX-License-Identifier: BSD-3-Clause
# tools/ci/fx_build.sh - sourced by tools/ci/fx-mc.sh and fx-cov-mc.sh: the
# float build at the radar scale's bounds (configs/firmware_fixed_radar.h),
# whose mtt-track is compared with host-fixed-radar's.
#
#   fx_float_radar ROOT   configures and builds ROOT/build/fx-float-radar's mtt-track
fx_float_radar() {
  cmake --preset host-float -B "$1/build/fx-float-radar" -DMTT_CONFIG_HEADER="$1/configs/firmware_fixed_radar.h" \
    -DMTT_BUILD_TESTS=OFF -DMTT_BUILD_FUZZ=OFF -DMTT_INSTALL=OFF >/dev/null
  cmake --build "$1/build/fx-float-radar" -j2 --target mtt-track >/dev/null
}
