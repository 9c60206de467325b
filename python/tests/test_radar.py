# SPDX-License-Identifier: BSD-3-Clause
"""mtt_sim.radar, the radar sensor: noise statistics, clutter uniform in range and bearing, range rate,
coverage, determinism, the polar file, the user's conversion to x, y, radar_compare without polar mtt-track."""

import copy
import glob
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import numpy as np

from mtt_sim import csvio, gen, radar, radar_compare, scenario

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
FAKE = os.path.join(HERE, "fake_mtt_track.py")

BASE = {
    "name": "radar_unit",
    "area": {"x": [-20000, 20000], "y": [-20000, 20000]},
    "scans": {"count": 50, "dt": 1.0},
    "sensor": {"kind": "radar", "position": [500.0, -300.0], "sigma_range": 20.0, "sigma_bearing": 0.004,
               "range_min": 1000, "range_max": 15000},
    "pd": 1.0,
    "clutter": {"model": "none"},
    "targets": [{"id": 0, "x": 6000, "y": 2000, "vx": 0, "vy": 0}],
    "tracker": {"association": "lm-ihpda", "measurement": "polar", "sensor_xy": [500.0, -300.0],
                "meas_sigma": [20.0, 0.004]},
}


def make(overrides=None, **top):
    d = copy.deepcopy(BASE)
    d.update(top)
    return scenario.loads(json.dumps(d), "radar_unit.json", overrides)


def tmpdir(tc):
    d = tempfile.mkdtemp(prefix="mtt_radar_test_")
    tc.addCleanup(shutil.rmtree, d, True)
    return d


def angle_diff(a, b):
    return np.mod(np.asarray(a) - np.asarray(b) + math.pi, 2 * math.pi) - math.pi


class TestRadarNoise(unittest.TestCase):
    def test_range_and_bearing_noise_have_the_sigmas(self):
        n = 4000
        scn = make(["scans.count=4000"])
        run = gen.generate(scn, 3)
        d = run["det"]
        self.assertEqual(len(d["range"]), n)  # PD 1, no clutter, always inside the coverage
        r = radar.sensor(scn)
        r0 = math.hypot(6000 - 500, 2000 + 300)
        b0 = math.atan2(2000 + 300, 6000 - 500)
        er = d["range"] - r0
        eb = angle_diff(d["bearing"], b0)
        # the mean within 4 standard errors, the standard deviation within 4 of its standard errors
        for e, s in ((er, r["sr"]), (eb, r["sb"])):
            self.assertLess(abs(e.mean()), 4 * s / math.sqrt(n))
            self.assertLess(abs(e.std(ddof=1) / s - 1.0), 4 / math.sqrt(2 * n))
        self.assertLess(abs(np.corrcoef(er, eb)[0, 1]), 4 / math.sqrt(n))
        self.assertNotIn("range_rate", d)  # no sigma_range_rate: no range rate

    def test_range_rate_is_the_radial_velocity_of_a_straight_line_target(self):
        scn = make(["scans.count=40", "scans.dt=0.01", "sensor.sigma_range_rate=1e-9", "sensor.range_rate_max=400",
                    "targets.0.vx=-120", "targets.0.vy=45"])
        run = gen.generate(scn, 0)
        t, d = run["truth"], run["det"]
        self.assertEqual(len(t["x"]), 40)
        # the truth's range, differentiated numerically (central differences over one scan,
        # 0.01 s: the difference's error, the third derivative times dt^2 / 6, is below 1e-5 m/s)
        rng = np.hypot(t["x"] - 500.0, t["y"] + 300.0)
        fd = (rng[2:] - rng[:-2]) / 0.02
        order = np.argsort(d["scan"])
        rr = d["range_rate"][order][1:-1]
        np.testing.assert_allclose(rr, fd, atol=1e-4)
        self.assertTrue((np.abs(rr) > 50).all() and (np.abs(rr) < math.hypot(120, 45) + 1e-9).all())

    def test_range_rate_noise_has_its_sigma(self):
        n = 3000
        scn = make([f"scans.count={n}", "sensor.sigma_range_rate=2.5", "sensor.range_rate_max=400",
                    "targets.0.vx=30", "targets.0.vy=-10", "targets.0.x=-8000", "targets.0.y=500",
                    "scans.dt=0.01"])
        run = gen.generate(scn, 5)
        t, d = run["truth"], run["det"]
        order = np.argsort(d["scan"], kind="stable")
        dx, dy = t["x"] - 500.0, t["y"] + 300.0
        radial = (dx * t["vx"] + dy * t["vy"]) / np.hypot(dx, dy)
        e = d["range_rate"][order] - radial
        self.assertLess(abs(e.mean()), 4 * 2.5 / math.sqrt(n))
        self.assertLess(abs(e.std(ddof=1) / 2.5 - 1.0), 4 / math.sqrt(2 * n))


class TestRadarClutter(unittest.TestCase):
    def clutter_run(self, *over):
        scn = make(["scans.count=400", "pd=0", *over],
                   clutter={"model": "poisson", "mean": 50})
        return scn, gen.generate(scn, 11)

    def test_uniform_in_range_and_bearing(self):
        scn, run = self.clutter_run()
        d = run["det"]
        n = len(d["range"])
        self.assertTrue((run["det"]["origin"] == -1).all())
        self.assertLess(abs(n - 20000), 4 * math.sqrt(20000))  # Poisson(50) per scan, 400 scans
        # chi-square of the counts in 10 range bins and 12 bearing bins: below the 0.999 quantiles
        # of 9 and 11 degrees of freedom (27.88, 31.26); a uniform-in-area draw would put
        # ~3 times more points in the outer range bin than in the inner one
        counts, _ = np.histogram(d["range"], bins=10, range=(1000, 15000))
        self.assertLess(((counts - n / 10) ** 2 / (n / 10)).sum(), 27.88)
        counts, _ = np.histogram(d["bearing"], bins=12, range=(-math.pi, math.pi))
        self.assertLess(((counts - n / 12) ** 2 / (n / 12)).sum(), 31.26)
        self.assertTrue((d["bearing"] >= -math.pi).all() and (d["bearing"] < math.pi).all())

    def test_density_is_per_range_times_bearing(self):
        # density 1e-3 per m rad over 14 km x 2 pi: mean 87.96 per scan
        scn = make(["scans.count=200", "pd=0"], clutter={"model": "poisson", "density": 1e-3})
        run = gen.generate(scn, 2)
        mean = 1e-3 * 14000 * 2 * math.pi
        self.assertAlmostEqual(scenario.clutter_measure(scn), 14000 * 2 * math.pi)
        self.assertLess(abs(len(run["det"]["range"]) / 200 - mean), 4 * math.sqrt(mean / 200))

    def test_clutter_range_rate_uniform_in_its_span(self):
        scn = make(["scans.count=200", "pd=0", "sensor.sigma_range_rate=1", "sensor.range_rate_max=300"],
                   clutter={"model": "poisson", "mean": 50})
        rr = gen.generate(scn, 4)["det"]["range_rate"]
        self.assertTrue((np.abs(rr) <= 300).all())
        counts, _ = np.histogram(rr, bins=10, range=(-300, 300))
        self.assertLess(((counts - len(rr) / 10) ** 2 / (len(rr) / 10)).sum(), 27.88)


class TestRadarCoverage(unittest.TestCase):
    def test_sector_and_annulus(self):
        # a 90 degree sector facing north-east, 2 to 9 km; one target crossing out of it, one never in it
        scn = make(["scans.count=60", "sensor.position=[0,0]", "sensor.range_min=2000", "sensor.range_max=9000",
                    "sensor.bearing=[0,1.5707963267948966]", "tracker.sensor_xy=[0,0]"],
                   clutter={"model": "poisson", "mean": 30},
                   targets=[{"id": 0, "x": 3000, "y": 3000, "vx": 150, "vy": 0},
                            {"id": 1, "x": -5000, "y": -5000, "vx": 0, "vy": 0}])
        run = gen.generate(scn, 1)
        t, d = run["truth"], run["det"]
        self.assertNotIn(1, set(t["target"].tolist()))
        r = np.hypot(t["x"], t["y"])
        self.assertTrue((r <= 9000).all() and (t["x"] >= 0).all())
        # target 0 leaves at range 9 km: x = sqrt(9000^2 - 3000^2) = 8485 m, at t = 36.6 s
        self.assertEqual(int(t["scan"].max()), 36)
        self.assertTrue(((d["range"] >= 2000) & (d["range"] <= 9000)).all())
        self.assertTrue(((d["bearing"] >= 0) & (d["bearing"] <= math.pi / 2)).all())
        self.assertGreater(len(d["range"]), 60 * 30 * 0.8)

    def test_sector_across_pi(self):
        r = radar.sensor(make(["sensor.bearing=[2.5,3.8]"]))
        self.assertEqual(radar.in_coverage(r, [5000] * 4, [3.0, -3.0, 2.4, -2.5]).tolist(),
                         [True, True, False, True])

    def test_validation(self):
        for over, key in ((["meas_sigma=[1,1]"], "meas_sigma"), (["sensor.range_max=500"], "sensor.range_max"),
                          (["sensor.sigma_range_rate=1"], "sensor.range_rate_max"),
                          (["sensor.kind=\"xy\""], "sensor.kind"), (["sensor.output=\"cart\""], "sensor.output"),
                          (["sensor.bearing=[0,7]"], "sensor.bearing"), (["sensor.sigma_range=0"], "sensor.sigma_range"),
                          (["resolution=5"], "resolution"), (["sensor.beam=1"], "sensor.beam")):
            with self.subTest(over=over):
                with self.assertRaises(scenario.ScenarioError) as cm:
                    make(over)
                self.assertIn(f"'{key}'", str(cm.exception))

    def test_default_position_is_the_area_centre(self):
        scn = make(["area.x=[0,10000]", "area.y=[-4000,0]", "sensor.position=null"])
        r = radar.sensor(scn)
        self.assertEqual((r["xs"], r["ys"]), (5000.0, -2000.0))


class TestRadarDeterminismAndFiles(unittest.TestCase):
    def scn(self, *over):
        return make(["scans.count=30", "sensor.range_rate_max=400", *over],
                    clutter={"model": "poisson", "mean": 20}, pd=0.8,
                    targets=[{"id": 0, "x": 6000, "y": 2000, "vx": 50, "vy": -20},
                             {"id": 1, "x": -4000, "y": 7000, "vx": -30, "vy": 10}])

    def test_same_seed_same_bytes(self):
        s = self.scn()
        a, b, c = gen.generate(s, 9), gen.generate(s, 9), gen.generate(s, 10)
        fa, fb, fc = (csvio.format_det(r["det"], r["times"]) for r in (a, b, c))
        self.assertEqual(fa, fb)
        self.assertNotEqual(fa, fc)
        self.assertEqual(fa.splitlines()[0], "scan,time,range,bearing,amplitude")

    def test_range_rate_and_output_leave_the_other_numbers(self):
        plain = gen.generate(self.scn(), 9)["det"]
        rate = gen.generate(self.scn("sensor.sigma_range_rate=2"), 9)["det"]
        xy = gen.generate(self.scn("sensor.output=\"xy\""), 9)["det"]
        for k in ("range", "bearing", "scan", "origin"):
            np.testing.assert_array_equal(plain[k], rate[k])
        np.testing.assert_array_equal(plain["origin"], xy["origin"])
        self.assertNotIn("range", xy)
        x, y = radar.to_xy(plain["range"], plain["bearing"], 500.0, -300.0)
        np.testing.assert_allclose(xy["x"], x, atol=1e-4)
        np.testing.assert_allclose(xy["y"], y, atol=1e-4)

    def test_polar_file_and_converter(self):
        d = tmpdir(self)
        run = gen.generate(self.scn("sensor.sigma_range_rate=2", "scans.count=8", "clutter.mean=0", "pd=0.3"), 1)
        paths = gen.write_run(run, d, "p")
        with open(paths["det"]) as f:
            lines = f.read().splitlines()
        self.assertEqual(lines[0], "scan,time,range,bearing,amplitude,range_rate")
        empty = [ln for ln in lines[1:] if ln.split(",")[2] == ""]
        self.assertTrue(empty and all(ln.count(",") == 5 and ln.endswith(",,,,") for ln in empty), lines)
        det, times = csvio.read_polar_det(paths["det"])
        np.testing.assert_allclose(det["range"], run["det"]["range"][np.argsort(run["det"]["scan"], kind="stable")],
                                   rtol=1e-9)
        self.assertEqual(sorted(times), list(range(8)))
        # the converter: x, y file back to range and bearing
        out = os.path.join(d, "xy.det.csv")
        r = subprocess.run([sys.executable, "-m", "mtt_sim.radar", "convert", paths["det"], out,
                            "--sensor-xy", "500", "-300"], capture_output=True, text=True,
                           env=dict(os.environ, PYTHONPATH=os.path.join(REPO, "python")), timeout=120)
        self.assertEqual(r.returncode, 0, r.stderr)
        xy, times2 = csvio.read_det(out)
        self.assertEqual(times, times2)
        np.testing.assert_allclose(np.hypot(xy["x"] - 500, xy["y"] + 300), det["range"], rtol=1e-8)
        np.testing.assert_allclose(angle_diff(np.arctan2(xy["y"] + 300, xy["x"] - 500), det["bearing"]), 0,
                                   atol=1e-8)
        # the generator's "output": "xy" writes the converter's bytes
        xrun = gen.generate(self.scn("sensor.sigma_range_rate=2", "scans.count=8", "clutter.mean=0", "pd=0.3",
                                     "sensor.output=\"xy\""), 1)
        with open(out) as f:
            self.assertEqual(f.read(), csvio.format_det(xrun["det"], xrun["times"]))

    def test_bad_polar_file(self):
        d = tmpdir(self)
        p = os.path.join(d, "bad.csv")
        with open(p, "w") as f:
            f.write("scan,time,range,bearing,amplitude,range_rate\n0,0,100,0.1,,\n")
        with self.assertRaises(csvio.FormatError) as cm:
            csvio.read_polar_det(p)
        self.assertIn(":2: field 'range_rate'", str(cm.exception))


class TestShippedRadarScenario(unittest.TestCase):
    def test_radar_quickstart(self):
        files = sorted(glob.glob(os.path.join(REPO, "scenarios", "recorded", "radar_*.json")) +
                       glob.glob(os.path.join(REPO, "scenarios", "radar", "*.json")))
        self.assertIn(os.path.join(REPO, "scenarios", "recorded", "radar_quickstart.json"), files)
        self.assertIn(os.path.join(REPO, "scenarios", "radar", "crossing3.json"), files)
        for path in files:
            with self.subTest(path=path):
                with open(path) as f:
                    scn = scenario._strip_comments(json.load(f))
                scenario.validate(scn, path)  # no I/O: loading would fetch the wheel
                base = os.path.basename(path)[:-5]
                self.assertEqual(scn["name"], base if base.startswith("radar_") else "radar_" + base)
                r, t = radar.sensor(scn), scn["tracker"]
                # the tracker is told the radar's facts
                self.assertEqual(t["measurement"], "polar")
                self.assertEqual(t["sensor_xy"], [r["xs"], r["ys"]])
                self.assertEqual(t["meas_sigma"], [r["sr"], r["sb"]])
                self.assertEqual(t["pd"], scn["pd"])
                c = scn["clutter"]  # a mean per scan over the coverage, or a density per m rad
                lam = c["density"] if "density" in c else c["mean"] / radar.clutter_measure(r)
                self.assertAlmostEqual(t["clutter_density"] / lam, 1.0, delta=1e-9)
                self.assertTrue(set(t) <= scenario.TRACKER_KEYS)
        with open(os.path.join(REPO, "scenarios", "recorded", "radar_quickstart.json")) as f:
            scn = scenario._strip_comments(json.load(f))
        self.assertEqual((scn["scans"]["dt"], scn["sensor"]["sigma_range"], scn["clutter"]["mean"]), (10.0, 50.0, 200))
        self.assertAlmostEqual(math.degrees(scn["sensor"]["sigma_bearing"]), 0.15, places=12)


class TestRadarCompare(unittest.TestCase):
    def test_polar_rows_skipped_without_polar_mtt_track(self):
        d = tmpdir(self)
        s = copy.deepcopy(BASE)
        s.update(clutter={"model": "poisson", "mean": 5}, pd=0.9)
        s["scans"]["count"] = 12
        s["targets"] = [{"id": 0, "x": 6000, "y": 2000, "vx": 20, "vy": 0}]
        s["tracker"]["vmax"] = 100
        s["tracker"]["clutter_density"] = 5 / (14000 * 2 * math.pi)
        s["metrics"] = {"match_distance": 200, "gospa_c": 200}
        p = os.path.join(d, "radar_unit.json")
        with open(p, "w") as f:
            json.dump(s, f)
        ok, msg = radar_compare.polar_support(FAKE)
        self.assertFalse(ok)
        self.assertIn("mtt-track exit", msg)  # the stand-in reads x, y files only
        r = subprocess.run([sys.executable, "-m", "mtt_sim.radar_compare", "--scenario", p, "--runs", "1",
                            "--jobs", "1", "--out", os.path.join(d, "out"), "--mtt-track", FAKE, "--no-stonesoup",
                            "--sweep", "20", "100", "--shuffle-check"],
                           capture_output=True, text=True, env=dict(os.environ, PYTHONPATH=os.path.join(REPO, "python")),
                           timeout=600)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("refuses polar input", r.stderr)
        self.assertIn("refuses range rate", r.stderr)
        self.assertFalse(radar_compare.polar_support(FAKE, True)[0])
        with open(os.path.join(d, "out", "radar_unit", "summary.json")) as f:
            summ = json.load(f)
        rows = {row["row"]: row for row in summ["rows"]}
        self.assertIn("skipped", rows["polar"])
        self.assertIn("skipped", rows["polar+rr"])
        self.assertEqual(rows["xy sigma=20"]["runs_ok"], 1)
        self.assertGreater(rows["xy sigma=20"]["tracked"], 0.5)
        x = rows["xy sigma=20"]  # GOSPA p 1: the parts add up to it, each at least 0
        self.assertAlmostEqual(x["gospa_loc"] + x["gospa_missed"] + x["gospa_false"], x["gospa"],
                               delta=1e-9 * x["gospa"])
        self.assertGreaterEqual(min(x["gospa_loc"], x["gospa_missed"], x["gospa_false"]), 0.0)
        self.assertIn("GOSPA = localisation + missed + false", r.stdout)
        self.assertIn(summ["acceptance"]["best_xy"], ("xy sigma=20", "xy sigma=100"))
        self.assertNotIn("gospa_ratio", summ["acceptance"])  # no figure for a row that did not run
        self.assertIn("tracks byte-identical", r.stdout)

    def test_converted_settings(self):
        scn = make(clutter={"model": "poisson", "mean": 100}, tracker=dict(BASE["tracker"], range_rate_sigma=2))
        c = radar_compare.converted_scenario(scn, 150.0)
        self.assertEqual(c["sensor"]["output"], "xy")
        self.assertFalse({"measurement", "sensor_xy", "range_rate_sigma"} & set(c["tracker"]))
        self.assertEqual(c["tracker"]["meas_sigma"], [150.0, 150.0])
        self.assertAlmostEqual(c["tracker"]["clutter_density"], 100 / (math.pi * (15000 ** 2 - 1000 ** 2)))
        self.assertEqual(scn["tracker"]["measurement"], "polar")  # the original is unchanged


if __name__ == "__main__":
    unittest.main()
