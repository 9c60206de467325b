# SPDX-License-Identifier: BSD-3-Clause
# tools/ci/clang-fuzz.sh - sourced by tools/ci/ci-robustness.sh and tools/fuzz/fuzz-long.sh:
# the sanitizer flags and a Clang that links libFuzzer (docs/ROBUSTNESS.md).
#
#   SAN_FLAGS       ASan+UBSan, no recovery, frame pointers, debug info
#   ensure_clang    sets CLANG to clang-14 or clang if it links
#                   -fsanitize=fuzzer,address,undefined; as root with apt-get,
#                   installs clang-14 libclang-rt-14-dev once when missing.
#                   Returns non-zero when there is none.

SAN_FLAGS='-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -g'
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"

CLANG=""
find_clang() {
  local c
  for c in clang-14 clang; do
    if command -v "$c" >/dev/null 2>&1 && echo 'int LLVMFuzzerTestOneInput(const char *d, unsigned long n){(void)d;(void)n;return 0;}' \
         | "$c" -x c -fsanitize=fuzzer,address,undefined -o /dev/null - >/dev/null 2>&1; then
      CLANG="$c"
      return 0
    fi
  done
  return 1
}
ensure_clang() {
  find_clang && return 0
  if [[ "$(id -u)" -eq 0 ]] && command -v apt-get >/dev/null 2>&1; then
    echo "installing clang-14 libclang-rt-14-dev" >&2
    apt-get update -qq >/dev/null 2>&1 || true
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
      clang-14 libclang-rt-14-dev >/dev/null 2>&1 || true
  fi
  find_clang
}
