# SPDX-License-Identifier: BSD-3-Clause
# tools/bench/cg_ir.sh - sourced by the bench scripts (bench.sh, s0_table5.sh,
# s4_table2.sh): the instructions of one workload under callgrind.
#
#   cg_ir FRAMES CMD [ARG...]   runs CMD under valgrind --tool=callgrind and
#                               prints the inclusive Ir of mtt_tracker_step
#                               divided by FRAMES (rounded to a whole number)
#
# mtt-bench zeroes the counters when its timed frames start, so FRAMES is its
# --frames; for a whole mtt-track run it is the run's frame count.
cg_ir() {
  local fr="$1" f
  shift
  f="$(mktemp "${TMPDIR:-/tmp}/mtt-cg.XXXXXX")"
  valgrind --tool=callgrind --callgrind-out-file="$f" "$@" >/dev/null 2>&1
  callgrind_annotate --inclusive=yes "$f" 2>/dev/null |
    awk -v fr="$fr" '/mtt_tracker_step/ {gsub(",", "", $1); printf "%.0f", $1 / fr; exit}'
  rm -f "$f"
}
