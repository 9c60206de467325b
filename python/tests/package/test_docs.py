# SPDX-License-Identifier: BSD-3-Clause
"""The Python examples of docs/PYTHON.md and README.md run and print what the page says."""

import os
import re
import subprocess
import sys

import pytest

from conftest import REPO, missing


def blocks(path):
    with open(os.path.join(REPO, path), encoding="utf-8") as f:
        return re.findall(r"```python\n(.*?)```", f.read(), re.S)


def run(code, tmp_path):
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=tmp_path,
                       timeout=300)
    assert p.returncode == 0, p.stderr
    return p.stdout


def test_numpy_example_readme_and_docs(tmp_path):
    readme = [b for b in blocks("README.md") if "import mtt" in b]
    docs = [b for b in blocks("docs/PYTHON.md") if "import mtt\n" in b]
    assert len(readme) == 1 and len(docs) == 1
    assert readme[0] == docs[0]  # one example, shown twice
    assert len(readme[0].strip().splitlines()) <= 15
    out = run(readme[0], tmp_path).splitlines()
    assert out == ["[(0, True, array([18.,  5.,  2.,  0.])), (3, True, array([40., 27.,  0.,  3.]))]", "2"]


def test_stonesoup_example(tmp_path):
    try:
        import stonesoup  # noqa: F401
    except ImportError:
        missing("stonesoup not installed")
    code = [b for b in blocks("docs/PYTHON.md") if "MttTracker" in b]
    assert len(code) == 1
    out = run(code[0], tmp_path)
    m = re.fullmatch(r"(\d+) tracks; mean GOSPA ([0-9.]+)\n", out)
    assert m, out
    assert int(m.group(1)) >= 2 and 0.0 < float(m.group(2)) < 10.0
