#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# tools/ci/regress-mc.sh - the "no regression" check of a change of
# behaviour (#25 item 5): each scenario file with its own settings, tracked
# by another revision's host-float mtt-track and by this tree's, on the same
# detections (mtt_sim.mc, seeds 0 .. RUNS-1); one line per scenario with
# GOSPA, confirmed false tracks per scan and ID switches per run, old -> new.
#
#   tools/ci/regress-mc.sh REV RUNS SCENARIO.json...
#   e.g. tools/ci/regress-mc.sh HEAD~1 100 scenarios/*.json
#
# REV is built in a temporary worktree (as identity.sh does); this tree's
# mtt-track is build/host-float's (built here if missing).  Output of each run
# under build/regress-mc/<scenario>.<old|new>/.  The goal of #25 item 5:
# GOSPA within 2 % and false tracks the same or lower; this script prints the
# figures and does not judge them.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$ROOT"
usage() { sed -n '3,/^set -euo/p' "${BASH_SOURCE[0]}" | sed '$d' | sed 's/^# \{0,1\}//'; }
[[ "${1:-}" == -h || "${1:-}" == --help ]] && { usage; exit 0; }
[[ $# -ge 3 ]] || { usage >&2; exit 2; }
rev="$(git rev-parse --verify --quiet "$1^{commit}")" || { echo "regress-mc: '$1' is not a revision" >&2; exit 2; }
runs="$2"
shift 2
[[ "$runs" =~ ^[1-9][0-9]*$ ]] || { echo "regress-mc: RUNS must be a positive integer, not '$runs'" >&2; exit 2; }
for sc in "$@"; do
  [[ -f "$sc" ]] || { echo "regress-mc: no scenario file '$sc'" >&2; exit 2; }
done

new="$ROOT/build/host-float/tools/track/mtt-track"
[[ -x "$new" ]] || { cmake --preset host-float >/dev/null && cmake --build --preset host-float -j2 --target mtt-track >/dev/null; }
tmp="$(mktemp -d)"
trap 'git worktree remove --force "$tmp/tree" >/dev/null 2>&1 || true; rm -rf "$tmp"' EXIT
git worktree add --detach --quiet "$tmp/tree" "$rev"
(cd "$tmp/tree" && cmake --preset host-float -DMTT_BUILD_TESTS=OFF >/dev/null &&
  cmake --build --preset host-float -j2 --target mtt-track >/dev/null)
old="$tmp/tree/build/host-float/tools/track/mtt-track"

out="$ROOT/build/regress-mc"
mkdir -p "$out"
# field LOG LABEL: the last column of the summary line LABEL
field() { grep -E "$2" "$1" | awk '{print $NF}'; }
echo "regress-mc: ${rev:0:12} -> this tree, $runs runs per scenario"
for sc in "$@"; do
  n="$(basename "$sc" .json)"
  for v in old new; do
    b="$new"; [[ $v == old ]] && b="$old"
    echo "regress-mc: $n ($v)" >&2
    PYTHONPATH=python python3 -m mtt_sim.mc --scenario "$sc" --runs "$runs" --out "$out/$n.$v" \
      --mtt-track "$b" --tracker mtt-track --no-plots --jobs 2 >"$out/$n.$v.log" 2>&1 ||
      { echo "regress-mc: $n ($v) failed: $out/$n.$v.log" >&2; exit 1; }
  done
  g0="$(field "$out/$n.old.log" 'GOSPA mean')"; g1="$(field "$out/$n.new.log" 'GOSPA mean')"
  f0="$(field "$out/$n.old.log" 'false tracks per scan')"; f1="$(field "$out/$n.new.log" 'false tracks per scan')"
  i0="$(field "$out/$n.old.log" 'ID switches')"; i1="$(field "$out/$n.new.log" 'ID switches')"
  printf '%-28s GOSPA %s -> %s (%s)  false/scan %s -> %s  ID sw/run %s -> %s\n' "$n" "$g0" "$g1" \
    "$(python3 -c "print('%+.2f %%' % ((float('$g1') / float('$g0') - 1) * 100))")" "$f0" "$f1" "$i0" "$i1"
done
