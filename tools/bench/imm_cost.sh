#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# tools/bench/imm_cost.sh - instructions per frame of motion = imm (the default
# CV + CA models) against cv, per association mode, on mtt-bench's dense
# workloads (callgrind, tools/bench/cg_ir.sh).
#
#   ./tools/bench/imm_cost.sh [MODES] [SIZES] [FRAMES]
#
# MODES a comma list (default: the JPDA family and jipda), SIZES a comma list
# of dense target counts (default 16,64), FRAMES the timed frames (default 50).
# Needs the bench preset (cmake --preset bench && cmake --build build/bench)
# and valgrind.  Prints a Markdown table: mode, workload, cv, imm, ratio.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
. "$ROOT/tools/bench/cg_ir.sh"
if [[ "${1:-}" == "--help" || "${1:-}" == "-h" ]]; then
  sed -n '3,12p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
  exit 0
fi
modes="${1:-jipda,jpda,cheap-jpda,suboptimal-jpda,nnjpda,jpda-star,adaptive-jpda}"
sizes="${2:-16,64}"
frames="${3:-50}"
bench="$ROOT/build/bench/tools/bench/mtt-bench"
[[ -x "$bench" ]] || { echo "imm_cost.sh: $bench not built (cmake --preset bench && cmake --build build/bench)" >&2; exit 2; }
command -v valgrind >/dev/null || { echo "imm_cost.sh: valgrind not found" >&2; exit 2; }
echo "| mode | workload | cv | imm | ratio |"
echo "|---|---|---|---|---|"
IFS=, read -ra M <<<"$modes"
IFS=, read -ra N <<<"$sizes"
for m in "${M[@]}"; do
  for n in "${N[@]}"; do
    echo "imm_cost.sh: $m dense-$n" >&2
    cv=$(cg_ir "$frames" "$bench" --frames "$frames" --dense "$n" --modes "$m" --motion cv)
    imm=$(cg_ir "$frames" "$bench" --frames "$frames" --dense "$n" --modes "$m" --motion imm)
    awk -v m="$m" -v n="$n" -v a="$cv" -v b="$imm" 'BEGIN {
      printf "| %s | dense-%s | %\047d | %\047d | %.2f× |\n", m, n, a, b, (a > 0) ? b / a : 0 }'
  done
done
