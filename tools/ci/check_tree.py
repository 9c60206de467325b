#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Checks of the tree's shape that a review would otherwise do by hand.

    python3 tools/ci/check_tree.py            # from anywhere inside the repository

1. Size caps of the docs: README.md <= 10 KB, a reference doc in docs/ or
   a report in docs/reports/ <= 40 KB, docs/ALGORITHMS.md <= 80 KiB
   (CHANGELOG.md, the history, has none).
2. Every tracked source file (C, C++, headers, Python, shell, CMake, the
   linker script) carries "SPDX-License-Identifier: BSD-3-Clause" in its
   first five lines.
3. No public header (include/mtt/) includes a header of src/.
4. README.md's C example stands verbatim in examples/minimal/main.c, which
   CI compiles and runs (ctest example.minimal).

Prints one line per problem (file: what) and a summary; exits 1 on any.
"""
import os
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
SPDX = "SPDX-License-Identifier: BSD-3-Clause"
CAPS = {"README.md": 10_000, "docs/ALGORITHMS.md": 81_920}
REF_CAP = 40_000
SOURCE_ENDINGS = (".c", ".h", ".cpp", ".py", ".sh", ".cmake", ".ld", ".toml", ".cmake.in")
SOURCE_NAMES = ("CMakeLists.txt", "run")


def tracked():
    try:
        out = subprocess.run(["git", "-C", ROOT, "ls-files"], capture_output=True, text=True, check=True).stdout
        return out.split("\n")[:-1]
    except (OSError, subprocess.CalledProcessError):
        # Not a git checkout (an unpacked archive): every file below ROOT.
        files = []
        for d, dirs, names in os.walk(ROOT):
            dirs[:] = [x for x in dirs if not x.startswith((".git", "build", ".deps"))]
            files += [os.path.relpath(os.path.join(d, n), ROOT) for n in names]
        return files


def main():
    problems = []
    files = tracked()
    for f in files:
        path = os.path.join(ROOT, f)
        if not os.path.isfile(path):
            continue
        size = os.path.getsize(path)
        cap = CAPS.get(f)
        if cap is None and f.startswith("docs/") and f.endswith(".md") and f.count("/") <= 2:
            cap = REF_CAP
        if cap is not None and size > cap:
            problems.append(f"{f}: {size} bytes, over its cap of {cap}")
        if f.endswith(SOURCE_ENDINGS) or os.path.basename(f) in SOURCE_NAMES:
            with open(path, encoding="utf-8", errors="replace") as fh:
                head = "".join(fh.readline() for _ in range(5))
            if SPDX not in head:
                problems.append(f"{f}: no '{SPDX}' in its first five lines")
        if f.startswith("include/mtt/") and f.endswith(".h"):
            with open(path, encoding="utf-8") as fh:
                for n, line in enumerate(fh, 1):
                    s = line.strip()
                    if s.startswith("#") and "include" in s and ('"real_ops.h"' in s or "src/" in s or "_internal.h" in s):
                        problems.append(f"{f}:{n}: a public header includes a private one: {s}")
    readme = os.path.join(ROOT, "README.md")
    example = os.path.join(ROOT, "examples", "minimal", "main.c")
    if os.path.isfile(readme) and os.path.isfile(example):
        import re
        with open(readme, encoding="utf-8") as fh:
            blocks = re.findall(r"```c\n(.*?)```", fh.read(), re.S)
        with open(example, encoding="utf-8") as fh:
            code = fh.read()
        if len(blocks) != 1:
            problems.append(f"README.md: {len(blocks)} C examples, expected 1")
        elif blocks[0] not in code:
            problems.append("README.md: its C example is not verbatim in examples/minimal/main.c")
    for p in problems:
        print(p)
    print(f"check_tree: {len(files)} files, {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
