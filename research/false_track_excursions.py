# SPDX-License-Identifier: BSD-3-Clause
"""Where the max_accel default's false tracks on a calibration scene come from.

    PYTHONPATH=python python3 research/false_track_excursions.py [--scene ajaccio] [--seed 0] [--mtt-track PATH]

One run of scenarios/recorded/calibration_SCENE.json with its own settings
(the max_accel default): its detections drawn by mtt_sim.gen, tracked by
mtt-track.  A confirmed track counts as false at a scan when it is more
than c (the scene's gospa_c) from the one aircraft, as GOSPA scores it.
Prints the false-track scans per track (an excursion of the aircraft's own
track, or a track elsewhere), and for the first excursions the truth's
acceleration over the three steps before (|second difference| / dT²), the
nearest detection to the truth and the speed: an excursion follows a kink
of the piecewise-linear recorded truth with no detection near it.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

import numpy as np
import pandas as pd


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--scene", default="ajaccio")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--mtt-track", default="build/host-float/tools/track/mtt-track")
    ap.add_argument("--show", type=int, default=10, help="excursions to list (default 10)")
    a = ap.parse_args(argv)
    scen = f"scenarios/recorded/calibration_{a.scene}.json"
    c = json.load(open(scen))["metrics"]["gospa_c"]
    with tempfile.TemporaryDirectory() as d:
        env = dict(os.environ, PYTHONPATH="python")
        subprocess.run([sys.executable, "-m", "mtt_sim.gen", scen, "--seed", str(a.seed), "--out", d],
                       check=True, env=env, stdout=subprocess.DEVNULL)
        stem = os.path.join(d, f"calibration_{a.scene}")
        subprocess.run([a.mtt_track, "--config", stem + ".settings.json", "--detections", stem + ".det.csv",
                        "--tracks", stem + ".tracks.csv"], check=True)
        truth = pd.read_csv(stem + ".truth.csv")
        tracks = pd.read_csv(stem + ".tracks.csv")
        det = pd.read_csv(stem + ".det.csv")
    if truth.target.nunique() != 1:
        sys.exit("expected one aircraft")
    dt = float(np.median(np.diff(truth.time)))
    t = truth.set_index("scan")
    xy = t[["x", "y"]].to_numpy()
    acc = np.full(len(t), np.nan)
    acc[1:-1] = np.hypot(*(xy[2:] - 2 * xy[1:-1] + xy[:-2]).T) / dt ** 2
    t["acc"] = acc
    conf = tracks[tracks.status == "confirmed"].merge(t[["x", "y"]], left_on="scan", right_index=True,
                                                       suffixes=("", "_t"))
    conf["d"] = np.hypot(conf.x - conf.x_t, conf.y - conf.y_t)
    far = conf[conf.d > c]
    main_track = conf.groupby("track").size().idxmax()
    print(f"{scen} seed {a.seed}: {conf.scan.nunique()} scans with a confirmed track, "
          f"{len(far)} false-track scans (> c = {c:g} from the aircraft)")
    for tid, g in far.groupby("track"):
        kind = "the aircraft's own track" if tid == main_track else "another track"
        print(f"  track {tid} ({kind}): {len(g)} scans, median distance {g.d.median():.0f}")
    print("first excursions of the aircraft's track: scan, error, truth acceleration over the three "
          "steps before and at it, nearest detection to the truth, speed")
    own = far[far.track == main_track]
    for _, r in own.head(a.show).iterrows():
        s = int(r.scan)
        dd = det[det.scan == s]
        near = np.hypot(dd.x - t.x[s], dd.y - t.y[s]).min() if len(dd) else float("nan")
        print(f"  {s:5d} {r.d:7.0f} m  {np.round(t.acc.loc[s - 3:s].to_numpy(), 1)} m/s^2  "
              f"{near:7.0f} m  {np.hypot(t.vx[s], t.vy[s]):4.0f} m/s")


if __name__ == "__main__":
    main()
