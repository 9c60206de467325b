#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""A stand-in for mtt-track used by the harness tests (NOT the project's tracker).

Same command line and files as docs/FORMATS.md's mtt-track:

    fake_mtt_track.py --config S.json --detections D.det.csv --tracks T.tracks.csv

A deliberately simple global-nearest-neighbour CV Kalman tracker: gate at
chi-square 13.8, greedy nearest assignment, two-point initiation within vmax,
confirmed after 3 updates, deleted after 3 misses in a row.  It exists so the
Monte Carlo machinery (subprocess, timing, parsing, scoring, plots) can be
tested without the C build.  With env FAKE_MTT_FAIL=1 it fails like a bad
input (exit 2, one line on stderr, no tracks file).
"""

import json
import os
import sys

import numpy as np

from mtt_sim import csvio


def main():
    args = dict(zip(sys.argv[1::2], sys.argv[2::2]))
    if os.environ.get("FAKE_MTT_FAIL") == "1":
        print("fake-mtt-track: forced failure", file=sys.stderr)
        return 2
    with open(args["--config"]) as f:
        cfg = json.load(f)
    det, times = csvio.read_det(args["--detections"])
    sx, sy = cfg.get("meas_sigma", [1.0, 1.0])
    R = np.diag([sx * sx, sy * sy])
    q = float(cfg.get("process_psd", 5.0))
    vmax = float(cfg.get("vmax", 60.0))
    H = np.hstack([np.eye(2), np.zeros((2, 2))])
    tracks = []  # dict(id, x, P, hits, miss, conf)
    next_id = 0
    for it in cfg.get("initial_tracks", []):
        P = np.array(it["P"], float).reshape(4, 4) if "P" in it else np.diag([sx * sx, sy * sy, 2 * sx * sx, 2 * sy * sy])
        tracks.append({"id": next_id, "x": np.array([it["x"], it["y"], it["vx"], it["vy"]], float), "P": P,
                       "hits": 3, "miss": 0, "conf": True})
        next_id += 1
    prev_unused = np.zeros((0, 2))
    prev_t = None
    lines = [csvio.TRACKS_HEADER]
    for k in sorted(times):
        t = times[k]
        m = det["scan"] == k
        z = np.column_stack([det["x"][m], det["y"][m]])
        dt = (t - prev_t) if prev_t is not None else 1.0
        F = np.eye(4)
        F[0, 2] = F[1, 3] = dt
        Q1 = q * np.array([[dt ** 3 / 3, dt ** 2 / 2], [dt ** 2 / 2, dt]])
        Q = np.zeros((4, 4))
        Q[np.ix_([0, 2], [0, 2])] = Q1
        Q[np.ix_([1, 3], [1, 3])] = Q1
        used = np.zeros(len(z), bool)
        cands = []
        for ti, tr in enumerate(tracks):
            if prev_t is not None:
                tr["x"] = F @ tr["x"]
                tr["P"] = F @ tr["P"] @ F.T + Q
            S = H @ tr["P"] @ H.T + R
            Si = np.linalg.inv(S)
            for j in range(len(z)):
                v = z[j] - tr["x"][:2]
                d2 = float(v @ Si @ v)
                if d2 <= 13.8:
                    cands.append((d2, ti, j))
        cands.sort()
        done = set()
        for d2, ti, j in cands:
            if ti in done or used[j]:
                continue
            tr = tracks[ti]
            S = H @ tr["P"] @ H.T + R
            K = tr["P"] @ H.T @ np.linalg.inv(S)
            tr["x"] = tr["x"] + K @ (z[j] - tr["x"][:2])
            tr["P"] = (np.eye(4) - K @ H) @ tr["P"]
            tr["hits"] += 1
            tr["miss"] = 0
            tr["conf"] = tr["conf"] or tr["hits"] >= 3
            used[j] = True
            done.add(ti)
        for ti, tr in enumerate(tracks):
            if ti not in done:
                tr["miss"] += 1
        tracks = [tr for tr in tracks if tr["miss"] < 3]
        unused = z[~used]
        if prev_t is not None and len(prev_unused) and len(unused):
            for a in unused:
                d = np.hypot(*(prev_unused - a).T)
                j = int(np.argmin(d))
                if d[j] <= vmax * dt:
                    b = prev_unused[j]
                    P = np.block([[R, R / dt], [R / dt, 2 * R / dt ** 2]])
                    tracks.append({"id": next_id, "x": np.array([a[0], a[1], (a[0] - b[0]) / dt, (a[1] - b[1]) / dt]),
                                   "P": P, "hits": 1, "miss": 0, "conf": False})
                    next_id += 1
        prev_unused = unused
        prev_t = t
        for tr in tracks:
            x, P = tr["x"], tr["P"]
            lines.append(f"{k},{t:.10g},{tr['id']},{'confirmed' if tr['conf'] else 'tentative'},"
                         f"{x[0]:.10g},{x[1]:.10g},{x[2]:.10g},{x[3]:.10g},,{P[0, 0]:.10g},{P[0, 1]:.10g},{P[1, 1]:.10g}")
    with open(args["--tracks"], "w") as f:
        f.write("\n".join(lines) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
