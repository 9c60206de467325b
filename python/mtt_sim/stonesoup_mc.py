#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Monte Carlo runs of a scenario through Stone Soup's JPDA: a baseline on mtt's own detections.

    PYTHONPATH=python python3 -m mtt_sim.stonesoup_mc --scenario scenarios/split_fast.json --runs 50 \\
        --out out/ss_fast

Run r draws seed SEED0 + r with mtt_sim.gen exactly as mtt_sim.mc does
(the same detections, handed over with the digits mtt-track reads from the
detections file), tracks it with Stone Soup's MultiTargetMixtureTracker + JPDA
and scores it with mtt_sim.metrics.score_run: OUT/report.txt (also printed)
and OUT/summary.json have mc's shape, one mode named "stonesoup-jpda".
Every Stone Soup track counts as a confirmed track (Stone Soup has no
tentative state: the initiator holds its candidates until they are sure).

Stone Soup configuration (docs/PYTHON.md "Stone Soup JPDA baseline"), every
number from the scenario's tracker settings:
  KalmanPredictor with CombinedLinearGaussianTransitionModel of
  ConstantVelocity(process_psd) per axis; KalmanUpdater with LinearGaussian
  (mapping x, y; R = diag(meas_sigma^2)); JPDA (--associator ehm:
  JPDAwithEHM, the same probabilities, faster) with PDAHypothesiser
  (prob_detect = pd, prob_gate = pg, clutter_spatial_density =
  clutter_density, or the scenario's mean clutter / area when the tracker
  estimates it, clutter_density = 0); MultiMeasurementInitiator fed with the
  detections JPDA left unassociated: its own GNN (GNNWith2DAssignment,
  DistanceHypothesiser with the Mahalanobis distance gated at --init-gate,
  default sqrt(-2 ln(1 - pg))), prior velocity N(0, --vel-std^2) per axis
  (default vmax^2 / 3, the variance of a uniform speed in [-vmax, vmax]),
  --min-points detections to confirm (default 5), candidates dropped after
  --hold scans without one (default 1: 5 detections in a row); track
  deleter --deleter (default steps:3, UpdateTimeStepsDeleter(3)); the
  scenario's initial_tracks enter as tracks 0, 1, ... with the two-point
  covariance (docs/ALGORITHMS.md §12.1) of the first scan interval.

Needs Stone Soup (pip install stone-soup; the module itself imports without
it).  Progress on stderr.  Exit status: 0 if every run succeeded, 1 if some
failed, 2 on bad arguments or without Stone Soup.
"""

from __future__ import annotations

import argparse
import datetime
import json
import math
import os
import sys
import time

import numpy as np

from . import mc, report, scenario

MODE = "stonesoup-jpda"
T0 = datetime.datetime(2000, 1, 1)
DEFAULTS = {"process_psd": 5.0, "pd": 0.9, "pg": 0.999, "vmax": 60.0, "clutter_density": 0.0}  # docs/FORMATS.md
# the initiation and deletion chosen on the tuning seeds (docs/PYTHON.md "Stone Soup JPDA baseline"):
# 5 detections in 5 consecutive scans start a track, 3 scans without one end it
MIN_POINTS, HOLD, DELETER = 5, 1, "steps:3"


def stonesoup_version() -> str | None:
    try:
        import stonesoup
    except ImportError:
        return None
    return stonesoup.__version__


def mean_clutter(scn: dict) -> float:
    """Mean number of clutter detections per scan of the scenario's clutter model."""
    cl = scn.get("clutter", {})
    if cl.get("model") == "poisson":
        return float(cl["mean"]) if "mean" in cl else float(cl["density"]) * scenario.clutter_measure(scn)
    if cl.get("model") == "binomial":
        return int(cl["n"]) * float(cl["p"])
    return 0.0


class JpdaTracker:
    """A callable for mc.one_run: ``tracker(run) -> (tracks table, seconds)``.

    ``min_points``: updates a candidate needs to become a track; ``deleter``:
    "steps:N" (UpdateTimeStepsDeleter, no detection in the last N scans),
    "covar:F" (CovarianceBasedDeleter on the position covariance's trace >
    F (sigma_x^2 + sigma_y^2)), or both joined by "+" (deleted when either
    says so); ``vel_std``: the initiator's prior velocity standard deviation
    per axis (default vmax / sqrt(3)); ``init_gate``: the initiator's
    Mahalanobis gate (default sqrt(-2 ln(1 - pg))); ``hold``: scans without
    a detection after which a candidate is dropped (UpdateTimeStepsDeleter);
    ``associator``: "jpda" (JPDA) or "ehm" (JPDAwithEHM, the same marginals).
    """

    def __init__(self, scn: dict, min_points: int = MIN_POINTS, deleter: str = DELETER,
                 vel_std: float | None = None, init_gate: float | None = None, hold: int = HOLD,
                 associator: str = "jpda"):
        trk = scn["tracker"]
        self.cfg = {k: float(trk.get(k, v)) for k, v in DEFAULTS.items()}
        self.cfg["meas_sigma"] = [float(v) for v in (trk["meas_sigma"] if "meas_sigma" in trk else scn["meas_sigma"])]
        if self.cfg["clutter_density"] <= 0.0:  # mtt estimates it: give Stone Soup the true mean
            self.cfg["clutter_density"] = mean_clutter(scn) / scenario.clutter_measure(scn)
        if self.cfg["clutter_density"] <= 0.0:
            raise scenario.ScenarioError("Stone Soup's PDAHypothesiser needs a clutter density > 0 "
                                         "(tracker.clutter_density, or clutter in the scenario)")
        self.deleter = []
        for part in deleter.split("+"):
            kind, _, arg = part.partition(":")
            try:
                val = float(arg)
            except ValueError:
                val = 0.0
            if kind not in ("steps", "covar") or val <= 0.0:
                raise ValueError(f"deleter must be steps:N, covar:F or both joined by +, not {deleter!r}")
            self.deleter.append((kind, val))
        if min_points < 1 or hold < 1:
            raise ValueError("min_points and hold must be >= 1")
        if associator not in ("jpda", "ehm"):
            raise ValueError(f"associator must be jpda or ehm, not {associator!r}")
        self.min_points, self.hold, self.associator = int(min_points), int(hold), associator
        self.cfg["vel_std"] = float(vel_std) if vel_std is not None else self.cfg["vmax"] / math.sqrt(3.0)
        self.cfg["init_gate"] = (float(init_gate) if init_gate is not None
                                 else math.sqrt(-2.0 * math.log(1.0 - self.cfg["pg"])))
        if self.cfg["vel_std"] <= 0.0 or self.cfg["init_gate"] <= 0.0:
            raise ValueError("vel_std and init_gate must be > 0")
        self.initial = trk.get("initial_tracks") or []

    def _components(self):
        from stonesoup.dataassociator.neighbour import GNNWith2DAssignment
        from stonesoup.dataassociator.probability import JPDA, JPDAwithEHM
        from stonesoup.deleter.error import CovarianceBasedDeleter
        from stonesoup.deleter.multi import CompositeDeleter
        from stonesoup.deleter.time import UpdateTimeStepsDeleter
        from stonesoup.hypothesiser.distance import DistanceHypothesiser
        from stonesoup.hypothesiser.probability import PDAHypothesiser
        from stonesoup.initiator.simple import MultiMeasurementInitiator
        from stonesoup.measures import Mahalanobis
        from stonesoup.models.transition.linear import CombinedLinearGaussianTransitionModel, ConstantVelocity
        from stonesoup.predictor.kalman import KalmanPredictor
        from stonesoup.tracker.simple import MultiTargetMixtureTracker
        from stonesoup.types.state import GaussianState

        c = self.cfg
        self.meas_model, updater = self._measurement()
        predictor = KalmanPredictor(CombinedLinearGaussianTransitionModel(
            [ConstantVelocity(c["process_psd"]), ConstantVelocity(c["process_psd"])]))
        jpda = (JPDA if self.associator == "jpda" else JPDAwithEHM)(PDAHypothesiser(
            predictor, updater, clutter_spatial_density=c["clutter_density"], prob_detect=c["pd"], prob_gate=c["pg"]))
        deleters = [UpdateTimeStepsDeleter(int(arg)) if kind == "steps"
                    else CovarianceBasedDeleter(arg * self._position_variance(), mapping=[0, 2])
                    for kind, arg in self.deleter]
        deleter = deleters[0] if len(deleters) == 1 else CompositeDeleter(deleters, intersect=False)
        v2 = c["vel_std"] ** 2
        initiator = MultiMeasurementInitiator(
            prior_state=GaussianState(np.zeros(4), np.diag([0.0, v2, 0.0, v2])),
            deleter=UpdateTimeStepsDeleter(self.hold), measurement_model=self.meas_model,
            data_associator=GNNWith2DAssignment(DistanceHypothesiser(
                predictor, updater, Mahalanobis(), missed_distance=c["init_gate"])),
            updater=updater, min_points=self.min_points)
        return MultiTargetMixtureTracker(initiator=initiator, deleter=deleter, detector=None,
                                         data_associator=jpda, updater=updater)

    def _measurement(self):
        """(measurement model, updater): LinearGaussian on x, y with R = diag(meas_sigma^2), KalmanUpdater."""
        from stonesoup.models.measurement.linear import LinearGaussian
        from stonesoup.updater.kalman import KalmanUpdater

        sx, sy = self.cfg["meas_sigma"]
        model = LinearGaussian(4, (0, 2), np.diag([sx * sx, sy * sy]))
        return model, KalmanUpdater(model)

    def _position_variance(self) -> float:
        """sigma_x^2 + sigma_y^2 of one detection (the covariance deleter's unit)."""
        sx, sy = self.cfg["meas_sigma"]
        return sx * sx + sy * sy

    def _vector(self, z):
        """A detection's Stone Soup state vector from its row of :meth:`detections`."""
        return z.reshape(2, 1)

    def seeded_tracks(self, dt: float, t0: datetime.datetime) -> list:
        """The scenario's initial_tracks as Stone Soup tracks ([x, vx, y, vy]), §12.1's covariance or "P"."""
        from stonesoup.types.state import GaussianState
        from stonesoup.types.track import Track

        out = []
        perm = [0, 2, 1, 3]  # mtt's x, y, vx, vy -> Stone Soup's x, vx, y, vy
        for s in self.initial:
            if "P" in s:
                P = np.asarray(s["P"], float).reshape(4, 4)[np.ix_(perm, perm)]
            else:
                P = np.zeros((4, 4))
                for i, sig in ((0, self.cfg["meas_sigma"][0]), (2, self.cfg["meas_sigma"][1])):
                    r = sig * sig
                    P[i:i + 2, i:i + 2] = [[r, r / dt], [r / dt, 2.0 * r / (dt * dt)]]
            out.append(Track([GaussianState([s["x"], s["vx"], s["y"], s["vy"]], P, timestamp=t0)]))
        return out

    def detections(self, run: dict) -> list:
        """Per scan, the (n, 2) detections as mtt-track reads them from the run's file (%.10g), in file order."""
        det = run["det"]
        scans = np.asarray(det["scan"], int)
        xy = np.column_stack([mc.text_values(det["x"], 10), mc.text_values(det["y"], 10)])
        return [xy[scans == k] for k in range(len(run["times"]))]

    @staticmethod
    def _record(k, live, ids, rows):
        """Rows (scan, id, x, y, vx, vy, pxx, pxy, pyy) of the live tracks; new ones get the next ids
        in the order of their position (Stone Soup's tracks are a set)."""
        new = sorted((tr for tr in live if tr not in ids), key=lambda tr: (tr.state_vector[0, 0], tr.state_vector[2, 0]))
        for tr in new:
            ids[tr] = len(ids)
        for tr in live:
            x, P = tr.state_vector.ravel(), tr.covar
            rows.append((k, ids[tr], x[0], x[2], x[1], x[3], P[0, 0], P[0, 2], P[2, 2]))

    def __call__(self, run: dict):
        from stonesoup.types.detection import Detection

        times = mc.text_values(run["times"], 10)
        dt = float(times[1] - times[0]) if len(times) > 1 else 1.0
        per_scan = self.detections(run)
        tracker = self._components()  # outside the timing: the first run of a process imports Stone Soup here
        t_start = time.perf_counter()
        ts = [T0 + datetime.timedelta(seconds=float(t - times[0])) for t in times]
        ids = {}  # Stone Soup track -> our id
        for tr in self.seeded_tracks(dt, ts[0]):
            ids[tr] = len(ids)
            tracker._tracks.add(tr)  # MultiTargetMixtureTracker keeps its tracks there; no public setter
        rows = []
        try:
            for k, t in enumerate(ts):
                # at scan 0 the seeded tracks' prediction is over 0 s (F = I, Q = 0): mtt's first frame (§15)
                dets = {Detection(self._vector(z), timestamp=t, measurement_model=self.meas_model)
                        for z in per_scan[k]}
                _, live = tracker.update_tracker(t, dets)
                self._record(k, live, ids, rows)
        except (np.linalg.LinAlgError, ValueError) as e:
            raise mc.TrackerError(f"Stone Soup: {e}") from None
        elapsed = time.perf_counter() - t_start
        rows.sort(key=lambda r: (r[0], r[1]))
        a = np.array(rows, float).reshape(-1, 9)
        scan = a[:, 0].astype(int)
        tracks = {"scan": scan, "time": times[scan], "track": a[:, 1].astype(int),
                  "confirmed": np.ones(len(a), bool), "existence": np.ones(len(a))}
        for i, name in enumerate(("x", "y", "vx", "vy", "pxx", "pxy", "pyy")):
            tracks[name] = a[:, 2 + i]
        return tracks, elapsed


class EkfJpdaTracker(JpdaTracker):
    """JpdaTracker on a radar's polar detections: Stone Soup's CartesianToBearingRange with an EKF.

    The measurement model is CartesianToBearingRange(4, (0, 2)) at the
    tracker settings' ``sensor_xy`` (translation_offset), noise covariance
    diag(sigma_b^2, sigma_r^2) in Stone Soup's [bearing, range] order from
    ``meas_sigma`` = [sigma_r, sigma_b]; ExtendedKalmanUpdater; the
    PDAHypothesiser's clutter density is the settings' polar
    ``clutter_density`` (per range x bearing: the measurement space's own
    unit). The initiator is the same, its first covariance the detection's
    converted through the model's inverse Jacobian (Stone Soup's
    SimpleMeasurementInitiator for a reversible model). No range rate.
    """

    def __init__(self, scn: dict, *args, **kwargs):
        super().__init__(scn, *args, **kwargs)
        trk = scn["tracker"]
        if trk.get("measurement") != "polar" or "sensor_xy" not in trk:
            raise scenario.ScenarioError("the EKF JPDA needs polar tracker settings (measurement polar, sensor_xy, "
                                         "meas_sigma [sigma_range, sigma_bearing])")
        if self.initial:
            raise scenario.ScenarioError("the EKF JPDA takes no initial_tracks")
        self.cfg["sensor_xy"] = [float(v) for v in trk["sensor_xy"]]

    def _measurement(self):
        from stonesoup.models.measurement.nonlinear import CartesianToBearingRange
        from stonesoup.updater.kalman import ExtendedKalmanUpdater

        sr, sb = self.cfg["meas_sigma"]
        xs, ys = self.cfg["sensor_xy"]
        model = CartesianToBearingRange(4, (0, 2), np.diag([sb * sb, sr * sr]),
                                        translation_offset=np.array([[xs], [ys]]))
        return model, ExtendedKalmanUpdater(model)

    def _position_variance(self) -> float:
        return 2.0 * self.cfg["meas_sigma"][0] ** 2

    def _vector(self, z):
        from stonesoup.types.angle import Bearing
        from stonesoup.types.array import StateVector

        return StateVector([Bearing(z[0]), z[1]])

    def detections(self, run: dict) -> list:
        """Per scan, the (n, 2) [bearing, range] as mtt-track reads them from the polar file (%.10g), in file order."""
        det = run["det"]
        if "range" not in det:
            raise mc.TrackerError("the EKF JPDA needs a radar's polar detections")
        scans = np.asarray(det["scan"], int)
        z = np.column_stack([mc.text_values(det["bearing"], 10), mc.text_values(det["range"], 10)])
        return [z[scans == k] for k in range(len(run["times"]))]


def _fmt_s(ms_per_frame, nscan) -> str:
    return "-" if ms_per_frame is None else f"{ms_per_frame * nscan / 1e3:.2f} s"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    mc.add_run_arguments(ap)
    ap.add_argument("--min-points", type=int, default=MIN_POINTS,
                    help=f"detections a candidate needs to become a track (default {MIN_POINTS})")
    ap.add_argument("--deleter", default=DELETER,
                    help="steps:N = no detection in the last N scans, covar:F = position covariance trace > "
                         f"F (sx^2 + sy^2), or both joined by + (default {DELETER})")
    ap.add_argument("--vel-std", type=float, help="initiator's prior velocity std per axis, m/s "
                    "(default vmax / sqrt(3))")
    ap.add_argument("--init-gate", type=float, help="initiator's Mahalanobis gate (default sqrt(-2 ln(1 - pg)))")
    ap.add_argument("--hold", type=int, default=HOLD,
                    help=f"scans without a detection after which the initiator drops a candidate (default {HOLD})")
    ap.add_argument("--associator", choices=("jpda", "ehm"), default="jpda",
                    help="jpda: JPDA, ehm: JPDAwithEHM (the same association probabilities; default jpda)")
    a = ap.parse_args(argv)
    if a.runs < 1 or a.jobs < 1:
        ap.error("--runs and --jobs must be >= 1")
    version = stonesoup_version()
    if version is None:
        print("stonesoup_mc.py: Stone Soup is not installed (pip install stone-soup, or pip install '.[stonesoup]')",
              file=sys.stderr)
        return 2
    try:
        scn = scenario.load(a.scenario, a.set)
        trk = JpdaTracker(scn, a.min_points, a.deleter, a.vel_std, a.init_gate, a.hold, a.associator)
    except (scenario.ScenarioError, ValueError, OSError) as e:
        print(f"stonesoup_mc.py: {e}", file=sys.stderr)
        return 2
    os.makedirs(a.out, exist_ok=True)
    res = mc.monte_carlo(scn, [MODE], a.runs, trk, a.jobs, a.seed0,
                         keep_root=os.path.join(a.out, "run0"))
    label = (f"Stone Soup {version} {'JPDA' if a.associator == 'jpda' else 'JPDAwithEHM'} (min_points "
             f"{a.min_points}, deleter {a.deleter}, vel_std {trk.cfg['vel_std']:.4g}, init_gate "
             f"{trk.cfg['init_gate']:.4g}, hold {a.hold})")
    summary = mc.build_summary(scn, a.scenario, a.set, [MODE], a.runs, a.seed0, label, res)
    summary["stonesoup"] = {"version": version, "min_points": a.min_points, "deleter": a.deleter,
                            "hold": a.hold, "associator": a.associator, "config": trk.cfg}
    with open(os.path.join(a.out, "summary.json"), "w", encoding="utf-8") as f:
        json.dump(summary, f, indent=1)
        f.write("\n")
    tpf = summary["results"][MODE]["totals"]["time_per_frame_ms"]["mean"]
    text = report.full_report(summary) + (
        f"{label}; wall time per run {res['wall_s'] / a.runs:.2f} s ({res['jobs']} jobs), "
        f"Stone Soup's tracking {_fmt_s(tpf, len(summary['scan_times']))} per run (one process)\n")
    with open(os.path.join(a.out, "report.txt"), "w", encoding="utf-8") as f:
        f.write(text)
    sys.stdout.write(text)
    return 1 if summary["results"][MODE]["runs_failed"] else 0


if __name__ == "__main__":
    sys.exit(main())
