#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The figure store: docs/reports/figures.tsv holds every figure that the
# docs cite in more than one place (firmware .text, stack, busiest frame,
# sizeof(mtt_tracker), coverage, headline results), one line each:
#
#     key<TAB>value<TAB>command that produces it
#
# (# starts a comment line; value is the plain number: 16260, 99.3, 0.244).
# In the Markdown a cited figure is marked, on one line:
#
#     <!-- fig:fw.m0plus_fixed.text -->16,260<!-- /fig -->
#
# The text between the markers is a number, with or without thousands
# separators ("," or a space); formatting (bold, units) goes outside. It
# matches the store when the store's value, rounded half up to the
# citation's decimals, equals it: a citation may round (12 for 12.4, 0.79
# for 0.787), never differ.
#
#   tools/ci/figures.sh --check [FILE.md ...]   every marked figure equals the store (CI, fast);
#                                               without files: every tracked *.md
#   tools/ci/figures.sh --update [FILE.md ...]  rewrite the marked spans from the store (keeps
#                                               each span's decimals and separators)
#   tools/ci/figures.sh --measure [fw] [sizes] [--log FILE]
#                                               re-measure the firmware figures (ci-firmware.sh,
#                                               slow: cross builds and qemu) and the host sizes
#                                               (sizes.sh) and write them into the store; --log
#                                               parses a saved ci-firmware.sh output instead of
#                                               running it. Then run --update.
#   tools/ci/figures.sh --list                  the store
#
# Exit 1 (naming file:line) on a mismatch, an unknown key or a broken marker.
set -euo pipefail
ROOT="$(git -C "$(dirname "$0")" rev-parse --show-toplevel)"
cd "$ROOT"
# the measuring scripts, beside this one
find_script() {
  [[ -f "tools/ci/$1" ]] && { echo "tools/ci/$1"; return 0; }
  echo "figures.sh: tools/ci/$1 not found" >&2
  return 1
}
# the checker, updater and parser (Python 3, standard library only)
py() {
  python3 - "$@" <<'PY'
import decimal, os, re, subprocess, sys

store_path, mode, args = sys.argv[1], sys.argv[2], sys.argv[3:]
MARK = re.compile(r"<!-- fig:([A-Za-z0-9_.-]+) -->(.*?)<!-- /fig -->")
OPEN = re.compile(r"<!-- fig:")
FENCE = re.compile(r"^\s{0,3}(```|~~~)")
CODE_SPAN = re.compile(r"(`+)(.+?)\1")
NUM = re.compile(r"^-?\d{1,3}(?:([, \u2009\u202f])\d{3})*(?:\.\d+)?$|^-?\d+(?:\.\d+)?$")


def read_store():
    rows, order = {}, []
    with open(store_path, encoding="utf-8") as f:
        for no, line in enumerate(f, 1):
            line = line.rstrip("\n")
            if not line or line.startswith("#"):
                continue
            parts = line.split("\t")
            if len(parts) < 2 or parts[0] == "key":
                continue
            key, value = parts[0], parts[1]
            cmd = parts[2] if len(parts) > 2 else ""
            rows[key] = [value, cmd]
            order.append(key)
    return rows, order


def write_store(rows, order):
    with open(store_path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    out, done = [], set()
    for line in lines:
        parts = line.split("\t")
        if line and not line.startswith("#") and len(parts) >= 2 and parts[0] in rows:
            k = parts[0]
            out.append("\t".join([k, rows[k][0], rows[k][1]]))
            done.add(k)
        else:
            out.append(line)
    for k in order:
        if k not in done:
            out.append("\t".join([k, rows[k][0], rows[k][1]]))
    with open(store_path, "w", encoding="utf-8") as f:
        f.write("\n".join(out) + "\n")


def parse_cited(text):
    """(Decimal, decimals, separator) of a cited span, or None."""
    m = NUM.match(text)
    if not m:
        return None
    sep = m.group(1) if m.lastindex else None
    plain = re.sub(r"[, \u2009\u202f]", "", text)
    decimals = len(plain.split(".")[1]) if "." in plain else 0
    return decimal.Decimal(plain), decimals, sep


def rounded(value, decimals):
    q = decimal.Decimal(1).scaleb(-decimals)
    return decimal.Decimal(value).quantize(q, rounding=decimal.ROUND_HALF_UP)


def fmt(value, decimals, sep):
    s = f"{rounded(value, decimals):f}"
    if sep:
        neg = s.startswith("-")
        ip, _, fp = s.lstrip("-").partition(".")
        groups = []
        while len(ip) > 3:
            groups.insert(0, ip[-3:])
            ip = ip[:-3]
        groups.insert(0, ip)
        s = ("-" if neg else "") + sep.join(groups) + ("." + fp if fp else "")
    return s


def md_files(paths):
    if paths:
        return paths
    out = subprocess.run(["git", "ls-files", "-co", "--exclude-standard", "-z", "--", "*.md"],
                         capture_output=True, check=True).stdout.decode()
    return sorted(p for p in out.split("\0") if p and os.path.isfile(p))


def check_or_update(update):
    rows, _ = read_store()
    bad, n, used, changed = 0, 0, set(), []
    for path in md_files(args):
        with open(path, encoding="utf-8") as f:
            lines = f.read().split("\n")
        dirty = False
        fence = None
        for i, line in enumerate(lines):
            fm = FENCE.match(line)
            if fm:                       # fenced code shows markers as text: not figures
                fence = fm.group(1) if fence is None else (None if fm.group(1) == fence else fence)
                continue
            if fence is not None or "<!-- fig:" not in line:
                continue
            spans = [(c.start(), c.end()) for c in CODE_SPAN.finditer(line)]
            if any(a <= o.start() < b for o in OPEN.finditer(line) for a, b in spans):
                continue                 # a marker quoted in a code span
            if len(OPEN.findall(line)) != len(MARK.findall(line)):
                print(f"{path}:{i + 1}: a fig marker without its <!-- /fig --> on the same line")
                bad += 1

            def one(m):
                nonlocal bad, n, dirty
                key, text = m.group(1), m.group(2)
                n += 1
                used.add(key)
                if key not in rows:
                    print(f"{path}:{i + 1}: {key}: not in {store_path}")
                    bad += 1
                    return m.group(0)
                cited = parse_cited(text)
                if cited is None:
                    print(f"{path}:{i + 1}: {key}: '{text}' is not a number")
                    bad += 1
                    return m.group(0)
                num, decimals, sep = cited
                value = rows[key][0]
                if rounded(value, decimals) == num:
                    return m.group(0)
                if update:
                    dirty = True
                    new = fmt(value, decimals, sep)
                    changed.append(f"{path}:{i + 1}: {key}: {text} -> {new}")
                    return f"<!-- fig:{key} -->{new}<!-- /fig -->"
                print(f"{path}:{i + 1}: {key}: cited {text}, store {value}")
                bad += 1
                return m.group(0)

            lines[i] = MARK.sub(one, line)
        if dirty:
            with open(path, "w", encoding="utf-8") as f:
                f.write("\n".join(lines))
    for c in changed:
        print("updated " + c)
    unused = sorted(set(rows) - used)
    if unused and not args:
        print("figures: not cited anywhere (kept in the store): " + " ".join(unused))
    if bad:
        print(f"figures: {bad} problem(s) in {n} marked figures")
        return 1
    print(f"figures: {n} marked figures, all equal to {store_path}"
          + (f" ({len(changed)} rewritten)" if changed else ""))
    return 0


PRESET_KEY = {"cortex-m4f": "m4f", "cortex-m4f-small": "m4f_small", "cortex-m0plus": "m0plus",
              "cortex-m0plus-small": "m0plus_small", "cortex-m0plus-fixed": "m0plus_fixed"}


def measure():
    rows, order = read_store()
    got = {}
    it = iter(args)
    for opt in it:
        path = next(it)
        text = open(path, encoding="utf-8", errors="replace").read()
        if opt == "--fw":
            for m in re.finditer(r"^(?:ci-firmware: )?(cortex-[\w-]+)( \(on-target parameter path\))?: "
                                 r"library in a firmware \(image difference\): \.text (\d+) .*?"
                                 r"sizeof\(mtt_tracker\) (\d+)", text, re.M):
                k = PRESET_KEY.get(m.group(1))
                if not k:
                    continue
                if m.group(2):
                    got[f"fw.{k}.text_params"] = m.group(3)
                else:
                    got[f"fw.{k}.text"] = m.group(3)
                    got[f"fw.{k}.sizeof"] = m.group(4)
            for m in re.finditer(r"^(?:ci-firmware: )?(cortex-[\w-]+): worst-case stack of "
                                 r"mtt_tracker_step: (\d+) bytes", text, re.M):
                k = PRESET_KEY.get(m.group(1))
                if k:
                    got[f"fw.{k}.stack"] = m.group(2)
            for m in re.finditer(r"^(?:ci-firmware: )?(cortex-[\w-]+): (IMM (?:run: )?)?busiest frame "
                                 r"\d+: \d+ ticks = (\d+) instructions", text, re.M):
                k = PRESET_KEY.get(m.group(1))
                if k:
                    got[f"fw.{k}.{'imm_busiest' if m.group(2) else 'busiest'}"] = m.group(3)
            a, b = got.get("fw.m0plus_fixed.busiest"), got.get("fw.m0plus_small.busiest")
            if a and b:
                got["fw.m0plus_fixed.ratio"] = f"{decimal.Decimal(a) / decimal.Decimal(b):.3f}"
        elif opt == "--sizes":
            for m in re.finditer(r"^(float|double)\s+tracks=(\d+)\s+meas=\d+\s+pairs=\d+\s+gated=\d+\s+"
                                 r"baselines=(\d) imm=(\d) sizeof\(mtt_tracker\) = (\d+) bytes", text, re.M):
                got[f"sizes.{m.group(1)}.t{m.group(2)}.b{m.group(3)}.imm{m.group(4)}"] = m.group(5)
    if not got:
        print("figures: nothing measured (no figure lines in the output)")
        return 1
    for k, v in sorted(got.items()):
        old = rows.get(k, [None])[0]
        if k not in rows:
            cmd = "tools/ci/ci-firmware.sh" if k.startswith("fw.") else "tools/ci/sizes.sh"
            rows[k] = [v, cmd]
            order.append(k)
        rows[k][0] = v
        print(f"{k}\t{v}" + ("" if old == v else f"\t(was {old})"))
    write_store(rows, order)
    print(f"figures: {len(got)} figures written to {store_path}; run tools/ci/figures.sh --update")
    return 0


if mode == "--list":
    rows, order = read_store()
    for k in order:
        print(f"{k}\t{rows[k][0]}")
    sys.exit(0)
sys.exit(measure() if mode == "--measure" else check_or_update(mode == "--update"))
PY
}

mode="${1:-}"
[[ -n "$mode" ]] || { sed -n '3,32p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }
shift
STORE=docs/reports/figures.tsv
case "$mode" in
  --check|--update|--list)
    py "$STORE" "$mode" "$@" ;;
  --measure)
    what=() log=""
    while [[ $# -gt 0 ]]; do
      case "$1" in
        fw|sizes) what+=("$1") ;;
        --log) log="$2"; shift ;;
        *) echo "figures.sh: unknown argument $1" >&2; exit 2 ;;
      esac
      shift
    done
    [[ ${#what[@]} -gt 0 ]] || what=(fw sizes)
    tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
    args=()
    for w in "${what[@]}"; do
      case "$w" in
        fw)
          if [[ -z "$log" ]]; then
            log="$tmp/fw.log"
            bash "$(find_script ci-firmware.sh)" 2>&1 | tee "$log" || true
          fi
          args+=(--fw "$log") ;;
        sizes)
          bash "$(find_script sizes.sh)" > "$tmp/sizes.log"
          args+=(--sizes "$tmp/sizes.log") ;;
      esac
    done
    py "$STORE" --measure "${args[@]}" ;;
  *) echo "figures.sh: unknown mode $mode (--check, --update, --measure, --list)" >&2; exit 2 ;;
esac
