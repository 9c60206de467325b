# SPDX-License-Identifier: BSD-3-Clause
"""mtt.Tracker against mtt-track: the same tracks (ids, status, states to the
printed precision) on the bundled scenarios, the same settings errors, and
bad input that raises and changes nothing."""

import glob
import json
import math
import os

import numpy as np
import pytest

import mtt
from mtt import _core

from conftest import REPO, run_mtt_track

REAL_FMT = "%.9g" if mtt.REAL == "float" else "%.17g"
CLI_TESTS = next((d for d in (os.path.join(REPO, "tools", "track", "tests"),)
                  if os.path.isdir(d)), None)


def python_rows(settings, det_path, confirmed_only=False):
    """Track the detections file with mtt.Tracker as mtt-track does (each scan
    at its time minus the first scan's, detections in file order); rows as
    mtt-track writes them, without the time column."""
    from mtt_sim import csvio

    det, times = csvio.read_det(det_path)
    scans = sorted(times)
    interval = times[scans[1]] - times[scans[0]] if len(scans) > 1 else None
    trk = mtt.Tracker(settings, interval=interval)
    rows = []
    for k in scans:
        sel = det["scan"] == k
        z = np.column_stack([det["x"][sel], det["y"][sel], det["amp"][sel]])
        for t in trk.step(times[k] - times[scans[0]], z):
            if confirmed_only and not t.confirmed:
                continue
            vals = [*t.state, t.existence, t.covar[0, 0], t.covar[0, 1], t.covar[1, 1]]
            rows.append(",".join([str(k), str(t.id), "confirmed" if t.confirmed else "tentative",
                                  *(REAL_FMT % v for v in vals)]))
    return rows, trk


def mtt_track_rows(exe, settings, det, out, *extra):
    p = run_mtt_track(exe, settings, det, out, *extra)
    assert p.returncode == 0, p.stderr
    with open(out) as f:
        lines = f.read().splitlines()
    assert lines[0] == "scan,time,track,status,x,y,vx,vy,existence,pxx,pxy,pyy"
    return [",".join(ln.split(",")[:1] + ln.split(",")[2:]) for ln in lines[1:]]


def test_version_and_build():
    assert mtt.__version__ == _core.VERSION
    assert mtt.__version__.count(".") == 2
    assert mtt.REAL in ("float", "double")
    assert mtt.MAX_TRACKS >= 1 and mtt.MAX_MEAS >= 1


SCENARIOS = sorted(os.path.basename(p)[:-5] for p in glob.glob(os.path.join(REPO, "scenarios", "*.json")))


@pytest.mark.parametrize("name", SCENARIOS)
def test_reproduces_mtt_track_on_scenario(name, mtt_track, scenario_run, tmp_path):
    scn, run, files = scenario_run(name)
    expect = mtt_track_rows(mtt_track, files["settings"], files["det"], str(tmp_path / "t.csv"))
    got, trk = python_rows(files["settings"], files["det"])
    assert len(expect) > 0
    assert got == expect
    # the settings as a dict give the same tracker as the file
    got_dict, _ = python_rows(run["settings"], files["det"])
    assert got_dict == expect
    assert trk.stats["total"]["frames"] == len(run["times"])


def _modes():
    """The association modes built into this library."""
    row = next(r for r in mtt.settings.params_table() if r.key == "association")
    out = []
    for name in row.names:
        try:
            mtt.Tracker({"association": name})
            out.append(name)
        except ValueError:
            pass
    return out


@pytest.mark.parametrize("mode", _modes())
def test_reproduces_mtt_track_every_mode(mode, mtt_track, scenario_run, tmp_path):
    scn, run, files = scenario_run("crossing3", 2, mode)
    expect = mtt_track_rows(mtt_track, files["settings"], files["det"], str(tmp_path / "t.csv"),
                            "--confirmed-only")
    got, _ = python_rows(files["settings"], files["det"], confirmed_only=True)
    assert got == expect


def test_reproduces_mtt_track_seeded(mtt_track, tmp_path):
    settings = os.path.join(CLI_TESTS, "seeded.json")
    det = os.path.join(CLI_TESTS, "valid.det.csv")
    expect = mtt_track_rows(mtt_track, settings, det, str(tmp_path / "t.csv"))
    got, _ = python_rows(settings, det)
    assert got == expect
    assert any(r.split(",")[1] == "0" for r in got)


def test_imm_reproduces_mtt_track_with_model_probabilities(mtt_track, scenario_run, tmp_path):
    """motion = imm: Track.model_probabilities are the mu_j columns of mtt-track's tracks file."""
    scn, run, files = scenario_run("manoeuvre", 1)
    settings = dict(run["settings"], motion="imm",
                    imm_models=[{"model": "cv", "process_psd": 1.0}, {"model": "ca", "process_psd": 400.0}])
    path = str(tmp_path / "imm.json")
    with open(path, "w") as f:
        json.dump(settings, f)
    out = str(tmp_path / "t.csv")
    p = run_mtt_track(mtt_track, path, files["det"], out)
    assert p.returncode == 0, p.stderr
    with open(out) as f:
        lines = f.read().splitlines()
    assert lines[0] == "scan,time,track,status,x,y,vx,vy,existence,pxx,pxy,pyy,mu_0,mu_1"
    expect = [",".join(ln.split(",")[:1] + ln.split(",")[2:]) for ln in lines[1:]]
    from mtt_sim import csvio
    det, times = csvio.read_det(files["det"])
    scans = sorted(times)
    trk = mtt.Tracker(settings, interval=times[scans[1]] - times[scans[0]])
    got = []
    for k in scans:
        sel = det["scan"] == k
        z = np.column_stack([det["x"][sel], det["y"][sel], det["amp"][sel]])
        for t in trk.step(times[k] - times[scans[0]], z):
            assert t.model_probabilities is not None and len(t.model_probabilities) == 2
            assert abs(float(sum(t.model_probabilities)) - 1.0) < 1e-4
            vals = [*t.state, t.existence, t.covar[0, 0], t.covar[0, 1], t.covar[1, 1],
                    *t.model_probabilities]
            got.append(",".join([str(k), str(t.id), "confirmed" if t.confirmed else "tentative",
                                 *(REAL_FMT % v for v in vals)]))
    assert len(expect) > 100
    assert got == expect
    # the reader of mtt_sim takes the mu columns
    tab = csvio.read_tracks(out)
    assert tab["mu"].shape == (len(expect), 2)
    # a CV tracker has none
    assert all(t.model_probabilities is None for t in mtt.Tracker({}).step(0.0, [[1.0, 2.0]]))


BAD_CONFIGS = sorted(glob.glob(os.path.join(CLI_TESTS or "", "cfg_*.json")))


@pytest.mark.parametrize("path", BAD_CONFIGS, ids=lambda p: os.path.basename(p))
def test_settings_errors_as_mtt_track(path, mtt_track, tmp_path):
    """Every bad settings file of mtt-track's tests: ValueError with mtt-track's message."""
    det = os.path.join(CLI_TESTS, "valid.det.csv")
    p = run_mtt_track(mtt_track, path, det, str(tmp_path / "t.csv"))
    if p.returncode == 0:  # valid in this configuration (a mode built in)
        mtt.Tracker(path)
        return
    assert p.returncode == 2
    expect = p.stderr.strip().splitlines()[0]
    assert expect.startswith("mtt-track: ")
    with pytest.raises(ValueError) as e:
        mtt.Tracker(path)
    assert str(e.value) == expect[len("mtt-track: "):]


@pytest.mark.parametrize("settings, key, text", [
    ({"pd": 1.5}, "pd", "must be in (0, 1], found 1.5"),
    ({"pd": True}, "pd", "must be a number, found a boolean"),
    ({"pd": "0.9"}, "pd", "must be a number, found a string"),
    ({"meas_sigma": [1.0]}, "meas_sigma", "must be an array of 2 numbers, found 1 elements"),
    ({"meas_sigma": [1.0, -2.0]}, "meas_sigma[1]", "must be in [1e-9, 1e9], found -2"),
    ({"meas_sigma": (1.0, float("nan"))}, "meas_sigma[1]", "must be a finite number"),
    ({"pdd": 0.9}, "pdd", "unknown key (did you mean 'pd'?)"),
    ({"initiate": 1}, "initiate", "must be true or false, found a number"),
    ({"association": "lm-ihpdaa"}, "association", "unknown association 'lm-ihpdaa' (expected one of: "),
    ({"intensity_gate": {"blend": [2.0, 1.0]}}, "intensity_gate.blend", "must be increasing (I_lo < I_hi), found [2, 1]"),
    ({"intensity_gate": 3}, "intensity_gate", "must be an object with the keys f1, f2, blend, found a number"),
    ({"terminate_threshold": 0.99, "confirm_threshold": 0.9}, "terminate_threshold",
     "must be below confirm_threshold, found 0.99"),
    ({"vmax": 1e39}, "vmax", "1e+39 does not fit the tracker's real type (mtt_real=float)")
    if mtt.REAL == "float" else ({"vmax": 0.0}, "vmax", "must be > 0, found 0"),
    ({"initial_tracks": [{"x": 0, "y": 0, "vx": 1}]}, "initial_tracks[0].vy",
     "missing: every initial track needs x, y, vx and vy"),
    ({"initial_tracks": [{"x": 0, "y": 0, "vx": 1, "vy": 0, "P": np.eye(4).tolist()[:3]}]},
     "initial_tracks[0].P", "must be a 4x4 covariance: 16 numbers row-major (or 4 rows of 4), found 3 elements"),
    ({"initial_tracks": [{"x": 0, "y": 0, "vx": 1, "vy": 0, "P": (-np.eye(4)).tolist()}]},
     "initial_tracks[0].P", "must be a symmetric positive definite covariance"),
])
def test_dict_settings_errors(settings, key, text):
    with pytest.raises(ValueError) as e:
        mtt.Tracker(settings)
    assert e.value.key == key
    msg = str(e.value)
    assert msg.startswith(f"settings: key '{key}': ")
    assert msg[len(f"settings: key '{key}': "):].startswith(text)


def test_dict_settings_accept_numpy_and_defaults():
    t = mtt.Tracker({"pd": np.float32(0.8), "meas_sigma": np.array([2.0, 3.0]), "initiate": np.bool_(True)})
    assert t.param("pd") == (pytest.approx(0.8),)
    assert t.param("meas_sigma") == (2.0, 3.0)
    d = mtt.Tracker()
    assert d.param("association") == (0.0,)  # lm-ihpda
    assert d.tracks == [] and d.time is None


def test_seeded_tracks_from_dict():
    t = mtt.Tracker({"initial_tracks": [{"x": 1, "y": 2, "vx": 3, "vy": 4},
                                        {"x": 5, "y": 6, "vx": 0, "vy": 0, "P": np.eye(4).ravel().tolist()}]},
                    interval=2.0)
    ts = t.tracks
    assert [x.id for x in ts] == [0, 1]
    assert all(x.confirmed and x.existence == 1.0 for x in ts)
    np.testing.assert_array_equal(ts[0].state, [1, 2, 3, 4])
    np.testing.assert_array_equal(ts[1].covar, np.eye(4))
    sx = t.param("meas_sigma")[0]
    # two-point covariance of ALGORITHMS.md §12.1 for dt = 2: [[R, R/dt], [R/dt, 2R/dt^2]]
    assert ts[0].covar[0, 0] == pytest.approx(sx * sx)
    assert ts[0].covar[0, 2] == pytest.approx(sx * sx / 2.0)
    assert ts[0].covar[2, 2] == pytest.approx(2.0 * sx * sx / 4.0)
    assert ts[0].model_probabilities is None


def _scene(k):
    """Two targets moving apart plus one fixed clutter point; amplitudes known."""
    return np.array([[10.0 + 2 * k, 0.0, 3.0], [0.0, 10.0 + 2 * k, 3.0], [50.0, 50.0, 0.5]])


def _stepped():
    t = mtt.Tracker({"clutter_density": 1e-4, "meas_sigma": [1.0, 1.0], "vmax": 10.0, "snr_rho": 2.0})
    for k in range(6):
        t.step(float(k), _scene(k))
    return t


def test_step_tracks_a_simple_scene():
    t = _stepped()
    conf = [x for x in t.tracks if x.confirmed]
    assert len(conf) >= 2
    ids = [x.id for x in t.tracks]
    assert ids == sorted(ids)
    near = [x for x in conf if abs(x.state[0] - 20.0) < 1.0 and abs(x.state[1]) < 1.0]
    assert len(near) == 1 and near[0].state[2] == pytest.approx(2.0, abs=0.3)
    assert near[0].covar.shape == (4, 4) and near[0].state.shape == (4,)
    s = t.stats
    assert set(s) == {"last", "total"}
    assert list(s["last"]) == list(_core.COUNT_FIELDS)
    assert s["total"]["frames"] == 6 and s["total"]["meas_in"] == 18 and s["last"]["meas_in"] == 3


def test_empty_scans_and_two_columns():
    t = mtt.Tracker()
    assert t.step(0.0, np.zeros((0, 2))) == []
    assert t.step(1.0, []) == []
    assert t.step(2.0, None) == []
    t.step(3.0, [[1.0, 2.0], [3.0, 4.0]])
    assert t.stats["total"]["meas_in"] == 2 and t.stats["total"]["frames"] == 4


@pytest.mark.parametrize("time, det", [
    (5.0, _scene(6)),                 # not later than the last step (5)
    (4.0, _scene(6)),                 # earlier
    (float("nan"), _scene(6)),
    (float("inf"), _scene(6)),
    (1e39 if mtt.REAL == "float" else float("inf"), _scene(6)),
    ("six", _scene(6)),
    (6.0, np.ones((3, 4))),           # bad shapes
    (6.0, np.ones(3)),
    (6.0, np.ones((2, 3, 1))),
    (6.0, [[1.0, "x"]]),
    (6.0, [[float("nan"), 1.0]]),     # non-finite coordinates
    (6.0, [[1.0, float("inf"), 1.0]]),
    (6.0, [[1.0, 1.0, -1.0]]),        # negative amplitude
    (6.0, [[1.0, 1.0, float("inf")]]),
])
def test_bad_step_raises_and_changes_nothing(time, det):
    t = _stepped()
    before = t._core.state_bytes()
    tracks = [(x.id, x.state.copy()) for x in t.tracks]
    stats = t.stats
    with pytest.raises(ValueError):
        t.step(time, det)
    assert t._core.state_bytes() == before
    assert [(x.id, x.state.tolist()) for x in t.tracks] == [(i, s.tolist()) for i, s in tracks]
    assert t.stats == stats and t.time == 5.0
    # and the tracker goes on as if nothing happened
    ref = _stepped()
    a, b = t.step(6.0, _scene(6)), ref.step(6.0, _scene(6))
    assert [(x.id, x.state.tolist()) for x in a] == [(x.id, x.state.tolist()) for x in b]


def test_bad_settings_types():
    with pytest.raises(TypeError):
        mtt.Tracker(42)
    with pytest.raises(ValueError, match="cannot read"):
        mtt.Tracker("/nonexistent/settings.json")


def test_track_arrays_are_snapshots():
    t = _stepped()
    tr = t.tracks[0]
    with pytest.raises(ValueError):
        tr.state[0] = 1.0  # read-only
    old = tr.state.copy()
    t.step(6.0, _scene(6))
    np.testing.assert_array_equal(tr.state, old)
    assert "Track(id=" in repr(tr) and math.isfinite(tr.existence)
