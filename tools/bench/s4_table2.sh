#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# tools/bench/s4_table2.sh - [S4] Table 2 on scenarios/crossing3.json: the time
# of LM-IPDAF over all tracks (lm-ipda-all) against LM-IPDAF* over the
# cluster (lm-ipda), measured as docs/reports/PERFORMANCE.md measures.
#
#   ./tools/bench/s4_table2.sh [--seeds N] [--frames N] [--cg-frames N] [--run-frames N]
#   ./tools/bench/s4_table2.sh --summary     the summary of the last TSV only
#
# For seeds 0..N-1 (default 5), with the `bench` preset (-O2, float):
# - "busiest" and "crossing" (scan 39, t = 40 s): mtt-bench replays the scan,
#   wall = median of --frames (default 1000) frames in us; Ir = callgrind's
#   inclusive Ir of mtt_tracker_step per frame over --cg-frames (default 100);
# - "run": the whole 80-scan run, wall = the mean over its scans 0..79 of
#   mtt-bench's median for that scan (--run-frames repetitions, default 200);
#   Ir = inclusive Ir of mtt_tracker_step of the run through mtt-track / 80.
# saving = 1 - lm-ipda / lm-ipda-all, as [S4] states its reductions.  Writes
# out/bench/s4_table2.tsv and prints it, then per workload the means over the
# seeds of both modes' wall and Ir and the saving of those means, with the
# range of the per-seed savings.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$ROOT"
. tools/bench/cg_ir.sh
seeds=5
frames=1000
cg_frames=100
run_frames=200
summary_only=0
while (($#)); do
  case "$1" in
    --seeds) seeds="$2"; shift 2 ;;
    --frames) frames="$2"; shift 2 ;;
    --cg-frames) cg_frames="$2"; shift 2 ;;
    --run-frames) run_frames="$2"; shift 2 ;;
    --summary) summary_only=1; shift ;;
    -h|--help) sed -n '3,21p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "s4_table2.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
summarise() {
  awk -F'\t' 'NR > 1 {l = $2; n[l]++; wa[l] += $6; wc[l] += $7; ia[l] += $9; ic[l] += $10
      w = $8 + 0; i = $11 + 0
      if (!(l in wlo) || w < wlo[l]) wlo[l] = w; if (!(l in whi) || w > whi[l]) whi[l] = w
      if (!(l in ilo) || i < ilo[l]) ilo[l] = i; if (!(l in ihi) || i > ihi[l]) ihi[l] = i}
    END {for (l in n) printf "mean of %d seeds, %s: wall %.2f against %.2f us (%.1f %%; seeds %.1f to %.1f %%), Ir %.0f against %.0f (%.1f %%; seeds %.1f to %.1f %%)\n",
      n[l], l, wa[l] / n[l], wc[l] / n[l], 100 * (1 - wc[l] / wa[l]), wlo[l], whi[l],
      ia[l] / n[l], ic[l] / n[l], 100 * (1 - ic[l] / ia[l]), ilo[l], ihi[l]}' "$1" | sort
}
if ((summary_only)); then summarise out/bench/s4_table2.tsv; exit 0; fi
command -v valgrind >/dev/null || { echo "s4_table2.sh: needs valgrind (apt-get install valgrind)" >&2; exit 1; }
out=out/bench
mkdir -p "$out"
cmake --preset bench >/dev/null
cmake --build --preset bench >/dev/null
bench=build/bench/tools/bench/mtt-bench
track=build/bench/tools/track/mtt-track
tsv="$out/s4_table2.tsv"
printf 'seed\tworkload\tscan\ttracks\tpairs\twall lm-ipda-all\twall lm-ipda\twall saving\tIr lm-ipda-all\tIr lm-ipda\tIr saving\n' > "$tsv"
# the settings of mode $2 from the scenario's settings $1, into $3
with_mode() { python3 -c 'import json, sys; s = json.load(open(sys.argv[1])); s["association"] = sys.argv[2]; json.dump(s, open(sys.argv[3], "w"))' "$@"; }
# mean over scans 0..79 of mtt-bench's median wall time per frame (us) of mode $3
run_us() {
  local k
  for ((k = 0; k < 80; ++k)); do
    "$bench" --frames "$run_frames" --dense 0 --det "$2" --config "$1" --modes "$3" --scan "$k" |
      awk '/^scan-/ {print $5; exit}'
  done | awk '{t += $1; n++} END {printf "%.2f", t / n}'
}
for ((s = 0; s < seeds; ++s)); do
  d="$out/s4t2/s$s"
  PYTHONPATH=python python3 -m mtt_sim.gen scenarios/crossing3.json --seed "$s" --out "$d" >/dev/null
  det="$d/crossing3.det.csv"
  with_mode "$d/crossing3.settings.json" lm-ipda-all "$d/all.json"
  with_mode "$d/crossing3.settings.json" lm-ipda "$d/cluster.json"
  for label in busiest crossing run; do
    row="" scan="" tracks="" pairs=""
    for mode in lm-ipda-all lm-ipda; do
      if [[ $label == run ]]; then
        cfg="$d/all.json"; [[ $mode == lm-ipda ]] && cfg="$d/cluster.json"
        scan=1-80 tracks=- pairs=-
        wall=$(run_us "$d/crossing3.settings.json" "$det" "$mode")
        ir=$(cg_ir 80 "$track" --config "$cfg" --detections "$det" --tracks /dev/null)
      else
        sel=(); [[ $label == crossing ]] && sel=(--scan 39)
        args=(--dense 0 --det "$det" --config "$d/crossing3.settings.json" --modes "$mode" "${sel[@]}")
        read -r scan tracks pairs wall < <("$bench" --frames "$frames" "${args[@]}" |
          awk '/^scan-/ {sub("scan-", "", $1); print $1, $3, $4, $5; exit}')
        ir=$(cg_ir "$cg_frames" "$bench" --frames "$cg_frames" "${args[@]}")
      fi
      row+=$'\t'"$wall"$'\t'"$ir"
      printf '\r  seed %s %s %s   ' "$s" "$label" "$mode" >&2
    done
    awk -v s="$s" -v l="$label" -v sc="$scan" -v t="$tracks" -v p="$pairs" -v r="$row" 'BEGIN {
      split(substr(r, 2), v, "\t");
      printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%.1f%%\t%s\t%s\t%.1f%%\n", s, l, sc, t, p, v[1], v[3],
             100 * (1 - v[3] / v[1]), v[2], v[4], 100 * (1 - v[4] / v[2]) }' >> "$tsv"
  done
done
echo >&2
cat "$tsv"
summarise "$tsv"
