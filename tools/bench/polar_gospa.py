#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""tools/bench/polar_gospa.py - polar detections against their Cartesian
conversion with a constant meas_sigma (ALGORITHMS.md §3.2).

For each seed, a scenario's truth (mtt_sim.gen) is seen by a radar at
--sensor: range and bearing with noise sigma_r, sigma_b, detection
probability pd, and clutter uniform in range x bearing (density per metre
radian) over the truth's span, each detection with a range rate (noise
--rr-sigma; clutter uniform in +-vmax).  mtt-track runs on the polar file
without and with its range_rate column (measurement polar) and on its plain
conversion r (cos b, sin b) with each constant meas_sigma of --cart-sigmas;
the mean GOSPA (c = --gospa-c), identity switches and false confirmed
tracks per scan are printed.

  PYTHONPATH=python python3 tools/bench/polar_gospa.py --mtt-track build/host-float/tools/track/mtt-track \\
      --scenario scenarios/crossing3.json --seeds 0 1 2
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

from mtt_sim import csvio, metrics


def radar(truth, sensor, sr, sb, srr, vmax, pd, dens, rng, margin=300.0):
    dx, dy = truth["x"] - sensor[0], truth["y"] - sensor[1]
    r_all, b_all = np.hypot(dx, dy), np.arctan2(dy, dx)
    rr_all = (dx * truth["vx"] + dy * truth["vy"]) / r_all
    r_lo, r_hi = max(r_all.min() - margin, 1.0), r_all.max() + margin
    b_lo, b_hi = b_all.min() - margin / r_lo, b_all.max() + margin / r_lo
    rows = []
    scans = np.unique(truth["scan"])
    for k in scans:
        sel = truth["scan"] == k
        t = float(truth["time"][sel][0])
        for r, b, rr in zip(r_all[sel], b_all[sel], rr_all[sel]):
            if rng.random() < pd:
                rows.append((int(k), t, r + sr * rng.standard_normal(), b + sb * rng.standard_normal(),
                             rr + srr * rng.standard_normal()))
        for _ in range(rng.poisson(dens * (r_hi - r_lo) * (b_hi - b_lo))):
            rows.append((int(k), t, rng.uniform(r_lo, r_hi), rng.uniform(b_lo, b_hi), rng.uniform(-vmax, vmax)))
    return rows


def write(path, header, rows, tail=()):
    """Rows (scan, time, a, b[, ...]) with an empty amplitude before the columns of tail."""
    with open(path, "w") as f:
        f.write(header + "\n")
        for row in rows:
            extra = "".join(f",{row[4 + i]:.10g}" for i in range(len(tail)))
            f.write(",".join(f"{v:.10g}" for v in row[:4]) + "," + extra + "\n")


def run(exe, settings, det, work, stem):
    s = os.path.join(work, stem + ".json")
    tr = os.path.join(work, stem + ".tracks.csv")
    with open(s, "w") as f:
        json.dump(settings, f)
    subprocess.run([exe, "--config", s, "--detections", det, "--tracks", tr], check=True)
    return csvio.read_tracks(tr)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--mtt-track", required=True)
    ap.add_argument("--scenario", default="scenarios/crossing3.json")
    ap.add_argument("--seeds", type=int, nargs="+", default=[0, 1, 2])
    ap.add_argument("--sensor", type=float, nargs=2, default=[700.0, -3000.0])
    ap.add_argument("--sigma", type=float, nargs=2, default=[5.0, 0.01], help="sigma_r (m), sigma_b (rad)")
    ap.add_argument("--density", type=float, default=0.05, help="clutter per metre radian")
    ap.add_argument("--pd", type=float, default=0.9)
    ap.add_argument("--rr-sigma", type=float, default=1.0, help="range rate sigma, length/time")
    ap.add_argument("--cart-sigmas", type=float, nargs="+", default=[5.0, 10.0, 20.0, 30.0, 40.0])
    ap.add_argument("--gospa-c", type=float, default=50.0)
    a = ap.parse_args()
    res = {}
    with tempfile.TemporaryDirectory() as work:
        for seed in a.seeds:
            d = os.path.join(work, f"s{seed}")
            subprocess.run([sys.executable, "-m", "mtt_sim.gen", a.scenario, "--seed", str(seed), "--out", d,
                            "--stem", "x"], check=True, stdout=subprocess.DEVNULL)
            truth = csvio.read_truth(os.path.join(d, "x.truth.csv"))
            with open(os.path.join(d, "x.settings.json")) as f:
                base = json.load(f)
            nscan = int(truth["scan"].max()) + 1
            vmax = float(base.get("vmax", 60.0))
            rows = radar(truth, a.sensor, a.sigma[0], a.sigma[1], a.rr_sigma, vmax, a.pd, a.density,
                         np.random.default_rng(1000 + seed))
            pol = os.path.join(d, "p.det.csv")
            write(pol, "scan,time,range,bearing,amplitude", rows)
            polr = os.path.join(d, "pr.det.csv")
            write(polr, "scan,time,range,bearing,amplitude,range_rate", rows, tail=("range_rate",))
            cart = os.path.join(d, "c.det.csv")
            write(cart, "scan,time,x,y,amplitude",
                  [(k, t, a.sensor[0] + r * np.cos(b), a.sensor[1] + r * np.sin(b)) for k, t, r, b, _ in rows])
            mean_r = float(np.mean(np.hypot(truth["x"] - a.sensor[0], truth["y"] - a.sensor[1])))
            ps = dict(base, measurement="polar", sensor_xy=a.sensor, meas_sigma=a.sigma, clutter_density=a.density)
            runs = {"polar": (ps, pol), "polar + range rate": (dict(ps, range_rate_sigma=a.rr_sigma), polr)}
            for s in a.cart_sigmas:
                runs[f"cartesian {s:g}"] = (dict(base, meas_sigma=[s, s], clutter_density=a.density / mean_r), cart)
            for name, (st, det) in runs.items():
                tracks = run(a.mtt_track, st, det, d, name.replace(" ", "_"))
                sc = metrics.score_run(truth, tracks, nscan, a.gospa_c / 2.0, a.gospa_c)
                r = res.setdefault(name, {"gospa": [], "idsw": [], "false": []})
                r["gospa"].append(float(np.mean(sc["gospa"])))
                r["idsw"].append(int(sc["mot"]["idsw"]))
                r["false"].append(float(np.mean(sc["conf_false"])))
    print("| input | mean GOSPA | ID switches (total) | false tracks / scan |")
    print("|---|---|---|---|")
    for name, r in res.items():
        print(f"| {name} | {np.mean(r['gospa']):.2f} | {sum(r['idsw'])} | {np.mean(r['false']):.3f} |")


if __name__ == "__main__":
    main()
