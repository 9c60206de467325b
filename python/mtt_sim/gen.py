#!/usr/bin/env python3
"""Generate one run of a scenario: DIR/<name>.det.csv, .truth.csv, .settings.json.

    PYTHONPATH=python python3 -m mtt_sim.gen scenarios/crossing3.json --seed 7 --out out/gen
    PYTHONPATH=python python3 -m mtt_sim.gen scenarios/dense.json --seed 1 --out out/gen --set random_targets.count=80

Formats: docs/FORMATS.md.  Same scenario + seed = same bytes.
"""

import argparse
import sys

from . import generate, scenario


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
        scn = scenario.load(a.scenario, a.set)
        run = generate.generate(scn, a.seed, a.assoc)
        paths = generate.write_run(run, a.out, a.stem)
    except (scenario.ScenarioError, OSError) as e:
        print(f"gen.py: {e}", file=sys.stderr)
        return 2
    ndet = len(run["det"]["x"])
    ntgt = int((run["det"]["origin"] >= 0).sum())
    print(f"{paths['det']}: {len(run['times'])} scans, {ndet} detections ({ntgt} from targets, "
          f"{int((run['det']['origin'] == -1).sum())} clutter, {int((run['det']['origin'] == -2).sum())} merged)")
    print(f"{paths['truth']}: {len(run['truth']['x'])} rows, {len(set(run['truth']['target'].tolist()))} targets")
    print(f"{paths['settings']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
