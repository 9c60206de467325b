# SPDX-License-Identifier: BSD-3-Clause
"""Why TrackEval's CLEAR-MOT and the hand-written loop it replaced differ on quickstart's CV q 500.

    PYTHONPATH=python python3 research/clear_mot_ties.py [--seed 0] [--mtt-track PATH]

One run of scenarios/recorded/quickstart.json with ``process_psd`` 500 and
``motion`` cv (the compare table's row), scored by mtt_sim.metrics.clear_mot
(TrackEval) and by the loop of commit f438b03 (read with ``git show``);
then scored again with every track moved by at most 1e-4 m (a fixed
function of its id), which breaks exact ties in distance. Prints the ID
switches and track swaps of both, and the number of confirmed tracks per
scan that sit exactly where another one does.
"""
import argparse
import importlib.util
import subprocess
import sys
import tempfile

import numpy as np

from mtt_sim import gen, mc, metrics, scenario


def old_metrics():
    src = subprocess.run(["git", "show", "f438b03:python/mtt_sim/metrics.py"], check=True,
                         capture_output=True, text=True).stdout
    with tempfile.NamedTemporaryFile("w", suffix=".py", delete=False) as f:
        f.write(src)
    spec = importlib.util.spec_from_file_location("metrics_f438b03", f.name)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--mtt-track", default="build/host-float/tools/track/mtt-track")
    a = ap.parse_args(argv)
    scn = scenario.load("scenarios/recorded/quickstart.json")
    scn["tracker"]["process_psd"] = 500
    scn["tracker"]["motion"] = "cv"
    run = gen.generate(scn, a.seed, scn["tracker"]["association"])
    tracks, _ = mc._track_process(run, scn["tracker"]["association"], a.mtt_track, None, 600.0)
    fr = metrics.frames(run["truth"], tracks, len(run["times"]), True)
    cut = float(scn["metrics"]["match_distance"])
    old = old_metrics()
    dup = sum(len(h) - len(np.unique(np.asarray(hxy), axis=0)) for _g, _gxy, h, hxy in fr if len(h) > 1)
    print(f"quickstart, cv q 500, seed {a.seed}: {dup} confirmed track positions equal to another's in its scan")
    for label, f in (("as written", fr),
                     ("ties broken", [(g, gxy, h, np.asarray(hxy, float) + 1e-4 * np.c_[np.sin(np.asarray(h, float)),
                                                                                      np.cos(np.asarray(h, float))])
                                      for g, gxy, h, hxy in fr])):
        t, o = metrics.clear_mot(f, cut), old.clear_mot(f, cut)
        print(f"  {label}: TrackEval ID switches {t['idsw']}, swaps {t['swaps']}; "
              f"f438b03's loop {o['idsw']}, {o['swaps']}; FN {t['fn']} / {o['fn']}, FP {t['fp']} / {o['fp']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
