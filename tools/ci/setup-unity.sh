#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# tools/ci/setup-unity.sh - put the Unity C test framework (ThrowTheSwitch) into
# .deps/unity/ without reaching GitHub.
#
# Unity is never committed.  Debian's cjson source package carries an upstream
# copy of Unity under tests/unity, and Debian's archive is reachable where
# GitHub is not, so this script:
#   1. does nothing if .deps/unity/unity.c already exists;
#   2. makes sure apt has a deb-src source (derived from the existing Debian
#      'deb' sources: deb822 /etc/apt/sources.list.d/*.sources or a classic
#      /etc/apt/sources.list), written to /etc/apt/sources.list.d/mtt-deb-src.*;
#   3. apt-get update (only when the source index is missing), installs
#      dpkg-dev if dpkg-source is missing;
#   4. apt-get source cjson in a temporary directory and copies Unity's
#      src/unity.c, unity.h, unity_internals.h and its license to .deps/unity/.
#
# Needs root (for apt).  Usage: tools/ci/setup-unity.sh [--force]
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
DEST="$ROOT/.deps/unity"
SRC_PKG="cjson"

say() { printf 'setup-unity: %s\n' "$*"; }
die() { printf 'setup-unity: error: %s\n' "$*" >&2; exit 1; }

case "${1:-}" in
  -h|--help)
    sed -n '3,19p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
    exit 0 ;;
  --force) rm -rf "$DEST" ;;
  "") ;;
  *) die "unknown argument '$1' (try --help)" ;;
esac

if [[ -f "$DEST/unity.c" && -f "$DEST/unity.h" && -f "$DEST/unity_internals.h" ]]; then
  if grep -q '^#include "../examples/unity_config.h"' "$DEST/unity_internals.h"; then
    say "$DEST is an unpatched copy from an older version of this script: replacing it"
    rm -rf "$DEST"
  else
    say "Unity already present in $DEST (nothing to do)"
    exit 0
  fi
fi

command -v apt-get >/dev/null 2>&1 \
  || die "apt-get not found. Get Unity yourself (https://github.com/ThrowTheSwitch/Unity, v2.6.0) and configure with -DUNITY_SOURCE_DIR=<dir>, or copy src/unity.c, unity.h, unity_internals.h to $DEST/"
if [[ "$(id -u)" -ne 0 ]]; then
  die "needs root for apt (adding a deb-src source, apt-get update). Re-run as root (e.g. sudo $0), or configure with -DUNITY_SOURCE_DIR=<dir containing unity.c>"
fi

APT_DIR=/etc/apt
LIST_D="$APT_DIR/sources.list.d"

# --- 1. a deb-src source --------------------------------------------------
have_deb_src() {
  local f
  for f in "$LIST_D"/*.sources; do
    [[ -f "$f" ]] || continue
    grep -Eq '^[[:space:]]*Types:.*\bdeb-src\b' "$f" && return 0
  done
  for f in "$APT_DIR/sources.list" "$LIST_D"/*.list; do
    [[ -f "$f" ]] || continue
    grep -Eq '^[[:space:]]*deb-src[[:space:]]' "$f" && return 0
  done
  return 1
}

added_src=0
if have_deb_src; then
  say "a deb-src source is already configured"
else
  # deb822: copy every stanza of the Debian .sources files with Types: deb-src.
  deb822=()
  if [[ -f "$LIST_D/debian.sources" ]]; then
    deb822=("$LIST_D/debian.sources")
  else
    for f in "$LIST_D"/*.sources; do
      [[ -f "$f" ]] || continue
      grep -Eqi '^[[:space:]]*URIs:.*debian' "$f" && deb822+=("$f")
    done
  fi
  if ((${#deb822[@]})); then
    out="$LIST_D/mtt-deb-src.sources"
    {
      echo "# Written by mtt tools/ci/setup-unity.sh: source packages of ${deb822[*]}"
      for f in "${deb822[@]}"; do
        # Keep URIs/Suites/Components/Signed-By, replace the Types line.
        sed -E 's/^([[:space:]]*Types:).*/\1 deb-src/' "$f"
        echo
      done
    } >"$out"
    say "wrote $out (deb-src derived from ${deb822[*]})"
    added_src=1
  fi
  # Classic one-line format.
  classic=()
  for f in "$APT_DIR/sources.list" "$LIST_D"/*.list; do
    [[ -f "$f" ]] || continue
    [[ "$f" == "$LIST_D/mtt-deb-src.list" ]] && continue
    grep -Eq '^[[:space:]]*deb[[:space:]].*debian' "$f" && classic+=("$f")
  done
  if ((${#classic[@]})); then
    out="$LIST_D/mtt-deb-src.list"
    {
      echo "# Written by mtt tools/ci/setup-unity.sh: source packages of ${classic[*]}"
      grep -hE '^[[:space:]]*deb[[:space:]].*debian' "${classic[@]}" \
        | sed -E 's/^[[:space:]]*deb[[:space:]]/deb-src /'
    } >"$out"
    say "wrote $out (deb-src derived from ${classic[*]})"
    added_src=1
  fi
  ((added_src)) || die "found no Debian 'deb' source in $APT_DIR/sources.list or $LIST_D/ to derive a deb-src source from"
fi

# --- 2. source index and dpkg-source ---------------------------------------
# (no 'apt-cache ... | grep -q': grep's early exit would fail the pipe under pipefail)
knows_src() { [[ "$(apt-cache showsrc "$SRC_PKG" 2>/dev/null)" == *"Package: $SRC_PKG"* ]]; }
if ((added_src)) || ! knows_src; then
  say "apt-get update"
  apt-get update -qq || die "apt-get update failed"
fi
knows_src || die "apt knows no source package '$SRC_PKG' even after apt-get update"

if ! command -v dpkg-source >/dev/null 2>&1; then
  say "installing dpkg-dev (for dpkg-source)"
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq dpkg-dev >/dev/null \
    || die "could not install dpkg-dev"
fi

# --- 3. fetch cjson's source and take Unity out of it ----------------------
tmp="$(mktemp -d "${TMPDIR:-/tmp}/mtt-unity.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT
say "apt-get source $SRC_PKG (in $tmp)"
# apt downloads as root unsandboxed when _apt cannot write to $tmp: make it writable.
chmod 0777 "$tmp"
(cd "$tmp" && apt-get source -qq "$SRC_PKG" >"$tmp/apt-source.log" 2>&1) \
  || { cat "$tmp/apt-source.log" >&2; die "apt-get source $SRC_PKG failed"; }

unity_c="$(find "$tmp" -path '*/tests/unity/src/unity.c' -print -quit)"
if [[ -z "$unity_c" ]]; then
  unity_c="$(find "$tmp" -path '*/unity/*' -name unity.c -print -quit)"
fi
[[ -n "$unity_c" ]] || die "no tests/unity/src/unity.c in the $SRC_PKG source package"
usrc="$(dirname "$unity_c")"
uroot="$(dirname "$usrc")"
for f in unity.h unity_internals.h; do
  [[ -f "$usrc/$f" ]] || die "$f missing next to $unity_c"
done

# Stage next to DEST and move into place, so a failure never leaves a
# half-filled .deps/unity that a later run would take as complete.
stage="$tmp/stage"
mkdir -p "$stage"
cp "$usrc/unity.c" "$usrc/unity.h" "$usrc/unity_internals.h" "$stage/"
# cJSON's copy of Unity includes its example config from unity_internals.h;
# restore upstream's opt-in form (the build defines UNITY_INCLUDE_DOUBLE itself).
patched=0
if grep -q '^#include "../examples/unity_config.h"' "$stage/unity_internals.h"; then
  sed -i 's|^#include "../examples/unity_config.h"|#ifdef UNITY_INCLUDE_CONFIG_H\n#include "unity_config.h"\n#endif|' \
    "$stage/unity_internals.h"
  patched=1
fi
lic=""
for f in LICENSE.txt LICENSE license.txt docs/license.txt COPYING; do
  if [[ -f "$uroot/$f" ]]; then lic="$uroot/$f"; break; fi
done
if [[ -n "$lic" ]]; then
  cp "$lic" "$stage/LICENSE.txt"
else
  say "warning: no license file found beside Unity in $uroot (Unity is MIT licensed)"
fi
ver=""
if [[ -f "$uroot/release/version.info" ]]; then
  ver="$(head -n1 "$uroot/release/version.info" | tr -d '[:space:]')"
fi
if [[ -z "$ver" ]]; then
  ver="$( (grep -E '#define[[:space:]]+UNITY_VERSION_(MAJOR|MINOR|BUILD)[[:space:]]' "$stage/unity.h" || true) \
          | awk '{print $3}' | paste -sd. -)"
fi
rel="${unity_c#"$tmp"/}"
srcname="${rel%%/*}"   # cjson-<version>
{
  echo "Unity ${ver:-(unknown version)} (https://github.com/ThrowTheSwitch/Unity, MIT license)"
  echo "copied by tools/ci/setup-unity.sh from Debian source package ${srcname:-$SRC_PKG}, ${uroot#"$tmp"/}"
  if ((patched)); then
    echo "unity_internals.h: '#include \"../examples/unity_config.h\"' (a cJSON change) replaced by"
    echo "upstream's '#ifdef UNITY_INCLUDE_CONFIG_H / #include \"unity_config.h\" / #endif'"
  fi
} >"$stage/SOURCE.txt"
mkdir -p "$(dirname "$DEST")"
rm -rf "$DEST"
mv "$stage" "$DEST"
say "copied Unity ${ver:-(unknown version)} from Debian source ${srcname:-$SRC_PKG} (${uroot#"$tmp"/}) to $DEST:"
for f in "$DEST"/*; do printf '  %s\n' "$(basename "$f")"; done
