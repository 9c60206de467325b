# SPDX-License-Identifier: BSD-3-Clause
"""Differential test: the library (double build) against python/mtt_ref.

mtt_ref is an independent reference of the per-frame pipeline, written from
docs/ALGORITHMS.md (not from src/).  Both run the same scenes; after every
frame they must report the same live tracks (id, confirmed, age, and for the
IHPDA modes the measurement used) and the same state, covariance and
existence within REL = 1e-9 relative, with an absolute floor (see close()).

Scenes: N_RANDOM random small scenes (1-6 targets, 3-30 frames, clutter,
random valid parameters, random seeded tracks; deterministic seeds), the
regression cases of test/differential/cases/, and a few full scenarios made
by the simulation package's generator from scenarios/*.json.  The JPDA
family (mtt_ref.tracker.JPDA_MODES: [S1]'s variants, §13) has its own rows:
N_JPDA random scenes, the mode taken in turn, and coalesce3 and crossing3.

A scene in which the reference took a decision on two numbers closer than
1e-9 relative (mtt_ref.tracker TIE_REL: a gate or threshold test, an argmax)
is "tie-sensitive": two correct double implementations may decide it
differently, so a disagreement there is counted apart, not failed, and
the count is printed.  Every other disagreement fails the test, except the
scenes that EXPECTED_FAILURES explains.

Run:  ctest --preset host-double -R differential
  or  MTT_DIFF_DRIVER=build/host-double/test/differential/mtt-diff-driver PYTHONPATH=python \
      python3 -m unittest -v python/tests/test_differential.py
  or  PYTHONPATH=python python3 python/tests/test_differential.py [-v]
      (finds the driver under build/host-double)
Environment: MTT_DIFF_SCENES (default 2000) random scenes, MTT_DIFF_JPDA_SCENES
(default 350) those of the JPDA family; MTT_DIFF_KEEP=DIR
writes every failing scene there.
"""

import glob
import json
import math
import os
import subprocess
import sys
import tempfile
import unittest
from collections import Counter

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.environ.get("MTT_SOURCE_DIR") or os.path.dirname(os.path.dirname(HERE))

from mtt_ref import Scene, parse_driver_output, read_scene, two_point_cov, write_scene  # noqa: E402

REL = 1e-9
N_RANDOM = int(os.environ.get("MTT_DIFF_SCENES", "2000"))
N_JPDA = int(os.environ.get("MTT_DIFF_JPDA_SCENES", "350"))
# The JPDA-family rows, in turn: [S1]'s gate-shrink variants first (§13.7).
JPDA_ROWS = ("jpda-vg", "adaptive-nnjpda", "adaptive-jpda-star", "jpda", "nnjpda", "jpda-star", "adaptive-jpda")
CASES_DIR = os.path.join(ROOT, "test", "differential", "cases")

# EXPECTED TO FAIL: scenes known to disagree because of a bug in the C library:
# file name under test/differential/cases/ -> the bug (KNOWN_C_BUGS below, with
# the diagnosis).  A case listed here must still fail (so the list cannot go
# stale); once the library is fixed, remove it from this list (and the bug from
# KNOWN_C_BUGS) and it becomes a plain regression.
EXPECTED_FAILURES = {}


def _valid(d):
    x, y, a = d
    return math.isfinite(x) and math.isfinite(y) and (a is None or (math.isfinite(a) and a >= 0.0))


# The C bugs behind EXPECTED_FAILURES: diagnosis, and the trigger that tells a
# random scene that disagrees because of this bug (it is then counted under
# the bug, not failed; any scene without the trigger that disagrees fails).
KNOWN_C_BUGS = {}
# Fixed, kept as regressions: "meas-at-max" (a frame with exactly MTT_MAX_MEAS
# valid detections lost their input order: the cap's heap was built but not
# re-sorted; cases meas-at-max-rank-tie.scene, meas-at-max-birth-order.scene).

# Readings the spec once left open (the reference's "SPEC GAP" marks in
# python/mtt_ref/tracker.py), now stated in docs/ALGORITHMS.md as [CHOICE]
# paragraphs; the library and the reference agree with them on every scene.
# Topic -> (section, a phrase of that section that states it, regression cases
# or "" when the random scenes cover it).  test_regression_cases checks that each section
# still says it.
SPEC_GAPS_DOCUMENTED = {
    "birth velocity cap": ("12.1", "Velocity cap.", "birth-velocity-cap.scene"),
    "birth order": ("12.1", "Birth order.", "birth-pair-order.scene"),
    "first frame": ("15", "First frame.", "first-frame-seeded.scene"),
    "track age": ("15", "Track age.", "first-frame-seeded.scene"),
    "IPDA's reported measurement": ("6", "Reported measurement.", ""),
    "row ties: ihpda's selection": ("7.4", "Scope of this tie rule.", "row-tie-ihpda-rank.scene"),
    "row ties: MMR": ("10.1", "Ties, precisely.", "row-tie-mmr-index.scene"),
    "missing amplitude": ("7.1", "whatever set a row is computed over", ""),
    "f2 clamp": ("12.2", "peak of the **configured** f2", "intensity-clamp-at-f2-peak.scene"),
    "intensity gate and dT": ("12.2", "Frame interval.", ""),
    "caps: order and ties": ("16", "Overflow of the bounds: order and ties.", ""),
    "gate cap ties": ("7.2", "equal d² at the cut: the lower measurement index stays", ""),
    "LM rounding": ("8.2", "where rounding decides", ""),
    "LM over all tracks": ("8.3", "P̃'s sum runs over σ's gate and j", ""),
}


def algorithms_section(number):
    """Text of section `number` ("12.1", "15") of docs/ALGORITHMS.md, up to the next heading."""
    with open(os.path.join(ROOT, "docs", "ALGORITHMS.md"), encoding="utf-8") as fh:
        lines = fh.read().split("\n")
    out, inside = [], False
    for line in lines:
        if line.startswith("#"):
            inside = line.lstrip("#").strip().startswith(number + " ") or \
                     line.lstrip("#").strip().startswith(number + ". ")
            continue
        if inside:
            out.append(line)
    return "\n".join(out)


# The one place that knows where the scenario generator lives (python/mtt_sim).
def generate_scenario(scenario, seed, out):
    """Run the simulation package's generator; returns (settings dict, det.csv path)."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.path.join(ROOT, "python") + os.pathsep + env.get("PYTHONPATH", "")
    cmd = [sys.executable, "-m", "mtt_sim.gen",
           os.path.join(ROOT, "scenarios", scenario + ".json"), "--seed", str(seed), "--out", out]
    subprocess.run(cmd, check=True, capture_output=True, env=env)
    name = os.path.join(out, scenario)
    with open(name + ".settings.json") as fh:
        settings = json.load(fh)
    return settings, name + ".det.csv"


def find_driver():
    """MTT_DIFF_DRIVER (ctest sets it).  Only a direct run of this file looks under
    build/host-double, so that a `unittest discover` of python/tests in another
    build skips this test instead of running it a second time."""
    d = os.environ.get("MTT_DIFF_DRIVER")
    if d or __name__ != "__main__":
        return d
    for cand in glob.glob(os.path.join(ROOT, "build", "host-double", "**", "mtt-diff-driver"), recursive=True):
        return cand
    return None


# ---------------------------------------------------------------------------
# scenes
# ---------------------------------------------------------------------------

def loguniform(rng, lo, hi):
    return float(math.exp(rng.uniform(math.log(lo), math.log(hi))))


def random_scene(seed):
    """A small random scene with valid parameters; the same seed gives the same scene."""
    rng = np.random.default_rng([17, seed])
    mode = rng.choice(["lm-ihpda", "lm-ipda", "lm-ihpda", "lm-ipda", "ihpda", "ipda"])
    if mode == "lm-ipda" and seed % 3 == 2:
        mode = "lm-ipda-all"          # by the seed, so the other scenes' random draws stay as they were
    side = 100.0
    sig = (loguniform(rng, 0.3, 3.0), loguniform(rng, 0.3, 3.0))
    n_frames = int(rng.integers(3, 31))
    stress = rng.random() < 0.03      # over the bounds: MTT_MAX_MEAS, _GATED, _PAIRS, _TRACKS
    bad_data = rng.random() < 0.05    # NaN / infinite coordinates, negative amplitudes
    const_dt = rng.random() < 0.5
    clutter_rate = loguniform(rng, 0.2, 25.0) if rng.random() < 0.9 else 0.0   # per frame
    if stress:
        n_frames = int(rng.integers(3, 6))
        clutter_rate = float(rng.uniform(150.0, 330.0))
        sig = (loguniform(rng, 2.0, 4.0), loguniform(rng, 2.0, 4.0))
    lam_true = clutter_rate / (side * side)
    par = {
        "association": str(mode),
        "process_psd": loguniform(rng, 0.01, 10.0),
        "meas_sigma": list(sig),
        "pd": float(rng.uniform(0.5, 1.0)) if rng.random() < 0.9 else 1.0,
        "pg": float(rng.choice([0.9, 0.99, 0.999, 0.9999])) if rng.random() < 0.5 else float(rng.uniform(0.8, 0.9999)),
        "clutter_density": (max(lam_true, 1e-5) * loguniform(rng, 0.5, 2.0)) if rng.random() < 0.5 else 0.0,
        "snr_rho": 0.0 if rng.random() < 0.3 else loguniform(rng, 0.3, 30.0),
        "markov_p11": float(rng.uniform(0.85, 1.0)),
        "markov_p21": 0.0 if rng.random() < 0.7 else float(rng.uniform(0.0, 0.05)),
        "existence_init": float(rng.uniform(0.02, 0.5)),
        "confirm_threshold": float(rng.uniform(0.6, 0.999)),
        "terminate_threshold": 0.0 if rng.random() < 0.15 else float(rng.uniform(0.001, 0.05)),
        "merge_threshold": float(rng.choice([0.0, 0.5, 1.0, 1.0, 3.0, 10.0])),
        "initiate": bool(rng.random() < 0.85),
        "vmax": float(rng.uniform(2.0, 15.0)),
    }
    rx_gate = np.random.default_rng([17, seed, 2])
    if rng.random() < 0.15:
        # the intensity initial gate (§12.2): f(I) is tens of length units per frame,
        # so these scenes are wider and their amplitudes are on the scale of [S2] (0-2000)
        par["init_gate"] = "intensity"
        side = 1000.0
        if rng.random() < 0.5:
            k = loguniform(rng, 0.02, 1.0)
            par["intensity_gate.f1"] = [k * c for c in (-0.0007, 0.5072, 39.70)]
            par["intensity_gate.f2"] = [k * c for c in (-0.0001, 0.2097, 57.25)]
            if rx_gate.random() < 0.5:      # an f2 of its own: its peak moves, or it has none
                par["intensity_gate.f2"] = [k * float(rx_gate.choice([0.0, -loguniform(rx_gate, 1e-5, 2e-3)])),
                                       k * float(rx_gate.uniform(0.05, 1.0)), k * float(rx_gate.uniform(0.0, 60.0))]
            lo = float(rng.uniform(50.0, 300.0))
            par["intensity_gate.blend"] = [lo, lo + float(rng.uniform(1.0, 200.0))]
    amp_scale = loguniform(rng, 30.0, 600.0) if par.get("init_gate") == "intensity" else 1.0
    if par["existence_init"] >= par["confirm_threshold"]:
        par["existence_init"] = 0.5 * par["confirm_threshold"]
    # edge values of the parameter ranges (own stream, so the other scenes stay as they were)
    rx = np.random.default_rng([17, seed, 1])
    dt_scale = 1.0
    if rx.random() < 0.1:
        extremes = {
            "pg": [0.5, 0.999999, 0.99999999],
            "pd": [1.0, 0.05],
            "snr_rho": [1e6, 1e-6],
            "markov_p11": [1.0, 0.0, 0.5],
            "markov_p21": [1.0, 0.3],
            "existence_init": [0.999, 1e-6],
            "confirm_threshold": [1.0, 1e-3],
            "terminate_threshold": [0.0, 0.5],
            "merge_threshold": [1e6, 1e-9],
            "process_psd": [1e-9, 1e4],
            "clutter_density": [1e-12, 10.0],
        }
        for k in rx.choice(sorted(extremes), size=int(rx.integers(1, 5)), replace=False):
            par[str(k)] = float(rx.choice(extremes[str(k)]))
        if par["terminate_threshold"] >= par["confirm_threshold"]:
            par["terminate_threshold"] = 0.5 * par["confirm_threshold"]
        dt_scale = float(rx.choice([1.0, 1e-4, 1e-2, 30.0]))
        par["vmax"] /= min(dt_scale, 1.0)
    rho_true = loguniform(rng, 0.5, 20.0)
    amp_mode = rng.choice(["full", "full", "rounded", "missing", "none"])
    # targets: constant velocity with a little acceleration noise
    n_tgt = int(rng.integers(1, 7))
    pos = rng.uniform(0.2 * side, 0.8 * side, size=(n_tgt, 2))
    if rng.random() < 0.3:        # close formation: shared gates, merges
        pos = pos[0] + rng.normal(0.0, 3.0 * max(sig), size=(n_tgt, 2))
    vel = rng.normal(0.0, 3.0, size=(n_tgt, 2))
    pd_true = min(1.0, par["pd"] * rng.uniform(0.9, 1.1))
    seeded = []
    for k in range(n_tgt):
        if rng.random() < 0.4:
            x = np.concatenate([pos[k], vel[k]]) + rng.normal(0.0, 1.0, 4) * [sig[0], sig[1], 0.5, 0.5]
            if rng.random() < 0.5:
                P = two_point_cov(sig[0], sig[1], 1.0)
            else:
                A = rng.normal(0.0, 1.0, (4, 4))
                P = A @ A.T + np.diag(rng.uniform(0.2, 3.0, 4))
                P = 0.5 * (P + P.T)
            seeded.append((list(x), list(P.ravel())))
    frames = []
    t = float(rng.uniform(-5.0, 5.0))
    for f in range(n_frames):
        if f > 0:
            dt = (1.0 if const_dt else float(rng.uniform(0.3, 2.5))) * dt_scale
            t += dt
            vel = vel + rng.normal(0.0, 0.2, size=vel.shape) * math.sqrt(dt)
            pos = pos + vel * dt
        dets = []
        for k in range(n_tgt):
            if rng.random() < pd_true:
                z = pos[k] + rng.normal(0.0, 1.0, 2) * sig
                dets.append((float(z[0]), float(z[1]), float(rng.exponential(1.0 + rho_true))))
        for _ in range(int(rng.poisson(clutter_rate))):
            z = rng.uniform(0.0, side, 2)
            dets.append((float(z[0]), float(z[1]), float(rng.exponential(1.0))))
        order = rng.permutation(len(dets))
        dets = [(x, y, a * amp_scale) for x, y, a in (dets[i] for i in order)]
        if amp_mode == "rounded":
            dets = [(x, y, round(a, 1)) for x, y, a in dets]
        elif amp_mode == "missing":
            dets = [(x, y, None if rng.random() < 0.15 else a) for x, y, a in dets]
        elif amp_mode == "none":
            dets = [(x, y, None) for x, y, a in dets]
        if bad_data and dets:
            for _ in range(int(rng.integers(1, 4))):
                i = int(rng.integers(0, len(dets)))
                x, y, a = dets[i]
                kind = int(rng.integers(0, 4))
                dets[i] = [(float("nan"), y, a), (x, float("inf"), a), (x, y, -1.0),
                           (x, y, float("nan"))][kind]
        frames.append((t, dets))
    rx3 = np.random.default_rng([17, seed, 3])
    if stress and rx3.random() < 0.4:
        # one frame with exactly MTT_MAX_MEAS valid detections (the boundary of the cap)
        t_f, dets = frames[int(rx3.integers(0, len(frames)))]
        while sum(map(_valid, dets)) > 256:
            dets.pop()
        while sum(map(_valid, dets)) < 256:
            z = rx3.uniform(0.0, side, 2)
            dets.append((float(z[0]), float(z[1]), None if amp_mode == "none" else float(rx3.exponential(1.0))))
    return Scene(params=par, tracks=seeded, frames=frames)


def scenario_scene(scenario, seed, mode, tmp):
    """A full scenario through the generator, as a differential scene."""
    settings, det = generate_scenario(scenario, seed, tmp)
    par = {}
    for k, v in settings.items():
        if k == "initial_tracks":
            continue
        if isinstance(v, dict):               # intensity_gate: {"f1": ...} -> intensity_gate.f1
            par.update({f"{k}.{kk}": vv for kk, vv in v.items()})
        else:
            par[k] = v
    par["association"] = mode
    rows = np.genfromtxt(det, delimiter=",", names=True, dtype=None, encoding=None, missing_values="",
                         filling_values=np.nan)
    frames, t0 = [], None
    for scan in sorted(set(rows["scan"].tolist())):
        r = rows[rows["scan"] == scan]
        t = float(r["time"][0])
        t0 = t if t0 is None else t0
        dets = [(float(a["x"]), float(a["y"]), None if math.isnan(a["amplitude"]) else float(a["amplitude"]))
                for a in r if not math.isnan(a["x"])]
        frames.append((t - t0, dets))
    tracks = []
    sx, sy = par.get("meas_sigma", [1.0, 1.0])
    for it in settings.get("initial_tracks", []):
        P = it.get("P")
        if P is None:
            P = two_point_cov(sx, sy, frames[1][0] - frames[0][0]).ravel()
        tracks.append(([it["x"], it["y"], it["vx"], it["vy"]], list(np.ravel(P))))
    return Scene(params=par, tracks=tracks, frames=frames)


# ---------------------------------------------------------------------------
# comparison
# ---------------------------------------------------------------------------

def close(a, b, floor):
    """|a - b| <= REL * max(|a|, |b|) + floor.

    The floor is REL times the natural scale of the quantity (see compare()):
    an entry that is zero in exact arithmetic (a covariance term of a
    decorrelated axis, a velocity of 0) has no relative precision of its own,
    only that of the terms it is computed from."""
    return abs(a - b) <= REL * max(abs(a), abs(b)) + floor


def compare(ref, drv):
    """First difference between two runs (lists per frame), or None."""
    if len(ref) != len(drv):
        return f"frame count: reference {len(ref)}, driver {len(drv)}"
    for k, (fr, fd) in enumerate(zip(ref, drv)):
        ir, id_ = [t[0] for t in fr], [t[0] for t in fd]
        if ir != id_:
            return f"frame {k}: track ids: reference {ir}, driver {id_}"
        for tr, td in zip(fr, fd):
            tid = tr[0]
            if tr[1] != td[1]:
                return f"frame {k} track {tid}: confirmed reference {tr[1]}, driver {td[1]}"
            if tr[5] != td[5]:
                return f"frame {k} track {tid}: age reference {tr[5]}, driver {td[5]}"
            if tr[6] != td[6]:
                return f"frame {k} track {tid}: measurement reference {tr[6]}, driver {td[6]}"
            # floors: REL * sqrt(P_ii) for x_i (a billionth of the track's own standard
            # deviation) and REL * sqrt(P_ii P_jj) for P_ij (a billionth on the
            # correlation scale); REL * 1e-6 for the existence, a probability that
            # is computed from O(1) terms
            sd = np.sqrt(np.abs(np.diag(tr[3])))
            for i in range(4):
                if not close(tr[2][i], td[2][i], REL * sd[i]):
                    return f"frame {k} track {tid}: x[{i}] reference {tr[2][i]!r}, driver {td[2][i]!r}"
            for i in range(4):
                for j in range(4):
                    if not close(tr[3][i, j], td[3][i, j], REL * sd[i] * sd[j]):
                        return (f"frame {k} track {tid}: P[{i}][{j}] reference {tr[3][i, j]!r}, "
                                f"driver {td[3][i, j]!r}")
            if not close(tr[4], td[4], REL * 1e-6):
                return f"frame {k} track {tid}: existence reference {tr[4]!r}, driver {td[4]!r}"
    return None


def run_driver(driver, scene_text):
    p = subprocess.run([driver], input=scene_text, capture_output=True, text=True, check=False)
    if p.returncode != 0:
        raise RuntimeError(f"driver exit {p.returncode}: {p.stderr.strip()}")
    return parse_driver_output(p.stdout)


def check_scene(driver, scene, events=None):
    """-> (difference or None, near_ties); adds the reference's path counts to events."""
    text = write_scene(scene)
    ref, ties = scene.run_reference()
    if events is not None:
        events.update(scene.events)
    drv = run_driver(driver, text)
    mode = scene.params.get("association", "lm-ihpda")
    return compare(ref, drv), ties


def minimize(scene, fails):
    """Shrink a failing scene (drop seeded tracks, frames from the end and the start,
    detections) while fails(scene) stays true; for the regression cases."""
    import copy
    sc = copy.deepcopy(scene)
    changed = True
    while changed:
        changed = False
        for i in reversed(range(len(sc.tracks))):
            trial = copy.deepcopy(sc)
            del trial.tracks[i]
            if fails(trial):
                sc, changed = trial, True
        while len(sc.frames) > 1:
            trial = copy.deepcopy(sc)
            trial.frames.pop()
            if not fails(trial):
                break
            sc, changed = trial, True
        while len(sc.frames) > 1 and not sc.tracks:
            trial = copy.deepcopy(sc)
            trial.frames.pop(0)
            if not fails(trial):
                break
            sc, changed = trial, True
        for f in range(len(sc.frames)):
            for i in reversed(range(len(sc.frames[f][1]))):
                trial = copy.deepcopy(sc)
                del trial.frames[f][1][i]
                if fails(trial):
                    sc, changed = trial, True
    return sc


class Differential(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.driver = find_driver()
        if not cls.driver or not os.path.exists(cls.driver):
            raise unittest.SkipTest("no mtt-diff-driver: set MTT_DIFF_DRIVER (ctest does) or build host-double")

    def _report(self, title, n, failures, tie_fail, tie_pass, known):
        n_known = sum(known.values())
        print(f"\ndifferential {title}: {n} scenes, {n - len(failures) - len(tie_fail) - n_known} agree "
              f"({tie_pass} of them tie-sensitive), {len(tie_fail)} tie-sensitive disagree, "
              f"{n_known} disagree by a known C bug"
              + "".join(f" ({v} {k})" for k, v in sorted(known.items()))
              + f", {len(failures)} disagree otherwise", file=sys.stderr)
        for name, diff in failures[:20]:
            print(f"  {name}: {diff}", file=sys.stderr)

    def _keep(self, name, scene):
        keep = os.environ.get("MTT_DIFF_KEEP")
        if keep:
            os.makedirs(keep, exist_ok=True)
            write_scene(scene, os.path.join(keep, name + ".scene"))

    def _run_many(self, title, named_scenes, events):
        failures, tie_fail, tie_pass, n = [], [], 0, 0
        known = Counter()
        for name, scene in named_scenes:
            n += 1
            events["scene " + scene.params["association"]] += 1
            events["frame"] += len(scene.frames)
            diff, ties = check_scene(self.driver, scene, events)
            bug = next((k for k, b in KNOWN_C_BUGS.items() if b["trigger"](scene)), None)
            if diff is None:
                tie_pass += bool(ties)
            elif bug:
                known[bug] += 1
            elif ties:
                tie_fail.append((name, diff))
            else:
                failures.append((name, diff))
                self._keep(name, scene)
        self._report(title, n, failures, tie_fail, tie_pass, known)
        print("  paths run (reference counts): " + ", ".join(f"{k} {v}" for k, v in sorted(events.items())),
              file=sys.stderr)
        return n, failures, tie_fail

    def test_random_scenes(self):
        events = Counter()
        n, failures, tie_fail = self._run_many(
            "random", ((f"random-{s}", random_scene(s)) for s in range(N_RANDOM)), events)
        self.assertGreaterEqual(n, N_RANDOM)
        # the scenes must exercise every stage, or agreement means little
        if N_RANDOM >= 1000:
            for path in ("birth", "birth velocity cap", "merge", "delete", "confirm", "LM pair shared",
                         "MMR contested measurement", "final recomputation, smaller G_f",
                         "gate taken by others (m = 0)", "rho off (missing amplitude)",
                         "equal amplitudes ranked by index", "scene lm-ihpda", "scene lm-ipda",
                         "scene lm-ipda-all", "LM outside the gates",
                         "scene ihpda", "scene ipda", "intensity gate pass", "intensity gate reject",
                         "intensity gate clamp", "intensity gate without amplitude: vmax",
                         "bad detection skipped"):
                self.assertGreaterEqual(events[path], 10, path)
            for path in ("gate cap", "pairs cap", "measurement cap", "birth dropped (table full)",
                         "merge candidates cap"):
                self.assertGreaterEqual(events[path], 1, path)
        self.assertLessEqual(len(tie_fail), max(1, n // 100), "too many tie-sensitive disagreements")
        self.assertEqual(failures, [])

    def test_regression_cases(self):
        files = sorted(glob.glob(os.path.join(CASES_DIR, "*.scene")))
        for path in files:
            name = os.path.basename(path)
            with open(path) as fh:
                scene = read_scene(fh.read())
            diff, ties = check_scene(self.driver, scene)
            with self.subTest(case=name):
                if name in EXPECTED_FAILURES:
                    self.assertIn(EXPECTED_FAILURES[name], KNOWN_C_BUGS)
                    self.assertTrue(KNOWN_C_BUGS[EXPECTED_FAILURES[name]]["trigger"](scene), name)
                    self.assertIsNotNone(diff, f"{name} agrees now: remove it from EXPECTED_FAILURES")
                else:
                    # deliberate exact ties test the tie rules; a near tie cannot be decided
                    near = [t for t in ties if t not in scene.exact_ties]
                    self.assertEqual(near, [], f"{name} is tie-sensitive")
                    self.assertIsNone(diff, name)
        for name in EXPECTED_FAILURES:
            self.assertTrue(os.path.exists(os.path.join(CASES_DIR, name)), name)
        for topic, (section, phrase, cases) in SPEC_GAPS_DOCUMENTED.items():
            self.assertIn(phrase, algorithms_section(section), f"ALGORITHMS.md §{section} no longer states {topic}")
            for name in filter(None, cases.split(", ")):
                self.assertTrue(os.path.exists(os.path.join(CASES_DIR, name)), name)

    def test_jpda_family(self):
        """The JPDA family: the random scenes with the association replaced, each mode in turn."""
        def scenes():
            for s in range(N_JPDA):
                sc = random_scene(s)
                sc.params["association"] = JPDA_ROWS[s % len(JPDA_ROWS)]
                yield f"jpda-{s}-{sc.params['association']}", sc
        events = Counter()
        n, failures, tie_fail = self._run_many("jpda family", scenes(), events)
        self.assertGreaterEqual(n, N_JPDA)
        if N_JPDA >= 300:
            for path in ["scene " + m for m in JPDA_ROWS] + ["gate shrink", "adaptive equal share",
                                                               "jpda-star pruned", "jpda fallback (Cheap JPDA)"]:
                self.assertGreaterEqual(events[path], 10, path)
        self.assertLessEqual(len(tie_fail), max(1, n // 100), "too many tie-sensitive disagreements")
        self.assertEqual(failures, [])

    def test_scenarios(self):
        runs = [(scn, seed) for scn in ("crossing3", "coalesce3", "formations", "split") for seed in (0, 1)]
        scenes = []
        with tempfile.TemporaryDirectory() as tmp:
            for scn, seed in runs:
                for mode in ("lm-ihpda", "lm-ipda", "lm-ipda-all"):
                    scenes.append((f"{scn}-s{seed}-{mode}", scenario_scene(scn, seed, mode, tmp)))
            for scn in ("coalesce3", "crossing3"):             # [S1]'s gate-shrink variants
                for mode in JPDA_ROWS[:3]:
                    scenes.append((f"{scn}-s0-{mode}", scenario_scene(scn, 0, mode, tmp)))
        n, failures, tie_fail = self._run_many("scenarios", scenes, Counter())
        self.assertEqual(n, 3 * len(runs) + 6)
        self.assertEqual(failures + tie_fail, [])


if __name__ == "__main__":
    unittest.main()
