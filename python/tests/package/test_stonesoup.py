# SPDX-License-Identifier: BSD-3-Clause
"""mtt.stonesoup.MttTracker in a Stone Soup pipeline: a DetectionReader feeds it,
Stone Soup's GOSPAMetric (through its MultiManager) scores it, and the figures
equal those of mtt-track's tracks of the same detections scored the same way."""

import datetime
import os

import numpy as np
import pytest

from conftest import missing, run_mtt_track

try:
    import stonesoup  # noqa: F401
except ImportError:  # pragma: no cover - CI installs the extra
    stonesoup = None

T0 = datetime.datetime(2024, 1, 1, 12, 0, 0)


@pytest.fixture(scope="module")
def ss():
    if stonesoup is None:
        missing("stonesoup not installed (pip install .[stonesoup])")
    from stonesoup.base import Property
    from stonesoup.reader.base import DetectionReader
    from stonesoup.buffered_generator import BufferedGenerator
    from stonesoup.types.detection import Detection

    class ScanReader(DetectionReader):
        """Scans of a detections table: (timestamp, list of Detection) in file order."""
        det: dict = Property(doc="detections table (mtt_sim.csvio)")
        times: dict = Property(doc="scan -> time in seconds")

        @BufferedGenerator.generator_method
        def detections_gen(self):
            for k in sorted(self.times):
                ts = T0 + datetime.timedelta(seconds=self.times[k] - self.times[min(self.times)])
                sel = np.flatnonzero(self.det["scan"] == k)
                dets = []
                for i in sel:
                    a = self.det["amp"][i]
                    md = {} if np.isnan(a) else {"amplitude": float(a)}
                    dets.append(Detection(np.array([[self.det["x"][i]], [self.det["y"][i]]]),
                                          timestamp=ts, metadata=md))
                yield ts, dets

    return {"ScanReader": ScanReader}


def truth_paths(truth, time0):
    """Stone Soup ground truth, times counted from the first scan's time0 as the detections'."""
    from stonesoup.types.groundtruth import GroundTruthPath, GroundTruthState

    paths = {}
    for i in range(len(truth["scan"])):
        ts = T0 + datetime.timedelta(seconds=float(truth["time"][i] - time0))
        p = paths.setdefault(int(truth["target"][i]), GroundTruthPath(id=str(int(truth["target"][i]))))
        p.append(GroundTruthState([truth["x"][i], truth["vx"][i], truth["y"][i], truth["vy"][i]],
                                  timestamp=ts))
    return set(paths.values())


def gospa(tracks, truths, c):
    from stonesoup.measures import Euclidean
    from stonesoup.metricgenerator.manager import MultiManager
    from stonesoup.metricgenerator.ospametric import GOSPAMetric

    gen = GOSPAMetric(c=c, p=1, measure=Euclidean(mapping=(0, 2)))
    mgr = MultiManager([gen])
    mgr.add_data({"tracks": tracks, "groundtruth_paths": truths})
    m = mgr.generate_metrics()["gospa_generator"]["GOSPA Metrics"]
    return {s.timestamp: s.value["distance"] for s in m.value}


def tracks_from_csv(path, time0):
    """Stone Soup tracks of mtt-track's rows: every row of each id that was ever confirmed."""
    from mtt_sim import csvio
    from stonesoup.types.state import GaussianState
    from stonesoup.types.track import Track

    t = csvio.read_tracks(path)
    ever = set(t["track"][t["confirmed"]].tolist())
    out = {}
    for i in range(len(t["scan"])):
        tid = int(t["track"][i])
        if tid not in ever:
            continue
        ts = T0 + datetime.timedelta(seconds=float(t["time"][i] - time0))
        x = [t["x"][i], t["vx"][i], t["y"][i], t["vy"][i]]
        out.setdefault(tid, Track(id=str(tid))).append(GaussianState(x, np.eye(4), timestamp=ts))
    return set(out.values())


@pytest.mark.parametrize("name, seed", [("crossing3", 3), ("formations", 1)])
def test_pipeline_gospa_equals_mtt_track(name, seed, ss, mtt_track, scenario_run, tmp_path):
    from mtt_sim import csvio
    from mtt.stonesoup import MttTracker
    from stonesoup.types.track import Track

    scn, run, files = scenario_run(name, seed)
    det, times = csvio.read_det(files["det"])
    reader = ss["ScanReader"](det=det, times=times)
    tracker = MttTracker(detector=reader, settings=files["settings"])
    ever = set()
    steps = 0
    for ts, tracks in tracker:
        steps += 1
        assert all(isinstance(t, Track) and t.metadata["confirmed"] for t in tracks)
        assert not (tracks & tracker.tentative_tracks)
        for t in tracks:
            assert t.state.timestamp == ts and t.state_vector.shape == (4, 1)
            assert 0.0 <= t.metadata["existence"] <= 1.0
        ever |= tracks
    assert steps == len(times) and ever

    csv = str(tmp_path / "t.tracks.csv")
    p = run_mtt_track(mtt_track, files["settings"], files["det"], csv)
    assert p.returncode == 0, p.stderr
    ref = tracks_from_csv(csv, times[min(times)])
    assert sorted(t.id for t in ever) == sorted(t.id for t in ref)

    truths = truth_paths(run["truth"], times[min(times)])
    c = float(scn.get("metrics", {}).get("gospa_c", scn.get("metrics", {}).get("match_distance", 10.0)))
    mine, theirs = gospa(ever, truths, c), gospa(ref, truths, c)
    assert list(mine) == list(theirs)
    np.testing.assert_allclose([mine[k] for k in mine], [theirs[k] for k in theirs], rtol=1e-6, atol=1e-9)
    assert max(mine.values()) > 0.0
    print(f"\n{name} seed {seed}: {len(ever)} tracks ever confirmed; Stone Soup GOSPA (c={c:g}, p=1) "
          f"mean over {len(mine)} scans: MttTracker {np.mean(list(mine.values())):.6f}, "
          f"mtt-track {np.mean(list(theirs.values())):.6f}")


def test_identities_same_for_sets_in_any_order(ss, scenario_run):
    """A detector that yields sets (Stone Soup's readers do): the confirmed tracks, their
    identities and states are the same whatever order each scan's set iterates in."""
    import random
    from mtt_sim import csvio
    from mtt.stonesoup import MttTracker
    from stonesoup.types.detection import Detection

    scn, run, files = scenario_run("crossing3", 3)
    det, times = csvio.read_det(files["det"])
    order = [None, random.Random(7), "reversed"]
    trackers = [MttTracker(settings=files["settings"]) for _ in order]
    births = 0
    for k in sorted(times):
        ts = T0 + datetime.timedelta(seconds=times[k] - times[min(times)])
        sel = np.flatnonzero(det["scan"] == k)
        dets = {Detection(np.array([[det["x"][i]], [det["y"][i]]]), timestamp=ts,
                          metadata={} if np.isnan(det["amp"][i]) else {"amplitude": float(det["amp"][i])})
                for i in sel}
        out = []
        for how, trk in zip(order, trackers):
            lst = sorted(dets, key=lambda d: (d.state_vector[0, 0], d.state_vector[1, 0]))
            if how == "reversed":
                lst.reverse()
            elif how is not None:
                how.shuffle(lst)
            _, tracks = trk.update_tracker(ts, set(lst) if how is None else lst)
            out.append({t.id: t.state_vector.ravel().tolist() for t in tracks | trk.tentative_tracks})
        assert out[1] == out[0] and out[2] == out[0], f"scan {k}"
        births = max(births, max((int(i) for i in out[0]), default=-1) + 1)
    assert births > 3  # identities were handed out: the targets' and clutter's


def test_track_objects_stable_and_cv_order(ss):
    from mtt.stonesoup import MttTracker
    from stonesoup.types.detection import Detection

    trk = MttTracker(settings={"meas_sigma": [1.0, 1.0], "vmax": 10.0, "clutter_density": 1e-4})
    seen = {}
    for k in range(8):
        ts = T0 + datetime.timedelta(seconds=k)
        dets = [Detection([[10.0 + 2 * k], [5.0 - k]], timestamp=ts, metadata={"amplitude": 2.0}),
                Detection([[-30.0], [40.0 + 3 * k]], timestamp=ts)]
        t, tracks = trk.update_tracker(ts, dets)
        assert t == ts
        for tr in tracks | trk.tentative_tracks:
            assert seen.setdefault(tr.id, tr) is tr  # the same Track object every scan
    conf = sorted(trk.tracks, key=lambda t: int(t.id))
    assert len(conf) == 2
    a = next(t for t in conf if abs(t.state_vector[0, 0] - 24.0) < 1.0)
    # CV order [x, vx, y, vy]
    np.testing.assert_allclose(a.state_vector.ravel(), [24.0, 2.0, -2.0, -1.0], atol=0.2)
    mt = {t.id: t for t in trk.mtt.tracks}[int(a.id)]
    P = mt.covar
    assert a.covar[1, 1] == P[2, 2] and a.covar[0, 1] == P[0, 2] and a.covar[2, 3] == P[1, 3]
    assert len(a.states) == 7 and a.metadata["existence"] == pytest.approx(mt.existence)


def test_bad_detection_raises_and_changes_nothing(ss):
    from mtt.stonesoup import MttTracker
    from stonesoup.types.detection import Detection

    trk = MttTracker()
    trk.update_tracker(T0, [Detection([[1.0], [2.0]], timestamp=T0)])
    before = trk.mtt._core.state_bytes()
    t1 = T0 + datetime.timedelta(seconds=1)
    with pytest.raises(ValueError):
        trk.update_tracker(t1, [Detection([[1.0], [2.0], [3.0]], timestamp=t1)])
    with pytest.raises(ValueError):
        trk.update_tracker(T0, [])  # not later
    with pytest.raises(ValueError):
        trk.update_tracker(t1, [Detection([[1.0], [2.0]], timestamp=t1, metadata={"amplitude": -1})])
    assert trk.mtt._core.state_bytes() == before
    with pytest.raises(AttributeError):
        iter(trk)  # no detector
