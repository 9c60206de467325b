#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# tools/bench/s0_table5.sh - [S0] Table 5 in instructions, at the frame the
# paper timed and at the busiest frame (docs/reports/RESULTS.md, formations).
#
#   ./tools/bench/s0_table5.sh [--seeds N] [--frames N]
#
# For seeds 0..N-1 of scenarios/formations.json (default 5): mtt-bench of the
# `bench` preset replays scan 14 (the formations' overlap, [S0]'s timed
# frame) and the busiest scan (most tracks + gated pairs) with lm-ihpda,
# ihpda-2d and ihpda (lm_ihpda_variant s0), under valgrind --tool=callgrind
# with the counters zeroed when the timed frames start; per frame =
# inclusive Ir of mtt_tracker_step / timed frames (default 50).  Writes
# out/bench/s0_table5.tsv (seed, frame label, scan, lm-ihpda's tracks and
# gated pairs there, Ir per mode, lm-ihpda against ihpda-2d) and prints it.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$ROOT"
. tools/bench/cg_ir.sh
seeds=5
frames=50
while (($#)); do
  case "$1" in
    --seeds) seeds="$2"; shift 2 ;;
    --frames) frames="$2"; shift 2 ;;
    -h|--help) sed -n '3,15p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "s0_table5.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
command -v valgrind >/dev/null || { echo "s0_table5.sh: needs valgrind (apt-get install valgrind)" >&2; exit 1; }
out=out/bench
mkdir -p "$out"
cmake --preset bench >/dev/null
cmake --build --preset bench >/dev/null
bench=build/bench/tools/bench/mtt-bench
modes="lm-ihpda ihpda-2d ihpda"
printf 'seed\tframe\tscan\ttracks\tpairs\tlm-ihpda\tihpda-2d\tihpda\tlm-ihpda/ihpda-2d\n' > "$out/s0_table5.tsv"
for ((s = 0; s < seeds; ++s)); do
  d="$out/s0t5/s$s"
  PYTHONPATH=python python3 -m mtt_sim.gen scenarios/formations.json --seed "$s" --out "$d" >/dev/null
  for label in busiest overlap; do
    sel=(); [[ $label == overlap ]] && sel=(--scan 14)
    row="" scan="" tracks="" pairs=""
    for mode in $modes; do
      args=(--frames "$frames" --dense 0 --det "$d/formations.det.csv" --config "$d/formations.settings.json"
            --modes "$mode" --variant s0 "${sel[@]}")
      if [[ $mode == lm-ihpda ]]; then # the frame's scan, and lm-ihpda's tracks and pairs there
        read -r scan tracks pairs < <("$bench" "${args[@]}" | awk '/^scan-/ {sub("scan-", "", $1); print $1, $3, $4; exit}')
      fi
      ir=$(cg_ir "$frames" "$bench" "${args[@]}")
      row+=$'\t'"$ir"
      printf '\r  seed %s %s %s   ' "$s" "$label" "$mode" >&2
    done
    awk -v s="$s" -v l="$label" -v sc="$scan" -v t="$tracks" -v p="$pairs" -v r="$row" 'BEGIN {
      n = split(substr(r, 2), v, "\t");
      printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%+.1f%%\n", s, l, sc, t, p, v[1], v[2], v[3], 100 * (v[1] / v[2] - 1) }' >> "$out/s0_table5.tsv"
  done
done
echo >&2
cat "$out/s0_table5.tsv"
