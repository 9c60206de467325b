#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Where a scenario's split-off tracks come from (docs/reports/MOTION.md "Split targets").

For every split-off track (non-empty ``parent`` in the tracks file) of
RUNS runs: the detection nearest its first estimate (within 3 sigma) and
that detection's origin.  Classes: ``dup-parent`` (a detection of the
parent's own target), ``dup-tracked`` (of another target that a confirmed
track other than the child already holds within the match distance),
``untracked`` (of a target without such a track), ``merged`` (of two
unresolved targets), ``clutter`` (clutter or no detection near); and the
split's onset (the first scan of the parent's run of p_split >= 0.01
before the birth): ``near`` when another confirmed track was within two
match distances of the parent then, else ``alone``.  Per class: tracks
per run, and their confirmed scans that are false (unmatched under the
scores' matching) per scan, against every confirmed false track-scan.

    PYTHONPATH=python python3 research/split_false_origin.py scenarios/crossing3.json --runs 100 --seed0 1000 \
        --set tracker.motion=imm --set tracker.split=true --set tracker.split_dv=20 \
        --set tracker.split_known_speed=true --set tracker.split_confirm=0.95 [--mtt-track BINARY]

(the tracker's association is lm-ihpda, as mc's --assoc lm-ihpda).
"""
import argparse
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from mtt_sim import csvio, gen, mc, metrics  # noqa: E402
from mtt_sim import scenario as scnmod  # noqa: E402

CLASSES = ("dup-parent", "dup-tracked", "untracked", "merged", "clutter")


def one(scn, seed, exe):
    run = gen.generate(scn, seed, "lm-ihpda")
    nscan = len(run["times"])
    with tempfile.TemporaryDirectory(prefix="sfo_") as td:
        p = gen.write_run(run, td, "r")
        mc.run_tracker(exe, p["settings"], p["det"], os.path.join(td, "t.csv"))
        tr = csvio.read_tracks(os.path.join(td, "t.csv"))
    md = float(scn["metrics"]["match_distance"])
    gate = 3.0 * float(max(scn["meas_sigma"]))
    fr = metrics.frames(run["truth"], tr, nscan)
    det, trk = run["det"], tr  # detections with their origin; the tracks file
    ids, par, scan = (np.asarray(trk[k], int) for k in ("track", "parent", "scan"))
    tx, ty = np.asarray(trk["x"], float), np.asarray(trk["y"], float)
    ps, conf = np.asarray(trk["p_split"], float), np.asarray(trk["confirmed"], bool)
    held = []  # per scan: {track id: truth id} of the matched confirmed tracks
    false = []  # per scan: unmatched confirmed track ids
    for gid, gxy, hid, hxy in fr:
        pairs = metrics.match(gxy, hxy, md) if len(gid) and len(hxy) else []
        held.append({int(hid[j]): int(gid[i]) for i, j in pairs})
        false.append(set(int(h) for h in hid) - set(held[-1]))
    cls = {}
    for tid in np.unique(ids[par >= 0]):
        r = np.nonzero(ids == tid)[0]
        k0 = int(scan[r].min())
        i0 = r[np.argmin(scan[r])]
        pid = int(par[i0])
        dk = np.nonzero(np.asarray(det["scan"], int) == k0)[0]
        d = np.hypot(np.asarray(det["x"], float)[dk] - tx[i0], np.asarray(det["y"], float)[dk] - ty[i0])
        org = int(np.asarray(det["origin"], int)[dk[np.argmin(d)]]) if len(d) and d.min() <= gate else -1
        holders = {h: g for h, g in held[k0].items() if h != tid}
        if org == -2:
            c = "merged"
        elif org < 0:
            c = "clutter"
        elif holders.get(pid) == org:
            c = "dup-parent"
        elif org in holders.values():
            c = "dup-tracked"
        else:
            c = "untracked"
        # the split's onset: the first scan of the parent's run of p_split >= 0.01 before the birth
        ks = k0
        while ks > 0 and np.any((ids == pid) & (scan == ks - 1) & (ps >= 0.01)):
            ks -= 1
        pk = np.nonzero((ids == pid) & (scan == ks))[0]
        ok = np.nonzero((scan == ks) & conf & (ids != pid) & (ids != tid))[0]
        near = len(pk) and len(ok) and np.hypot(tx[ok] - tx[pk[0]], ty[ok] - ty[pk[0]]).min() <= 2.0 * md
        cls[int(tid)] = (c, "near" if near else "alone")
    nc, fs = {}, {}
    for h, key in cls.items():
        nc[key] = nc.get(key, 0) + 1
        fs[key] = fs.get(key, 0) + sum(1 for k in range(nscan) if h in false[k])
    return nc, fs, sum(len(f) for f in false), nscan


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("scenario")
    ap.add_argument("--runs", type=int, default=100)
    ap.add_argument("--seed0", type=int, default=1000)
    ap.add_argument("--set", action="append", default=[])
    ap.add_argument("--mtt-track", default=None)
    a = ap.parse_args()
    scn = scnmod.load(a.scenario, a.set)
    exe = mc.find_mtt_track(a.mtt_track)
    nc, fs = {}, {}
    tot = scans = 0
    for s in range(a.seed0, a.seed0 + a.runs):
        n1, f1, t1, k1 = one(scn, s, exe)
        for key in n1:
            nc[key] = nc.get(key, 0) + n1[key]
            fs[key] = fs.get(key, 0) + f1[key]
        tot += t1
        scans += k1
    print(f"{a.runs} runs, {scans} scans: confirmed false track-scans per scan {tot / scans:.4f}")
    print("| child started on | onset | split-off tracks per run | their confirmed false per scan |")
    print("|---|---|---|---|")
    for c in CLASSES:
        for o in ("near", "alone"):
            if (c, o) in nc:
                print(f"| {c} | {o} | {nc[c, o] / a.runs:.2f} | {fs[c, o] / scans:.4f} |")
    print(f"| all split-offs | | {sum(nc.values()) / a.runs:.2f} | {sum(fs.values()) / scans:.4f} |")


if __name__ == "__main__":
    main()
