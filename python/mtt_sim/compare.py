#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Side-by-side table of a scenario: mtt's default against a constant-velocity sweep, a hand-tuned IMM and Stone Soup.

    PYTHONPATH=python python3 -m mtt_sim.compare --scenario scenarios/recorded/quickstart.json \\
        --runs 5 --out out/compare/quickstart

For each scenario, on the same detections (run r uses seed SEED0 + r in every
row, as mtt_sim.mc does), the rows are:

  default         the scenario's tracker settings as they stand (for the
                  recorded scenes: the sensor's facts and max_accel only)
  cv q=Q          process_psd Q (motion cv) for each Q of --sweep
                  (default 1 5 20 100 500 2000), other settings unchanged
  imm (hand)      --imm's settings (default: cv 5 + cv 500, 0.95 on the
                  transition diagonal, the best IMM found on the tuning scenes)
  stonesoup-jpda  Stone Soup's JPDA (mtt_sim.stonesoup_mc) at the sweep's
                  best Q (--no-stonesoup leaves it out; needs stonesoup)

Columns: GOSPA per scan (the scenario's metrics), ID switches per run,
confirmed false tracks per scan, the fraction of target-scans with a
confirmed track, and the default's acceptance figures against the best CV
(#25: GOSPA <= 0.92 x, ID switches <=, false tracks <= 1.1 x + 0.01).
With several scenarios a last table gives the mean over them.  Writes
OUT/<scenario>/table.txt and summary.json, OUT/<scenario>/scene_default.png
(run 0, tracks coloured by identity), OUT/table.txt; prints the tables.
Progress goes to stderr.  Exit status 0, 1 if a run failed, 2 on bad
arguments.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time

from . import mc, scenario

SWEEP = (1.0, 5.0, 20.0, 100.0, 500.0, 2000.0)
IMM_HAND = {"motion": "imm",
            "imm_models": [{"model": "cv", "process_psd": 5}, {"model": "cv", "process_psd": 500}],
            "imm_transition": [[0.95, 0.05], [0.05, 0.95]], "imm_initial": [1.0, 0.0]}


def _with(scn: dict, settings: dict) -> dict:
    s = json.loads(json.dumps(scn))
    for k, v in settings.items():
        if v is None:
            s["tracker"].pop(k, None)
        else:
            s["tracker"][k] = v
    return s


def _row(name: str, res: dict) -> dict:
    t = res["totals"]
    return {"row": name, "runs_ok": res["runs_ok"], "runs_failed": res["runs_failed"],
            "gospa": t["gospa_mean"], "idsw": t["idsw_per_run"], "false": t["confirmed_false_per_scan"],
            "tracked": t["confirmed_true_fraction"], "ms_per_frame": t["time_per_frame_ms"]["mean"]}


def run_rows(scn: dict, runs: int, exe: str, jobs: int, seed0: int, sweep, imm: dict, stonesoup: bool,
             keep_default: str | None, log=sys.stderr) -> list[dict]:
    """The rows of one scenario (see the module's doc)."""
    mode = scenario.tracker_value(scn, "association")
    rows = []

    def one(name, s, tracker=None, keep=None):
        t0 = time.monotonic()
        res = mc.monte_carlo(s, [mode if tracker is None else "stonesoup-jpda"], runs,
                             exe if tracker is None else tracker, jobs, seed0, keep_root=keep, progress=None)
        r = _row(name, list(res["results"].values())[0])
        rows.append(r)
        log.write(f"  {scn['name']}: {name:16s} GOSPA {r['gospa']:9.2f}  ({time.monotonic() - t0:.0f} s)\n")
        log.flush()
        return res

    res_default = one("default", scn, keep=keep_default)
    for q in sweep:
        one(f"cv q={q:g}", _with(scn, {"process_psd": q, "motion": "cv"}))
    one("imm (hand)", _with(scn, {**imm, "process_psd": None}))
    cvs = [r for r in rows if r["row"].startswith("cv q=")]
    best = min(cvs, key=lambda r: r["gospa"])
    if stonesoup:
        from .stonesoup_mc import JpdaTracker

        s = _with(scn, {"process_psd": float(best["row"][5:])})
        one(f"stonesoup-jpda q={best['row'][5:]}", s, tracker=JpdaTracker(s))
    rows[0]["_res"] = res_default
    return rows


def acceptance(rows: list[dict]) -> dict:
    """The default against the best CV row (#25's acceptance) and Stone Soup."""
    d = rows[0]
    best = min((r for r in rows if r["row"].startswith("cv q=")), key=lambda r: r["gospa"])
    out = {"best_cv": best["row"], "gospa_ratio": d["gospa"] / best["gospa"],
           "gospa_ok": d["gospa"] <= 0.92 * best["gospa"], "idsw_ok": d["idsw"] <= best["idsw"],
           "false_ok": d["false"] <= 1.1 * best["false"] + 0.01}
    ss = [r for r in rows if r["row"].startswith("stonesoup")]
    if ss:
        out["beats_stonesoup"] = d["gospa"] < ss[0]["gospa"] and d["false"] <= ss[0]["false"]
    return out


def table(name: str, rows: list[dict], acc: dict | None) -> str:
    lines = [f"{name}", f"{'row':24s} {'GOSPA':>9s} {'ID sw/run':>9s} {'false/scan':>10s} {'tracked':>8s} "
             f"{'ms/frame':>8s}"]
    for r in rows:
        if "skipped" in r:  # a row that could not run (mtt_sim.radar_compare's polar rows): why
            lines.append(f"{r['row']:24s} skipped: {r['skipped']}")
            continue
        ms = "-" if r.get("ms_per_frame") is None else f"{r['ms_per_frame']:.3f}"
        lines.append(f"{r['row']:24s} {r['gospa']:9.2f} {r['idsw']:9.2f} {r['false']:10.4f} {r['tracked']:8.3f} "
                     f"{ms:>8s}")
    if acc is not None:
        lines.append(f"default / best CV ({acc['best_cv']}): GOSPA x{acc['gospa_ratio']:.3f} "
                     f"({'ok' if acc['gospa_ok'] else 'above 0.92'}), ID switches "
                     f"{'ok' if acc['idsw_ok'] else 'more'}, false tracks {'ok' if acc['false_ok'] else 'more'}"
                     + ("" if "beats_stonesoup" not in acc else
                        f", Stone Soup {'beaten' if acc['beats_stonesoup'] else 'not beaten'}"))
    return "\n".join(lines) + "\n"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    mc.add_run_arguments(ap, scenarios=True, runs=5, per="row")
    ap.add_argument("--sweep", type=float, nargs="+", default=list(SWEEP), metavar="Q",
                    help="process_psd values of the CV rows (default 1 5 20 100 500 2000)")
    ap.add_argument("--imm", help="settings JSON object of the hand-tuned IMM row (default: cv 5 + cv 500)")
    ap.add_argument("--no-stonesoup", action="store_true", help="leave out the Stone Soup row")
    ap.add_argument("--no-plots", action="store_true", help="skip the scene plots")
    ap.add_argument("--mtt-track", dest="mtt_track", help="mtt-track binary (as mtt_sim.mc)")
    a = ap.parse_args(argv)
    if a.runs < 1 or a.jobs < 1:
        ap.error("--runs and --jobs must be >= 1")
    try:
        imm = IMM_HAND if a.imm is None else json.loads(a.imm)
        if not isinstance(imm, dict):
            raise ValueError("--imm: must be a JSON object of settings")
        scns = [(f, scenario.load(f, a.set)) for f in a.scenario]
    except (scenario.ScenarioError, OSError, ValueError) as e:
        print(f"compare.py: {e}", file=sys.stderr)
        return 2
    stonesoup = not a.no_stonesoup
    if stonesoup:
        from .stonesoup_mc import stonesoup_version

        if stonesoup_version() is None:
            print("compare.py: Stone Soup is not installed (pip install '.[stonesoup]', or --no-stonesoup)",
                  file=sys.stderr)
            return 2
    exe = mc.find_tracker("auto", a.mtt_track)
    if exe is None:
        print("compare.py: no mtt-track binary (give --mtt-track or build build/host-float)", file=sys.stderr)
        return 2
    os.makedirs(a.out, exist_ok=True)
    text, failed, allrows = "", 0, []
    for k, (f, scn) in enumerate(scns):
        sys.stderr.write(f"[scenario {k + 1}/{len(scns)}] {f}\n")
        d = os.path.join(a.out, scn["name"])
        os.makedirs(d, exist_ok=True)
        rows = run_rows(scn, a.runs, exe, a.jobs, a.seed0, a.sweep, imm, stonesoup, os.path.join(d, "run0"))
        res = rows[0].pop("_res")
        acc = acceptance(rows)
        t = table(f"{scn['name']} ({a.runs} runs, seeds {a.seed0}..{a.seed0 + a.runs - 1})", rows, acc)
        failed += sum(r["runs_failed"] for r in rows)
        with open(os.path.join(d, "table.txt"), "w", encoding="utf-8") as fh:
            fh.write(t)
        with open(os.path.join(d, "summary.json"), "w", encoding="utf-8") as fh:
            json.dump({"scenario": f, "runs": a.runs, "seed0": a.seed0, "rows": rows, "acceptance": acc}, fh,
                      indent=1)
        if not a.no_plots:
            from . import plot

            summ = mc.build_summary(scn, f, a.set, [scenario.tracker_value(scn, "association")], a.runs,
                                    a.seed0, exe, res)
            for p in plot.plot_all(summ, d):
                if os.path.basename(p).startswith("scene_"):
                    os.replace(p, os.path.join(d, "scene_default.png"))
                elif os.path.isfile(p):
                    os.remove(p)
        sys.stdout.write(t + "\n")
        sys.stdout.flush()
        text += t + "\n"
        allrows.append(rows)
    if len(allrows) > 1:
        mean = []
        for i, r in enumerate(allrows[0]):
            name = r["row"] if not r["row"].startswith("stonesoup") else "stonesoup-jpda (best q)"
            vals = [rs[i] for rs in allrows]
            mean.append({"row": name, "runs_ok": sum(v["runs_ok"] for v in vals),
                         "runs_failed": sum(v["runs_failed"] for v in vals),
                         **{c: sum(v[c] for v in vals) / len(vals) for c in ("gospa", "idsw", "false", "tracked")},
                         "ms_per_frame": None})
        t = table(f"mean over {len(allrows)} scenarios", mean, None)
        sys.stdout.write(t)
        text += t
    with open(os.path.join(a.out, "table.txt"), "w", encoding="utf-8") as fh:
        fh.write(text)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
