# SPDX-License-Identifier: BSD-3-Clause
"""mtt_sim.recording: recorded trajectories as scenario truth (CSV and a fake traffic wheel, no network)."""

import copy
import glob
import gzip
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import unittest
import zipfile

from mtt_sim import csvio, gen, recording, scenario

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
FAKE = os.path.join(HERE, "fake_mtt_track.py")

try:
    import pandas  # noqa: F401

    HAVE_PANDAS = True
except ImportError:
    HAVE_PANDAS = False

# Target 7: x 0 -> 100 -> 300 m at t = 100, 110, 120 s (speed 10 then 20 m/s), y = 50.
# Target 9: samples at 100, 102, 114, 116 s: a 12 s gap between 102 and 114.
XY_CSV = """# a hand-made recording
time,id,x,y,alt
100,7,0,50,1000
110,7,100,50,1000
120,7,300,50,1000
102,9,10,20,0
100,9,0,20,0
114,9,110,20,0
116,9,130,20,0
"""

BASE = {
    "name": "rec",
    "area": {"x": [-1000, 1000], "y": [-1000, 1000]},
    "scans": {"dt": 2.0},
    "pd": 1.0,
    "meas_sigma": [1.0, 1.0],
    "clutter": {"model": "none"},
    "truth": {"recording": {"source": "rec.csv", "max_gap": 10}},
    "tracker": {"association": "lm-ihpda", "meas_sigma": [1.0, 1.0]},
}


def tmpdir(test):
    d = tempfile.mkdtemp(prefix="mtt_rec_")
    test.addCleanup(shutil.rmtree, d, ignore_errors=True)
    return d


def write(d, name, text):
    p = os.path.join(d, name)
    with open(p, "w") as f:
        f.write(text)
    return p


def scn_file(d, csv_text=XY_CSV, csv_name="rec.csv", overrides=None, **top):
    """Write the CSV and a scenario beside it (the source is relative to the scenario's folder); load it."""
    write(d, csv_name, csv_text)
    s = copy.deepcopy(BASE)
    s.update(top)
    p = write(d, "rec.json", json.dumps(s))
    return scenario.load(p, overrides)


def by_target(truth):
    out = {}
    for k, t, i, x, y, vx, vy in zip(*(truth[c] for c in ("scan", "time", "target", "x", "y", "vx", "vy"))):
        out.setdefault(int(i), {})[int(k)] = (float(t), float(x), float(y), float(vx), float(vy))
    return out


class TestProjection(unittest.TestCase):
    def test_hand_computed_metres(self):
        # WGS84 a = 6378137 m, e^2 = 0.00669437999: on the equator 0.01 degree east is
        # a sin(0.01 deg) = 1113.19490 m; 0.01 degree north is a (1 - e^2) sin(0.01 deg) = 1105.74275 m
        e, n = recording.project([0.0, 0.01], [0.01, 0.0], (0.0, 0.0))
        self.assertAlmostEqual(e[0], 1113.19490, delta=1e-4)
        self.assertAlmostEqual(n[0], 0.0, delta=1e-3)
        self.assertAlmostEqual(e[1], 0.0, delta=1e-9)
        self.assertAlmostEqual(n[1], 1105.74275, delta=2e-3)
        # the tangent plane's shortfall at 150 km from the origin: a th^3 / 6 = 13.8 m
        th = 150e3 / 6378137.0
        e, _ = recording.project([0.0], [math.degrees(th)], (0.0, 0.0))
        self.assertAlmostEqual(150e3 - e[0], 13.83, delta=0.01)

    def test_origin_elsewhere_is_zero_and_axes(self):
        e, n = recording.project([48.85, 48.86, 48.85], [2.35, 2.35, 2.36], (48.85, 2.35))
        self.assertAlmostEqual(e[0], 0.0, delta=1e-6)
        self.assertAlmostEqual(n[0], 0.0, delta=1e-6)
        self.assertAlmostEqual(e[1], 0.0, delta=0.1)  # north: east stays ~0
        # meridian radius M = a (1 - e^2) / (1 - e^2 sin^2 lat)^1.5 at 48.85 N: M * 0.01 deg = 1112.068 m
        self.assertAlmostEqual(n[1], 1112.068, delta=0.01)
        # 0.01 deg east: N cos(lat) sin(0.01 deg), N = a / sqrt(1 - e^2 sin^2 lat): 733.913 m
        self.assertAlmostEqual(e[2], 733.913, delta=1e-3)
        self.assertGreater(n[2], 0.0)  # the plane curves away: a point due east is slightly 'north'


class TestCsvTruth(unittest.TestCase):
    def test_interpolation_gaps_velocity(self):
        d = tmpdir(self)
        scn = scn_file(d)
        self.assertEqual(scn["scans"]["count"], 11)  # 100 .. 120 s at 2 s
        run = gen.generate(scn, 0)
        tr = by_target(run["truth"])
        self.assertEqual(sorted(tr), [7, 9])  # integer ids are kept
        t7 = tr[7]
        self.assertEqual(sorted(t7), list(range(11)))
        self.assertEqual(t7[0], (0.0, 0.0, 50.0, 10.0, 0.0))
        self.assertEqual(t7[2], (4.0, 40.0, 50.0, 10.0, 0.0))  # t = 104: 40 m, segment slope 10 m/s
        # t = 110 exactly: velocity_window's default, one scan (2 s): x(109) = 90, x(111) = 120, 30 m / 2 s
        self.assertEqual(t7[5][1:4], (100.0, 50.0, 15.0))
        self.assertEqual(t7[8][1:4], (220.0, 50.0, 20.0))  # t = 116: 100 + 20 * 6
        self.assertEqual(t7[10][1:4], (300.0, 50.0, 20.0))  # last sample
        # target 9: samples 100, 102 | 12 s gap > max_gap 10 | 114, 116; unsorted rows are sorted
        self.assertEqual(sorted(tr[9]), [0, 1, 7, 8])
        self.assertEqual(tr[9][1][1], 10.0)
        self.assertEqual(tr[9][1][3], 5.0)  # at 102, before the gap: the segment before it
        self.assertEqual(tr[9][7], (14.0, 110.0, 20.0, 10.0, 0.0))
        self.assertEqual(tr[9][8], (16.0, 130.0, 20.0, 10.0, 0.0))
        # PD 1, sigma 1, no clutter: one detection per truth row, near it
        self.assertEqual(len(run["det"]["x"]), len(run["truth"]["x"]))
        self.assertTrue((run["det"]["origin"] >= 0).all())

    def test_velocity_window(self):
        d = tmpdir(self)
        # 0: the segment's slope (at t = 110 exactly the next segment's, 20 m/s)
        t7 = by_target(gen.generate(scn_file(d, overrides=["truth.recording.velocity_window=0"]), 0)["truth"])[7]
        self.assertEqual([t7[k][3] for k in (0, 5, 6, 10)], [10.0, 20.0, 20.0, 20.0])
        tr = by_target(gen.generate(scn_file(d, overrides=["truth.recording.velocity_window=8"]), 0)["truth"])
        t7, t9 = tr[7], tr[9]
        # t = 112: [108, 116]: x 80 -> 220, 140 m / 8 s; t = 104: [100, 108] inside the first segment
        self.assertAlmostEqual(t7[6][3], 17.5, places=12)
        self.assertAlmostEqual(t7[2][3], 10.0, places=12)
        # t = 100, the first sample: [100, 104]: 10 m/s; t = 120, the last: [116, 120]: x 220 -> 300, 20 m/s
        self.assertAlmostEqual(t7[0][3], 10.0, places=12)
        self.assertAlmostEqual(t7[10][3], 20.0, places=12)
        # target 9: the window stops at the 12 s gap (> max_gap 10): at 102, [98, 106] -> [100, 102], 10 m / 2 s;
        # at 114, [110, 118] -> [114, 116], 20 m / 2 s
        self.assertAlmostEqual(t9[1][3], 5.0, places=12)
        self.assertAlmostEqual(t9[7][3], 10.0, places=12)
        self.assertEqual(t9[1][1:3], (10.0, 20.0))  # positions are the interpolation, whatever the window
        for bad in ("-1", '"a"'):
            with self.assertRaises(scenario.ScenarioError):
                scn_file(d, overrides=[f"truth.recording.velocity_window={bad}"])

    def test_max_gap_default_three_scans(self):
        d = tmpdir(self)
        scn = scn_file(d, overrides=["truth.recording.max_gap=12"])  # a gap of exactly max_gap is bridged
        self.assertEqual(sorted(by_target(gen.generate(scn, 0)["truth"])[9]), list(range(9)))
        s = copy.deepcopy(BASE)
        del s["truth"]["recording"]["max_gap"]
        write(d, "rec.csv", XY_CSV)
        p = write(d, "rec2.json", json.dumps(s))
        # default 3 dt = 6 s: target 7's 10 s spacing is a gap everywhere: seen at its own samples only
        tr = by_target(gen.generate(scenario.load(p), 0)["truth"])
        self.assertEqual((sorted(tr[7]), sorted(tr[9])), ([0, 5, 10], [0, 1, 7, 8]))
        # dt 4: default 12 s bridges both
        tr = by_target(gen.generate(scenario.load(p, ["scans.dt=4"]), 0)["truth"])
        self.assertEqual((sorted(tr[7]), sorted(tr[9])), ([0, 1, 2, 3, 4, 5], [0, 1, 2, 3, 4]))

    def test_area_clips(self):
        d = tmpdir(self)
        scn = scn_file(d, area={"x": [0, 250], "y": [0, 100]})
        t7 = by_target(gen.generate(scn, 0)["truth"])[7]
        self.assertEqual(sorted(t7), list(range(9)))  # t = 118: x = 260 > 250, t = 116: 220 inside
        run = gen.generate(scn, 0)
        self.assertTrue((run["det"]["x"] <= 250 + 10).all())

    def test_window_start_duration_t0(self):
        d = tmpdir(self)
        scn = scn_file(d, overrides=["truth.recording.start=4", "truth.recording.duration=10", "scans.t0=50"])
        self.assertEqual(scn["scans"]["count"], 6)  # recording 104 .. 114 s
        tr = by_target(gen.generate(scn, 0)["truth"])
        self.assertEqual(tr[7][0], (50.0, 40.0, 50.0, 10.0, 0.0))  # scan 0 at t0 = 50 is recording time 104
        self.assertEqual(tr[7][5][:2], (60.0, 180.0))  # 114 s
        self.assertEqual(sorted(tr[9]), [5])  # 114 (116 is after the window)

    def test_ids_filter_min_points_names(self):
        d = tmpdir(self)
        text = XY_CSV.replace(",7,", ",ab7,").replace(",9,", ",zz9,") + "119,q,5,5,0\n"
        scn = scn_file(d, text)
        tr = by_target(gen.generate(scn, 0)["truth"])
        self.assertEqual(sorted(tr), [0, 2])  # sorted names ab7, q, zz9 -> 0, 1, 2; q has one sample
        scn = scn_file(d, text, overrides=["truth.recording.first_id=10", 'truth.recording.ids=["zz9"]'])
        self.assertEqual(sorted(by_target(gen.generate(scn, 0)["truth"])), [10])
        scn = scn_file(d, overrides=["truth.recording.min_points=4"])
        self.assertEqual(sorted(by_target(gen.generate(scn, 0)["truth"])), [9])  # 7 has 3 samples

    def test_airborne_only(self):
        d = tmpdir(self)
        text = "time,id,x,y,onground\n100,5,0,0,true\n102,5,10,0,1\n104,5,20,0,false\n106,5,30,0,\n108,5,40,0,0\n"
        self.assertEqual(sorted(by_target(gen.generate(scn_file(d, text), 0)["truth"])[5]), [0, 1, 2, 3, 4])
        scn = scn_file(d, text, overrides=["truth.recording.airborne_only=true"])
        self.assertEqual(sorted(by_target(gen.generate(scn, 0)["truth"])[5]), [2, 3, 4])  # the taxi is left out
        with self.assertRaisesRegex(scenario.ScenarioError, r"rec\.csv:3: field 'onground': 'yes'"):
            scn_file(d, text.replace(",1\n", ",yes\n"))
        with self.assertRaisesRegex(scenario.ScenarioError, r"'airborne_only' needs an 'onground' column"):
            gen.generate(scn_file(d, overrides=["truth.recording.airborne_only=true"]), 0)
        with self.assertRaisesRegex(scenario.ScenarioError, r"key 'truth\.recording\.airborne_only': must be true or false"):
            scn_file(d, overrides=["truth.recording.airborne_only=1"])

    def test_lat_lon_and_iso_times(self):
        d = tmpdir(self)
        text = ("time,id,lat,lon\n"
                "2024-05-01T10:00:00Z,A1,0.0,0.0\n"
                "2024-05-01T10:00:10Z,A1,0.0,0.01\n")
        scn = scn_file(d, text, overrides=["truth.recording.origin=[0,0]", "scans.dt=5"])
        tr = by_target(gen.generate(scn, 0)["truth"])
        self.assertEqual(sorted(tr), [0])
        t, x, y, vx, vy = tr[0][1]
        self.assertEqual(t, 5.0)
        self.assertAlmostEqual(x, 1113.19490 / 2, delta=1e-4)
        self.assertAlmostEqual(y, 0.0, delta=1e-3)
        self.assertAlmostEqual(vx, 111.319490, delta=1e-5)
        # default origin: the recording's mean position (0, 0.005): the target runs from -556.6 to 556.6 m
        scn = scn_file(d, text, overrides=["scans.dt=5"])
        tr = by_target(gen.generate(scn, 0)["truth"])
        self.assertAlmostEqual(tr[0][0][1], -556.5975, delta=1e-3)
        self.assertAlmostEqual(tr[0][2][1], 556.5975, delta=1e-3)

    def test_determinism_and_sensor_model(self):
        d = tmpdir(self)
        scn = scn_file(d, overrides=["pd=0.7", "meas_sigma=[5,5]", "clutter.model=poisson", "clutter.mean=4"])
        a, b, c = gen.generate(scn, 3), gen.generate(scn, 3), gen.generate(scn, 4)
        fa, fb, fc = (csvio.format_det(r["det"], r["times"]) for r in (a, b, c))
        self.assertEqual(fa, fb)
        self.assertNotEqual(fa, fc)
        self.assertEqual(csvio.format_truth(a["truth"]), csvio.format_truth(c["truth"]))  # truth has no randomness
        out = tmpdir(self)
        p1 = gen.write_run(a, out, "one")
        p2 = gen.write_run(b, out, "two")
        for k in ("det", "truth", "settings"):
            with open(p1[k], "rb") as f1, open(p2[k], "rb") as f2:
                self.assertEqual(f1.read(), f2.read(), k)
        self.assertEqual(csvio.read_truth(p1["truth"])["x"].tolist(), a["truth"]["x"].tolist())

    def test_errors_name_file_line_field(self):
        d = tmpdir(self)
        cases = [
            ("time,id,x\n1,a,2\n", r"rec\.csv:1: field 'y': missing column"),
            ("time,id,x,y\n1,a,2,3\n2,a,zz,3\n", r"rec\.csv:3: field 'x': 'zz' is not a finite number"),
            ("time,id,x,y\n1,a,2,3\nnoon,a,2,3\n", r"rec\.csv:3: field 'time'"),
            ("time,id,x,y\n1,a,2,3\n2,,2,3\n", r"rec\.csv:3: field 'id': empty"),
            ("time,id,x,y\n1,a,2,3\n2,a,2\n", r"rec\.csv:3: 3 fields, the header has 4"),
            ("time,id,lat,lon\n1,a,95,3\n", r"rec\.csv:2: field 'lat'/'lon'"),
            ("# only a comment\n", r"rec\.csv: empty file"),
        ]
        for text, pat in cases:
            with self.subTest(pat=pat):
                with self.assertRaisesRegex(scenario.ScenarioError, pat):
                    scn_file(d, text)
        with self.assertRaisesRegex(scenario.ScenarioError, r"nope\.csv: No such file"):
            scn_file(d, overrides=["truth.recording.source=nope.csv"])
        with self.assertRaisesRegex(scenario.ScenarioError, r"ids zz not in the recording"):
            gen.generate(scn_file(d, overrides=['truth.recording.ids=["zz"]', "scans.count=3"]), 0)
        with self.assertRaisesRegex(scenario.ScenarioError, r"'origin' is for lat/lon recordings"):
            gen.generate(scn_file(d, overrides=["truth.recording.origin=[1,2]"]), 0)
        with self.assertRaisesRegex(scenario.ScenarioError, r"'start' 50 s is after the recording's end"):
            scn_file(d, overrides=["truth.recording.start=50"])

    def test_schema_errors(self):
        def bad(pat, **change):
            s = copy.deepcopy(BASE)
            s.update(change)
            with self.assertRaisesRegex(scenario.ScenarioError, pat):
                scenario.validate(s, "x.json")

        rec = BASE["truth"]["recording"]
        bad(r"x\.json: key 'truth\.recording\.foo': unknown key", truth={"recording": dict(rec, foo=1)})
        bad(r"key 'truth\.replay': unknown key", truth={"replay": {}})
        bad(r"key 'truth\.recording': missing", truth={})
        bad(r"key 'truth\.recording\.source'", truth={"recording": {"max_gap": 3}})
        bad(r"key 'truth\.recording\.max_gap': must be > 0", truth={"recording": dict(rec, max_gap=0)})
        bad(r"key 'truth\.recording\.min_points': must be >= 2", truth={"recording": dict(rec, min_points=1)})
        bad(r"key 'truth\.recording\.origin': must be \[lat, lon\]", truth={"recording": dict(rec, origin=[100, 0])})
        bad(r"key 'truth\.recording\.ids'", truth={"recording": dict(rec, ids=[])})
        bad(r"key 'targets': not with truth\.recording", targets=[{"id": 0, "x": 0, "y": 0, "vx": 0, "vy": 0}])
        bad(r"key 'truth_process_psd': not with truth\.recording", truth_process_psd=1)
        s = copy.deepcopy(BASE)
        del s["truth"]
        with self.assertRaisesRegex(scenario.ScenarioError, r"key 'scans\.count': missing"):
            scenario.validate(s, "x.json")


def fake_wheel(path, samples):
    """A zip laid out like the traffic wheel, with gzipped JSON-records samples {name: [records]}."""
    with zipfile.ZipFile(path, "w") as z:
        z.writestr("traffic/__init__.py", "")
        for name, records in samples.items():
            z.writestr(f"traffic/data/samples/{name}.json.gz", gzip.compress(json.dumps(records).encode()))
    return path


ORBIT = [  # a traffic-like sample: epoch ms, icao24, degrees, and columns the reader ignores
    {"timestamp": 1515748470000 + 5000 * i, "icao24": "39b415", "latitude": 0.0, "longitude": 0.002 * i,
     "groundspeed": 158, "track": 90, "callsign": "CALIBRA", "altitude": 1000, "onground": False}
    for i in range(5)
] + [
    {"timestamp": 1515748480000 + 5000 * i, "icao24": "400123", "latitude": 0.001 * i, "longitude": 0.0,
     "groundspeed": 100, "track": 0, "callsign": "X", "altitude": 2000, "onground": i == 0}
    for i in range(3)
]


class TestTruthAccelerations(unittest.TestCase):
    def test_circle_and_bridged_gap(self):
        import numpy as np
        # a circle r 2000 m at 100 m/s sampled every second, seen every 5 s:
        # the second difference of a chord polygon, 2 r (1 - cos(w 5)) / 5^2
        t = np.arange(0.0, 200.0, 1.0)
        w = 100.0 / 2000.0
        x, y = 2000.0 * np.cos(w * t), 2000.0 * np.sin(w * t)
        a = recording.sample_accelerations(t, np.array(["c"] * len(t), dtype=object), x, y, 5.0)
        self.assertEqual(len(a), len(np.arange(0.0, 199.0 + 1e-9, 5.0)) - 2)
        np.testing.assert_allclose(a, 2 * 2000.0 * (1 - math.cos(w * 5.0)) / 25.0, rtol=1e-9)
        # east at 100 m/s for 10 s, then north: one 28.28 m/s^2 step at a 5 s period
        t2 = np.arange(0.0, 21.0, 1.0)
        x2 = np.where(t2 <= 10.0, 100.0 * t2, 1000.0)
        y2 = np.where(t2 <= 10.0, 0.0, 100.0 * (t2 - 10.0))
        a2 = recording.sample_accelerations(t2, np.array(["k"] * len(t2), dtype=object), x2, y2, 5.0)
        np.testing.assert_allclose(a2, [0.0, 500.0 * math.sqrt(2.0) / 25.0, 0.0], atol=1e-9)

    def test_sample_jitter_is_the_noise_about_a_smooth_path(self):
        import numpy as np
        # a 2 km orbit at 100 m/s (5 m/s^2, an airliner's hardest turn) sampled every 5 s:
        # the quadratic leaves under 5 m
        t = np.arange(0.0, 3000.0, 5.0)
        w = 100.0 / 2000.0
        x, y = 2000.0 * np.cos(w * t), 2000.0 * np.sin(w * t)
        ids = np.array(["c"] * len(t), dtype=object)
        smooth, n = recording.sample_jitter(t, ids, x, y)
        self.assertEqual(n, 2 * (len(t) - 6))
        self.assertLess(smooth, 5.0)
        self.assertGreater(smooth, 0.5)
        # white noise of 40 per axis on it comes out as 40 (the leverage corrected)
        rng = np.random.default_rng(3)
        jit, _ = recording.sample_jitter(t, ids, x + rng.normal(0, 40.0, len(t)), y + rng.normal(0, 40.0, len(t)))
        self.assertAlmostEqual(jit, 40.0, delta=2.5)
        # a gap of 60 s: the windows across it are skipped
        keep = (t < 1000.0) | (t >= 1060.0)
        _, n2 = recording.sample_jitter(t[keep], ids[keep], x[keep], y[keep])
        self.assertEqual(n2, 2 * (int(keep.sum()) - 6 - 6))


class TestTrafficWheel(unittest.TestCase):
    def setUp(self):
        self.d = tmpdir(self)
        self.wheel = fake_wheel(os.path.join(self.d, "traffic-2.13-py3-none-any.whl"),
                                {"calibration/fake": ORBIT, "collections/other": ORBIT[:2]})
        self.env = os.environ.get("MTT_SIM_TRAFFIC_WHEEL")
        os.environ["MTT_SIM_TRAFFIC_WHEEL"] = self.wheel
        self.addCleanup(self._restore)
        recording._CACHE.clear()

    def _restore(self):
        if self.env is None:
            os.environ.pop("MTT_SIM_TRAFFIC_WHEEL", None)
        else:
            os.environ["MTT_SIM_TRAFFIC_WHEEL"] = self.env
        recording._CACHE.clear()

    def test_sample_list(self):
        self.assertEqual(recording.traffic_samples(), ["calibration/fake", "collections/other"])

    @unittest.skipUnless(HAVE_PANDAS, "pandas is not installed (the traffic reader's optional dependency)")
    def test_traffic_sample_truth(self):
        s = copy.deepcopy(BASE)
        s["truth"] = {"recording": {"source": "traffic:calibration/fake", "origin": [0, 0]}}
        s["scans"] = {"dt": 5.0}
        scn = scenario.loads(json.dumps(s), "t.json")
        self.assertEqual(scn["scans"]["count"], 5)  # 0 .. 20 s
        tr = by_target(gen.generate(scn, 0)["truth"])
        self.assertEqual(sorted(tr), [0, 1])  # icao24 39b415, 400123 in sorted order (hex names are not numbers)
        east = 6378137.0 * math.sin(math.radians(0.002))  # 222.6390 m per sample
        self.assertEqual(sorted(tr[0]), [0, 1, 2, 3, 4])
        self.assertAlmostEqual(tr[0][3][1], 3 * east, delta=1e-3)
        self.assertAlmostEqual(tr[0][3][3], east / 5.0, delta=1e-4)
        self.assertEqual(sorted(tr[1]), [2, 3, 4])  # starts 10 s after the first sample
        north = 6378137.0 * (1 - 0.0066943799901413165) * math.sin(math.radians(0.001))
        self.assertAlmostEqual(tr[1][4][2], 2 * north, delta=1e-2)
        # airborne_only: 400123's first sample (10 s) is on the ground
        scn = scenario.loads(json.dumps(s), "t.json", ["truth.recording.airborne_only=true"])
        self.assertEqual(sorted(by_target(gen.generate(scn, 0)["truth"])[1]), [3, 4])

    def test_unknown_sample_lists_available(self):
        s = copy.deepcopy(BASE)
        s["truth"] = {"recording": {"source": "traffic:calibration/nope"}}
        with self.assertRaisesRegex(scenario.ScenarioError,
                                    r"traffic:calibration/nope: no such sample .*available: calibration/fake, "
                                    r"collections/other"):
            scenario.loads(json.dumps(s), "t.json")

    def test_missing_wheel_env(self):
        os.environ["MTT_SIM_TRAFFIC_WHEEL"] = os.path.join(self.d, "absent.whl")
        with self.assertRaisesRegex(scenario.ScenarioError, r"MTT_SIM_TRAFFIC_WHEEL: .*absent\.whl: no such file"):
            recording.traffic_wheel()

    def test_fetch_failure_says_what_to_run(self):
        # pip with no index and an empty links folder fails at once, without the network
        code = ("import sys; from mtt_sim import recording\n"
                "try:\n    recording.traffic_wheel()\n"
                "except recording.RecordingError as e:\n    print(e); sys.exit(3)\n")
        env = dict(os.environ, MTT_SIM_CACHE=os.path.join(self.d, "cache"), PIP_NO_INDEX="1",
                   PIP_FIND_LINKS=self.d + "/nolinks", PYTHONPATH=os.path.join(REPO, "python"))
        env.pop("MTT_SIM_TRAFFIC_WHEEL")
        os.makedirs(self.d + "/nolinks")
        p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=300)
        self.assertEqual(p.returncode, 3, p.stdout + p.stderr)
        self.assertIn("could not fetch the traffic wheel", p.stdout)
        self.assertIn("pip download traffic==2.13 --no-deps -d", p.stdout)
        self.assertIn("MTT_SIM_TRAFFIC_WHEEL", p.stdout)


class TestShippedRecordedScenarios(unittest.TestCase):
    """scenarios/recorded/*.json: valid, the issue's sensor settings, the tracker told the sensor's facts (no I/O)."""

    def test_files(self):
        # the radar scenes (radar_*.json) are test_radar.py's
        files = sorted(f for f in glob.glob(os.path.join(REPO, "scenarios", "recorded", "*.json"))
                       if not os.path.basename(f).startswith("radar_"))
        names = {os.path.basename(f)[:-5] for f in files}
        self.assertIn("quickstart", names)
        self.assertGreaterEqual(len([n for n in names if n.startswith("calibration_")]), 20)
        for path in files:
            with self.subTest(path=path):
                with open(path) as f:
                    raw = json.load(f)
                self.assertTrue(set(raw["tracker"]) <= scenario.TRACKER_KEYS)
                scn = scenario._strip_comments(raw)
                scenario.validate(scn, path)  # validation only: loading would fetch the wheel
                self.assertEqual(scn["name"], os.path.basename(path)[:-5])
                src = scn["truth"]["recording"]["source"]
                quick = scn["name"] == "quickstart"
                self.assertEqual(src, "traffic:collections/quickstart" if quick
                                 else "traffic:calibration/" + scn["name"][len("calibration_"):])
                dt, sigma, mean = (4.0, 50.0, 100) if quick else (5.0, 30.0, 64)
                self.assertEqual((scn["scans"]["dt"], scn["meas_sigma"], scn["pd"]), (dt, [sigma, sigma], 0.9))
                self.assertEqual(scn["clutter"], {"model": "poisson", "mean": mean})
                t = scn["tracker"]
                # the sensor's facts and max_accel only (#25): no process_psd, no motion
                self.assertEqual((t["meas_sigma"], t["pd"], t["max_accel"], t["vmax"]), ([sigma, sigma], 0.9, 10, 350))
                self.assertFalse({"process_psd", "motion"} & set(t))
                self.assertEqual(scn["metrics"], {"match_distance": 10 * sigma, "gospa_c": 10 * sigma})
                self.assertAlmostEqual(t["clutter_density"] * scenario.area_size(scn) / mean, 1.0, delta=1e-9)


class TestMonteCarloOnRecording(unittest.TestCase):
    def test_progress_line_and_scores(self):
        d = tmpdir(self)
        write(d, "rec.csv", XY_CSV)
        s = copy.deepcopy(BASE)
        s["tracker"] = {"association": "lm-ihpda", "meas_sigma": [1.0, 1.0], "vmax": 30}
        s["metrics"] = {"match_distance": 10, "gospa_c": 10}
        p = write(d, "rec.json", json.dumps(s))
        out = os.path.join(d, "out")
        env = dict(os.environ, PYTHONPATH=os.path.join(REPO, "python"))
        r = subprocess.run([sys.executable, "-m", "mtt_sim.mc", "--scenario", p, "--runs", "2", "--jobs", "1",
                            "--out", out, "--mtt-track", FAKE, "--tracker", "mtt-track"],
                           capture_output=True, text=True, env=env, timeout=600)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("[run 0/2]", r.stderr)
        self.assertIn("[run 2/2]", r.stderr)
        with open(os.path.join(out, "summary.json")) as f:
            summ = json.load(f)
        self.assertEqual(len(summ["scan_times"]), 11)
        self.assertEqual(summ["results"]["lm-ihpda"]["runs_ok"], 2)


if __name__ == "__main__":
    unittest.main()
