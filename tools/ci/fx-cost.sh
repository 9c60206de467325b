#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# tools/ci/fx-cost.sh - cost of the fixed-point kernels on Cortex-M0+
# (docs/FIXED_POINT.md, "Cost"): .text per kernel (arm-none-eabi-gcc
# -mcpu=cortex-m0plus -mthumb -Os) and instructions per call under
# qemu-system-arm -icount shift=0 (tools/fw-measure/fx_cost.c), beside the
# soft-float helpers and newlib functions they replace; then the prediction
# stage's arithmetic per track (mtt_kalman_predict + mtt_kalman_innov,
# the gate's (area, widths, peak, d^2 and p of 4 candidates per track), and
# the update's (the PDA update with 3 measurements and mtt_cov_ok),
# tools/fw-measure/fx_stage_cost.c) built as float (soft float) and as fixed point.
#
#   ./tools/ci/fx-cost.sh [OUTDIR]     (default build/fx-cost)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
OUT="${1:-$ROOT/build/fx-cost}"
mkdir -p "$OUT"
CC=arm-none-eabi-gcc
CPU=(-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft)
CFLAGS=("${CPU[@]}" -std=c99 -Os -ffunction-sections -fdata-sections
        -Wall -Wextra -Wpedantic -Wconversion -Werror -Wno-type-limits
        -DMTT_FX_KERNELS -I"$ROOT/include" -I"$ROOT/src" -I"$ROOT/examples/firmware")

"$CC" "${CFLAGS[@]}" -c "$ROOT/src/fixed/fx_math.c" -o "$OUT/fx_math.o"
echo "== .text per kernel (bytes, -Os, Thumb-1; tables are .rodata)"
# hex() for mawk (no strtonum)
HEX='function hex(s,  i, v) { v = 0; s = tolower(s); for (i = 1; i <= length(s); ++i) v = v * 16 + index("0123456789abcdef", substr(s, i, 1)) - 1; return v }'
arm-none-eabi-nm -S --size-sort "$OUT/fx_math.o" | awk "$HEX"'{ printf "%-22s %5d %s\n", $4, hex($2), $3 }'
arm-none-eabi-size -A "$OUT/fx_math.o" | awk '$1 ~ /^\.(text|rodata)/ { s[$1 ~ /text/ ? "text" : "rodata"] += $2 }
  END { printf "fx_math.o total: .text %d .rodata %d bytes\n", s["text"], s["rodata"] }'

"$CC" "${CFLAGS[@]}" -Wno-double-promotion -specs=nano.specs -nostartfiles -Wl,--gc-sections \
  -T"$ROOT/examples/firmware/mps2.ld" \
  "$ROOT/examples/firmware/startup.c" "$ROOT/examples/firmware/semihost.c" "$ROOT/examples/firmware/fmt.c" \
  "$ROOT/tools/fw-measure/fx_cost.c" "$OUT/fx_math.o" -lm -o "$OUT/fx-cost.elf"
echo "== soft-float helpers and libm in the same image (bytes)"
arm-none-eabi-nm -S --size-sort "$OUT/fx-cost.elf" |
  grep -E ' (__aeabi_(fadd|fmul|fdiv|fcmplt|lmul|idiv|uidiv)|__(add|mul|div)sf3|__lesf2|__ltsf2|sqrtf|expf|logf|__ieee754_(sqrt|exp|log)f|__divsi3|__udivsi3)$' |
  awk "$HEX"'{ printf "%-22s %5d\n", $4, hex($2) }'

echo "== instructions per call (qemu mps2-an385, -icount shift=0; mean over 1024 inputs)"
qemu-system-arm -machine mps2-an385 -semihosting-config enable=on,target=native \
  -nographic -monitor none -serial none -icount shift=0 -kernel "$OUT/fx-cost.elf" 2>&1 |
  tee "$OUT/fx-cost.txt" | awk '/^C / { printf "%-32s %8.1f\n", $2, $3 / 10 } /^END/ { print }'

echo "== the prediction stage per track (predict + innovation; instructions per track, 32 tracks)"
DEFS=("-DMTT_USER_CONFIG=\"$ROOT/configs/firmware.h\"") # the firmware configuration
for build in float fixed; do
  if [[ "$build" == fixed ]]; then
    extra=(-DMTT_REAL_FIXED "$ROOT/src/fixed/fx_cov.c" "$ROOT/src/fixed/fx_math.c")
  else
    extra=(-DMTT_SMALL_LOG=1)
  fi
  "$CC" "${CPU[@]}" -std=c99 -Os -ffunction-sections -fdata-sections -Wall -Wextra -Wconversion -Werror \
    -I"$ROOT/include" -I"$ROOT/src" -I"$ROOT/examples/firmware" "${DEFS[@]}" \
    -specs=nano.specs -nostartfiles -Wl,--gc-sections -T"$ROOT/examples/firmware/mps2.ld" \
    "$ROOT/examples/firmware/startup.c" "$ROOT/examples/firmware/semihost.c" "$ROOT/examples/firmware/fmt.c" \
    "$ROOT/tools/fw-measure/fx_stage_cost.c" "$ROOT/src/filter/kalman.c" "$ROOT/src/filter/motion_cv.c" "$ROOT/src/assoc/gate.c" "${extra[@]}" -lm \
    -o "$OUT/stage-$build.elf"
  qemu-system-arm -machine mps2-an385 -semihosting-config enable=on,target=native \
    -nographic -monitor none -serial none -icount shift=0 -kernel "$OUT/stage-$build.elf" 2>&1 |
    tee "$OUT/stage-$build.txt" | awk '/^S / { print }'
done
