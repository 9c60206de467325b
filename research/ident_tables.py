#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""The tables of docs/reports/IDENTITY.md.

rows: one `python3 -m mtt_sim.mc` call per row (association mode plus
settings overrides), all on seeds 0..N-1, so every row sees the same
detections; prints one Markdown table (ID switches per run, coalescence or
switch, GOSPA and its localisation / missed / false parts, confirmed false
tracks per scan, confirmed track fraction).  ID switches are CLEAR-MOT's
target-side count (a target lost and re-acquired by a new track counts);
track swaps count a track that moves from one target to another
(mtt_sim.metrics.clear_mot).

    PYTHONPATH=python research/ident_tables.py rows --scenario scenarios/crossing3.json \\
        --runs 100 --out out/ident/crossing3 --rows s0 contest lm-ipda jipda jpda

approach: [S2]'s claim on scenarios/approach.json, init_gate intensity
against vmax on the same detections: births and false initiations per frame
(a birth farther than match_distance from every target present), confirmed
false tracks per scan, and per appearance (range) the frames from its first
frame to its first confirmed true track.

    PYTHONPATH=python research/ident_tables.py approach --runs 100

targets: per target, over the runs of one row: the first covered scan
(counted from 0: the first scan in which a confirmed track is matched to
the target), the uncovered scans after it, the loss episodes (covered, then
not), the mean matched distance.

    PYTHONPATH=python research/ident_tables.py targets --scenario scenarios/dim.json \
        --runs 30 --row contest

All three run the mtt-track binary (--mtt-track, else $MTT_TRACK, else
build/host-float/tools/track/mtt-track), never an installed mtt package, so the
figures are those of the build in this tree.
"""
import argparse
import json
import multiprocessing
import os
import subprocess
import sys
import tempfile

import numpy as np

from mtt_sim import csvio, gen, mc, metrics, scenario

# name: (association, overrides)
ROWS = {
    "s0": ("lm-ihpda", ['tracker.lm_ihpda_variant="s0"']),
    "contest": ("lm-ihpda", ['tracker.lm_ihpda_variant="contest"']),
    "contest-noadapt": ("lm-ihpda", ['tracker.lm_ihpda_variant="contest"', "tracker.adapt_s_min=1"]),
    "contest-pure": ("lm-ihpda", ['tracker.lm_ihpda_variant="contest"', "tracker.amplitude_eta=0"]),
    "lm-ipda": ("lm-ipda", []),
    "jipda": ("jipda", []),
    "jpda": ("jpda", []),
}


def rows(a):
    res = []
    for name in a.rows:
        mode, sets = ROWS[name]
        out = os.path.join(a.out, name)
        cmd = ["nice", "-n", "10", sys.executable, "-m", "mtt_sim.mc", "--scenario", a.scenario,
               "--runs", str(a.runs), "--seed0", str(a.seed0), "--jobs", str(a.jobs), "--out", out, "--no-plots",
               "--tracker", "mtt-track", "--assoc", mode]
        if a.mtt_track:
            cmd += ["--mtt-track", a.mtt_track]
        for kv in sets + a.set:
            cmd += ["--set", kv]
        print("#", " ".join(cmd[3:]), file=sys.stderr, flush=True)
        subprocess.run(cmd, check=False, stdout=subprocess.DEVNULL)
        with open(os.path.join(out, "summary.json")) as f:
            s = json.load(f)
        r = s["results"][mode]
        res.append((name, mode, r["totals"], r["per_scan"], r.get("seeded"), r["runs_failed"]))
    print(f"\n{os.path.basename(a.scenario)}, {a.runs} runs (seeds {a.seed0}-{a.seed0 + a.runs - 1}), "
          f"overrides {a.set or 'none'}, confirmed tracks\n")
    print("| row | mode | ID switches / run | track swaps / run | coalescence or switch | GOSPA "
          "| loc / missed / false | conf. false / scan | track fraction | failed |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for name, mode, t, ps, sd, failed in res:
        cs = "–" if not sd else f"{100.0 * sd['rate']:.1f} % ({sd['coalescence']}/{sd['switch']}/{sd['lost']})"
        parts = " / ".join(f"{np.mean(ps[k]):.3f}" for k in ("gospa_loc_mean", "gospa_missed_mean", "gospa_false_mean"))
        print(f"| {name} | {mode} | {t['idsw_per_run']:.3f} | {t['swaps_per_run']:.3f} | {cs} | {t['gospa_mean']:.3f} "
              f"| {parts} | {t['confirmed_false_per_scan']:.4f} | {t['confirmed_true_fraction']:.4f} | {failed} |")


GATES = ("intensity", "vmax")


def track_run(scn, seed, exe):
    """Generate run `seed` of `scn`, track it with mtt-track: (run, tracks, scans, match distance)."""
    run = gen.generate(scn, seed)
    with tempfile.TemporaryDirectory(prefix="mtt_id_") as td:
        paths = gen.write_run(run, td, "run")
        tp = os.path.join(td, "run.tracks.csv")
        mc.run_tracker(exe, paths["settings"], paths["det"], tp)
        tr = csvio.read_tracks(tp)
    return run, tr, len(run["times"]), float(scn["metrics"]["match_distance"])


def approach_one(args):
    scn_path, sets, gate, seed, exe = args
    scn = scenario.load(scn_path, list(sets) + [f'tracker.init_gate="{gate}"'])
    run, tr, nscan, cut = track_run(scn, seed, exe)
    truth = run["truth"]
    targets = scenario.expand_targets(scn)
    first_conf = {t["id"]: None for t in targets}
    seen = set()
    births = false_births = conf_false = 0
    for k in range(nscan):
        tm = truth["scan"] == k
        txy = np.stack([truth["x"][tm], truth["y"][tm]], axis=1) if tm.any() else np.zeros((0, 2))
        tid = truth["target"][tm] if tm.any() else np.zeros(0, int)
        km = tr["scan"] == k
        ids = tr["track"][km]
        xy = np.stack([tr["x"][km], tr["y"][km]], axis=1) if km.any() else np.zeros((0, 2))
        for j, i in enumerate(ids):
            if i in seen:
                continue
            seen.add(i)
            births += 1
            if len(txy) == 0 or metrics.distances(xy[j:j + 1], txy).min() > cut:
                false_births += 1
        cxy = xy[tr["confirmed"][km]]
        pairs = metrics.match(txy, cxy, cut)
        conf_false += len(cxy) - len(pairs)
        for ti, _ in pairs:
            t = int(tid[ti])
            if first_conf[t] is None:
                first_conf[t] = k
    lat = {t["id"]: (None if first_conf[t["id"]] is None else first_conf[t["id"]] - t["first_scan"] + 1)
           for t in targets}
    return gate, births / nscan, false_births / nscan, conf_false / nscan, lat


def approach(a):
    exe = mc.find_mtt_track(a.mtt_track)
    targets = scenario.expand_targets(scenario.load(a.scenario, a.set))
    items = [(a.scenario, tuple(a.set), g, s, exe) for g in GATES for s in range(a.seed0, a.seed0 + a.runs)]
    with multiprocessing.get_context("fork").Pool(a.jobs) as pool:
        res = pool.map(approach_one, items)
    print(f"\n{os.path.basename(a.scenario)}, {a.runs} runs (seeds {a.seed0}-{a.seed0 + a.runs - 1}), overrides {a.set or 'none'}\n")
    print("| init_gate | births / frame | false initiations / frame | confirmed false / scan | "
          + " | ".join(f"target {t['id']} ({t['vx']:.0f} px/fr)" for t in targets) + " |")
    print("|---|---|---|---|" + "---|" * len(targets))
    for g in GATES:
        rs = [r for r in res if r[0] == g]
        cells = []
        for t in targets:
            v = [r[4][t["id"]] for r in rs]
            ok = [x for x in v if x is not None]
            cells.append((f"{np.mean(ok):.1f}" if ok else "–") + f" ({len(v) - len(ok)} never)")
        print(f"| {g} | {np.mean([r[1] for r in rs]):.2f} | {np.mean([r[2] for r in rs]):.2f} | "
              f"{np.mean([r[3] for r in rs]):.4f} | " + " | ".join(cells) + " |")


def targets_one(args):
    scn_path, sets, seed, exe = args
    run, tr, nscan, cut = track_run(scenario.load(scn_path, list(sets)), seed, exe)
    truth = run["truth"]
    tids = sorted({int(t) for t in truth["target"]})
    cov = {t: np.zeros(nscan, bool) for t in tids}
    dist = {t: [] for t in tids}
    for k in range(nscan):
        tm = truth["scan"] == k
        txy = np.stack([truth["x"][tm], truth["y"][tm]], axis=1)
        km = (tr["scan"] == k) & tr["confirmed"]
        xy = np.stack([tr["x"][km], tr["y"][km]], axis=1) if km.any() else np.zeros((0, 2))
        for ti, j in metrics.match(txy, xy, cut):
            t = int(truth["target"][tm][ti])
            cov[t][k] = True
            dist[t].append(float(np.hypot(*(txy[ti] - xy[j]))))
    out = []
    for t in tids:
        c = cov[t]
        first = int(np.argmax(c)) if c.any() else nscan
        after = c[first:]
        losses = int(np.sum(after[:-1] & ~after[1:])) if len(after) > 1 else 0
        out.append((t, first, int((~after).sum()), losses, dist[t]))
    return out


def targets(a):
    exe = mc.find_mtt_track(a.mtt_track)
    mode, sets = ROWS[a.row]
    sets = list(sets) + [f'tracker.association="{mode}"'] + a.set
    items = [(a.scenario, tuple(sets), s, exe) for s in range(a.seed0, a.seed0 + a.runs)]
    with multiprocessing.get_context("fork").Pool(a.jobs) as pool:
        res = [r for rs in pool.map(targets_one, items) for r in rs]
    print(f"\n{os.path.basename(a.scenario)}, row {a.row}, {a.runs} runs (seeds {a.seed0}-{a.seed0 + a.runs - 1}), "
          f"overrides {a.set or 'none'}, confirmed tracks\n")
    print("| target | first covered scan (mean) | uncovered scans after it | loss episodes | mean matched distance |")
    print("|---|---|---|---|---|")
    for t in sorted({r[0] for r in res}) + ["all"]:
        rs = [r for r in res if t == "all" or r[0] == t]
        d = [x for r in rs for x in r[4]]
        print(f"| {t} | {np.mean([r[1] for r in rs]):.2f} | {np.mean([r[2] for r in rs]):.2f} | "
              f"{np.mean([r[3] for r in rs]):.3f} | {np.mean(d) if d else float('nan'):.2f} |")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("rows")
    r.add_argument("--scenario", required=True)
    r.add_argument("--runs", type=int, required=True)
    r.add_argument("--out", required=True)
    r.add_argument("--rows", nargs="+", required=True, choices=sorted(ROWS))
    g = sub.add_parser("targets")
    g.add_argument("--scenario", required=True)
    g.add_argument("--runs", type=int, required=True)
    g.add_argument("--row", required=True, choices=sorted(ROWS))
    q = sub.add_parser("approach")
    q.add_argument("--scenario", default=os.path.join("scenarios", "approach.json"))
    q.add_argument("--runs", type=int, default=100)
    for p in (r, g, q):
        p.add_argument("--jobs", type=int, default=2)
        p.add_argument("--seed0", type=int, default=0, help="seed of the first run (default 0; tune on another range)")
        p.add_argument("--mtt-track", default=None)
        p.add_argument("--set", action="append", default=[], help="scenario override KEY=VALUE (repeatable)")
    a = ap.parse_args()
    {"rows": rows, "targets": targets, "approach": approach}[a.cmd](a)


if __name__ == "__main__":
    main()
