# SPDX-License-Identifier: BSD-3-Clause
"""Polar detections through the package (ALGORITHMS.md section 3.2):
mtt.Tracker.step with range, bearing under measurement polar, and
mtt.stonesoup.MttTracker with CartesianToBearingRange detections."""

import datetime

import numpy as np
import pytest

import mtt

from conftest import missing

SENSOR = [-500.0, 200.0]
SETTINGS = {"association": "lm-ihpda", "motion": "cv", "process_psd": 1.0, "measurement": "polar",
            "sensor_xy": SENSOR, "meas_sigma": [5.0, 0.004], "pd": 0.9, "clutter_density": 1e-3,
            "vmax": 200.0}


def scene():
    """A target from range 1.5 km to 5 km, three clutter detections a scan (range, bearing)."""
    rng = np.random.default_rng(11)
    out, truth = [], []
    for k in range(40):
        x, y = 1000.0 + 80.0 * k, 800.0 + 10.0 * k
        dx, dy = x - SENSOR[0], y - SENSOR[1]
        z = [[np.hypot(dx, dy) + rng.normal(0, 5.0), np.arctan2(dy, dx) + rng.normal(0, 0.004)]]
        z += np.column_stack([rng.uniform(500, 6000, 3), rng.uniform(-0.5, 0.8, 3)]).tolist()
        out.append(np.array(z))
        truth.append((x, y))
    return out, truth


def test_polar_step_tracks_the_target():
    zs, truth = scene()
    trk = mtt.Tracker(SETTINGS)
    assert trk.polar
    err = []
    for k, z in enumerate(zs):
        conf = [t for t in trk.step(float(k), z) if t.confirmed]
        if k >= 10:
            assert len(conf) == 1
            err.append(np.hypot(*(conf[0].state[:2] - truth[k])))
    # cross-range noise 6 m to 22 m over the run: the track is well inside it
    assert 1.0 < np.sqrt(np.mean(np.square(err))) < 15.0


def test_polar_rows_are_checked_and_cov_refused():
    trk = mtt.Tracker(SETTINGS)
    for bad, msg in (([[0.0, 0.1]], "range = 0.0 must be > 0"), ([[100.0, np.nan]], "bearing"),
                     ([[1.0, 2.0, 3.0, 4.0, 5.0]], r"\[range, bearing\]")):
        with pytest.raises(ValueError, match=msg):
            trk.step(1.0, bad)
    with pytest.raises(ValueError, match="meas_sigma"):
        trk.step(1.0, [[100.0, 0.1]], [[1.0, 0.0, 1.0]])
    assert trk.time is None  # nothing stepped


def test_cartesian_settings_do_not_take_polar():
    s = dict(SETTINGS)
    s.pop("measurement")
    assert not mtt.Tracker(s).polar


def assert_same_tracks(ss, ref):
    """MttTracker ss's confirmed tracks are mtt.Tracker ref's: one, the same states."""
    got = {int(t.id): t.state_vector.ravel() for t in ss.tracks}
    want = {t.id: t.state for t in ref.tracks if t.confirmed}
    assert set(got) == set(want) and len(got) == 1
    for i, sv in got.items():
        np.testing.assert_allclose(sv[[0, 2, 1, 3]], want[i], rtol=1e-9, atol=1e-9)


def test_stonesoup_takes_bearing_range_detections():
    try:
        from stonesoup.models.measurement.nonlinear import CartesianToBearingRange
        from stonesoup.types.detection import Detection
    except ImportError:  # pragma: no cover - CI installs the extra
        missing("stonesoup not installed (pip install .[stonesoup])")
    from mtt.stonesoup import MttTracker

    zs, _ = scene()
    t0 = datetime.datetime(2024, 1, 1)
    model = CartesianToBearingRange(ndim_state=4, mapping=(0, 2), noise_covar=np.diag([0.004 ** 2, 25.0]),
                                    translation_offset=np.array([[SENSOR[0]], [SENSOR[1]]]))
    ss = MttTracker(settings=SETTINGS)
    ref = mtt.Tracker(SETTINGS)
    for k, z in enumerate(zs):
        ts = t0 + datetime.timedelta(seconds=k)
        dets = {Detection(np.array([[b], [r]]), timestamp=ts, measurement_model=model) for r, b in z}
        ss.update_tracker(ts, dets)
        ref.step(float(k), z)
    assert_same_tracks(ss, ref)
    other = CartesianToBearingRange(ndim_state=4, mapping=(0, 2), noise_covar=np.diag([0.01 ** 2, 25.0]),
                                    translation_offset=np.array([[SENSOR[0]], [SENSOR[1]]]))
    with pytest.raises(ValueError, match="meas_sigma"):
        ss.update_tracker(t0 + datetime.timedelta(seconds=100),
                          [Detection(np.array([[0.1], [900.0]]), measurement_model=other)])


SETTINGS_RR = dict(SETTINGS, range_rate_sigma=0.5)


def scene_rr():
    """scene() with each detection's range rate: the target's u . v plus noise, the clutter's
    uniform in +-100."""
    zs, truth = scene()
    rng = np.random.default_rng(12)
    out = []
    for k, z in enumerate(zs):
        x, y = truth[k]
        dx, dy = x - SENSOR[0], y - SENSOR[1]
        rr = (dx * 80.0 + dy * 10.0) / np.hypot(dx, dy)
        col = np.concatenate([[rr + rng.normal(0, 0.5)], rng.uniform(-100, 100, len(z) - 1)])
        out.append(np.column_stack([z, np.full(len(z), np.nan), col]))
    return out, truth


def test_polar_step_with_range_rate():
    zs, truth = scene_rr()
    trk = mtt.Tracker(SETTINGS_RR)
    err = []
    for k, z in enumerate(zs):
        conf = [t for t in trk.step(float(k), z) if t.confirmed]
        if k >= 10:
            assert len(conf) == 1
            err.append(np.hypot(*(conf[0].state[2:4] - (80.0, 10.0))))
    assert 0.05 < np.sqrt(np.mean(np.square(err))) < 3.0  # the velocity, m/s
    with pytest.raises(ValueError, match="range_rate = inf must be finite"):
        trk.step(100.0, [[100.0, 0.1, np.nan, np.inf]])
    no_sigma = mtt.Tracker(SETTINGS)
    with pytest.raises(ValueError, match="range_rate_sigma is 0"):
        no_sigma.step(1.0, zs[0])
    assert no_sigma.time is None


def test_split_takes_polar_and_range_rates():
    """split = true tracks polar detections and their range rates (ALGORITHMS.md sections 3.2, 14.3)."""
    s = dict(SETTINGS_RR, motion="imm", split=True,
             imm_models=[{"model": "cv", "process_psd": 1.0}, {"model": "ca", "process_psd": 50.0}],
             imm_transition=[[0.95, 0.05], [0.1, 0.9]], imm_initial=[0.9, 0.1])
    zs, truth = scene()
    zr, _ = scene_rr()
    for scans in (zs, zr):
        trk = mtt.Tracker(s)
        for k, z in enumerate(scans):
            conf = [t for t in trk.step(float(k), z) if t.confirmed]
        assert len(conf) == 1
        assert np.hypot(*(conf[0].state[:2] - truth[-1])) < 30.0
        if scans is zr:
            assert np.hypot(*(conf[0].state[2:4] - (80.0, 10.0))) < 3.0  # the velocity, m/s


def test_stonesoup_takes_bearing_range_rate_detections():
    try:
        from stonesoup.models.measurement.nonlinear import CartesianToBearingRangeRate
        from stonesoup.types.detection import Detection
    except ImportError:  # pragma: no cover - CI installs the extra
        missing("stonesoup not installed (pip install .[stonesoup])")
    from mtt.stonesoup import MttTracker

    zs, _ = scene_rr()
    t0 = datetime.datetime(2024, 1, 1)
    model = CartesianToBearingRangeRate(ndim_state=4, mapping=(0, 2), velocity_mapping=(1, 3),
                                        noise_covar=np.diag([0.004 ** 2, 25.0, 0.25]),
                                        translation_offset=np.array([[SENSOR[0]], [SENSOR[1]]]))
    ss = MttTracker(settings=SETTINGS_RR)
    ref = mtt.Tracker(SETTINGS_RR)
    for k, z in enumerate(zs):
        ts = t0 + datetime.timedelta(seconds=k)
        dets = {Detection(np.array([[b], [r], [rr]]), timestamp=ts, measurement_model=model)
                for r, b, _, rr in z}
        ss.update_tracker(ts, dets)
        ref.step(float(k), z)
    assert_same_tracks(ss, ref)
