#!/usr/bin/env python3
"""Replot figures from a Monte Carlo summary, or draw one run's scene.

    PYTHONPATH=python python3 -m mtt_sim.plot summary out/crossing3/summary.json [--out DIR]
    PYTHONPATH=python python3 -m mtt_sim.plot scene --det D.det.csv --truth D.truth.csv --tracks D.tracks.csv \
        [--scenario scenarios/crossing3.json] [--settings D.settings.json] \
        [--scans 12 13 14 15] --out scene.png
    PYTHONPATH=python python3 -m mtt_sim.plot models --truth D.truth.csv --tracks D.tracks.csv \
        --scenario scenarios/manoeuvre.json --out models.png     # IMM: model probabilities
    PYTHONPATH=python python3 -m mtt_sim.plot split --truth D.truth.csv --tracks D.tracks.csv \
        --scenario scenarios/split_fast.json --out split.png       # split = true: P(split) over time
"""

import argparse
import json
import os
import sys

from . import csvio, plots, report, scenario


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    s = sub.add_parser("summary", help="curves and run-0 scenes from summary.json")
    s.add_argument("summary")
    s.add_argument("--out", help="output directory (default: the summary's directory)")
    s.add_argument("--print", action="store_true", help="also print the tables")
    c = sub.add_parser("scene", help="scene of one run")
    c.add_argument("--det", required=True)
    c.add_argument("--truth", required=True)
    c.add_argument("--tracks", required=True)
    c.add_argument("--scenario", help="scenario JSON (area, zoom, gate scans, units)")
    c.add_argument("--settings", help="tracker settings JSON (meas_sigma for the gates)")
    c.add_argument("--scans", type=int, nargs="*", help="scans for the zoomed gate panels")
    c.add_argument("--title", default="")
    c.add_argument("--out", required=True)
    mo = sub.add_parser("models", help="IMM: model probabilities of one run over time")
    mo.add_argument("--truth", required=True)
    mo.add_argument("--tracks", required=True)
    mo.add_argument("--scenario", required=True, help="scenario JSON (turn windows, match distance)")
    mo.add_argument("--names", nargs="*", help="model names (default: imm_models of the scenario)")
    mo.add_argument("--title", default="")
    mo.add_argument("--out", required=True)
    sp = sub.add_parser("split", help="split = true: P(split) of one run over time, and the split-off tracks")
    sp.add_argument("--truth", required=True)
    sp.add_argument("--tracks", required=True)
    sp.add_argument("--scenario", required=True, help="scenario JSON (its splits, units)")
    sp.add_argument("--title", default="")
    sp.add_argument("--out", required=True)
    a = ap.parse_args(argv)
    try:
        if a.cmd == "split":
            scn = scenario.load(a.scenario)
            plots.split_probability(csvio.read_tracks(a.tracks), csvio.read_truth(a.truth), scn.get("splits", []),
                                    a.out, title=a.title, units=scn.get("units"))
            print(a.out)
            return 0
        if a.cmd == "models":
            scn = scenario.load(a.scenario)
            models = scn["tracker"].get("imm_models") or []
            names = a.names or [f"{m['model']} (q {m['process_psd']:g})" for m in models] or None
            plots.model_probabilities(csvio.read_tracks(a.tracks), csvio.read_truth(a.truth),
                                      scenario.manoeuvre_windows(scn), a.out, names=names,
                                      match_distance=scn.get("metrics", {}).get("match_distance", 75.0),
                                      title=a.title)
            print(a.out)
            return 0
        if a.cmd == "summary":
            with open(a.summary, encoding="utf-8") as f:
                summ = json.load(f)
            base = os.path.dirname(os.path.abspath(a.summary))
            paths = plots.plot_all(summ, base, a.out)
            if a.print:
                sys.stdout.write(report.full_report(summ))
            print("\n".join(paths))
            return 0
        det, times_map = csvio.read_det(a.det)
        truth = csvio.read_truth(a.truth)
        tracks = csvio.read_tracks(a.tracks)
        times = [times_map[k] for k in sorted(times_map)]
        area, zoom, scans, units = None, None, a.scans, None
        sigma = [1.0, 1.0]
        if a.scenario:
            scn = scenario.load(a.scenario)
            area, units = scn["area"], scn.get("units")
            zoom = scn.get("report", {}).get("zoom")
            scans = scans if scans is not None else scn.get("report", {}).get("gate_scans", [])
            sigma = scenario.tracker_value(scn, "meas_sigma")
        if a.settings:
            with open(a.settings, encoding="utf-8") as f:
                sigma = json.load(f).get("meas_sigma", sigma)
        if area is None:
            xs = list(det["x"]) + list(truth["x"])
            ys = list(det["y"]) + list(truth["y"])
            area = {"x": [min(xs), max(xs)], "y": [min(ys), max(ys)]}
        plots.scene(det, truth, tracks, a.out, area=area, meas_sigma=sigma, times=times,
                    gate_scans=scans or [], zoom=zoom, title=a.title or os.path.basename(a.tracks), units=units)
        print(a.out)
        return 0
    except (OSError, ValueError, KeyError) as e:
        print(f"plot.py: {e}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
