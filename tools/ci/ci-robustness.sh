#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# tools/ci/ci-robustness.sh - the robustness step of CI (docs/ROBUSTNESS.md).
#
#   ./tools/ci/ci-robustness.sh [--fuzz-seconds N] [--soak-frames N]
#
#   1. installs clang-14 and libclang-rt-14-dev when missing (root, apt-get
#      update at most once; idempotent)
#   2. the whole unit test suite under ASan+UBSan (build/robust-asan, gcc),
#      with the soak and fuzz replays it registers
#   3. a fuzz smoke run of each libFuzzer harness (build/robust-fuzz, clang,
#      ASan+UBSan), N seconds each (default 60), from tools/fuzz/corpus/<harness>
#   4. a soak of N frames (default 100000) under ASan+UBSan, every mode
#
# Prints "robustness: N passed, M failed" at the end (each step is one
# check) and exits non-zero if any step failed.  Budget: about 6 minutes on
# 2 cores with the defaults.
set -uo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$ROOT"

FUZZ_SECONDS=60
SOAK_FRAMES=100000
while (($#)); do
  case "$1" in
    --fuzz-seconds) FUZZ_SECONDS="$2"; shift 2 ;;
    --soak-frames) SOAK_FRAMES="$2"; shift 2 ;;
    -h|--help) sed -n '3,18p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "ci-robustness.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done

say() { printf 'ci-robustness: %s\n' "$*"; }
passed=0
failed=0
ok() { passed=$((passed + 1)); say "PASS $*"; }
failed_names=()
bad() { failed=$((failed + 1)); failed_names+=("$*"); say "FAIL $*"; }

# Modes to leave out of the fuzz smoke run while a finding is open
# (docs/ROBUSTNESS.md); none are open.
export MTT_FUZZ_SKIP_MODES="${MTT_FUZZ_SKIP_MODES-}"

# shellcheck source=tools/ci/clang-fuzz.sh
source "$ROOT/tools/ci/clang-fuzz.sh"

# ---------------------------------------------------------------- deps
ensure_clang || say "no clang with -fsanitize=fuzzer: the fuzz smoke runs will fail"

# ---------------------------------------------------------------- 1. unit tests under ASan+UBSan
ASAN_DIR="$ROOT/build/robust-asan"
say "=== unit tests under ASan+UBSan ($ASAN_DIR)"
log="$(mktemp "${TMPDIR:-/tmp}/mtt-robust.XXXXXX")"
trap 'rm -f "$log"' EXIT
if cmake -S "$ROOT" -B "$ASAN_DIR" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
     -DCMAKE_C_FLAGS="$SAN_FLAGS" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g" \
     -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
     -DMTT_WERROR=OFF -DMTT_INSTALL=OFF >"$log" 2>&1 \
   && cmake --build "$ASAN_DIR" >>"$log" 2>&1; then
  # symbols.*: the sanitizer runtime's symbols are not the library's.
  if (cd "$ASAN_DIR" && ctest --output-on-failure -j2 -E '^symbols\.') 2>&1 | tee -a "$log" | tail -n 3; then
    ok "unit tests under ASan+UBSan"
  else
    grep -E 'Failed|\*\*\*' "$log" | head -n 20
    bad "unit tests under ASan+UBSan"
  fi
else
  tail -n 30 "$log"
  bad "ASan+UBSan build"
fi

# ---------------------------------------------------------------- 2. fuzz smoke runs
FUZZ_DIR="$ROOT/build/robust-fuzz"
say "=== libFuzzer smoke runs, seed 1, about ${FUZZ_SECONDS}s each ($FUZZ_DIR)"
if [[ -n "$CLANG" ]] && CC="$CLANG" cmake -S "$ROOT" -B "$FUZZ_DIR" -G Ninja \
     -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g" \
     -DCMAKE_C_FLAGS="$SAN_FLAGS -fsanitize=fuzzer-no-link" \
     -DMTT_WERROR=OFF -DMTT_BUILD_TESTS=OFF -DMTT_INSTALL=OFF >"$log" 2>&1 \
   && cmake --build "$FUZZ_DIR" >>"$log" 2>&1; then
  for h in tracker settings detections; do
    exe="$FUZZ_DIR/tools/fuzz/fuzz_$h"
    if [[ ! -x "$exe" ]]; then
      bad "fuzz_$h was not built"
      continue
    fi
    work="$FUZZ_DIR/ci-work/$h"
    art="$FUZZ_DIR/ci-artifacts/$h/"
    mkdir -p "$work" "$art"
    # A fresh copy of the committed corpus each time: the smoke run is
    # reproducible from the tree, not from an earlier run's findings.
    rm -rf "${work:?}"/*
    cp "$ROOT/tools/fuzz/corpus/$h/"* "$work/" 2>/dev/null || true
    # A fixed seed and a fixed number of executions (about FUZZ_SECONDS
    # here): CI replays the same inputs every time, so it passes or fails
    # on the code, not on the machine's speed; -max_total_time only caps a
    # slow machine.  Long, unseeded runs are for finding new bugs
    # (docs/ROBUSTNESS.md).
    case "$h" in
      tracker) runs=$((FUZZ_SECONDS * 70)) ;;
      settings) runs=$((FUZZ_SECONDS * 25000)) ;;
      *) runs=$((FUZZ_SECONDS * 15000)) ;;
    esac
    if "$exe" -seed=1 -runs="$runs" -max_total_time=$((FUZZ_SECONDS * 3)) -timeout=20 \
         -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$art" "$work" >"$log" 2>&1; then
      execs="$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")"
      ok "fuzz_$h: ${execs:-?} executions (seed 1, at most $runs)"
    else
      grep -v '^#' "$log" | tail -n 40
      # the finding itself, so that a CI log alone reproduces it
      for f in "$art"*; do
        [[ -f "$f" ]] && say "artifact $(basename "$f") ($(wc -c <"$f") bytes), base64: $(base64 -w0 "$f" | head -c 8192)"
      done
      bad "fuzz_$h (artifacts in $art)"
    fi
  done
else
  [[ -n "$CLANG" ]] && tail -n 30 "$log"
  bad "libFuzzer build (clang: ${CLANG:-none})"
fi

# ---------------------------------------------------------------- 3. soak under sanitizers
say "=== soak: $SOAK_FRAMES frames, every mode, ASan+UBSan"
if [[ -x "$ASAN_DIR/tools/fuzz/mtt-soak" ]] \
   && "$ASAN_DIR/tools/fuzz/mtt-soak" --frames "$SOAK_FRAMES" --seed 1 --mode all \
        --progress $((SOAK_FRAMES / 4 > 0 ? SOAK_FRAMES / 4 : 1)); then
  ok "soak $SOAK_FRAMES frames"
else
  bad "soak $SOAK_FRAMES frames"
fi

for f in "${failed_names[@]}"; do say "FAIL $f"; done # again at the end: CI logs are read from the tail
echo "robustness: $passed passed, $failed failed"
((failed == 0))
