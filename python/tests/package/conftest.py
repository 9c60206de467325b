# SPDX-License-Identifier: BSD-3-Clause
"""Shared fixtures of the package tests (pytest): the repository, mtt-track, runs of the scenarios.

These tests import the INSTALLED packages mtt and mtt_sim (`pip install .[stonesoup,sim,test]`;
tools/ci/dev.sh test does it in a venv under build/).  The comparisons with
mtt-track need the binary of the same configuration (float, default bounds):
$MTT_TRACK, else build/host-float/tools/track/mtt-track.  With MTT_REQUIRE_ALL=1
(CI) a missing binary or Stone Soup fails instead of skipping.
"""

import os
import subprocess

import pytest

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))


def _require_all() -> bool:
    return os.environ.get("MTT_REQUIRE_ALL") == "1"


def missing(what: str):
    """Skip (locally) or fail (MTT_REQUIRE_ALL=1) for a missing prerequisite."""
    if _require_all():
        pytest.fail(f"{what} (MTT_REQUIRE_ALL=1)")
    pytest.skip(what)


def find_mtt_track():
    cands = [os.environ.get("MTT_TRACK")]
    cands.append(os.path.join(REPO, "build", "host-float", "tools", "track", "mtt-track"))
    for c in cands:
        if c and os.path.isfile(c) and os.access(c, os.X_OK):
            return c
    return None


@pytest.fixture(scope="session")
def mtt_track():
    exe = find_mtt_track()
    if exe is None:
        missing("mtt-track not built (cmake --preset host-float && cmake --build --preset host-float)")
    out = subprocess.run([exe, "--version"], capture_output=True, text=True).stdout
    import mtt
    if f"mtt_real={mtt.REAL}" not in out:
        missing(f"{exe} is not a {mtt.REAL} build: {out.strip()}")
    return exe


def run_mtt_track(exe, settings, det, tracks, *extra):
    return subprocess.run([exe, "--config", settings, "--detections", det, "--tracks", tracks, *extra],
                          capture_output=True, text=True)


@pytest.fixture(scope="session")
def scenario_run(tmp_path_factory):
    """scenario_run(name, seed, association=None) -> (run dict, files dict): one
    drawn run of scenarios/<name>.json written to det/truth/settings files."""
    from mtt_sim import gen, scenario

    cache = {}
    base = tmp_path_factory.mktemp("runs")

    def get(name, seed=1, association=None):
        key = (name, seed, association)
        if key not in cache:
            scn = scenario.load(os.path.join(REPO, "scenarios", f"{name}.json"))
            run = gen.generate(scn, seed, association)
            stem = f"{name}_{seed}_{association or 'default'}"
            cache[key] = (scn, run, gen.write_run(run, str(base), stem))
        return cache[key]

    return get
