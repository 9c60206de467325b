#!/usr/bin/env bash
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
for real in "" "-DMTT_REAL_DOUBLE"; do
  for bounds in "" "-DMTT_WITH_IMM=0" "-DMTT_WITH_BASELINES=0 -DMTT_WITH_IMM=0" \
      "-DMTT_MAX_TRACKS=16 -DMTT_MAX_MEAS=64 -DMTT_MAX_PAIRS=256 -DMTT_WITH_IMM=0" \
      "-DMTT_MAX_TRACKS=16 -DMTT_MAX_MEAS=64 -DMTT_MAX_PAIRS=256 -DMTT_WITH_BASELINES=0 -DMTT_WITH_IMM=0"; do
    # shellcheck disable=SC2086
    "$cc" -std=c99 -Iinclude $real $bounds "$tmp/s.c" -o "$tmp/s" && "$tmp/s"
  done
done
