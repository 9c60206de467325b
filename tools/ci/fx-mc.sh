#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# tools/ci/fx-mc.sh - float against fixed point on the same detections
# (docs/FIXED_POINT.md §7, "Float against fixed"): the Monte Carlo of
# python/mtt_sim (python3 -m mtt_sim.mc) with the float mtt-track and the
# fixed-point mtt-track, same scenarios, seeds and modes, and the table of
# GOSPA, track fraction, false tracks and ID switches side by side.
#
#   tools/ci/fx-mc.sh [RUNS] [SCENARIO...]     (default 200; crossing3 formations dim)
#
# The fixed side is build/host-fixed's mtt-track (cmake --workflow --preset
# test-fixed, or configure + build the preset); the float side is the same
# configuration in float, built here into build/fx-float (the host-float-small
# preset with the tools on): the same bounds (MTT_MAX_TRACKS 16, ...), so the
# tables compare the arithmetic alone.  Both run lm_ihpda_variant s0 (the
# fixed-point build has no contest variant).  Output under build/fx-mc/; the
# table (Markdown) on stdout.  GOSPA goal: fixed within 3 % of float.
# FX_MC_TABLE_ONLY=1 prints the table of the runs already under build/fx-mc/.
#
# FX_MC_SCALE=radar: the radar scale instead (docs/FIXED_POINT.md, "Scales"):
# the fixed side is build/host-fixed-radar's mtt-track (the test-fixed-radar
# workflow), the float side the same configuration in float
# (configs/firmware_fixed_radar.h: default bounds, the firmware switches),
# built into build/fx-float-radar; a SCENARIO may be a path under
# scenarios/ (recorded/quickstart).  FX_MC_SET adds --set KEY=VALUE
# settings to both sides (space-separated; the recorded scenes' max_accel
# derives an IMM in float, which the fixed build has not: FX_MC_SET=
# 'tracker.motion="cv"' compares the fixed default, CV with q = a² ΔT).
# The fixed side runs without --skip-out-of-range, so a run that met a
# detection outside the build's range fails and shows in "runs ok".
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$ROOT"
. tools/ci/fx_build.sh
RUNS="${1:-200}"
shift || true
SCENARIOS=("$@")
((${#SCENARIOS[@]})) || SCENARIOS=(crossing3 formations dim)
MODES=(lm-ihpda ihpda lm-ipda ipda)
OUT="$ROOT/build/fx-mc"
JOBS="${JOBS:-2}"
SET_ARGS=()
for kv in ${FX_MC_SET:-}; do SET_ARGS+=(--set "$kv"); done
if [[ "${FX_MC_SCALE:-default}" == radar ]]; then
  OUT="$ROOT/build/fx-mc-radar"
  declare -A BIN=([float]="$ROOT/build/fx-float-radar/tools/track/mtt-track"
    [fixed]="$ROOT/build/host-fixed-radar/tools/track/mtt-track")
  fx_float_radar "$ROOT"
else
  declare -A BIN=([float]="$ROOT/build/fx-float/tools/track/mtt-track" [fixed]="$ROOT/build/host-fixed/tools/track/mtt-track")
  cmake --preset host-float-small -B "$ROOT/build/fx-float" -DMTT_BUILD_TOOLS=ON -DMTT_BUILD_TESTS=OFF \
    -DMTT_BUILD_FUZZ=OFF -DMTT_INSTALL=OFF >/dev/null
  cmake --build "$ROOT/build/fx-float" -j2 --target mtt-track >/dev/null
fi
mkdir -p "$OUT"
for b in float fixed; do
  [[ -x "${BIN[$b]}" ]] || { echo "fx-mc: ${BIN[$b]} missing (build the host-$b preset)" >&2; exit 2; }
done
for scn in "${SCENARIOS[@]}"; do
  for b in float fixed; do
    [[ -n "${FX_MC_TABLE_ONLY:-}" ]] && continue # the table of the runs already made
    echo "fx-mc: $scn $b ($RUNS runs)" >&2
    PYTHONPATH=python nice -n 10 python3 -m mtt_sim.mc --scenario "scenarios/$scn.json" --runs "$RUNS" \
      --out "$OUT/${scn//\//_}-$b" --mtt-track "${BIN[$b]}" --tracker mtt-track --assoc "${MODES[@]}" \
      --set tracker.lm_ihpda_variant=s0 "${SET_ARGS[@]}" --no-plots --jobs "$JOBS" >/dev/null \
      2>"$OUT/${scn//\//_}-$b.log"
  done
done

python3 - "$OUT" "$RUNS" "${SCENARIOS[@]}" <<'PY'
import json, sys
out, runs, scns = sys.argv[1], sys.argv[2], sys.argv[3:]
print(f"| scenario | mode | GOSPA float | GOSPA fixed | fixed/float | track fraction float / fixed "
      f"| false tracks per scan float / fixed | ID switches per run float / fixed | runs ok float / fixed |")
print("|---|---|---|---|---|---|---|---|---|")
worst = 0.0
for scn in scns:
    s = {b: json.load(open(f"{out}/{scn.replace('/', '_')}-{b}/summary.json")) for b in ("float", "fixed")}
    for mode in s["float"]["modes"]:
        t = {b: s[b]["results"][mode]["totals"] for b in s}
        ok = {b: s[b]["results"][mode]["runs_ok"] for b in s}
        g0, g1 = t["float"]["gospa_mean"], t["fixed"]["gospa_mean"]
        r = g1 / g0 if g0 else float("nan")
        worst = max(worst, r)
        print(f"| {scn} | {mode} | {g0:.3f} | {g1:.3f} | **{r:.3f}** | "
              f"{t['float']['confirmed_true_fraction']:.3f} / {t['fixed']['confirmed_true_fraction']:.3f} | "
              f"{t['float']['confirmed_false_per_scan']:.4f} / {t['fixed']['confirmed_false_per_scan']:.4f} | "
              f"{t['float']['idsw_per_run']:.2f} / {t['fixed']['idsw_per_run']:.2f} | "
              f"{ok['float']} / {ok['fixed']} |")
print(f"\n{runs} runs per scenario and mode (seeds 0..{int(runs) - 1}, the same detections for both builds); "
      f"largest GOSPA ratio fixed/float {worst:.3f}: goal (<= 1.03) {'met' if worst <= 1.03 else 'NOT met'}")
PY
