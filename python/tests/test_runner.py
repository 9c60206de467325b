# SPDX-License-Identifier: BSD-3-Clause
"""Monte Carlo runner end to end: with a stand-in tracker always, with mtt-track if built."""

import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

from mtt_sim import mc

HERE = os.path.dirname(os.path.abspath(__file__))

FAKE = os.path.join(HERE, "fake_mtt_track.py")

# Two targets crossing in light clutter, 20 scans; one seeded track.
TINY = {
    "name": "tiny",
    "units": {"length": "m", "time": "s"},
    "area": {"x": [0, 400], "y": [0, 200]},
    "scans": {"count": 20, "dt": 1.0, "t0": 0.0},
    "pd": 0.95,
    "meas_sigma": [2.0, 2.0],
    "clutter": {"model": "poisson", "mean": 3},
    "amplitude": {"rho": 4.0},
    "targets": [
        {"id": 0, "x": 50, "y": 60, "vx": 10, "vy": 3},
        {"id": 1, "x": 50, "y": 140, "vx": 10, "vy": -3},
    ],
    "tracker": {
        "association": "lm-ihpda", "process_psd": 1, "meas_sigma": [2.0, 2.0], "pd": 0.95,
        "clutter_density": 3.75e-05, "snr_rho": 4.0, "vmax": 30,
        "initial_tracks": [{"x": 50, "y": 60, "vx": 10, "vy": 3}],
    },
    "tracker_notes": {"why": "unit test"},
    "metrics": {"match_distance": 10, "gospa_c": 10, "seeded_targets": [0]},
    "report": {"table_times": [5, 10, 15], "gate_scans": [5, 10]},
}


def tmpdir(test, prefix):
    d = tempfile.mkdtemp(prefix=prefix)
    test.addCleanup(shutil.rmtree, d, ignore_errors=True)
    return d


def run_mc(exe, out, extra=(), env=None):
    td = os.path.join(out, "_scenario")
    os.makedirs(td, exist_ok=True)
    scn_path = os.path.join(td, "tiny.json")
    with open(scn_path, "w") as f:
        json.dump(TINY, f)
    cmd = [sys.executable, "-m", "mtt_sim.mc", "--scenario", scn_path, "--runs", "2", "--jobs", "2",
           "--out", out, "--mtt-track", exe, *extra]
    return subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=600)


class TestRunnerWithStandIn(unittest.TestCase):
    """The harness itself, with tests/fake_mtt_track.py in place of the C tool."""

    def test_end_to_end(self):
        out = tmpdir(self, "mtt_mc_out_")
        p = run_mc(FAKE, out, ["--assoc", "lm-ihpda", "lm-ipda"])
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertIn("[run 4/4]", p.stderr)
        self.assertIn("Confirmed true tracks", p.stdout)
        self.assertIn("Tentative and confirmed tracks per scan", p.stdout)
        self.assertIn("coalescence-or-switch rate", p.stdout)
        with open(os.path.join(out, "summary.json")) as f:
            s = json.load(f)
        self.assertEqual(s["modes"], ["lm-ihpda", "lm-ipda"])
        r = s["results"]["lm-ihpda"]
        self.assertEqual(r["runs_ok"], 2)
        self.assertEqual(len(r["per_scan"]["conf_true_sum"]), 20)
        self.assertLessEqual(max(r["per_scan"]["conf_true_sum"]), 4)  # 2 targets x 2 runs
        self.assertEqual(r["seeded"]["runs"], 2)
        self.assertGreater(r["totals"]["time_per_frame_ms"]["mean"], 0)
        for png in ("confirmed_true.png", "counts.png", "gospa.png", "rmse.png",
                    "scene_lm-ihpda.png", "scene_lm-ipda.png"):
            self.assertTrue(os.path.getsize(os.path.join(out, png)) > 1000, png)
        for fn in ("tiny.det.csv", "tiny.truth.csv", "tiny.lm-ihpda.tracks.csv", "tiny.lm-ipda.settings.json"):
            self.assertTrue(os.path.isfile(os.path.join(out, "run0", fn)), fn)
        # replot from the summary
        q = subprocess.run([sys.executable, "-m", "mtt_sim.plot", "summary",
                            os.path.join(out, "summary.json"), "--out", os.path.join(out, "replot")],
                           capture_output=True, text=True, timeout=300)
        self.assertEqual(q.returncode, 0, q.stderr)
        self.assertTrue(os.path.isfile(os.path.join(out, "replot", "scene_lm-ipda.png")))

    def test_tracker_failure_is_reported(self):
        out = tmpdir(self, "mtt_mc_out_")
        env = dict(os.environ, FAKE_MTT_FAIL="1")
        p = run_mc(FAKE, out, ["--no-plots"], env=env)
        self.assertEqual(p.returncode, 1)
        self.assertIn("FAILED lm-ihpda run 0", p.stdout)
        self.assertIn("forced failure", p.stdout)
        with open(os.path.join(out, "summary.json")) as f:
            s = json.load(f)
        self.assertEqual(s["results"]["lm-ihpda"]["runs_failed"], 2)


class TestRunnerWithMttTrack(unittest.TestCase):
    """Two runs of the tiny scenario through the real mtt-track, if one is built."""

    def test_end_to_end_real_binary(self):
        exe = mc.find_mtt_track()
        if exe is None:
            self.skipTest("no mtt-track binary: set MTT_TRACK or build build/host-float/tools/track/mtt-track")
        out = tmpdir(self, "mtt_mc_real_")
        p = run_mc(exe, out)
        self.assertEqual(p.returncode, 0, p.stdout + p.stderr)
        with open(os.path.join(out, "summary.json")) as f:
            s = json.load(f)
        r = s["results"]["lm-ihpda"]
        self.assertEqual(r["runs_ok"], 2)
        # The seeded track starts on target 0 at scan 0; the other target is
        # found by two-point initiation: with PD 0.95 and little clutter, some
        # confirmed true track must exist by the last scan of both runs.
        self.assertGreater(r["per_scan"]["conf_true_sum"][-1], 0)


if __name__ == "__main__":
    unittest.main()
