#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Check every relative link and #anchor in the repository's tracked Markdown files.

    python3 tools/ci/check_links.py [FILE.md ...]

Without arguments it checks every *.md file that git tracks. A link is
relative when it has no URL scheme (http:, https:, mailto:, ...). Its path
must name a tracked file or a directory that holds tracked files, resolved
from the linking file's directory. An #anchor must match a heading of the
target Markdown file (GitHub's rule: lower case, punctuation dropped, spaces
to hyphens, -1, -2, ... for repeats) or an explicit <a id=...> / <a name=...>.
Links inside code spans and fenced code blocks are not links.

Prints one line per broken link (file:line: target: reason) and exits 1 if
there is any, else prints a summary and exits 0. Standard library only.
"""
import os
import re
import subprocess
import sys

SCHEME = re.compile(r"^[A-Za-z][A-Za-z0-9+.-]*:")
INLINE = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]*)>?(?:\s+\"[^\"]*\"|\s+'[^']*')?\s*\)")
REFDEF = re.compile(r"^\s{0,3}\[[^\]]+\]:\s*<?(\S+?)>?(?:\s+.*)?$")
HTML_ID = re.compile(r"<a\s+[^>]*(?:id|name)\s*=\s*[\"']([^\"']+)[\"']", re.I)
HEADING = re.compile(r"^\s{0,3}(#{1,6})\s+(.*?)\s*#*\s*$")
FENCE = re.compile(r"^\s{0,3}(```|~~~)")
CODE_SPAN = re.compile(r"(`+)(.+?)\1")


def repo_root():
    out = subprocess.run(["git", "rev-parse", "--show-toplevel"], capture_output=True,
                         text=True, check=True)
    return out.stdout.strip()


def tracked_files(root):
    out = subprocess.run(["git", "-C", root, "ls-files", "-z"], capture_output=True,
                         check=True)
    return {p for p in out.stdout.decode("utf-8").split("\0") if p}


def slug(text):
    """GitHub's anchor for a heading text."""
    text = re.sub(r"<[^>]+>", "", text)               # inline HTML
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", text)  # links keep their text
    text = text.replace("`", "").strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)              # \w keeps Unicode letters, digits, _
    return text.replace(" ", "-")


def lines_outside_code(text, blank_spans=True):
    """(line number, line) of every line outside fenced code; code spans
    blanked unless blank_spans is false."""
    fence = None
    for no, line in enumerate(text.splitlines(), 1):
        m = FENCE.match(line)
        if m:
            if fence is None:
                fence = m.group(1)
            elif m.group(1) == fence:
                fence = None
            continue
        if fence is None:
            yield no, (CODE_SPAN.sub(lambda s: " " * len(s.group(0)), line)
                       if blank_spans else line)


def anchors_of(path, cache):
    if path not in cache:
        found, seen = set(), {}
        with open(path, encoding="utf-8") as fh:
            text = fh.read()
        for _, line in lines_outside_code(text, blank_spans=False):
            m = HEADING.match(line)
            if m:
                base = slug(m.group(2))
                n = seen.get(base, 0)
                seen[base] = n + 1
                found.add(base if n == 0 else "%s-%d" % (base, n))
            found.update(HTML_ID.findall(line))
        cache[path] = found
    return cache[path]


def links_of(text):
    for no, line in lines_outside_code(text):
        for m in INLINE.finditer(line):
            yield no, m.group(1)
        m = REFDEF.match(line)
        if m:
            yield no, m.group(1)


def check(root, files, tracked):
    dirs = {os.path.dirname(p) for p in tracked}
    for p in list(dirs):
        while p:
            p = os.path.dirname(p)
            dirs.add(p)
    cache, broken, count = {}, [], 0
    for rel in files:
        with open(os.path.join(root, rel), encoding="utf-8") as fh:
            text = fh.read()
        for no, target in links_of(text):
            if not target or SCHEME.match(target) or target.startswith("//"):
                continue
            count += 1
            path, _, anchor = target.partition("#")
            path = path.split("?", 1)[0]
            if path:
                if path.startswith("/"):
                    dest = os.path.normpath(path.lstrip("/"))
                else:
                    dest = os.path.normpath(os.path.join(os.path.dirname(rel), path))
                if dest.startswith(".."):
                    broken.append((rel, no, target, "points outside the repository"))
                    continue
                if dest not in tracked and dest.rstrip("/") not in dirs:
                    broken.append((rel, no, target, "no such tracked file or directory"))
                    continue
            else:
                dest = rel
            if anchor and dest.endswith(".md") and (dest in tracked or dest == rel):
                if anchor not in anchors_of(os.path.join(root, dest), cache):
                    broken.append((rel, no, target, "no heading or anchor '#%s' in %s"
                                   % (anchor, dest)))
    return broken, count


def main(argv):
    root = repo_root()
    tracked = tracked_files(root)
    if argv:
        files = [os.path.relpath(os.path.abspath(a), root) for a in argv]
    else:
        files = sorted(p for p in tracked if p.endswith(".md") and os.path.exists(os.path.join(root, p)))
    broken, count = check(root, files, tracked)
    for rel, no, target, why in broken:
        print("%s:%d: %s: %s" % (rel, no, target, why))
    if broken:
        print("check_links: %d broken of %d relative links in %d files"
              % (len(broken), count, len(files)), file=sys.stderr)
        return 1
    print("check_links: %d relative links in %d files, all resolve" % (count, len(files)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
