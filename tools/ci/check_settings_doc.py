#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Check that docs/FORMATS.md's settings table is `mtt-track --list-settings`.

    tools/ci/check_settings_doc.py --mtt-track build/host-float/tools/track/mtt-track \
        --doc docs/FORMATS.md

`mtt-track --list-settings` prints the settings table from the library's
parameter table (mtt_params_info), header `| key | type | range | default |
meaning | tier |`.  The settings table of docs/FORMATS.md is the first
Markdown table whose header starts `| key | type | range | default | meaning`
and names only columns of that output (so it may leave out `tier`, which
docs/CONFIGURATION.md groups by: tools/ci/gen_configuration.py).  Its rows
must equal the output's, in those columns, one to one and in order (blanks
around cells do not count).  Exit 0 when they match; 1 with the differing
rows otherwise.
"""
import argparse
import subprocess
import sys

HEADER = ["key", "type", "range", "default", "meaning"]


def cells(line):
    """The cells of one Markdown table row, stripped."""
    line = line.strip()
    if not (line.startswith("|") and line.endswith("|")):
        return None
    return [c.strip() for c in line[1:-1].split("|")]


def table(lines, columns=None):
    """(header, rows) of the first table whose header starts with HEADER
    (and, given columns, names only those), or (None, None)."""
    for i, line in enumerate(lines):
        head = cells(line)
        if head is None or head[:len(HEADER)] != HEADER:
            continue
        if columns is not None and not set(head) <= set(columns):
            continue
        rows = []
        for row in lines[i + 2:]:  # i + 1 is the |---| separator
            c = cells(row)
            if c is None:
                break
            rows.append(c)
        return head, rows
    return None, None


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--mtt-track", required=True)
    ap.add_argument("--doc", required=True)
    a = ap.parse_args()

    out = subprocess.run([a.mtt_track, "--list-settings"], check=True,
                         capture_output=True, text=True).stdout
    out_head, out_rows = table(out.splitlines())
    if not out_rows:
        print("check_settings_doc: mtt-track --list-settings printed no table")
        return 1
    with open(a.doc, encoding="utf-8") as f:
        head, have = table(f.read().splitlines(), out_head)
    if have is None:
        print(f"check_settings_doc: {a.doc} has no table with the header "
              f"'| {' | '.join(HEADER)} |' (and only columns of "
              f"'| {' | '.join(out_head)} |')")
        return 1
    pick = [out_head.index(c) for c in head]
    want = [[r[j] if j < len(r) else "" for j in pick] for r in out_rows]
    bad = 0
    for k in range(max(len(want), len(have))):
        w = want[k] if k < len(want) else None
        h = have[k] if k < len(have) else None
        if w != h:
            bad += 1
            print(f"check_settings_doc: row {k + 1} differs:")
            print(f"  mtt-track: {'| ' + ' | '.join(w) + ' |' if w else '(none)'}")
            print(f"  {a.doc}: {'| ' + ' | '.join(h) + ' |' if h else '(none)'}")
    if bad:
        print(f"check_settings_doc: {bad} row(s) differ; paste the output of "
              f"'mtt-track --list-settings' into {a.doc} (its columns "
              f"{', '.join(head)})")
        return 1
    print(f"check_settings_doc: {len(want)} settings rows match")
    return 0


if __name__ == "__main__":
    sys.exit(main())
