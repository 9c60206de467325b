#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# tools/ci/identity.sh - the byte-identity check of a refactoring: the tracks
# files of every scenario x association mode x seed, against another revision.
#
#   ./tools/ci/identity.sh --write DIR      this tree's outputs into DIR
#   ./tools/ci/identity.sh --against REV    this tree's outputs and REV's (built
#                                           in a temporary worktree), compared
#
# The set (about 300 runs, about 1 minute a tree on 2 cores): for each
# scenarios/*.json and seeds 0 and 1, the detections of mtt_sim.gen tracked by
# the host-float mtt-track with the scenario's own settings and with each of
# the 16 association modes (IMM settings dropped for the modes without an IMM
# form); the host-fixed mtt-track with its four modes on seed 0; and the IMM
# with each IMM mode on manoeuvre.json.  A run's tracks file, stdout and stderr
# (--stats counters and error messages) are compared, so a change that moves
# a counter or a message is caught too.  Prints "IDENTICAL (N files)" or the
# files that differ, and exits 1 then.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
usage() { sed -n '3,18p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
MODES="lm-ihpda ihpda lm-ipda ipda ihpda-2d jipda jpda cheap-jpda suboptimal-jpda nnjpda jpda-star adaptive-jpda lm-ipda-all jpda-vg adaptive-nnjpda adaptive-jpda-star"

# write_outputs TREE DIR: build TREE's host-float and host-fixed tools, run the set.
write_outputs() {
  local tree="$1" out="$2" p ft xt gen s n seed d m
  mkdir -p "$out"
  for p in host-float host-fixed; do
    (cd "$tree" && cmake --preset "$p" -DMTT_BUILD_TESTS=OFF >/dev/null &&
       cmake --build --preset "$p" -j2 >"$out/.build-$p.log" 2>&1) ||
      { echo "identity.sh: build of $p failed in $tree (log $out/.build-$p.log)" >&2; return 1; }
  done
  rm -f "$out"/.build-*.log
  ft="$(find_bin "$tree/build/host-float")"; xt="$(find_bin "$tree/build/host-fixed")"
  gen="$(mktemp -d)"
  local total=0
  for s in "$tree"/scenarios/*.json; do
    n="$(basename "$s" .json)"
    for seed in 0 1; do
      d="$gen/$n.$seed"
      (cd "$tree" && PYTHONPATH=python python3 -m mtt_sim.gen "$s" --seed "$seed" --out "$d" --stem x >/dev/null)
      run "$ft" "$d/x.settings.json" "$d/x.det.csv" "$out/$n.$seed.own"
      for m in $MODES; do
        settings "$d/x.settings.json" "$d/$m.json" "$m" mode
        run "$ft" "$d/$m.json" "$d/x.det.csv" "$out/$n.$seed.$m"
      done
      if [[ "$seed" == 0 ]]; then
        for m in lm-ihpda ihpda lm-ipda ipda; do
          settings "$d/x.settings.json" "$d/fx$m.json" "$m" fixed
          run "$xt" "$d/fx$m.json" "$d/x.det.csv" "$out/$n.$seed.fixed.$m"
        done
      fi
      printf '\ridentity.sh: %s seed %s   ' "$n" "$seed" >&2
    done
  done
  d="$gen/manoeuvre.0"
  for m in lm-ihpda ihpda lm-ipda ipda jipda; do
    settings "$d/x.settings.json" "$d/imm$m.json" "$m" imm
    run "$ft" "$d/imm$m.json" "$d/x.det.csv" "$out/manoeuvre.0.imm.$m"
  done
  echo >&2
  # Error messages name the temporary directory: make them comparable.
  sed -i "s|$gen/|GEN/|g" "$out"/*.stderr
  rm -rf "$gen"
}

find_bin() {
  local p
  for p in "$1/tools/track/mtt-track" "$1/cli/mtt-track"; do
    [[ -x "$p" ]] && { echo "$p"; return; }
  done
  echo "identity.sh: no mtt-track under $1" >&2; return 1
}

# run BIN SETTINGS DET STEM: the tracks file, stdout and stderr (with the exit status).
run() {
  local rc=0
  "$1" --config "$2" --detections "$3" --tracks "$4.tracks.csv" --stats >"$4.stdout" 2>"$4.stderr" || rc=$?
  echo "rc=$rc" >>"$4.stderr"
}

# settings IN OUT MODE KIND: the scenario's settings with the association
# replaced (mode), reduced to the fixed build's keys (fixed), or with the IMM (imm).
settings() {
  python3 - "$@" <<'PY'
import json, sys
src, dst, mode, kind = sys.argv[1:5]
s = json.load(open(src))
s["association"] = mode
imm_modes = ("lm-ihpda", "ihpda", "lm-ipda", "ipda", "jipda")
def drop(pred):
    for k in list(s):
        if pred(k):
            s.pop(k)
if kind == "mode" and s.get("motion") == "imm" and mode not in imm_modes:
    drop(lambda k: k in ("motion", "split") or k.startswith(("imm_", "split_")))
elif kind == "fixed":
    drop(lambda k: k in ("motion", "split", "lm_ihpda_variant") or k.startswith(("imm_", "split_", "adapt_")))
elif kind == "imm":
    s["motion"] = "imm"
json.dump(s, open(dst, "w"))
PY
}

case "${1:-}" in
  --write)
    [[ $# -eq 2 ]] || { usage >&2; exit 2; }
    write_outputs "$ROOT" "$2"
    echo "identity.sh: $(ls "$2"/*.tracks.csv | wc -l) tracks files in $2" ;;
  --against)
    [[ $# -eq 2 ]] || { usage >&2; exit 2; }
    rev="$(git -C "$ROOT" rev-parse --verify --quiet "$2^{commit}")" ||
      { echo "identity.sh: '$2' is not a revision" >&2; exit 2; }
    tmp="$(mktemp -d)"
    trap 'git -C "$ROOT" worktree remove --force "$tmp/tree" >/dev/null 2>&1 || true; rm -rf "$tmp"' EXIT
    git -C "$ROOT" worktree add --detach --quiet "$tmp/tree" "$rev"
    write_outputs "$tmp/tree" "$tmp/ref"
    write_outputs "$ROOT" "$tmp/new"
    n="$(ls "$tmp/new" | wc -l)"
    if diff -rq "$tmp/ref" "$tmp/new" >"$tmp/diff"; then
      echo "identity.sh: IDENTICAL ($n files, $(ls "$tmp/new"/*.tracks.csv | wc -l) tracks files) against ${rev:0:12}"
    else
      echo "identity.sh: $(wc -l <"$tmp/diff") files DIFFER against ${rev:0:12}:"; head -20 "$tmp/diff"; exit 1
    fi ;;
  -h|--help) usage ;;
  *) usage >&2; exit 2 ;;
esac
