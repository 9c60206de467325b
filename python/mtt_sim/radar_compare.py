#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""A radar scene tracked four ways on the same detections: polar, polar plus range rate, converted to x, y, Stone Soup's EKF.

    PYTHONPATH=python python3 -m mtt_sim.radar_compare --scenario scenarios/recorded/radar_quickstart.json \\
        --runs 1 --out out/radar_compare/quickstart

For each scenario (a ``"sensor": {"kind": "radar"}`` one, mtt_sim/radar.py),
on the same detections (run r: seed SEED0 + r in every row, as mtt_sim.mc
does; the radar's random numbers do not depend on range rate or on the
output form), the rows are:

  polar           the scenario's tracker settings as they stand (measurement
                  polar, meas_sigma [sigma_range, sigma_bearing], max_accel)
  polar+rr        the same with range rate: sensor.sigma_range_rate and
                  tracker.range_rate_sigma = --range-rate-sigma (default 2)
  xy sigma=S      the detections converted by the user to x, y (sensor.output
                  xy: x = x_s + r cos b, y = y_s + r sin b) and tracked with one
                  constant meas_sigma [S, S] and clutter_density = the
                  clutter mean per scan / the coverage's area, for each S of
                  --sweep (default 50 100 150 200 300 500); the best GOSPA is
                  the reference
  stonesoup-ekf   Stone Soup's JPDA with an extended Kalman filter and
                  CartesianToBearingRange (mtt_sim.stonesoup_mc.EkfJpdaTracker)
                  at process_psd --stonesoup-q (default 50, quickstart's best
                  constant-velocity value of #25), JPDAwithEHM unless
                  --stonesoup-associator jpda; --no-stonesoup leaves it out
                  (slow: on radar_quickstart's first scans, 200 clutter points
                  each, about 3 s per scan with ehm, 8 s with jpda)

The polar rows need an mtt-track that reads polar detections (issue 26): the
command asks the binary first and, when it refuses ``measurement: polar``
(or the range_rate column), leaves that row out with mtt-track's message
(never a number in its place).  --shuffle-check also tracks run 0's files with each scan's rows
in a shuffled order and says whether the tracks files are byte-identical.

Columns as mtt_sim.compare's: GOSPA per scan, ID switches per run,
confirmed false tracks per scan, tracked fraction; then GOSPA's parts
(localisation, missed, false; p 1: their sum), averaged over the scans.  Acceptance (#26): polar
GOSPA <= 0.85 x the best xy, ID switches and false tracks no more; polar+rr
below polar in GOSPA and ID switches; polar ahead of Stone Soup in GOSPA
and false tracks.  Writes OUT/<scenario>/table.txt and summary.json; prints
the tables.  Exit status 0, 1 if a run failed, 2 on bad arguments.
"""

from __future__ import annotations

import argparse
import json
import os
import random
import sys
import tempfile
import time

import numpy as np

from . import compare, mc, radar, scenario

SWEEP = (50.0, 100.0, 150.0, 200.0, 300.0, 500.0)
RANGE_RATE_SIGMA = 2.0
STONESOUP_Q = 50.0
POLAR_ONLY = ("measurement", "sensor_xy", "range_rate_sigma")


def polar_support(exe: str, range_rate: bool = False) -> tuple[bool, str]:
    """(True, "") when mtt-track tracks a polar detections file (with its range_rate column
    and range_rate_sigma), else (False, its message)."""
    with tempfile.TemporaryDirectory(prefix="mtt_polar_probe_") as td:
        cfg, det, trk = (os.path.join(td, n) for n in ("s.json", "d.csv", "t.csv"))
        with open(cfg, "w", encoding="utf-8") as f:
            json.dump({"measurement": "polar", "sensor_xy": [0.0, 0.0], "meas_sigma": [10.0, 0.01],
                       **({"range_rate_sigma": 1.0} if range_rate else {})}, f)
        with open(det, "w", encoding="utf-8") as f:
            f.write("scan,time,range,bearing,amplitude,range_rate\n0,0,1000,0.5,,1\n1,1,1001,0.5,,1\n"
                    if range_rate else "scan,time,range,bearing,amplitude\n0,0,1000,0.5,\n1,1,1001,0.5,\n")
        try:
            mc.run_tracker(exe, cfg, det, trk, timeout=60.0)
        except mc.TrackerError as e:
            return False, str(e)
    return True, ""


def with_settings(scn: dict, sensor: dict | None = None, tracker: dict | None = None) -> dict:
    """A copy of scn with sensor keys set and tracker keys set (None: removed)."""
    s = json.loads(json.dumps(scn))
    for part, kv in (("sensor", sensor or {}), ("tracker", tracker or {})):
        for k, v in kv.items():
            if v is None:
                s[part].pop(k, None)
            else:
                s[part][k] = v
    return s


def converted_scenario(scn: dict, sigma: float) -> dict:
    """The user's x, y row: output xy, meas_sigma [S, S], clutter per the coverage's area, no polar keys."""
    r = radar.sensor(scn)
    mean = _clutter_mean(scn)
    return with_settings(scn, {"output": "xy"},
                         {**{k: None for k in POLAR_ONLY}, "meas_sigma": [sigma, sigma],
                          "clutter_density": mean / radar.coverage_area(r)})


def _clutter_mean(scn):
    from .stonesoup_mc import mean_clutter  # noqa: PLC0415 (the one definition of a scenario's mean clutter)

    return mean_clutter(scn)


def shuffle_check(scn: dict, exe: str, seed: int, out_dir: str) -> bool:
    """Track run ``seed``'s detections and a copy with each scan's rows shuffled; True if the tracks are the same bytes."""
    from . import gen  # noqa: PLC0415

    run = gen.generate(scn, seed)
    paths = gen.write_run(run, out_dir, "shuffle")
    with open(paths["det"], encoding="utf-8") as f:
        lines = f.read().splitlines()
    rows = {}
    for ln in lines[1:]:
        rows.setdefault(ln.split(",", 1)[0], []).append(ln)
    rnd = random.Random(12345)
    out = [lines[0]]
    for k in rows:  # scans stay in order; the rows of a scan are shuffled
        rnd.shuffle(rows[k])
        out += rows[k]
    shuffled = os.path.join(out_dir, "shuffle.shuffled.det.csv")
    with open(shuffled, "w", encoding="utf-8") as f:
        f.write("\n".join(out) + "\n")
    ta, tb = (os.path.join(out_dir, n) for n in ("shuffle.tracks.csv", "shuffle.shuffled.tracks.csv"))
    mc.run_tracker(exe, paths["settings"], paths["det"], ta)
    mc.run_tracker(exe, paths["settings"], shuffled, tb)
    with open(ta, "rb") as fa, open(tb, "rb") as fb:
        return fa.read() == fb.read()


def run_rows(scn, runs, exe, jobs, seed0, sweep, rr_sigma, stonesoup_q, support, associator="ehm",
             log=sys.stderr):
    """The rows of one scenario (the module's doc); a row left out is {"row", "skipped": reason}.

    ``support``: {"polar": (ok, message), "polar+rr": (ok, message)}, polar_support's answers."""
    rows = []
    mode = scenario.tracker_value(scn, "association")

    def one(name, s, tracker=None):
        t0 = time.monotonic()
        res = mc.monte_carlo(s, [mode if tracker is None else "stonesoup-jpda"], runs,
                             exe if tracker is None else tracker, jobs, seed0, progress=None)
        out = list(res["results"].values())[0]
        r = compare._row(name, out)
        # GOSPA's parts (p 1: their sum), each averaged over the scans as GOSPA is
        r.update({f"gospa_{k}": float(np.mean(out["per_scan"][f"gospa_{k}_mean"])) if out["runs_ok"] else None
                  for k in ("loc", "missed", "false")})
        rows.append(r)
        log.write(f"  {scn['name']}: {name:16s} GOSPA {r['gospa']:9.2f}  ({time.monotonic() - t0:.0f} s)\n")
        log.flush()

    polar_rows = (("polar", scn), ("polar+rr", with_settings(
        scn, {"sigma_range_rate": rr_sigma}, {"range_rate_sigma": rr_sigma})))
    for name, s in polar_rows:
        ok, msg = support[name]
        if ok:
            one(name, s)
        else:
            what = "polar input" if name == "polar" else "polar input with range rate"
            rows.append({"row": name, "skipped": f"mtt-track refuses {what}: {msg}"})
            log.write(f"  {scn['name']}: {name:16s} skipped (mtt-track refuses {what})\n")
    for sig in sweep:
        one(f"xy sigma={sig:g}", converted_scenario(scn, sig))
    if stonesoup_q is not None:
        from .stonesoup_mc import EkfJpdaTracker  # noqa: PLC0415

        s = with_settings(scn, tracker={"process_psd": stonesoup_q})
        one(f"stonesoup-ekf q={stonesoup_q:g}", s, tracker=EkfJpdaTracker(s, associator=associator))
    return rows


def acceptance(rows: list[dict]) -> dict:
    """#26's acceptance figures of the rows that ran."""
    by = {r["row"]: r for r in rows if "skipped" not in r}
    xy = [r for r in by.values() if r["row"].startswith("xy sigma=")]
    out = {}
    best = min(xy, key=lambda r: r["gospa"]) if xy else None
    if best:
        out["best_xy"] = best["row"]
    p, rr = by.get("polar"), by.get("polar+rr")
    ss = next((r for r in by.values() if r["row"].startswith("stonesoup")), None)
    if p and best:
        out.update(gospa_ratio=p["gospa"] / best["gospa"], gospa_ok=p["gospa"] <= 0.85 * best["gospa"],
                   idsw_ok=p["idsw"] <= best["idsw"], false_ok=p["false"] <= best["false"])
    if p and rr:
        out["rr_ok"] = rr["gospa"] < p["gospa"] and rr["idsw"] <= p["idsw"]
    if p and ss:
        out["beats_stonesoup"] = p["gospa"] < ss["gospa"] and p["false"] <= ss["false"]
    return out


def table(name: str, rows: list[dict], acc: dict) -> str:
    lines = compare.table(name, rows, None).splitlines()
    parts = [r for r in rows if r.get("gospa_loc") is not None]
    if parts:
        lines.append("GOSPA = localisation + missed + false (per scan):")
        lines += [f"  {r['row']:22s} {r['gospa_loc']:9.2f} + {r['gospa_missed']:8.2f} + {r['gospa_false']:8.2f}"
                  for r in parts]
    if "gospa_ratio" in acc:
        lines.append(f"polar / best xy ({acc['best_xy']}): GOSPA x{acc['gospa_ratio']:.3f} "
                     f"({'ok' if acc['gospa_ok'] else 'above 0.85'}), ID switches "
                     f"{'ok' if acc['idsw_ok'] else 'more'}, false tracks {'ok' if acc['false_ok'] else 'more'}")
    elif "best_xy" in acc:
        lines.append(f"best xy: {acc['best_xy']} (the polar rows did not run)")
    if "rr_ok" in acc:
        lines.append(f"range rate: {'lowers GOSPA and ID switches' if acc['rr_ok'] else 'does not lower both'}")
    if "beats_stonesoup" in acc:
        lines.append(f"Stone Soup EKF: {'beaten' if acc['beats_stonesoup'] else 'not beaten'} on GOSPA and false tracks")
    return "\n".join(lines) + "\n"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    mc.add_run_arguments(ap, scenarios=True, runs=1, per="row")
    ap.add_argument("--sweep", type=float, nargs="+", default=list(SWEEP), metavar="S",
                    help="meas_sigma values of the converted x, y rows (default 50 100 150 200 300 500)")
    ap.add_argument("--range-rate-sigma", type=float, default=RANGE_RATE_SIGMA,
                    help=f"sigma of the range rate in the polar+rr row (default {RANGE_RATE_SIGMA:g})")
    ap.add_argument("--stonesoup-q", type=float, default=STONESOUP_Q,
                    help=f"process_psd of the Stone Soup row (default {STONESOUP_Q:g})")
    ap.add_argument("--stonesoup-associator", choices=("jpda", "ehm"), default="ehm",
                    help="the Stone Soup row's JPDA (jpda) or JPDAwithEHM (ehm, the same association "
                         "probabilities, faster; default)")
    ap.add_argument("--no-stonesoup", action="store_true", help="leave out the Stone Soup row")
    ap.add_argument("--shuffle-check", action="store_true",
                    help="also check that run 0's detections in a shuffled order give byte-identical tracks")
    ap.add_argument("--mtt-track", dest="mtt_track", help="mtt-track binary (as mtt_sim.mc)")
    a = ap.parse_args(argv)
    if a.runs < 1 or a.jobs < 1 or a.range_rate_sigma <= 0:
        ap.error("--runs and --jobs must be >= 1, --range-rate-sigma > 0")
    try:
        scns = [(f, scenario.load(f, a.set)) for f in a.scenario]
    except (scenario.ScenarioError, OSError, ValueError) as e:
        print(f"radar_compare.py: {e}", file=sys.stderr)
        return 2
    for f, scn in scns:
        if not radar.is_radar(scn):
            print(f"radar_compare.py: {f}: not a radar scenario (no \"sensor\": {{\"kind\": \"radar\"}})",
                  file=sys.stderr)
            return 2
    if not a.no_stonesoup:
        from .stonesoup_mc import stonesoup_version  # noqa: PLC0415

        if stonesoup_version() is None:
            print("radar_compare.py: Stone Soup is not installed (pip install '.[stonesoup]', or --no-stonesoup)",
                  file=sys.stderr)
            return 2
    exe = mc.find_mtt_track(a.mtt_track)
    if exe is None:
        print("radar_compare.py: no mtt-track binary (give --mtt-track or build build/host-float)", file=sys.stderr)
        return 2
    support = {"polar": polar_support(exe), "polar+rr": polar_support(exe, True)}
    polar_ok = support["polar"]
    for name, (ok, msg) in support.items():
        if not ok:
            sys.stderr.write(f"radar_compare.py: {exe} refuses {'polar input' if name == 'polar' else 'range rate'} "
                             f"({msg}): the {name} row is left out\n")
    os.makedirs(a.out, exist_ok=True)
    text, failed = "", 0
    for k, (f, scn) in enumerate(scns):
        sys.stderr.write(f"[scenario {k + 1}/{len(scns)}] {f}\n")
        d = os.path.join(a.out, scn["name"])
        os.makedirs(d, exist_ok=True)
        rows = run_rows(scn, a.runs, exe, a.jobs, a.seed0, a.sweep, a.range_rate_sigma,
                        None if a.no_stonesoup else a.stonesoup_q, support, a.stonesoup_associator)
        acc = acceptance(rows)
        t = table(f"{scn['name']} ({a.runs} runs, seeds {a.seed0}..{a.seed0 + a.runs - 1}, "
                  f"{scn['scans']['count']} scans)", rows, acc)
        if a.shuffle_check:
            checks = [("polar", scn)] if polar_ok[0] else []
            best = acc.get("best_xy")
            if best:
                checks.append((best, converted_scenario(scn, float(best.split("=")[1]))))
            for name, s in checks:
                same = shuffle_check(s, exe, a.seed0, os.path.join(d, "shuffle_" + name.replace(" ", "_")))
                t += f"shuffled detections ({name}): tracks {'byte-identical' if same else 'DIFFER'}\n"
                acc[f"shuffle_identical {name}"] = same
        failed += sum(r.get("runs_failed", 0) for r in rows)
        with open(os.path.join(d, "table.txt"), "w", encoding="utf-8") as fh:
            fh.write(t)
        with open(os.path.join(d, "summary.json"), "w", encoding="utf-8") as fh:
            json.dump({"scenario": f, "runs": a.runs, "seed0": a.seed0, "overrides": a.set, "rows": rows,
                       "acceptance": acc}, fh, indent=1)
        sys.stdout.write(t + "\n")
        sys.stdout.flush()
        text += t + "\n"
    with open(os.path.join(a.out, "table.txt"), "w", encoding="utf-8") as fh:
        fh.write(text)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
