# SPDX-License-Identifier: BSD-3-Clause
"""mtt_sim.stonesoup_mc: Stone Soup's JPDA on the Monte Carlo's own detections, scored as mtt's runs."""

import os
import subprocess
import sys

import numpy as np
import pytest

from conftest import REPO, missing

SIGMA = 5.0
ONE_TARGET = [  # split_fast without the split and the clutter: one target at 25 m/s, PD 1, sigma 5 m
    "splits=[]", 'clutter={"model": "none"}', "pd=1.0", f"meas_sigma=[{SIGMA}, {SIGMA}]",
    f"tracker.meas_sigma=[{SIGMA}, {SIGMA}]", "tracker.pd=1.0", "scans.count=30",
]
UNSEEDED = ONE_TARGET + ["tracker.initial_tracks=[]", 'metrics={"match_distance": 50.0, "gospa_c": 100.0}']


@pytest.fixture(scope="module")
def ssmc():
    try:
        import stonesoup  # noqa: F401
    except ImportError:
        missing("stonesoup not installed (pip install .[stonesoup])")
    from mtt_sim import stonesoup_mc
    return stonesoup_mc


def load(overrides):
    from mtt_sim import scenario
    return scenario.load(os.path.join(REPO, "scenarios", "split_fast.json"), overrides)


@pytest.mark.parametrize("min_points", [None, 3])
def test_one_target_tracked_on_mc_detections(ssmc, tmp_path, min_points):
    from mtt_sim import csvio, gen, mc

    scn = load(UNSEEDED)
    seed = 7
    # the defaults: 5 detections in a row start a track; or min_points 3 (--min-points 3)
    trk = ssmc.JpdaTracker(scn) if min_points is None else ssmc.JpdaTracker(scn, min_points=min_points)
    n0 = (min_points or 5) - 1  # scans before the first track
    # the detections Stone Soup consumes are those of the file mtt-track reads for this seed
    run = gen.generate(scn, seed)
    det, _times = csvio.read_det(gen.write_run(run, str(tmp_path), "r")["det"])
    mine = trk.detections(run)
    assert len(mine) == 30 and sum(len(z) for z in mine) == 30  # PD 1, no clutter: one per scan
    for k, z in enumerate(mine):
        sel = det["scan"] == k
        assert np.array_equal(z, np.column_stack([det["x"][sel], det["y"][sel]]))

    res = mc.one_run(scn, ssmc.MODE, 0, seed, trk)
    assert res["ok"], res.get("error")
    sc = res["score"]
    c = scn["metrics"]["gospa_c"]
    # scans 0 to n0 - 1: no track yet: the target is missed, c/2
    assert list(sc["gospa"][:n0]) == [c / 2] * n0 and list(sc["n_confirmed"][:n0]) == [0] * n0
    # then exactly one track, the same id, on the target: with both axes' errors of standard
    # deviation <= sigma (a Kalman filter fed every measurement does no worse than the last one),
    # the distance is Rayleigh: P(> 4 sigma) = exp(-8) per scan, mean <= 1.25 sigma
    assert list(sc["n_confirmed"][n0:]) == [1] * (30 - n0)
    g = sc["gospa"][n0:]
    assert g.max() < 4 * SIGMA and g.mean() < 1.25 * SIGMA, g
    assert sc["mot"]["idsw"] == 0 and sc["mot"]["fp"] == 0 and sc["mot"]["fn"] == n0


def test_seeded_track_is_track_zero_from_scan_zero(ssmc):
    from mtt_sim import gen, mc

    scn = load(ONE_TARGET)
    trk = ssmc.JpdaTracker(scn)
    tracks, _ = trk(gen.generate(scn, 3))
    assert set(tracks["track"]) == {0}  # the seeded track follows the target; nothing else starts
    assert list(tracks["scan"]) == list(range(30))
    # scan 0: the given state [100, 300] updated with one detection of sigma 5 (prior P = R: halfway)
    d0 = np.hypot(tracks["x"][0] - 100.0, tracks["y"][0] - 300.0)
    assert 0.0 < d0 < 2 * SIGMA
    res = mc.one_run(scn, ssmc.MODE, 0, 3, trk)
    assert res["ok"] and res["score"]["seeded"]["failed"] is False
    assert res["score"]["gospa"][0] < 2 * SIGMA


def test_bad_arguments_and_no_stonesoup(ssmc, tmp_path):
    for bad in ("never", "steps:", "covar:2+never", "steps:0"):
        with pytest.raises(ValueError, match="steps:N, covar:F or both"):
            ssmc.JpdaTracker(load([]), deleter=bad)
    both = ssmc.JpdaTracker(load([]), deleter="covar:2+steps:3")._components().deleter
    assert [type(d).__name__ for d in both.deleters] == ["CovarianceBasedDeleter", "UpdateTimeStepsDeleter"]
    assert both.intersect is False and both.deleters[0].covar_trace_thresh == 2 * (10.0 ** 2 + 10.0 ** 2)
    with pytest.raises(ValueError, match="jpda or ehm"):
        ssmc.JpdaTracker(load([]), associator="lbp")
    with pytest.raises(ValueError, match="hold must be >= 1"):
        ssmc.JpdaTracker(load([]), hold=0)
    # clutter-free scenario and clutter_density 0 (mtt estimates it): Stone Soup has no density to take
    with pytest.raises(ValueError, match="clutter density > 0"):
        ssmc.JpdaTracker(load(UNSEEDED + ["tracker.clutter_density=0"]))
    code = ("import sys; sys.modules['stonesoup'] = None\n"  # Stone Soup absent: import fails
            "from mtt_sim import stonesoup_mc\n"
            f"sys.exit(stonesoup_mc.main(['--scenario', {os.path.join(REPO, 'scenarios', 'split.json')!r}, "
            f"'--runs', '1', '--out', {str(tmp_path / 'o')!r}]))")
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert p.returncode == 2 and "Stone Soup is not installed" in p.stderr, p.stderr
    assert not os.path.exists(tmp_path / "o")


def test_ekf_jpda_tracks_a_radar_target(ssmc, tmp_path):
    """EkfJpdaTracker (CartesianToBearingRange, EKF) on a radar's polar detections: one target at
    8 km, sigma_range 20 m, sigma_bearing 2 mrad (16 m across), PD 1, no clutter."""
    import json

    from mtt_sim import csvio, gen, mc, scenario

    scn = scenario.loads(json.dumps({
        "name": "radar_ekf", "area": {"x": [-20000, 20000], "y": [-20000, 20000]},
        "scans": {"count": 30, "dt": 2.0}, "pd": 1.0, "clutter": {"model": "none"},
        "sensor": {"kind": "radar", "position": [1000.0, -500.0], "sigma_range": 20.0, "sigma_bearing": 0.002,
                   "range_max": 15000},
        "targets": [{"id": 0, "x": 7000, "y": 5000, "vx": -40, "vy": 30}],
        "tracker": {"measurement": "polar", "sensor_xy": [1000.0, -500.0], "meas_sigma": [20.0, 0.002],
                    "pd": 1.0, "clutter_density": 1e-6, "vmax": 100, "process_psd": 1.0},
        "metrics": {"match_distance": 200, "gospa_c": 400}}), "radar_ekf.json")
    trk = ssmc.EkfJpdaTracker(scn)
    run = gen.generate(scn, 2)
    det, _ = csvio.read_polar_det(gen.write_run(run, str(tmp_path), "r")["det"])
    mine = trk.detections(run)
    for k, z in enumerate(mine):  # [bearing, range], the file's numbers
        sel = det["scan"] == k
        assert np.array_equal(z, np.column_stack([det["bearing"][sel], det["range"][sel]]))
    res = mc.one_run(scn, ssmc.MODE, 0, 2, trk)
    assert res["ok"], res.get("error")
    sc = res["score"]
    # 5 detections start the track (scan 4), then one track on the target: its position error is
    # below the larger per-axis sigma (20 m) on average and never above 4 times it
    assert list(sc["n_confirmed"][4:]) == [1] * 26
    g = sc["gospa"][4:]
    assert g.mean() < 20.0 and g.max() < 80.0, g
    assert sc["mot"]["idsw"] == 0 and sc["mot"]["fp"] == 0
    with pytest.raises(scenario.ScenarioError):
        ssmc.EkfJpdaTracker(scenario.load(os.path.join(REPO, "scenarios", "split_fast.json")))
