#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Monte Carlo throughput (runs/s) of mtt_sim.mc with one and two workers, local and on Dask.

    python3 tools/bench/mc_throughput.py [--scenario scenarios/crossing3.json] [--runs 80] [--repeat 2]

For each engine: --scheduler local with --jobs 1 and --jobs 2 (processes),
and a real local Dask cluster (mtt_sim.cluster: `dask scheduler`, `dask
worker --nworkers 1 --nthreads 1`) with one and with two workers.  Each
measurement is the best of --repeat calls of mtt_sim.mc.monte_carlo over
--runs runs of the scenario's mode (seeds 0..RUNS-1, mtt-track of
build/host-float or $MTT_TRACK); prints runs/s, the ratio two/one and
whether the totals of every call equal the serial ones (time per frame
aside), and the load average before and after (other work on the machine
lowers the two-worker figure).
"""
import argparse
import json
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))

from mtt_sim import mc, scenario  # noqa: E402


def strip(res):
    r = json.loads(json.dumps(mc._nan_to_none(res["results"])))
    for m in r.values():
        m["totals"].pop("time_per_frame_ms")
    return r


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--scenario", default="scenarios/crossing3.json")
    ap.add_argument("--runs", type=int, default=80)
    ap.add_argument("--repeat", type=int, default=2)
    ap.add_argument("--no-dask", action="store_true", help="local processes only")
    a = ap.parse_args()
    exe = mc.find_mtt_track()
    if exe is None:
        sys.exit("mc_throughput.py: no mtt-track (build build/host-float or set MTT_TRACK)")
    scn = scenario.load(a.scenario)
    modes = [scenario.tracker_value(scn, "association")]
    print(f"{a.scenario}, {a.runs} runs of {modes[0]}, best of {a.repeat}; {os.cpu_count()} cores, "
          f"load average {os.getloadavg()[0]:.2f} before")
    ref = strip(mc.monte_carlo(scn, modes, a.runs, exe, 1, 0, progress=None))

    def measure(name, jobs, scheduler):
        best, same = 0.0, True
        for _ in range(a.repeat):
            t0 = time.perf_counter()
            res = mc.monte_carlo(scn, modes, a.runs, exe, jobs, 0, progress=None, scheduler=scheduler)
            best = max(best, a.runs / (time.perf_counter() - t0))
            same = same and strip(res) == ref
        print(f"  {name:28s} {best:7.2f} runs/s   totals {'identical' if same else 'DIFFER'}")
        return best

    one = measure("local, --jobs 1", 1, "local")
    two = measure("local, --jobs 2", 2, "local")
    print(f"  local two/one: x{two / one:.2f}")
    if not a.no_dask:
        from mtt_sim.cluster import LocalDaskCluster

        with LocalDaskCluster(workers=1) as addr:
            d1 = measure("dask, 1 worker", 1, addr)
        with LocalDaskCluster(workers=2) as addr:
            d2 = measure("dask, 2 workers", 1, addr)
        print(f"  dask two/one: x{d2 / d1:.2f}")
    print(f"load average {os.getloadavg()[0]:.2f} after")


if __name__ == "__main__":
    main()
