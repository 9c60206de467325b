#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Draw one run of a scenario: ground truth and detections, and the command that writes them.

Command line: DIR/<name>.det.csv, .truth.csv, .settings.json.

    PYTHONPATH=python python3 -m mtt_sim.gen scenarios/crossing3.json --seed 7 --out out/gen
    PYTHONPATH=python python3 -m mtt_sim.gen scenarios/dense.json --seed 1 --out out/gen --set random_targets.count=80
    PYTHONPATH=python python3 -m mtt_sim.gen scenarios/recorded/radar_quickstart.json --seed 0 --out out/gen  # polar

Formats: docs/FORMATS.md.  Same scenario + seed = same bytes.

Model (every number comes from the scenario, see scenarios/README.md):

- Targets move with the constant-velocity model of docs/ALGORITHMS.md §2, except during
  their ``manoeuvres``: a coordinated turn {"scan": k0, "scans": n, "g": a}
  turns the velocity at constant speed over the n propagation steps from
  scan k0 to scan k0 + n, with turn rate w = a G0 / |v| (lateral
  acceleration a in standard gravities G0 = 9.80665 m/s^2, so metres and
  seconds; positive turns left, counter-clockwise) or a given ``turn_rate``
  w in rad per time unit; each step is the exact circular arc.  With
  ``truth_process_psd`` Sw > 0, each scan adds w ~ N(0, Q) with
  Q = Sw [[dt^3/3, dt^2/2], [dt^2/2, dt]] per axis (continuous white-noise
  acceleration, the tracker's own model); with Sw = 0 the motion is exact.
- With ``"truth": {"recording": ...}`` the targets are a recording's instead
  (mtt_sim/recording.py: the local tangent plane, linear interpolation at
  the scan times, absent in gaps longer than ``max_gap``); it draws nothing
  from the truth stream, and everything below applies unchanged.
- A target is in the sensor's field at scan k when first_scan <= k <=
  last_scan and its position is inside the area (bounds inclusive).  Only
  then does it have a truth row and a chance to be detected.
- Each target in the field is detected with its PD; the detection is its
  position plus N(0, diag(sx^2, sy^2)).  With ``resolution`` r > 0, target
  detections closer than r are merged (single linkage) into one at their
  mean position (amplitudes add): an unresolved pair.
- Clutter: ``poisson`` draws a Poisson count with mean density * area (or
  ``mean``) per scan; ``binomial`` draws Binomial(n, p); positions are
  uniform over the area.
- Amplitudes: clutter Exp(mean 1), target Exp(mean 1 + rho), rho the
  target's own ``rho`` if it has one, else the scenario's.  Without an
  ``amplitude`` object the amplitudes are still drawn (so the other numbers
  of a seed do not change) but written empty.
- With ``"sensor": {"kind": "radar", ...}`` the sensor is a radar instead
  (mtt_sim/radar.py: range, bearing, optional range rate, clutter uniform in
  range x bearing over its coverage, the polar detections file; or, with
  ``"output": "xy"``, the user's conversion of it to x, y).
- Detections of one scan are written in a random order (targets and clutter
  shuffled together) so that no tracker tie rule sees targets first.

Determinism: ``numpy.random.SeedSequence(seed)`` is spawned into four
independent PCG64 streams, truth / target detections / clutter / order, so a
given seed gives the same file bytes on every machine, and changing the
clutter model leaves the truth and the target detections of a seed unchanged
(common random numbers across settings).
"""

from __future__ import annotations

import argparse
import math
import sys

import numpy as np

from . import csvio, radar
from . import scenario as scnmod

__all__ = ["generate", "write_run", "cv_q", "main"]


def cv_q(dt: float, psd: float) -> np.ndarray:
    """Per-axis 2x2 process noise [[dt^3/3, dt^2/2], [dt^2/2, dt]] * psd (position, velocity)."""
    return psd * np.array([[dt ** 3 / 3.0, dt ** 2 / 2.0], [dt ** 2 / 2.0, dt]])


def _streams(seed: int):
    ss = np.random.SeedSequence(int(seed))
    return [np.random.Generator(np.random.PCG64(s)) for s in ss.spawn(4)]


def _random_targets(scn, rng, nscan, times):
    rt = scn.get("random_targets")
    if not rt or int(rt["count"]) == 0:
        return []
    a = scn["area"]
    m = float(rt.get("margin", 0.0))
    x0, x1 = a["x"][0] + m, a["x"][1] - m
    y0, y1 = a["y"][0] + m, a["y"][1] - m
    if x1 < x0 or y1 < y0:
        raise scnmod.ScenarioError("random_targets.margin leaves no room in the area")
    n = int(rt["count"])
    first = int(rt.get("first_id", 0))
    fs = int(rt.get("first_scan", 0))
    ls = int(rt.get("last_scan", nscan - 1))
    x = rng.uniform(x0, x1, n)
    y = rng.uniform(y0, y1, n)
    heading = rng.uniform(0.0, 2.0 * math.pi, n)
    speed = rng.uniform(float(rt["speed"][0]), float(rt["speed"][1]), n)
    pd = float(rt.get("pd", scn["pd"]))
    t_ref = times[min(fs, nscan - 1)]
    return [{"id": first + i, "x": float(x[i]), "y": float(y[i]),
             "vx": float(speed[i] * math.cos(heading[i])), "vy": float(speed[i] * math.sin(heading[i])),
             "t_ref": t_ref, "first_scan": fs, "last_scan": ls, "pd": pd} for i in range(n)]


def _turn_rate(t, k, s):
    """Turn rate of target t on the step from scan k to k + 1 (0: straight)."""
    for m in t.get("manoeuvres", ()):
        k0 = int(m["scan"])
        if k0 <= k < k0 + int(m["scans"]):
            if "turn_rate" in m:
                return float(m["turn_rate"])
            speed = math.hypot(s[2], s[3])
            return float(m["g"]) * scnmod.G0 / speed if speed > 0 else 0.0
    return 0.0


def _turn(s, w, dt):
    """Exact coordinated-turn step of state s = [x, y, vx, vy] in place."""
    sn, cs = math.sin(w * dt), math.cos(w * dt)
    vx, vy = s[2], s[3]
    s[0] += (sn * vx - (1.0 - cs) * vy) / w
    s[1] += ((1.0 - cs) * vx + sn * vy) / w
    s[2] = cs * vx - sn * vy
    s[3] = sn * vx + cs * vy


def _recorded_truth(scn, times):
    """_truth for ``truth.recording``: interpolated recorded positions, clipped to the area."""
    from . import recording  # noqa: PLC0415 (only for a recording)

    a = scn["area"]
    pd = float(scn["pd"])
    tracks = recording.truth_tracks(scn, times)
    rows = []
    present = [[] for _ in times]
    for tid in sorted(tracks):
        pres, x, y, vx, vy = tracks[tid]
        inside = pres & (x >= a["x"][0]) & (x <= a["x"][1]) & (y >= a["y"][0]) & (y <= a["y"][1])
        for k in np.flatnonzero(inside):
            present[k].append((tid, float(x[k]), float(y[k]), pd, None, float(vx[k]), float(vy[k])))
    for k, pres in enumerate(present):  # rows in scan order, ids ascending within a scan
        for tid, x, y, _, _, vx, vy in pres:
            rows.append((k, times[k], tid, x, y, vx, vy))
    return rows, present


def _truth(scn, rng, times):
    """Return (truth table, per-scan list of (id, x, y, pd, rho, vx, vy) present)."""
    rows, present = _truth_rows(scn, rng, times)
    if radar.is_radar(scn):  # the field is the area and the radar's coverage
        r = radar.sensor(scn)
        for k, pres in enumerate(present):
            z = np.zeros(len(pres))
            rng, brg, _ = radar.polar_of(r, [p[1] for p in pres], [p[2] for p in pres], z, z)
            present[k] = [p for p, inside in zip(pres, radar.in_coverage(r, rng, brg)) if inside]
        keep = {(k, p[0]) for k, pres in enumerate(present) for p in pres}
        rows = [row for row in rows if (row[0], row[2]) in keep]
    return _truth_table(rows), present


def _truth_rows(scn, rng, times):
    """The truth's rows (scan, time, id, x, y, vx, vy) inside the area, and the present lists."""
    if "truth" in scn:
        return _recorded_truth(scn, times)
    nscan = len(times)
    dt = float(scn["scans"]["dt"])
    psd = float(scn.get("truth_process_psd", 0.0))
    a = scn["area"]
    targets = scnmod.expand_targets(scn) + _random_targets(scn, rng, nscan, times)
    byid = {t["id"]: t for t in targets}
    splits = {}
    for s in scn.get("splits", []):
        splits.setdefault(int(s["scan"]), []).append(s)
    children = {int(s["child"]): s for s in scn.get("splits", [])}
    order = sorted(byid)
    chol = np.linalg.cholesky(cv_q(dt, psd)) if psd > 0 else None
    state = {}  # id -> np.array([x, y, vx, vy])
    rows = []
    present = []
    for k in range(nscan):
        # 1. propagate / create regular targets in id order
        for tid in order:
            t = byid[tid]
            if not t["first_scan"] <= k <= t["last_scan"]:
                state.pop(tid, None)
                continue
            if tid not in state:
                tau = times[k] - t["t_ref"]
                state[tid] = np.array([t["x"] + t["vx"] * tau, t["y"] + t["vy"] * tau, t["vx"], t["vy"]])
            else:
                s = state[tid]
                w = _turn_rate(t, k - 1, s)
                if w == 0.0:
                    s[0] += dt * s[2]
                    s[1] += dt * s[3]
                else:
                    _turn(s, w, dt)
                if chol is not None:
                    w = chol @ rng.standard_normal((2, 2))  # columns: x axis, y axis
                    s[0] += w[0, 0]
                    s[2] += w[1, 0]
                    s[1] += w[0, 1]
                    s[3] += w[1, 1]
        # 2. splits at this scan: the child starts at the parent's position
        for sp in splits.get(k, []):
            pid, cid = int(sp["parent"]), int(sp["child"])
            if pid not in state:
                raise scnmod.ScenarioError(f"split at scan {k}: parent {pid} is not alive")
            p = state[pid]
            c = p.copy()
            c[2] += float(sp["dv_child"][0])
            c[3] += float(sp["dv_child"][1])
            p[2] += float(sp["dv_parent"][0])
            p[3] += float(sp["dv_parent"][1])
            state[cid] = c
            byid[cid] = dict(byid[pid], id=cid, first_scan=k, manoeuvres=[])  # the child flies straight
            order = sorted(byid)
        # 3. record targets in the field
        pres = []
        for tid in order:
            if tid not in state:
                continue
            if tid in children and k < int(children[tid]["scan"]):
                continue
            s = state[tid]
            if a["x"][0] <= s[0] <= a["x"][1] and a["y"][0] <= s[1] <= a["y"][1]:
                rows.append((k, times[k], tid, s[0], s[1], s[2], s[3]))
                pres.append((tid, s[0], s[1], byid[tid]["pd"], byid[tid].get("rho"), s[2], s[3]))
        present.append(pres)
    return rows, present


def _truth_table(rows):
    truth = csvio.empty_truth()
    if rows:
        c = list(zip(*rows))
        truth = {"scan": np.array(c[0], int), "time": np.array(c[1], float), "target": np.array(c[2], int),
                 "x": np.array(c[3], float), "y": np.array(c[4], float),
                 "vx": np.array(c[5], float), "vy": np.array(c[6], float)}
    return truth


def _merge_unresolved(xy, amp, origin, r):
    """Single-linkage merge of points closer than r; returns merged arrays."""
    n = len(xy)
    parent = list(range(n))

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for i in range(n):
        for j in range(i + 1, n):
            if np.hypot(*(xy[i] - xy[j])) < r:
                parent[find(j)] = find(i)
    groups = {}
    for i in range(n):
        groups.setdefault(find(i), []).append(i)
    oxy, oamp, oorg = [], [], []
    for root in sorted(groups):
        g = groups[root]
        oxy.append(xy[g].mean(axis=0))
        oamp.append(amp[g].sum())
        oorg.append(origin[g[0]] if len(g) == 1 else -2)
    return np.array(oxy).reshape(-1, 2), np.array(oamp), np.array(oorg, int)


def _clutter_count(cl, area, rng):
    model = cl.get("model", "none")
    if model == "poisson":
        mean = float(cl["mean"]) if "mean" in cl else float(cl["density"]) * area
        return int(rng.poisson(mean))
    if model == "binomial":
        return int(rng.binomial(int(cl["n"]), float(cl["p"])))
    return 0


def generate(scn: dict, seed: int, association: str | None = None) -> dict:
    """Draw one run.

    Returns a dict: name, seed, times (array, every scan), truth (table),
    det (table plus ``origin``: target id, -1 clutter, -2 merged targets),
    settings (the tracker object, association optionally replaced) and
    seeded_targets (target ids of the tracker's initial_tracks, in order).
    """
    rng_truth, rng_det, rng_clut, rng_order = _streams(seed)
    times = scnmod.scan_times(scn)
    truth, present = _truth(scn, rng_truth, times)
    if radar.is_radar(scn):
        detections = _radar_detections(scn, present, times, rng_det, rng_clut, rng_order)
    else:
        detections = _xy_detections(scn, present, times, rng_det, rng_clut, rng_order)
    return {
        "name": scn["name"],
        "seed": int(seed),
        "times": np.array(times, float),
        "truth": truth,
        "det": detections,
        "settings": scnmod.tracker_settings(scn, association),
        "seeded_targets": scnmod.seeded_targets(scn),
    }


def _tables(cols):
    detections = {k: (np.concatenate(v) if v else np.zeros(0)) for k, v in cols.items()}
    detections["scan"] = detections["scan"].astype(int)
    detections["origin"] = detections["origin"].astype(int)
    return detections


def _radar_detections(scn, present, times, rng_det, rng_clut, rng_order):
    """The radar's detections table (range, bearing, range_rate with sigma_range_rate; x, y with output xy)."""
    r = radar.sensor(scn)
    amp_cfg = scn.get("amplitude")
    rho = float(amp_cfg["rho"]) if amp_cfg else 0.0
    cl = scn.get("clutter", {"model": "none"})
    measure = radar.clutter_measure(r)
    cols = {"scan": [], "time": [], "range": [], "bearing": [], "range_rate": [], "amp": [], "origin": []}
    for k, pres in enumerate(present):
        tr, tb, trr, tamp, org = radar.measure(r, pres, rng_det, rho)
        m = _clutter_count(cl, measure, rng_clut)
        cr, cb, crr, camp = radar.clutter(r, m, rng_clut)
        n = len(tr) + m
        perm = rng_order.permutation(n)
        cols["scan"].append(np.full(n, k, int))
        cols["time"].append(np.full(n, times[k]))
        for key, a, b in (("range", tr, cr), ("bearing", tb, cb), ("range_rate", trr, crr), ("amp", tamp, camp)):
            cols[key].append(np.concatenate([a, b])[perm])
        if not amp_cfg:
            cols["amp"][-1] = np.full(n, np.nan)
        cols["origin"].append(np.concatenate([org, -np.ones(m, int)])[perm])
    det = _tables(cols)
    if r["srr"] is None:
        del det["range_rate"]
    return radar.converted(det, r["xs"], r["ys"]) if r["output"] == "xy" else det


def _xy_detections(scn, present, times, rng_det, rng_clut, rng_order):
    """The x, y sensor's detections table."""
    sx, sy = (float(v) for v in scn["meas_sigma"])
    amp_cfg = scn.get("amplitude")
    rho = float(amp_cfg["rho"]) if amp_cfg else 0.0
    res = float(scn.get("resolution", 0.0))
    cl = scn.get("clutter", {"model": "none"})
    a = scn["area"]
    area = scnmod.area_size(scn)
    cols = {"scan": [], "time": [], "x": [], "y": [], "amp": [], "origin": []}
    for k, pres in enumerate(present):
        # target detections (draws made for every present target, detected or not)
        n = len(pres)
        u = rng_det.random(n)
        noise = rng_det.standard_normal((n, 2)) * np.array([sx, sy])
        # a target's own rho (optional) overrides the scenario's; the draws are
        # the same standard exponentials times the mean either way
        tamp = rng_det.exponential(1.0 + np.array([rho if p[4] is None else p[4] for p in pres], float), n)
        det = u < np.array([p[3] for p in pres], float) if n else np.zeros(0, bool)
        xy = np.array([[p[1], p[2]] for p in pres], float).reshape(-1, 2) + noise
        xy, tamp = xy[det], tamp[det]
        org = np.array([p[0] for p in pres], int)[det]
        if res > 0 and len(xy) > 1:
            xy, tamp, org = _merge_unresolved(xy, tamp, org, res)
        # clutter
        m = _clutter_count(cl, area, rng_clut)
        cx = rng_clut.uniform(a["x"][0], a["x"][1], m)
        cy = rng_clut.uniform(a["y"][0], a["y"][1], m)
        camp = rng_clut.exponential(1.0, m)
        allx = np.concatenate([xy[:, 0], cx])
        ally = np.concatenate([xy[:, 1], cy])
        alla = np.concatenate([tamp, camp])
        allo = np.concatenate([org, -np.ones(m, int)])
        perm = rng_order.permutation(len(allx))
        cols["scan"].append(np.full(len(allx), k, int))
        cols["time"].append(np.full(len(allx), times[k]))
        cols["x"].append(allx[perm])
        cols["y"].append(ally[perm])
        cols["amp"].append(alla[perm] if amp_cfg else np.full(len(allx), np.nan))
        cols["origin"].append(allo[perm])
    return _tables(cols)


def write_run(run: dict, out_dir: str, stem: str | None = None) -> dict:
    """Write <stem>.det.csv, <stem>.truth.csv, <stem>.settings.json; return the paths."""
    import os

    os.makedirs(out_dir, exist_ok=True)
    stem = stem or run["name"]
    paths = {
        "det": os.path.join(out_dir, f"{stem}.det.csv"),
        "truth": os.path.join(out_dir, f"{stem}.truth.csv"),
        "settings": os.path.join(out_dir, f"{stem}.settings.json"),
    }
    csvio.write_det(paths["det"], run["det"], run["times"])
    csvio.write_truth(paths["truth"], run["truth"])
    csvio.write_settings(paths["settings"], run["settings"])
    return paths


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("scenario", help="scenario JSON file (scenarios/*.json)")
    ap.add_argument("--seed", type=int, default=0, help="random seed (default 0)")
    ap.add_argument("--out", required=True, help="output directory")
    ap.add_argument("--assoc", help="replace the tracker's association mode in the settings file")
    ap.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                    help="override a scenario value by dotted path (repeatable), e.g. clutter.density=1e-4")
    ap.add_argument("--stem", help="file name stem (default: the scenario name)")
    a = ap.parse_args(argv)
    try:
        scn = scnmod.load(a.scenario, a.set)
        run = generate(scn, a.seed, a.assoc)
        paths = write_run(run, a.out, a.stem)
    except (scnmod.ScenarioError, OSError) as e:
        print(f"gen.py: {e}", file=sys.stderr)
        return 2
    ndet = len(run["det"]["scan"])
    ntgt = int((run["det"]["origin"] >= 0).sum())
    print(f"{paths['det']}: {len(run['times'])} scans, {ndet} detections ({ntgt} from targets, "
          f"{int((run['det']['origin'] == -1).sum())} clutter, {int((run['det']['origin'] == -2).sum())} merged)")
    print(f"{paths['truth']}: {len(run['truth']['x'])} rows, {len(set(run['truth']['target'].tolist()))} targets")
    print(f"{paths['settings']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
