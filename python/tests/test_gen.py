# SPDX-License-Identifier: BSD-3-Clause
"""mtt_sim.gen, the generator: determinism, statistics, docs/FORMATS.md conformity, shipped scenarios."""

import copy
import glob
import json
import math
import os
import re
import shutil
import sys
import tempfile
import unittest

import numpy as np

from mtt_sim import csvio, gen, scenario

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))

BASE = {
    "name": "unit",
    "area": {"x": [0, 100], "y": [0, 50]},
    "scans": {"count": 20, "dt": 0.5, "t0": 2.0},
    "pd": 0.9,
    "meas_sigma": [2.0, 1.0],
    "clutter": {"model": "poisson", "density": 0.002},
    "amplitude": {"rho": 3.0},
    "targets": [{"id": 0, "x": 10, "y": 25, "vx": 2, "vy": 0}],
    "tracker": {"association": "lm-ihpda", "meas_sigma": [2.0, 1.0]},
}


def make(overrides=None, **top):
    d = copy.deepcopy(BASE)
    d.update(top)
    return scenario.loads(json.dumps(d), "unit.json", overrides)


class TestTrackerKeys(unittest.TestCase):
    def test_tracker_keys_are_the_settings_table_of_formats_md(self):
        # a key added to the library and FORMATS.md must reach mtt_sim's own list
        import re
        doc = open(os.path.join(os.path.dirname(__file__), "..", "..", "docs", "FORMATS.md"),
                   encoding="utf-8").read()
        sec = doc[doc.index("## Tracker settings"):doc.index("## Command line")]
        keys = {k.split(".")[0] for k in re.findall(r"^\| `([a-z_0-9.]+)` \|", sec, re.M)}
        self.assertGreater(len(keys), 40)
        self.assertEqual(scenario.TRACKER_KEYS, keys)


class TestDeterminism(unittest.TestCase):
    def test_same_seed_same_bytes(self):
        scn = make()
        a, b, c = gen.generate(scn, 5), gen.generate(scn, 5), gen.generate(scn, 6)
        self.assertEqual(csvio.format_det(a["det"], a["times"]), csvio.format_det(b["det"], b["times"]))
        self.assertEqual(csvio.format_truth(a["truth"]), csvio.format_truth(b["truth"]))
        self.assertNotEqual(csvio.format_det(a["det"], a["times"]), csvio.format_det(c["det"], c["times"]))

    def test_clutter_change_keeps_target_detections(self):
        # independent streams: more clutter must not move the target detections
        a = gen.generate(make(), 3)
        b = gen.generate(make(["clutter.density=0.01"]), 3)
        ta = a["det"]["origin"] >= 0
        tb = b["det"]["origin"] >= 0
        ka = np.lexsort((a["det"]["x"][ta], a["det"]["scan"][ta]))
        kb = np.lexsort((b["det"]["x"][tb], b["det"]["scan"][tb]))
        np.testing.assert_array_equal(a["det"]["x"][ta][ka], b["det"]["x"][tb][kb])
        self.assertGreater(len(b["det"]["x"]), len(a["det"]["x"]))


class TestStatistics(unittest.TestCase):
    def test_poisson_clutter_count_and_uniformity(self):
        # lambda * area = 0.002 * 100 * 50 = 10 per scan; 2000 scans.
        # The mean count has standard error sqrt(10/2000) = 0.071: tolerance 0.3 (4.2 SE).
        # Poisson: variance = mean; the sample variance has SE about
        # sqrt(2*10^2/2000) = 0.32 (+ the 4th cumulant term, ~0.07): tolerance 1.5.
        # Uniform x on [0, 100]: mean 50, SE 28.9/sqrt(20000) = 0.2: tolerance 1.
        scn = make(["scans.count=2000", "pd=0"])
        run = gen.generate(scn, 11)
        clut = run["det"]["origin"] == -1
        counts = np.bincount(run["det"]["scan"][clut], minlength=2000)
        self.assertLess(abs(counts.mean() - 10.0), 0.3)
        self.assertLess(abs(counts.var() - 10.0), 1.5)
        x, y = run["det"]["x"][clut], run["det"]["y"][clut]
        self.assertTrue(np.all((x >= 0) & (x <= 100) & (y >= 0) & (y <= 50)))
        self.assertLess(abs(x.mean() - 50), 1.0)
        self.assertLess(abs(y.mean() - 25), 0.5)
        # clutter amplitude Exp(1): mean 1, SE 1/sqrt(20000) = 0.007: tolerance 0.03
        self.assertLess(abs(run["det"]["amp"][clut].mean() - 1.0), 0.03)

    def test_detection_rate_noise_and_target_amplitude(self):
        # one target, PD 0.7, no clutter, 3000 scans (target kept in the area by vx = 0).
        # Detection rate SE sqrt(0.7*0.3/3000) = 0.0084: tolerance 0.03 (3.6 SE).
        # Noise sample std SE ~ sigma/sqrt(2*2100) = 1.5 %: tolerance 6 %.
        # Target amplitude Exp(mean 1 + rho = 4): SE 4/sqrt(2100) = 0.087: tolerance 0.35.
        scn = make(["scans.count=3000", "pd=0.7", "clutter.density=0", "targets.0.vx=0"])
        run = gen.generate(scn, 4)
        d = run["det"]
        self.assertTrue(np.all(d["origin"] == 0))
        self.assertEqual(len(run["truth"]["x"]), 3000)
        self.assertLess(abs(len(d["x"]) / 3000 - 0.7), 0.03)
        ex = d["x"] - 10.0
        ey = d["y"] - 25.0
        self.assertLess(abs(ex.std() / 2.0 - 1), 0.06)
        self.assertLess(abs(ey.std() / 1.0 - 1), 0.06)
        self.assertLess(abs(ex.mean()), 0.2)
        self.assertLess(abs(d["amp"].mean() - 4.0), 0.35)

    def test_binomial_clutter_bounded(self):
        # Binomial(3, 0.3): never more than 3 per scan, mean 0.9 (SE 0.8/sqrt(2000) = 0.018)
        scn = make(["scans.count=2000", "pd=0", "clutter={\"model\": \"binomial\", \"n\": 3, \"p\": 0.3}"])
        run = gen.generate(scn, 2)
        counts = np.bincount(run["det"]["scan"], minlength=2000)
        self.assertLessEqual(counts.max(), 3)
        self.assertLess(abs(counts.mean() - 0.9), 0.08)

    def test_truth_process_noise(self):
        # exact CV without noise: x = 10 + 2 * (t - 2) (t_ref = t0 = 2)
        run = gen.generate(make(["clutter.density=0"]), 1)
        t = run["truth"]
        np.testing.assert_allclose(t["x"], 10 + 2 * (t["time"] - 2.0))
        np.testing.assert_allclose(t["y"], 25.0)
        noisy = gen.generate(make(["clutter.density=0", "truth_process_psd=0.5"]), 1)
        self.assertGreater(np.abs(noisy["truth"]["y"] - 25.0).max(), 0.01)

    def test_area_and_lifetime(self):
        # target leaves the 100-wide area: x = 10 + 20 * (t - 2) > 100 after t = 6.5 (scan 9).
        # first_scan 2, last_scan 30 (beyond the run): rows for scans 2..9 only.
        run = gen.generate(make(["targets.0.vx=20", "targets.0.first_scan=2", "targets.0.last_scan=30"]), 1)
        self.assertEqual(run["truth"]["scan"].tolist(), list(range(2, 10)))

    def test_split_and_resolution(self):
        # parent 0 at y 25; child 1 splits at scan 5 with +1 / -1 vertical velocity (dt 0.5):
        # separation 2 * 1 * 0.5 * (k - 5) = k - 5: below 3 (resolution) until scan 8.
        scn = make(["clutter.density=0", "pd=1", "meas_sigma=[0.01, 0.01]", "resolution=3",
                    "splits=[{\"parent\": 0, \"child\": 1, \"scan\": 5, \"dv_parent\": [0, -1], \"dv_child\": [0, 1]}]"])
        run = gen.generate(scn, 1)
        t = run["truth"]
        self.assertEqual(t["scan"][t["target"] == 1].min(), 5)
        k5 = t["scan"] == 5
        np.testing.assert_allclose(t["x"][k5][0], t["x"][k5][1])
        d = run["det"]
        per_scan = np.bincount(d["scan"], minlength=20)
        self.assertEqual(per_scan[:8].tolist(), [1] * 8)   # unresolved until separation 3
        self.assertEqual(per_scan[9:].tolist(), [2] * 11)
        self.assertTrue(np.all(d["origin"][(d["scan"] >= 5) & (d["scan"] < 8)] == -2))


class TestFormats(unittest.TestCase):
    def write(self, scn, seed=0):
        td = tempfile.mkdtemp(prefix="mtt_gen_test_")
        self.addCleanup(shutil.rmtree, td, ignore_errors=True)
        run = gen.generate(scn, seed)
        return run, gen.write_run(run, td)

    def test_det_file(self):
        run, p = self.write(make(["pd=0.5", "clutter.density=0.0002"]))  # mean 1 clutter: P(empty scan) = 0.18
        with open(p["det"]) as f:
            lines = f.read().splitlines()
        self.assertEqual(lines[0], "scan,time,x,y,amplitude")
        prev_scan, prev_time, seen = -1, -math.inf, set()
        empty = 0
        num = re.compile(r"^-?\d+(\.\d+)?(e[-+]?\d+)?$")
        for ln in lines[1:]:
            f = ln.split(",")
            self.assertEqual(len(f), 5, ln)
            k, t = int(f[0]), float(f[1])
            self.assertGreaterEqual(k, prev_scan)
            if k == prev_scan:
                self.assertEqual(t, prev_time)
            else:
                self.assertGreater(t, prev_time)
            prev_scan, prev_time = k, t
            seen.add(k)
            if f[2] == "":
                empty += 1
                self.assertEqual(f[3:], ["", ""], "empty scan row must be 'scan,time,,,'")
            else:
                for v in f[2:]:
                    self.assertRegex(v, num)
                self.assertGreaterEqual(float(f[4]), 0.0)
            self.assertNotIn("nan", ln.lower())
            self.assertNotIn("inf", ln.lower())
        self.assertEqual(seen, set(range(20)), "every scan must appear")
        self.assertGreater(empty, 0, "the test wants at least one empty scan")
        det, times = csvio.read_det(p["det"])
        self.assertEqual(len(det["x"]), len(run["det"]["x"]))
        np.testing.assert_allclose(sorted(times.values()), run["times"])

    def test_all_empty_scans(self):
        _, p = self.write(make(["pd=0", "clutter.density=0"]))
        with open(p["det"]) as f:
            lines = f.read().splitlines()
        self.assertEqual(lines[1:], [f"{k},{2 + 0.5 * k:.10g},,," for k in range(20)])

    def test_no_amplitude(self):
        _, p = self.write(make(amplitude=None))
        det, _ = csvio.read_det(p["det"])
        self.assertTrue(np.all(np.isnan(det["amp"])))

    def test_truth_and_settings(self):
        run, p = self.write(make())
        with open(p["truth"]) as f:
            lines = f.read().splitlines()
        self.assertEqual(lines[0], "scan,time,target,x,y,vx,vy")
        self.assertEqual(len(lines) - 1, 20)
        truth = csvio.read_truth(p["truth"])
        np.testing.assert_allclose(truth["vx"], 2.0)
        with open(p["settings"]) as f:
            s = json.load(f)
        self.assertEqual(s, {"association": "lm-ihpda", "meas_sigma": [2.0, 1.0]})
        self.assertEqual(gen.generate(make(), 0, "ipda")["settings"]["association"], "ipda")


class TestManoeuvres(unittest.TestCase):
    G0 = 9.80665

    def turn_run(self, man, **kw):
        scn = make(area={"x": [-5000, 5000], "y": [-5000, 5000]}, scans={"count": 12, "dt": 1.0},
                   targets=[dict({"id": 0, "x": 0.0, "y": 0.0, "vx": 100.0, "vy": 0.0, "manoeuvres": man}, **kw)])
        return scn, gen.generate(scn, 0)["truth"]

    def test_coordinated_turn_geometry(self):
        # 2 g left at 100 m/s from scan 2 for 5 scans: w = 2 G0 / 100 = 0.196 rad/s,
        # radius 100 / w = 509.9 m, centre (200, 509.9) (left of the east-bound
        # target at scan 2); scans 3..7 lie on that circle, the heading turns
        # by 5 w = 0.98 rad, then the motion is straight again at 100 m/s.
        _, t = self.turn_run([{"scan": 2, "scans": 5, "g": 2.0}])
        w = 2.0 * self.G0 / 100.0
        r = 100.0 / w
        np.testing.assert_allclose(t["x"][:3], [0.0, 100.0, 200.0])
        np.testing.assert_allclose(t["y"][:3], 0.0, atol=1e-12)
        np.testing.assert_allclose(np.hypot(t["x"][3:8] - 200.0, t["y"][3:8] - r), r, rtol=1e-12)
        np.testing.assert_allclose(np.hypot(t["vx"], t["vy"]), 100.0, rtol=1e-12)
        heading = np.arctan2(t["vy"], t["vx"])
        np.testing.assert_allclose(heading[:3], 0.0, atol=1e-15)
        np.testing.assert_allclose(heading[3:8], w * np.arange(1, 6), rtol=1e-12)
        np.testing.assert_allclose(heading[8:], 5 * w, rtol=1e-12)
        np.testing.assert_allclose(np.diff(t["x"][7:]), 100.0 * math.cos(5 * w), rtol=1e-12)

    def test_turn_rate_right(self):
        # turn_rate -0.1 rad/s for 4 scans from scan 0: heading -0.4 rad from scan 4 on
        _, t = self.turn_run([{"scan": 0, "scans": 4, "turn_rate": -0.1}])
        np.testing.assert_allclose(np.arctan2(t["vy"], t["vx"])[4:], -0.4, rtol=1e-12)
        self.assertTrue(np.all(t["y"][1:] < 0))

    def test_no_manoeuvre_same_bytes(self):
        a = gen.generate(make(), 4)
        b = gen.generate(make(["targets.0.manoeuvres=[]"]), 4)
        self.assertEqual(csvio.format_det(a["det"], a["times"]), csvio.format_det(b["det"], b["times"]))
        self.assertEqual(csvio.format_truth(a["truth"]), csvio.format_truth(b["truth"]))

    def test_windows(self):
        scn, _ = self.turn_run([{"scan": 2, "scans": 5, "g": 2.0}, {"scan": 8, "scans": 1, "g": -1.0}])
        self.assertEqual(scenario.manoeuvre_windows(scn), {0: [(3, 7), (9, 9)]})
        self.assertEqual(scenario.manoeuvre_windows(make()), {})

    def test_validation(self):
        bad = [
            ([{"scan": 2, "scans": 5}], "exactly one of"),
            ([{"scan": 2, "scans": 5, "g": 1, "turn_rate": 0.1}], "exactly one of"),
            ([{"scan": 2, "scans": 0, "g": 1}], "scans"),
            ([{"scan": 2, "scans": 5, "g": 1}, {"scan": 6, "scans": 1, "g": 1}], "overlap"),
            ([{"scan": 2, "scans": 5, "gee": 1}], "gee"),
            ({"scan": 2}, "must be a list"),
        ]
        for man, msg in bad:
            with self.subTest(man=man), self.assertRaisesRegex(scenario.ScenarioError, msg):
                self.turn_run(man)

    def test_manoeuvre_scenario_geometry(self):
        # scenarios/manoeuvre.json without truth noise: constant speeds, the
        # crossings of its _comment_targets (40 m apart at scans 33, 36, 75).
        scn = scenario.load(os.path.join(REPO, "scenarios", "manoeuvre.json"), ["truth_process_psd=0"])
        t = gen.generate(scn, 0)["truth"]
        self.assertEqual(len(t["x"]), 4 * 90)
        pos = {i: np.column_stack([t["x"][t["target"] == i], t["y"][t["target"] == i]]) for i in range(4)}
        for i, v in enumerate([200.0, 180.0, 160.0, math.hypot(170.0, 100.0)]):
            m = t["target"] == i
            np.testing.assert_allclose(np.hypot(t["vx"][m], t["vy"][m]), v, rtol=1e-9)
        for a, b, k in ((0, 3, 33), (1, 2, 36), (2, 3, 75)):
            d = np.hypot(*(pos[a] - pos[b]).T)
            self.assertEqual(int(np.argmin(d)), k)
            self.assertLess(d[k], 45.0)
        self.assertEqual(scenario.manoeuvre_windows(scn),
                         {0: [(21, 32), (46, 57)], 1: [(23, 32), (33, 42)], 2: [(29, 42), (63, 72)], 3: [(41, 50)]})


class TestScenarioFiles(unittest.TestCase):
    def test_shipped_scenarios(self):
        files = sorted(glob.glob(os.path.join(REPO, "scenarios", "*.json")))
        names = {os.path.basename(f)[:-5] for f in files}
        self.assertTrue({"crossing3", "formations", "coalesce3", "split", "dense", "manoeuvre"} <= names, names)
        for path in files:
            with self.subTest(path=path):
                with open(path) as f:
                    raw = json.load(f)
                # the tracker object is passed verbatim: docs/FORMATS.md keys only, no comments
                self.assertTrue(set(raw["tracker"]) <= scenario.TRACKER_KEYS, set(raw["tracker"]) - scenario.TRACKER_KEYS)
                scn = scenario.load(path)
                self.assertEqual(scn["name"], os.path.basename(path)[:-5])
                run = gen.generate(scn, 0)
                self.assertGreater(len(run["truth"]["x"]), 0)
                self.assertGreater(len(run["det"]["x"]), 0)

    def test_formations_geometry(self):
        # [S0]: 14 targets appear at frame 6; the x-extents of the two
        # formations overlap exactly in frames 13-15.
        scn = scenario.load(os.path.join(REPO, "scenarios", "formations.json"))
        t = gen.generate(scn, 0)["truth"]
        self.assertEqual(t["scan"].min(), 6)
        self.assertEqual(len(set(t["target"][t["scan"] == 6].tolist())), 14)
        overlap = []
        for k in range(6, 40):
            m = t["scan"] == k
            left = t["x"][m & (t["target"] < 7)]
            right = t["x"][m & (t["target"] >= 7)]
            if left.max() >= right.min() and left.min() <= right.max():
                overlap.append(k)
        self.assertEqual(overlap, [13, 14, 15])

    def test_crossing3_geometry(self):
        # [S4]: three targets at 15 m/s meet at t = 40 s (scan 39) inside 1600 x 400.
        scn = scenario.load(os.path.join(REPO, "scenarios", "crossing3.json"), ["truth_process_psd=0"])
        t = gen.generate(scn, 0)["truth"]
        np.testing.assert_allclose(np.hypot(t["vx"], t["vy"]), 15.0)
        m = t["time"] == 40.0
        np.testing.assert_allclose(t["x"][m], 800.0)
        np.testing.assert_allclose(t["y"][m], 200.0, atol=1e-9)
        self.assertEqual(len(t["x"]), 240)

    def test_unknown_key_rejected(self):
        with self.assertRaisesRegex(scenario.ScenarioError, "clutterr"):
            make(clutterr=1)
        with self.assertRaisesRegex(scenario.ScenarioError, "tracker._comment"):
            make(tracker={"_comment": "no"})

    def test_dense_count_override(self):
        scn = scenario.load(os.path.join(REPO, "scenarios", "dense.json"), ["random_targets.count=7"])
        self.assertEqual(len(set(gen.generate(scn, 0)["truth"]["target"].tolist())), 7)


if __name__ == "__main__":
    unittest.main()
