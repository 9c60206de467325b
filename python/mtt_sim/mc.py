#!/usr/bin/env python3
"""Monte Carlo runs of a scenario through the mtt tracker, with the papers' tables and plots.

    PYTHONPATH=python python3 -m mtt_sim.mc --scenario scenarios/crossing3.json --runs 500 --out out/crossing3 \
        --assoc lm-ipda lm-ihpda
    PYTHONPATH=python python3 -m mtt_sim.mc --scenario scenarios/formations.json --runs 10 --out out/formations

Run r uses seed SEED0 + r in every mode (identical detections across modes).
The tracker runs in-process through the mtt package when it is installed
(`pip install .`), else as one mtt-track process per run; --tracker forces
either (the scores are the same, in-process is faster: docs/PYTHON.md).
Prints the tables to stdout (also OUT/report.txt), writes OUT/summary.json,
OUT/*.png and the files of run 0 under OUT/run0/.  Progress goes to stderr.
Exit status: 0 if every run succeeded, 1 if some failed, 2 on bad arguments.
"""

import argparse
import json
import os
import sys

from . import plots, report, runner, scenario


def add_run_arguments(ap: argparse.ArgumentParser) -> None:
    """The options of every Monte Carlo command: scenario, runs, jobs, out, seed0, set."""
    ap.add_argument("--scenario", required=True, help="scenario JSON file")
    ap.add_argument("--runs", type=int, default=100, help="Monte Carlo runs per mode (default 100)")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1, help="worker processes (default: cores)")
    ap.add_argument("--out", required=True, help="output directory")
    ap.add_argument("--seed0", type=int, default=0, help="seed of run 0 (default 0)")
    ap.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                    help="override a scenario value by dotted path (repeatable)")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    add_run_arguments(ap)
    ap.add_argument("--mtt-track", dest="mtt_track",
                    help="mtt-track binary (default: $MTT_TRACK, then build/host-float/tools/track/mtt-track)")
    ap.add_argument("--tracker", choices=("auto", "in-process", "mtt-track"), default="auto",
                    help="auto (default): the mtt package in-process when it is installed, else "
                         "mtt-track; in-process / mtt-track: that one only")
    ap.add_argument("--assoc", nargs="+", metavar="MODE",
                    help="association mode(s) to compare (default: the scenario's tracker.association)")
    ap.add_argument("--timeout", type=float, default=600.0, help="seconds allowed per mtt-track call")
    ap.add_argument("--no-plots", action="store_true", help="skip the PNG figures")
    a = ap.parse_args(argv)
    if a.runs < 1 or a.jobs < 1:
        ap.error("--runs and --jobs must be >= 1")
    try:
        scn = scenario.load(a.scenario, a.set)
        modes = a.assoc or [scenario.tracker_value(scn, "association")]
        for m in modes:
            if m not in scenario.ASSOC_MODES:
                raise scenario.ScenarioError(f"--assoc: '{m}' is not one of {', '.join(scenario.ASSOC_MODES)}")
    except (scenario.ScenarioError, OSError) as e:
        print(f"mc.py: {e}", file=sys.stderr)
        return 2
    exe = runner.find_tracker(a.tracker, a.mtt_track)
    if exe is None:
        if a.tracker == "in-process":
            print("mc.py: --tracker in-process: the mtt package is not installed (pip install .)",
                  file=sys.stderr)
        else:
            print("mc.py: no mtt-track binary (give --mtt-track, set MTT_TRACK, build build/host-float, "
                  "or pip install . for the in-process tracker)", file=sys.stderr)
        return 2
    os.makedirs(a.out, exist_ok=True)
    mc = runner.monte_carlo(scn, modes, a.runs, exe, a.jobs, a.seed0,
                            keep_root=os.path.join(a.out, "run0"), timeout=a.timeout)
    summary = runner.build_summary(scn, a.scenario, a.set, modes, a.runs, a.seed0, exe, mc)
    with open(os.path.join(a.out, "summary.json"), "w", encoding="utf-8") as f:
        json.dump(summary, f, indent=1)
        f.write("\n")
    text = report.full_report(summary)
    with open(os.path.join(a.out, "report.txt"), "w", encoding="utf-8") as f:
        f.write(text)
    sys.stdout.write(text)
    if not a.no_plots and any(summary["results"][m]["runs_ok"] for m in modes):
        paths = plots.plot_all(summary, a.out)
        print("plots: " + ", ".join(os.path.relpath(p, a.out) for p in paths))
    failed = sum(summary["results"][m]["runs_failed"] for m in modes)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
