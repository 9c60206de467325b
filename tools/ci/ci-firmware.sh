#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# tools/ci/ci-firmware.sh - the firmware proof (docs/FIRMWARE.md), one CI step.
#
#   1. installs what it needs when missing (Debian, as root; apt-get update
#      at most once): gcc-arm-none-eabi libnewlib-arm-none-eabi
#      qemu-system-arm cppcheck clang-tidy
#   2. per cross preset (cortex-m4f, cortex-m4f-small, cortex-m0plus,
#      cortex-m0plus-small): configure + build (one check), ctest (each test
#      one check: no double helpers, qemu run, host comparison; with the IMM,
#      cortex-m4f and cortex-m0plus, the IMM run's qemu run and comparison
#      too), then prints (instructions: of the CV run and the IMM run)
#      the figures: library .text/.data/.bss in a firmware, sizeof(mtt_tracker),
#      worst-case stack of mtt_tracker_step, instructions per frame
#   3. cortex-m0plus-fixed (docs/FIXED_POINT.md): the fixed-point library,
#      built with link-time optimisation (-flto), and the firmware example;
#      checks: build, no float or double helper in the linked images (with
#      -flto libmtt.a holds GCC's IR, not code: every check and figure is
#      taken on the images), cppcheck of the fixed-point sources; then as in
#      2 (ctest with the no-float and no-double-helper checks, the same
#      figures; the stack from the link's call graph)
#   4. cppcheck and clang-tidy on src/, float and double (one check each)
#
# Ends with "ci-firmware: N passed, M failed" (tools/ci/dev.sh adds it to its
# total) and exits non-zero when anything failed.  The figures are
# benchmark figures, not checks: docs/FIRMWARE.md records them.
set -uo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$ROOT"

DEB_PACKAGES=(gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm cppcheck clang-tidy)
PRESETS=(cortex-m4f cortex-m4f-small cortex-m0plus cortex-m0plus-small)
FWCHECK=(python3 "$ROOT/tools/fw-measure/fwcheck.py")
passed=0
failed=0
failures=()

say() { printf 'ci-firmware: %s\n' "$*"; }
pass() { passed=$((passed + 1)); say "PASS $1"; }
fail() { failed=$((failed + 1)); failures+=("$1"); say "FAIL $1"; }
# check NAME CMD...: run CMD, count it as one check.
check() {
  local name="$1"; shift
  if "$@"; then pass "$name"; else fail "$name"; fi
}

# ---------------------------------------------------------------- deps
deps() {
  local missing=() p
  for p in "${DEB_PACKAGES[@]}"; do
    [[ "$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)" == "install ok installed" ]] \
      || missing+=("$p")
  done
  if ((${#missing[@]} == 0)); then
    say "Debian packages present: ${DEB_PACKAGES[*]}"
    return 0
  fi
  if [[ "$(id -u)" -ne 0 ]] || ! command -v apt-get >/dev/null 2>&1; then
    say "missing Debian packages: ${missing[*]} (run 'apt-get install ${missing[*]}' as root)"
    return 1
  fi
  say "apt-get update; apt-get install ${missing[*]}"
  apt-get update -qq || return 1
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" >/dev/null
}

# ---------------------------------------------------------------- cross builds
# ctest in build dir $1: each test is one check.
ctest_checks() {
  local preset="$1" log line nfail total
  log="$(mktemp "${TMPDIR:-/tmp}/mtt-fw-ctest.XXXXXX")"
  ctest --preset "$preset" 2>&1 | tee "$log"
  line="$(grep -E 'tests passed, [0-9]+ tests? failed out of [0-9]+' "$log" | tail -n1 || true)"
  rm -f "$log"
  if [[ -z "$line" ]]; then
    fail "$preset: ctest ran no test"
    return
  fi
  nfail="$(sed -E 's/.* ([0-9]+) tests? failed out of ([0-9]+).*/\1/' <<<"$line")"
  total="$(sed -E 's/.* ([0-9]+) tests? failed out of ([0-9]+).*/\2/' <<<"$line")"
  passed=$((passed + total - nfail))
  failed=$((failed + nfail))
  ((nfail == 0)) || failures+=("$preset: $nfail ctest(s)")
  say "$preset: ctest $((total - nfail)) passed, $nfail failed"
}

figures() {
  local preset="$1" b="$ROOT/build/$1"
  "${FWCHECK[@]}" size --label "$preset" --size arm-none-eabi-size --nm arm-none-eabi-nm \
    --lib "$b/examples/firmware/mtt-fw-size-lib.elf" --base "$b/examples/firmware/mtt-fw-size-base.elf" \
    --archive "$b/libmtt.a" --text-limit 16384 || return 1
  # the fixed-point build loads parameters prepared on the host; the same
  # figure with the on-target parameter path (mtt_params_check, ... in the image)
  if [[ -f "$b/examples/firmware/mtt-fw-size-params.elf" ]]; then
    "${FWCHECK[@]}" size --label "$preset (on-target parameter path)" --size arm-none-eabi-size \
      --nm arm-none-eabi-nm --lib "$b/examples/firmware/mtt-fw-size-params.elf" \
      --base "$b/examples/firmware/mtt-fw-size-base.elf" || return 1
  fi
  # -flto: the call graph of the size image's link (size_main.c stays out
  # of it, so mtt_tracker_step is a function of its own there)
  local lto=()
  grep -q '^CMAKE_INTERPROCEDURAL_OPTIMIZATION:BOOL=ON' "$b/CMakeCache.txt" && lto=(--lto)
  "${FWCHECK[@]}" stack --label "$preset" --build "$b" --src "$ROOT/src" "${lto[@]}" \
    --elf "$b/examples/firmware/mtt-fw-size-lib.elf" --objdump arm-none-eabi-objdump --limit 1024 || return 1
  local fl=()
  [[ "$preset" == "$FIXED_PRESET" ]] && fl=(--float) # no float helper either
  "${FWCHECK[@]}" doubles "${fl[@]}" --nm arm-none-eabi-nm "$b/examples/firmware/mtt-fw.elf" || return 1
  # M4F: the figure of record; M0+: ARMv6-M code on qemu's Cortex-M3 (AN385).
  # A library with the IMM (MTT_WITH_IMM) also runs the scene with
  # motion = imm (mtt-fw-imm.elf): its busiest frame is required and printed.
  local imm=()
  # (grep without -q reads all of nm's output: no SIGPIPE under pipefail)
  if arm-none-eabi-nm -g --defined-only "$b/libmtt.a" | grep -w mtt_imm_predict_track >/dev/null; then
    imm=(--out "$b/examples/firmware/fw-qemu-imm.txt" --imm)
  fi
  "${FWCHECK[@]}" insns --label "$preset" --out "$b/examples/firmware/fw-qemu.txt" "${imm[@]}" || return 1
}

cross() {
  local preset
  for preset in "${PRESETS[@]}"; do
    say "=== $preset"
    if ! { cmake --preset "$preset" >/dev/null && cmake --build --preset "$preset"; }; then
      fail "$preset: configure + build"
      continue
    fi
    pass "$preset: configure + build"
    ctest_checks "$preset"
    say "--- $preset figures"
    figures "$preset" || fail "$preset: figures"
  done
}

# ---------------------------------------------------------------- fixed point
# The fixed-point build (docs/FIXED_POINT.md): cortex-m0plus-fixed, with
# link-time optimisation.  One check that it builds, one that no float or
# double helper (__aeabi_f*, __aeabi_d*, libgcc's __*sf*/__*df*) is linked
# into the images, one cppcheck of the fixed-point sources; then the
# firmware example's ctest and figures.  The helper check reads the linked
# images' symbols (defined or not): with -flto -fno-fat-lto-objects the
# objects of libmtt.a hold GCC's IR, in which a float operation is not yet a
# call, so `nm -u libmtt.a` would find nothing whatever the code does.
FIXED_PRESET=cortex-m0plus-fixed
fixed_helpers() {
  local elf found=""
  for elf in "$@"; do
    [[ -f "$elf" ]] || { say "no image $elf"; return 1; }
    found+="$(arm-none-eabi-nm "$elf" | awk '{print $NF}' \
      | grep -E '^__aeabi_[fd]|^__[a-z]+[sd]f[0-9]?$|^__[a-z]+[sd]f[a-z]+[0-9]?$' | sort -u | tr '\n' ' ' || true)"
  done
  if [[ -n "$found" ]]; then
    say "float/double helpers linked: $found"
    return 1
  fi
}
fixed_cppcheck() {
  local b="$ROOT/build/$FIXED_PRESET" stages f files=()
  stages="$(sed -n 's/^MTT_FIXED_STAGES:[A-Z]*=//p' "$b/CMakeCache.txt")"
  for f in ${stages//;/ }; do files+=("src/$f.c"); done
  local cfg rc=0
  # the firmware configuration, and the radar scale's (per-detection R, the IMM)
  for cfg in firmware_fixed.h firmware_fixed_radar.h; do
    cppcheck --enable=warning,style,performance,portability --error-exitcode=1 --std=c99 \
      --inline-suppr --quiet --suppress=variableScope \
      --template='{file}:{line}: {severity}: {id}: {message}' \
      -I include -I src -DMTT_REAL_FIXED "-DMTT_USER_CONFIG=\"$ROOT/configs/$cfg\"" \
      "${files[@]}" || rc=1
  done
  return "$rc"
}
fixed() {
  local b="$ROOT/build/$FIXED_PRESET"
  say "=== $FIXED_PRESET (fixed point, -flto)"
  if ! { cmake --preset "$FIXED_PRESET" >/dev/null && cmake --build --preset "$FIXED_PRESET"; }; then
    fail "$FIXED_PRESET: configure + build"
    return
  fi
  pass "$FIXED_PRESET: configure + build"
  # the size image references every public function; mtt-fw.elf is the example
  check "$FIXED_PRESET: no float or double helper in the images" fixed_helpers \
    "$b/examples/firmware/mtt-fw-size-lib.elf" "$b/examples/firmware/mtt-fw.elf"
  check "$FIXED_PRESET: cppcheck of the converted stages" fixed_cppcheck
  # The firmware example: its ctest (no double and no float helper in the
  # images, the qemu run, the comparison with the fixed-point host build) and
  # the same figures as the other presets (.text, stack, busiest frame).
  if [[ -f "$b/examples/firmware/mtt-fw.elf" ]]; then
    ctest_checks "$FIXED_PRESET"
    say "--- $FIXED_PRESET figures"
    figures "$FIXED_PRESET" || fail "$FIXED_PRESET: figures"
  else
    say "$FIXED_PRESET: no firmware example yet (the pipeline is not converted: MTT_FIXED_COMPLETE OFF)"
  fi
}

# ---------------------------------------------------------------- static analysis
# Both: the library's include paths; the float build and the double build.
# cppcheck checks the configuration given (-D/-U) and nothing else;
# MTT_USER_CONFIG stays undefined (it names a header of the user's), and so
# does MTT_REAL_FIXED (the fixed-point build: its converted stages are
# checked by the cortex-m0plus-fixed step).
# --suppress=variableScope: the library declares its locals at the top of a
# block (one style through the code, for reading on paper); narrowing a
# scope changes no behaviour, so this style rule is off.
run_cppcheck() {
  local real="$1"
  cppcheck --enable=warning,style,performance,portability --error-exitcode=1 --std=c99 \
    --inline-suppr --quiet --suppress=variableScope \
    --template='{file}:{line}: {severity}: {id}: {message}' \
    -I include -I src -UMTT_USER_CONFIG -UMTT_REAL_FIXED "$real" src/
}

# -bugprone-easily-swappable-parameters: a rule about the shape of an API
# (adjacent parameters of one type): the comparators of mtt_sort take
# (a, b, ctx) by contract, the math helpers take several scalars; changing
# signatures is not a finding's minimal fix.
TIDY_CHECKS='-*,bugprone-*,cert-*,clang-analyzer-*,-bugprone-easily-swappable-parameters'
# bugprone-signed-char-misuse (= cert-str34-c) is about a char that holds a
# character (EOF confusion); int8_t declares a small signed integer, so
# that typedef is configured out (the check's CharTypdefsToIgnore option).
TIDY_CONFIG='{CheckOptions: [{key: bugprone-signed-char-misuse.CharTypdefsToIgnore, value: int8_t}, {key: cert-str34-c.CharTypdefsToIgnore, value: int8_t}]}'
run_clang_tidy() {
  local rc=0 f
  for f in src/*/*.c; do
    clang-tidy --quiet -checks="$TIDY_CHECKS" -config="$TIDY_CONFIG" -warnings-as-errors='*' "$f" -- \
      -std=c99 -Iinclude -Isrc "$@" 2>/dev/null || rc=1
  done
  return "$rc"
}

# The library at -O3 (CMake's Release, which the presets do not use): its
# inlining finds warnings -O2 does not (a maybe-uninitialized until 88e5f51).
run_o3() {
  local rc=0 f
  for f in src/*/*.c; do
    cc -std=c99 -O3 -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Wdouble-promotion -Werror \
      -Iinclude -Isrc "$@" -c "$f" -o /dev/null || rc=1
  done
  return "$rc"
}

# ---------------------------------------------------------------- main
start=$SECONDS
if ! deps; then
  fail "dependencies"
else
  pass "dependencies"
  cross
  fixed
  say "=== cppcheck (float, double)"
  check "cppcheck float" run_cppcheck -UMTT_REAL_DOUBLE
  check "cppcheck double" run_cppcheck -DMTT_REAL_DOUBLE
  say "=== clang-tidy (float, double)"
  check "clang-tidy float" run_clang_tidy
  check "clang-tidy double" run_clang_tidy -DMTT_REAL_DOUBLE
  say "=== gcc -O3 -Werror (float, double)"
  check "gcc -O3 float" run_o3
  check "gcc -O3 double" run_o3 -DMTT_REAL_DOUBLE
fi
say "done in $((SECONDS - start)) s"
if ((failed > 0)); then
  say "failed: ${failures[*]}"
fi
echo "ci-firmware: $passed passed, $failed failed"
((failed == 0))
