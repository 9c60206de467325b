# SPDX-License-Identifier: BSD-3-Clause
"""A covariance per detection through the package (ALGORITHMS.md section 3.1):
mtt.Tracker.step(..., cov=...) and mtt.stonesoup.MttTracker with each
detection's measurement model."""

import datetime

import numpy as np
import pytest

import mtt

from conftest import missing

SETTINGS = {"association": "ipda", "motion": "cv", "process_psd": 1.0, "meas_sigma": [1.0, 1.0],
            "pd": 0.9, "clutter_density": 1e-3, "vmax": 50.0, "initiate": False,
            "initial_tracks": [{"x": 0.0, "y": 0.0, "vx": 0.0, "vy": 0.0,
                                "P": [[4, 0, 0, 0], [0, 4, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]}]}


def scene():
    rng = np.random.default_rng(5)
    out = []
    for k in range(12):
        z = [[2.0 * k + rng.normal(0, 1.0), 0.5 * k + rng.normal(0, 1.0)]]
        z += rng.uniform(-20, 40, size=(3, 2)).tolist()
        out.append(np.array(z))
    return out


def run(cov_of=None):
    trk = mtt.Tracker(SETTINGS)
    for k, z in enumerate(scene()):
        trk.step(float(k + 1), z, None if cov_of is None else cov_of(z))
    return trk.track_table()


def test_meas_sigma_given_as_cov_gives_the_same_tracks():
    a = run()
    b = run(lambda z: np.tile([1.0, 0.0, 1.0], (len(z), 1)))
    c = run(lambda z: np.tile(np.eye(2), (len(z), 1, 1)))  # (n, 2, 2) form
    assert a.shape == b.shape == c.shape and len(a) >= 1
    np.testing.assert_array_equal(a[:, 0], b[:, 0])  # the same identities
    np.testing.assert_allclose(b[:, 2:6], a[:, 2:6], rtol=1e-4, atol=1e-4)
    np.testing.assert_array_equal(b, c)


def test_a_wide_cov_lets_a_far_detection_update_the_track():
    far = np.array([[9.0, 0.0]])
    plain = mtt.Tracker(SETTINGS)
    x_plain = plain.step(1.0, far)[0].state
    wide = mtt.Tracker(SETTINGS)
    x_wide = wide.step(1.0, far, [[20.0, 0.0, 20.0]])[0].state
    assert abs(x_plain[0]) < 1e-6  # outside meas_sigma's gate: the prediction
    assert x_wide[0] > 0.5         # inside its own: the track moves toward it


def test_bad_cov_raises_and_changes_nothing():
    trk = mtt.Tracker(SETTINGS)
    trk.step(1.0, [[1.0, 1.0]])
    before = trk._core.state_bytes()
    for bad, msg in (([[1.0, 2.0, 1.0]], "cov 0"), ([[-1.0, 0.0, 1.0]], "not a covariance"),
                     ([[1.0, 0.0]], "shape"), ([[np.nan, 0.0, 1.0]], "cov 0"),
                     ([[[1.0, 0.5], [0.4, 1.0]]], "not symmetric")):
        with pytest.raises(ValueError, match=msg):
            trk.step(2.0, [[1.0, 1.0]], bad)
    assert trk._core.state_bytes() == before


def test_split_takes_a_cov():
    """split = true takes each detection's covariance (ALGORITHMS.md section 14.3): the
    seeded track moves less towards a detection whose own R is 100 times meas_sigma's."""
    s = dict(SETTINGS, motion="imm", split=True, association="lm-ihpda")
    a, b = mtt.Tracker(s), mtt.Tracker(s)
    xa = a.step(1.0, [[6.0, 0.0]], [[0.0, 0.0, 0.0]])[0].state[0]  # zeros: meas_sigma's
    xb = b.step(1.0, [[6.0, 0.0]], [[100.0, 0.0, 100.0]])[0].state[0]
    assert xa > 1.0
    assert 0.0 < xb < 0.5 * xa


def test_stonesoup_takes_each_detections_measurement_model():
    try:
        from stonesoup.models.measurement.linear import LinearGaussian
        from stonesoup.types.detection import Detection
    except ImportError:  # pragma: no cover - CI installs the extra
        missing("stonesoup not installed (pip install .[stonesoup])")
    from mtt.stonesoup import MttTracker

    t0 = datetime.datetime(2024, 1, 1)
    covs = [np.array([[9.0, 2.0], [2.0, 4.0]]), np.array([[0.25, 0.0], [0.0, 0.5]])]
    ss = MttTracker(settings=SETTINGS)
    ref = mtt.Tracker(SETTINGS)
    for k, z in enumerate(scene()):
        ts = t0 + datetime.timedelta(seconds=k + 1)
        dets = []
        for i, p in enumerate(z):
            model = LinearGaussian(ndim_state=4, mapping=(0, 2), noise_covar=covs[i % 2])
            dets.append(Detection(np.array([[p[0]], [p[1]]]), timestamp=ts, measurement_model=model))
        ss.update_tracker(ts, set(dets))
        ref.step(float(k + 1) - 1.0, z, [covs[i % 2][[0, 0, 1], [0, 1, 1]] for i in range(len(z))])
    got = {int(t.id): t.state_vector.ravel() for t in ss.tracks}
    want = {t.id: t.state for t in ref.tracks if t.confirmed}
    assert set(got) == set(want) and len(got) >= 1
    for i, sv in got.items():
        np.testing.assert_allclose(sv[[0, 2, 1, 3]], want[i], rtol=1e-9, atol=1e-9)
