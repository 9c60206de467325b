#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# tools/ci/fx-cov-mc.sh - float against fixed point on Cartesian detections
# with a covariance per detection (ALGORITHMS.md §3.1, docs/FIXED_POINT.md
# §5): radar_quickstart's detections converted by the user to x, y
# (sensor.output xy), each given the conversion's linearised R by
# tools/ci/mtt_track_cov.py, tracked by build/fx-float-radar's mtt-track
# (built here, as tools/ci/fx-mc.sh does) and build/host-fixed-radar's, with
# CV motion and lm_ihpda_variant s0 on both; "one R" runs each binary on the
# same files without the covariances.  Prints GOSPA per row and mode.
#
#   tools/ci/fx-cov-mc.sh [RUNS]      (default 1; output under build/fx-cov-mc/)
#
# FX_COV_MOTION=imm: the IMM that max_accel derives (both builds) instead of
# CV (output under build/fx-cov-mc-imm/).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$ROOT"
. tools/ci/fx_build.sh
RUNS="${1:-1}"
MOTION="${FX_COV_MOTION:-cv}"
OUT="$ROOT/build/fx-cov-mc"
[[ "$MOTION" == cv ]] || OUT="$ROOT/build/fx-cov-mc-$MOTION"
declare -A BIN=([float]="$ROOT/build/fx-float-radar/tools/track/mtt-track"
  [fixed]="$ROOT/build/host-fixed-radar/tools/track/mtt-track")
fx_float_radar "$ROOT"
[[ -x "${BIN[fixed]}" ]] || { echo "fx-cov-mc: ${BIN[fixed]} missing (build the host-fixed-radar preset)" >&2; exit 2; }
mkdir -p "$OUT"
for b in float fixed; do
  for r in cov one; do
    tr="${BIN[$b]}"
    [[ $r == cov ]] && tr="$ROOT/tools/ci/mtt_track_cov.py"
    MTT_TRACK="${BIN[$b]}" MTT_COV_RADAR="0 0 50 0.002617993877991494" PYTHONPATH=python \
      python3 -m mtt_sim.mc --scenario scenarios/recorded/radar_quickstart.json --runs "$RUNS" \
      --out "$OUT/$b-$r" --mtt-track "$tr" --tracker mtt-track --assoc lm-ihpda ipda \
      --set sensor.output='"xy"' --set tracker.measurement='"cartesian"' --set 'tracker.meas_sigma=[100,100]' \
      --set tracker.clutter_density=3.25e-9 --set tracker.motion="\"$MOTION\"" --set tracker.lm_ihpda_variant=s0 \
      --no-plots --jobs 2 >"$OUT/$b-$r.log" 2>&1
    printf '%-5s %-3s ' "$b" "$r"
    grep -E "GOSPA mean per scan" "$OUT/$b-$r.log" | sed 's/.*GOSPA mean per scan (p=1, a=2, c=500) *//'
  done
done
