#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Check that every commit and tag cited in the repository's Markdown exists.

    python3 tools/ci/check_hashes.py [FILE.md ...]

Without arguments it checks every *.md file that git tracks (and untracked
ones not ignored). A citation is, outside fenced code:

- a code span whose whole text is 7 to 40 lower-case hexadecimal digits
  with at least one letter a-f and at least one digit (`82c967e`): a
  number (`1234567`, no letter), a word (`deadbeef`... has no digit), a
  constant (`0x1f`, the x) or a longer text is not one;
- the same token without backticks right after the word "commit",
  "commits" or "at" (commit 82c967e, at 82c967e);
- a tag: the word "tag" followed by a code span (tag `v1.0`);

and, inside fenced code, such a token as an argument of a git command on
the same line (git worktree add /tmp/r 82c967e).

A commit must resolve with `git rev-parse --verify --quiet X^{commit}`, a
tag with `git rev-parse --verify --quiet refs/tags/X^{commit}`. A shallow
clone misses old commits: run it on a full clone (CI: fetch-depth 0).

Prints one line per unresolved citation (file:line: text: reason) and exits
1 if there is any, else prints a summary and exits 0. Standard library only.
"""
import bisect
import os
import re
import subprocess
import sys

HEX = r"[0-9a-f]{7,40}"
SPAN_HASH = re.compile(r"(?<!`)`(" + HEX + r")`(?!`)")
WORD_HASH = re.compile(r"\b(?:[Cc]ommits?|at)\s+(" + HEX + r")\b")
TAG = re.compile(r"\b[Tt]ags?\s+`([^`\s]+)`")
GIT_LINE = re.compile(r"\bgit\s+(?:-C\s+\S+\s+)?(?:checkout|switch|show|log|diff|worktree\s+add|"
                      r"cherry-pick|revert|reset|rev-parse|merge-base|describe|archive|branch|tag)\b")
GIT_TOKEN = re.compile(r"(?<![\w./-])(" + HEX + r")(?![\w-])")
FENCE = re.compile(r"^\s{0,3}(```|~~~)")


def looks_like_hash(tok):
    return re.search(r"[a-f]", tok) is not None and re.search(r"[0-9]", tok) is not None


def git(*args, root):
    return subprocess.run(["git", "-C", root, *args], capture_output=True, text=True)


def resolves(ref, root, cache):
    if ref not in cache:
        cache[ref] = git("rev-parse", "--verify", "--quiet", ref + "^{commit}",
                         root=root).returncode == 0
    return cache[ref]


def citations(text):
    """(line number, kind, token) of every citation in a Markdown text."""
    fence = None
    prose = []                      # the text with fenced code blanked
    for no, line in enumerate(text.splitlines(), 1):
        m = FENCE.match(line)
        if m:
            if fence is None:
                fence = m.group(1)
            elif m.group(1) == fence:
                fence = None
            prose.append("")
            continue
        if fence is not None:
            prose.append("")
            if GIT_LINE.search(line):
                for t in GIT_TOKEN.findall(line):
                    if looks_like_hash(t):
                        yield no, "commit", t
            continue
        prose.append(line)
    body = "\n".join(prose)        # a citation may span a line break (tag\n`x`)
    starts = [0]
    for line in prose:
        starts.append(starts[-1] + len(line) + 1)

    def line_of(pos):
        return bisect.bisect_right(starts, pos)

    seen = set()
    for rx in (SPAN_HASH, WORD_HASH):
        for m in rx.finditer(body):
            t = m.group(1)
            key = (line_of(m.start(1)), t)
            if looks_like_hash(t) and key not in seen:
                seen.add(key)
                yield key[0], "commit", t
    for m in TAG.finditer(body):
        yield line_of(m.start(1)), "tag", m.group(1)


def main(argv):
    root = git("rev-parse", "--show-toplevel", root=".").stdout.strip()
    if not root:
        print("check_hashes: not in a git repository")
        return 2
    if argv:
        files = [os.path.relpath(os.path.abspath(f), root) for f in argv]
    else:
        out = git("ls-files", "-co", "--exclude-standard", "-z", "--", "*.md", root=root).stdout
        files = sorted({f for f in out.split("\0") if f})
    cache, bad, n = {}, 0, 0
    for f in files:
        path = os.path.join(root, f)
        if not os.path.isfile(path):
            continue
        with open(path, encoding="utf-8") as fh:
            text = fh.read()
        for no, kind, tok in sorted(set(citations(text))):
            n += 1
            ref = tok if kind == "commit" else "refs/tags/" + tok
            if not resolves(ref, root, cache):
                bad += 1
                print(f"{f}:{no}: {tok}: {kind} not in the repository")
    if bad:
        print(f"check_hashes: {bad} of {n} citations do not resolve")
        return 1
    print(f"check_hashes: {n} citations in {len(files)} files, all resolve")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
