# SPDX-License-Identifier: BSD-3-Clause
"""mtt_sim's Monte Carlo in-process (through the mtt package) gives the same
tracks and scores as its process-per-run path (mtt-track)."""

import os

import numpy as np
import pytest

from conftest import REPO


def same(a, b, path="score"):
    if isinstance(a, dict):
        assert set(a) == set(b), path
        for k in a:
            same(a[k], b[k], f"{path}.{k}")
    elif isinstance(a, (list, tuple, np.ndarray)):
        a, b = np.asarray(a), np.asarray(b)
        assert a.shape == b.shape, path
        if a.dtype.kind in "fc":
            np.testing.assert_array_equal(a, b, err_msg=path)  # NaN == NaN here
        else:
            assert a.tolist() == b.tolist(), path
    elif isinstance(a, float) and np.isnan(a):
        assert isinstance(b, float) and np.isnan(b), path
    else:
        assert a == b, path


@pytest.mark.parametrize("name, mode, seed", [
    ("crossing3", "lm-ipda", 5), ("crossing3", "lm-ihpda", 6), ("coalesce3", "ipda", 1),
    ("split", "lm-ipda", 2), ("formations", "jpda", 1)])
def test_in_process_run_equals_mtt_track_run(name, mode, seed, mtt_track, tmp_path):
    from mtt_sim import csvio, mc, scenario

    assert mc.find_tracker("auto") == mc.IN_PROCESS
    assert mc.find_tracker("mtt-track", mtt_track) == os.path.abspath(mtt_track)
    scn = scenario.load(os.path.join(REPO, "scenarios", f"{name}.json"))
    a = mc.one_run(scn, mode, 0, seed, mc.IN_PROCESS, keep_dir=str(tmp_path / "a"))
    b = mc.one_run(scn, mode, 0, seed, mtt_track, keep_dir=str(tmp_path / "b"))
    assert a["ok"] and b["ok"], (a.get("error"), b.get("error"))
    same(a["score"], b["score"])
    # the kept tracks files hold the same tracks
    ta = csvio.read_tracks(str(tmp_path / "a" / f"{scn['name']}.{mode}.tracks.csv"))
    tb = csvio.read_tracks(str(tmp_path / "b" / f"{scn['name']}.{mode}.tracks.csv"))
    assert len(tb["scan"]) > 0
    same(ta, tb, "tracks")


def test_in_process_forced_and_errors(tmp_path):
    from mtt_sim import mc, scenario

    with pytest.raises(ValueError):
        mc.find_tracker("fast")
    scn = scenario.load(os.path.join(REPO, "scenarios", "crossing3.json"), ["tracker.pd=1.5"])
    r = mc.one_run(scn, "lm-ipda", 0, 1, mc.IN_PROCESS)
    assert not r["ok"] and "key 'pd'" in r["error"]
    res = mc.monte_carlo(scenario.load(os.path.join(REPO, "scenarios", "crossing3.json")),
                         ["lm-ipda"], 2, mc.IN_PROCESS, jobs=1, progress=None)
    assert res["results"]["lm-ipda"]["runs_ok"] == 2
