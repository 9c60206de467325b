#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# tools/ci/dev.sh - the one entry point for developers and CI.
#
#   ./tools/ci/dev.sh deps    install what the build needs (idempotent)
#   ./tools/ci/dev.sh test    deps, then the workflows test-float, test-double,
#                            test-float-small, test-imm-nosplit, test-fixed,
#                            test-fixed-radar
#                            (configure + build + ctest each; test-imm-nosplit:
#                            the IMM without the split models, configs/imm_nosplit.h;
#                            test-fixed: the stages converted to fixed point
#                            so far, docs/FIXED_POINT.md; test-fixed-radar:
#                            the same at a radar's scale, configs/firmware_fixed_radar.h),
#                            then the Python package (python-package below),
#                            then tools/ci/coverage.sh --check (gcov builds of
#                            the default and the firmware configuration; prints
#                            "coverage src/: lines L%, branches B%" for each),
#                            then tools/ci/ci-firmware.sh (cross builds, qemu,
#                            static analysis; each check one test), then
#                            tools/ci/ci-robustness.sh (ASan+UBSan, fuzz, soak);
#                            ends with the line "N passed, M failed"
#   ./tools/ci/dev.sh demo    deps, build host-float, 50 Monte Carlo runs of
#                            scenarios/crossing3.json (lm-ihpda beside lm-ipda):
#                            metric tables on stdout, plots in out/demo
#   ./tools/ci/dev.sh python-package
#                            pip install .[stonesoup,sim,test] into the venv
#                            build/pyvenv (PyPI only, pip's cache reused) and
#                            pytest python/tests/package against the mtt-track of
#                            build/host-float; ends with "N passed, M failed"
#   ./tools/ci/dev.sh --help
#
# Works from any directory.  deps needs root for apt (as on CI); elsewhere it
# only reports what is missing.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$ROOT"

DEB_PACKAGES=(cmake ninja-build gcc pkg-config libcjson-dev dpkg-dev)
PY_MODULES=(numpy scipy matplotlib pandas trackeval optuna distributed)  # import names
PY_PIP=(numpy scipy matplotlib pandas trackeval optuna "dask[distributed]")  # what pip installs
PY_DEBS=(python3-numpy python3-scipy python3-matplotlib python3-pandas python3-optuna python3-distributed)
WORKFLOWS=(test-float test-double test-float-small test-imm-nosplit test-fixed test-fixed-radar)

say() { printf 'dev.sh: %s\n' "$*"; }
die() { printf 'dev.sh: error: %s\n' "$*" >&2; exit 1; }

usage() {
  sed -n '3,/^set -euo/p' "${BASH_SOURCE[0]}" | sed '$d' | sed 's/^# \{0,1\}//'
}

is_root() { [[ "$(id -u)" -eq 0 ]]; }

# ---------------------------------------------------------------- deps
apt_updated=0
apt_update_once() {
  if ((apt_updated == 0)); then
    say "apt-get update"
    apt-get update -qq
    apt_updated=1
  fi
}

deb_installed() {
  [[ "$(dpkg-query -W -f='${Status}' "$1" 2>/dev/null || true)" == "install ok installed" ]]
}

deps_debian() {
  local missing=() p
  for p in "${DEB_PACKAGES[@]}"; do
    deb_installed "$p" || missing+=("$p")
  done
  if ((${#missing[@]} == 0)); then
    say "Debian packages present: ${DEB_PACKAGES[*]}"
    return 0
  fi
  if ! is_root || ! command -v apt-get >/dev/null 2>&1; then
    die "missing Debian packages: ${missing[*]} (run 'apt-get install ${missing[*]}' as root)"
  fi
  apt_update_once
  say "apt-get install ${missing[*]}"
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" >/dev/null
}

deps_other() {
  # No dpkg: check the commands and say what is missing.
  local c missing=()
  for c in cmake ninja cc pkg-config; do
    command -v "$c" >/dev/null 2>&1 || missing+=("$c")
  done
  ((${#missing[@]} == 0)) || die "missing tools: ${missing[*]} (and cJSON headers for tools/io/)"
}

check_cmake_version() {
  local v
  v="$(cmake --version | sed -n 's/^cmake version \([0-9][0-9]*\.[0-9][0-9]*\).*/\1/p')"
  local major="${v%%.*}" minor="${v#*.}"
  if ((major < 3 || (major == 3 && minor < 25))); then
    die "cmake >= 3.25 needed (CMakePresets.json version 6), found ${v:-unknown}"
  fi
}

deps_python() {
  command -v python3 >/dev/null 2>&1 || die "python3 not found"
  local mods
  mods="$(IFS=,; echo "${PY_MODULES[*]}")"
  if python3 -c "import $mods" 2>/dev/null; then
    say "python3 modules present: ${PY_MODULES[*]}"
    return 0
  fi
  say "python3 -m pip install ${PY_PIP[*]}"
  if PIP_DISABLE_PIP_VERSION_CHECK=1 PIP_ROOT_USER_ACTION=ignore \
       python3 -m pip install --quiet "${PY_PIP[@]}" && python3 -c "import $mods"; then
    return 0
  fi
  # A Debian system python refuses pip (PEP 668): take Debian's packages.
  if [[ "$(command -v python3)" == /usr/bin/python3 ]] && is_root && command -v apt-get >/dev/null 2>&1; then
    apt_update_once
    say "apt-get install ${PY_DEBS[*]}"
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
      "${PY_DEBS[@]}" >/dev/null
    # TrackEval has no Debian package: pip beside Debian's packages.
    python3 -c "import trackeval" 2>/dev/null || PIP_DISABLE_PIP_VERSION_CHECK=1 \
      python3 -m pip install --quiet --break-system-packages trackeval || true
    python3 -c "import $mods" && return 0
  fi
  die "could not install python modules ${PY_MODULES[*]}"
}

cmd_deps() {
  if command -v dpkg-query >/dev/null 2>&1; then
    deps_debian
  else
    deps_other
  fi
  check_cmake_version
  "$ROOT/tools/ci/setup-unity.sh"
  deps_python
}

# Runs a CI script (with the arguments after the second) that prints
# "<prefix>: N passed, M failed" and adds its
# counts to cmd_test's passed/failed (each of its checks counts as one
# test); a non-zero exit that reported no failure counts as one.
run_counted() {
  local prefix="$1" script="$2" before=$failed rc=0 line
  shift 2
  say "=== tools/ci/$(basename "$script") $*"
  "$script" "$@" 2>&1 | tee "$log" || rc=${PIPESTATUS[0]}
  line="$(grep -E "^$prefix: [0-9]+ passed, [0-9]+ failed\$" "$log" | tail -n1 || true)"
  # the failed checks by name, repeated at the very end (a CI log is often read from its tail)
  while IFS= read -r f; do failures+=("$f"); done < <(grep -E '^[a-z-]+: FAIL ' "$log" || true)
  if [[ -n "$line" ]]; then
    passed=$((passed + $(sed -E "s/^$prefix: ([0-9]+) passed.*/\1/" <<<"$line")))
    failed=$((failed + $(sed -E 's/.* ([0-9]+) failed$/\1/' <<<"$line")))
  fi
  if ((rc != 0)) && ((failed == before)); then
    failed=$((failed + 1))
  fi
}

# ---------------------------------------------------------------- python package
# The package (pyproject.toml) in a venv under build/, so the system Python
# is not touched: pip install .[stonesoup,sim,test] (scikit-build-core builds the
# library and mtt._core; pip's cache keeps the second run short), then
# pytest python/tests/package.  MTT_REQUIRE_ALL=1: a missing mtt-track or
# Stone Soup fails the tests instead of skipping them.  Adds pytest's counts
# to passed/failed (a failed install counts as one failure).
PY_VENV="$ROOT/build/pyvenv"
run_python_package() {
  local rc=0 line n
  say "=== python package: venv $PY_VENV, pip install .[stonesoup,sim,test], pytest"
  if [[ ! -x "$PY_VENV/bin/python" ]] && ! python3 -m venv "$PY_VENV"; then
    if is_root && command -v apt-get >/dev/null 2>&1; then
      apt_update_once
      DEBIAN_FRONTEND=noninteractive apt-get install -y -qq python3-venv >/dev/null || true
    fi
    rm -rf "$PY_VENV"
    python3 -m venv "$PY_VENV" || { say "cannot create a venv"; failed=$((failed + 1)); return 0; }
  fi
  if ! PIP_DISABLE_PIP_VERSION_CHECK=1 "$PY_VENV/bin/python" -m pip install --quiet \
      -C "build-dir=$ROOT/build/pip/{wheel_tag}" "$ROOT[stonesoup,sim,test]"; then
    say "pip install of the package failed"
    failed=$((failed + 1))
    return 0
  fi
  # From build/ so that python/ (the sources, without the compiled module)
  # is not on sys.path: the tests import the installed package.
  (cd "$ROOT/build" && MTT_REQUIRE_ALL=1 MTT_TRACK="$ROOT/build/host-float/tools/track/mtt-track" \
     "$PY_VENV/bin/python" -m pytest -q -p no:cacheprovider "$ROOT/python/tests/package") 2>&1 \
    | tee "$log" || rc=${PIPESTATUS[0]}
  # pytest's last line: "3 failed, 77 passed, 1 error in 9.1s" (any order)
  line="$(grep -E '[0-9]+ (passed|failed|errors?)' "$log" | tail -n1 || true)"
  for n in $(grep -oE '[0-9]+ passed' <<<"$line" | grep -oE '^[0-9]+' || true); do
    passed=$((passed + n))
  done
  local bad=0
  for n in $(grep -oE '[0-9]+ (failed|errors?)' <<<"$line" | grep -oE '^[0-9]+' || true); do
    bad=$((bad + n))
  done
  failed=$((failed + bad))
  if ((rc != 0)) && ((bad == 0)); then
    failed=$((failed + 1))  # pytest failed without counting (collection, no tests)
  fi
}

cmd_python_package() {
  local passed=0 failed=0 log
  log="$(mktemp "${TMPDIR:-/tmp}/mtt-dev-py.XXXXXX")"
  # shellcheck disable=SC2064
  trap "rm -f '$log'" EXIT
  [[ -x "$ROOT/build/host-float/tools/track/mtt-track" ]] || {
    cmake --preset host-float >/dev/null && cmake --build --preset host-float -j2 >/dev/null; }
  run_python_package
  echo "$passed passed, $failed failed"
  ((failed == 0))
}

# ---------------------------------------------------------------- test
cmd_test() {
  cmd_deps
  local passed=0 failed=0 wf log rc line total nfail
  local failures=()
  log="$(mktemp "${TMPDIR:-/tmp}/mtt-dev-test.XXXXXX")"
  # shellcheck disable=SC2064
  trap "rm -f '$log'" EXIT
  for wf in "${WORKFLOWS[@]}"; do
    say "=== cmake --workflow --preset $wf"
    rc=0
    cmake --workflow --preset "$wf" 2>&1 | tee "$log" || rc=${PIPESTATUS[0]}
    # ctest: "100% tests passed, 0 tests failed out of 12"
    #        "83% tests passed, 2 tests failed out of 12"
    line="$(grep -E 'tests passed, [0-9]+ tests? failed out of [0-9]+' "$log" | tail -n1 || true)"
    if [[ -n "$line" ]]; then
      nfail="$(sed -E 's/.* ([0-9]+) tests? failed out of ([0-9]+).*/\1/' <<<"$line")"
      total="$(sed -E 's/.* ([0-9]+) tests? failed out of ([0-9]+).*/\2/' <<<"$line")"
      passed=$((passed + total - nfail))
      failed=$((failed + nfail))
    fi
    while IFS= read -r f; do failures+=("$wf: $f"); done < <(grep -E '^[[:space:]]+[0-9]+ - .*\(' "$log" || true)
    if ((rc != 0)); then
      say "workflow $wf failed (exit $rc); stopping"
      if [[ -z "$line" ]]; then
        # configure or build failed: count it as one failure
        failed=$((failed + 1))
      fi
      echo "$passed passed, $failed failed"
      return "$rc"
    fi
  done
  # The Python package against the mtt-track of test-float.
  run_python_package
  # Line and branch coverage of src/ (docs/COVERAGE.md), both configurations.
  run_counted coverage "$ROOT/tools/ci/coverage.sh" --check
  # The firmware proof: cross builds, qemu, static analysis.
  run_counted ci-firmware "$ROOT/tools/ci/ci-firmware.sh"
  # Robustness: unit tests under ASan+UBSan, fuzz smoke runs, soak.
  run_counted robustness "$ROOT/tools/ci/ci-robustness.sh"
  local f
  for f in "${failures[@]}"; do say "failed: $f"; done
  echo "$passed passed, $failed failed"
  ((failed == 0))
}

# ---------------------------------------------------------------- demo
cmd_demo() {
  cmd_deps
  cmake --preset host-float
  cmake --build --preset host-float
  [[ -x build/host-float/tools/track/mtt-track ]] \
    || die "build/host-float/tools/track/mtt-track was not built"
  mkdir -p out/demo
  # The library's default mode beside the LM-IPDA of [S4], 50 runs (~10 s).
  PYTHONPATH=python python3 -m mtt_sim.mc --scenario scenarios/crossing3.json --runs 50 --jobs 2 \
    --assoc lm-ihpda lm-ipda --out out/demo --mtt-track build/host-float/tools/track/mtt-track
  say "demo output in $ROOT/out/demo"
}

case "${1:-}" in
  deps) cmd_deps ;;
  test) cmd_test ;;
  demo) cmd_demo ;;
  python-package) cmd_python_package ;;
  -h|--help|help) usage ;;
  "") usage; exit 2 ;;
  *) printf 'dev.sh: unknown command %s\n\n' "$1" >&2; usage >&2; exit 2 ;;
esac
