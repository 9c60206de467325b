#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# tools/bench/bench.sh - the performance figures (docs/PERFORMANCE.md), from one command.
#
#   ./tools/bench/bench.sh [--frames N] [--quick]
#
# 1. builds the `bench` preset (Release -O2, float, bounds for 256 targets);
# 2. generates the formations scenario (seed 0) and replays its busiest frame;
# 3. wall time: mtt-bench over every mode, dense N = 4, 16, 64, 256 and the
#    formations peak (median and worst of N frames, per-stage shares, floor);
# 4. instructions: the same workloads under valgrind --tool=callgrind, with
#    the counters zeroed when the timed frames start; per frame =
#    inclusive Ir of mtt_tracker_step (and of the floor) / timed frames;
# 5. the real-target default (max_accel) against CV in instructions
#    (out/bench/default_vs_cv.tsv);
# 6. tables and plots in out/bench/ (bench.md, cost_vs_n.png).
# --quick: 100 timed frames and N = 4, 16, 64 (a smoke run).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$ROOT"
. tools/bench/cg_ir.sh
frames=1000
cg_frames=200
dense=4,16,64,256
while (($#)); do
  case "$1" in
    --frames) frames="$2"; shift 2 ;;
    --quick) frames=100; cg_frames=50; dense=4,16,64; shift ;;
    -h|--help) sed -n '3,17p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "bench.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
command -v valgrind >/dev/null || { echo "bench.sh: needs valgrind (apt-get install valgrind)" >&2; exit 1; }
out=out/bench
mkdir -p "$out"
cmake --preset bench >/dev/null
cmake --build --preset bench >/dev/null
bench=build/bench/tools/bench/mtt-bench
PYTHONPATH=python python3 -m mtt_sim.gen scenarios/formations.json --seed 0 --out "$out/formations" >/dev/null
det="$out/formations/formations.det.csv"
cfg="$out/formations/formations.settings.json"

{
  echo "machine: $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p' | head -1)"
  echo "compiler: $(cc --version | head -1), flags -O2 -DNDEBUG (preset bench)"
} | tee "$out/machine.txt"

echo "== wall time ($frames frames per workload)" >&2
"$bench" --frames "$frames" --dense "$dense" --det "$det" --config "$cfg" \
  --json "$out/wall.json" | tee "$out/wall.txt"

echo "== instructions (callgrind, $cg_frames timed frames per workload)" >&2
modes=$("$bench" --list-modes)
: > "$out/instructions.tsv"
for mode in $modes; do
  for n in ${dense//,/ } formations; do
    if [[ "$n" == formations ]]; then
      args=(--frames "$cg_frames" --dense 0 --det "$det" --config "$cfg" --modes "$mode")
    else
      args=(--frames "$cg_frames" --dense "$n" --modes "$mode")
    fi
    f="$out/cg.$mode.$n"
    valgrind --tool=callgrind --callgrind-out-file="$f" "$bench" "${args[@]}" >/dev/null 2>&1
    callgrind_annotate --inclusive=yes "$f" 2>/dev/null |
      awk -v mode="$mode" -v n="$n" -v fr="$cg_frames" '
        /mtt_tracker_step/ {gsub(",", "", $1); step = $1}
        /floor_run/ {gsub(",", "", $1); fl = $1}
        END {printf "%s\t%s\t%.0f\t%.0f\n", mode, n, step / fr, fl / fr}' >> "$out/instructions.tsv"
    rm -f "$f"
    printf '\r  %s N=%s   ' "$mode" "$n" >&2
  done
done
echo >&2

# The default of the real-target settings (ALGORITHMS.md §2.2: lm-ihpda
# contest, the motion from max_accel) against the CV frame of the same
# settings with process_psd (contest, CV): max_accel = sqrt(5), so the
# manoeuvring model's level is the CV level 5 at dT = 1.
echo "== default (max_accel) against CV, lm-ihpda contest (callgrind, $cg_frames frames)" >&2
printf 'workload\tcv\tdefault\tratio\n' > "$out/default_vs_cv.tsv"
for n in 16 64; do
  ir() { cg_ir "$cg_frames" "$bench" --frames "$cg_frames" --dense "$n" --modes lm-ihpda --variant contest "$@"; }
  cv=$(ir)
  dflt=$(ir --motion auto --set process_psd=0 --set max_accel=2.2360680)
  awk -v n="$n" -v a="$cv" -v b="$dflt" 'BEGIN {printf "dense-%s\t%s\t%s\t%.2f\n", n, a, b, b / a}' >> "$out/default_vs_cv.tsv"
done
cat "$out/default_vs_cv.tsv"
python3 tools/bench/plot_bench.py "$out"
