#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# tools/fuzz/fuzz-long.sh - a long, unseeded libFuzzer run of one harness, to find
# new bugs (docs/ROBUSTNESS.md).  CI's smoke runs are
# tools/ci/ci-robustness.sh; this is the run the execution totals come from.
#
#   ./tools/fuzz/fuzz-long.sh HARNESS SECONDS [WORKERS]
#
#   HARNESS   tracker | settings | detections
#   SECONDS   wall time of the run
#   WORKERS   parallel fuzzing processes (libFuzzer -fork; default 1)
#
# Build: build/fuzz-long, Clang, ASan+UBSan, -O2, edge coverage, with the
# library's comparison tracing left out (-fno-sanitize-coverage=trace-cmp).
# The numeric loops of the library compare indices with bounds on every
# iteration; tracing those took 60% of the time (perf) and guides nothing,
# so this build runs about 5x more inputs per second than the smoke build.
# The harness itself keeps comparison tracing: its decoder is where byte
# values matter.  For fuzz_tracker MTT_FUZZ_ONE_MODE=1 (one association mode
# per input, picked by the input's hash).
#
# Corpus: out/fuzz/corpus_<harness>, started from tools/fuzz/corpus/<harness> and
# grown by each run.  Crashes (kept going past with -ignore_crashes): written
# to out/fuzz/long-<harness>-crash-*; each one is a finding: reduce it, add it
# to tools/fuzz/regress/, fix it, list it in docs/ROBUSTNESS.md.
# Log: out/fuzz/long-<harness>-<UTC time>.log.  At the end it prints the
# executions, the crashes and the corpus size.
set -uo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$ROOT"

usage() { sed -n '3,30p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
if [[ "${1-}" == "-h" || "${1-}" == "--help" ]]; then usage; exit 0; fi
if (($# < 2 || $# > 3)); then usage >&2; exit 2; fi
H="$1"
SECONDS_RUN="$2"
WORKERS="${3-1}"
case "$H" in
  tracker|settings|detections) ;;
  *) echo "fuzz-long.sh: unknown harness '$H' (tracker, settings or detections)" >&2; exit 2 ;;
esac
if ! [[ "$SECONDS_RUN" =~ ^[1-9][0-9]*$ ]]; then
  echo "fuzz-long.sh: SECONDS must be a positive integer, not '$SECONDS_RUN'" >&2; exit 2
fi
if ! [[ "$WORKERS" =~ ^[1-9][0-9]*$ ]]; then
  echo "fuzz-long.sh: WORKERS must be a positive integer, not '$WORKERS'" >&2; exit 2
fi

# shellcheck source=tools/ci/clang-fuzz.sh
source "$ROOT/tools/ci/clang-fuzz.sh"
ensure_clang || { echo "fuzz-long.sh: no clang that links -fsanitize=fuzzer" >&2; exit 1; }

B="$ROOT/build/fuzz-long"
CC="$CLANG" cmake -S "$ROOT" -B "$B" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -g" \
  -DCMAKE_C_FLAGS="$SAN_FLAGS -fsanitize=fuzzer-no-link -fno-sanitize-coverage=trace-cmp" \
  -DMTT_WERROR=OFF -DMTT_BUILD_TESTS=OFF -DMTT_INSTALL=OFF >/dev/null \
  && cmake --build "$B" --target "fuzz_$H" >/dev/null \
  || { echo "fuzz-long.sh: building fuzz_$H in $B failed" >&2; exit 1; }

OUT="$ROOT/out/fuzz"
CORPUS="$OUT/corpus_$H"
mkdir -p "$CORPUS"
cp -n "$ROOT/tools/fuzz/corpus/$H/"* "$CORPUS/" 2>/dev/null || true
LOG="$OUT/long-$H-$(date -u +%Y%m%dT%H%M%SZ).log"
[[ "$H" == tracker ]] && export MTT_FUZZ_ONE_MODE=1

echo "fuzz-long: fuzz_$H for ${SECONDS_RUN}s, $WORKERS worker(s), corpus $CORPUS, log $LOG" >&2
# Fork mode even with one worker: a crash is recorded and the run goes on.
"$B/fuzz/fuzz_$H" -fork="$WORKERS" -ignore_crashes=1 -max_total_time="$SECONDS_RUN" \
  -timeout=20 -rss_limit_mb=2048 -artifact_prefix="$OUT/long-$H-" "$CORPUS" >"$LOG" 2>&1 &
pid=$!
trap 'kill "$pid" 2>/dev/null' INT TERM
# Progress: the newest fork-mode status line, once a minute (polling every
# 5 s, so that the end of the run is seen at once).
t=0
while kill -0 "$pid" 2>/dev/null; do
  sleep 5 & wait $! 2>/dev/null
  t=$((t + 5))
  if ((t % 60 == 0)); then
    line="$(grep -E '^#[0-9]+: ' "$LOG" | tail -n 1)"
    [[ -n "$line" ]] && echo "fuzz-long: $line" >&2
  fi
done
wait "$pid"
rc=$?

last="$(grep -E '^#[0-9]+: ' "$LOG" | tail -n 1)"
execs="$(sed -E 's/^#([0-9]+):.*/\1/' <<<"$last")"
crashes="$(sed -nE 's/.*oom\/timeout\/crash: ([0-9]+\/[0-9]+\/[0-9]+).*/\1/p' <<<"$last")"
echo "fuzz_$H: ${execs:-?} executions in ${SECONDS_RUN}s, oom/timeout/crash ${crashes:-?}," \
     "corpus $(find "$CORPUS" -type f | wc -l) inputs (exit $rc; log $LOG)"
[[ -z "$crashes" || "$crashes" == "0/0/0" ]]
