#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Print sizeof(mtt_tracker) for the default bounds and for a small firmware
# configuration, for float and double.  Usage: tools/ci/sizes.sh [CC]
set -euo pipefail
cd "$(dirname "$0")/../.."
cc=${1:-cc}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat > "$tmp/s.c" <<'C'
#include <stdio.h>
#include "mtt/mtt.h"
int main(void)
{
    printf("%-7s tracks=%-4d meas=%-4d pairs=%-5d gated=%-3d baselines=%d imm=%d sizeof(mtt_tracker) = %zu bytes\n",
           sizeof(mtt_real) == 4 ? "float" : "double", MTT_MAX_TRACKS, MTT_MAX_MEAS,
           MTT_MAX_PAIRS, MTT_MAX_GATED, MTT_WITH_BASELINES, MTT_WITH_IMM, sizeof(mtt_tracker));
    return 0;
}
C
# The small rows: the bounds of configs/firmware.h, with the contest variant
# (as README.md's table; the firmware presets leave it out), the first with
# the baselines too.  The header's values are defaults, so -D overrides them.
fw="-DMTT_USER_CONFIG=\"$PWD/configs/firmware.h\""
for real in "" "-DMTT_REAL_DOUBLE"; do
  for row in default no-imm no-baselines small-baselines small; do
    case "$row" in
      default) bounds=() ;;
      no-imm) bounds=(-DMTT_WITH_IMM=0) ;;
      no-baselines) bounds=(-DMTT_WITH_BASELINES=0 -DMTT_WITH_IMM=0) ;;
      small-baselines) bounds=("$fw" -DMTT_WITH_BASELINES=1 -DMTT_WITH_CONTEST=1) ;;
      small) bounds=("$fw" -DMTT_WITH_CONTEST=1) ;;
    esac
    # shellcheck disable=SC2086
    "$cc" -std=c99 -Iinclude $real "${bounds[@]}" "$tmp/s.c" -o "$tmp/s" && "$tmp/s"
  done
done
