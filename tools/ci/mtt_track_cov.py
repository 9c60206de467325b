#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""mtt-track on Cartesian detections that carry their own covariance (ALGORITHMS.md §3.1).

    MTT_TRACK=build/host-fixed-radar/tools/track/mtt-track MTT_COV_RADAR="XS YS SR SB" \\
        tools/ci/mtt_track_cov.py --config C --detections D.det.csv --tracks T.csv ...

A radar's detections converted by the user to x, y (mtt_sim.radar, sensor
output xy) carry no covariance; this wrapper adds each one's r_xx, r_xy,
r_yy -- the conversion's linearised covariance at the measured range r and
bearing b recovered from x, y and the radar at (XS, YS): R = J diag(SR^2,
SB^2) J', J = [[cos b, -r sin b], [sin b, r cos b]] -- and runs MTT_TRACK
on that file with the other arguments unchanged.  It stands in for mtt-track
in mtt_sim.mc (--mtt-track), so the Monte Carlo compares float and fixed
point on the same Cartesian detections with their own R
(docs/FIXED_POINT.md §5).
"""

import math
import os
import subprocess
import sys
import tempfile


def with_cov(src: str, dst: str, xs: float, ys: float, sr: float, sb: float) -> None:
    with open(src, encoding="utf-8") as f, open(dst, "w", encoding="utf-8") as g:
        for line in f:
            t = line.rstrip("\r\n")
            if t.startswith("#") or t == "":
                g.write(t + "\n")
            elif t.startswith("scan,"):
                g.write(t + ",r_xx,r_xy,r_yy\n")
            else:
                v = t.split(",")
                if v[2] == "":
                    g.write(t + ",,,\n")
                    continue
                dx, dy = float(v[2]) - xs, float(v[3]) - ys
                r, b = math.hypot(dx, dy), math.atan2(dy, dx)
                c, s = math.cos(b), math.sin(b)
                a, q = sr * sr, r * r * sb * sb
                g.write(f"{t},{a * c * c + q * s * s:.9g},{(a - q) * c * s:.9g},{a * s * s + q * c * c:.9g}\n")


def main() -> int:
    args = sys.argv[1:]
    track = os.environ["MTT_TRACK"]
    if "--detections" not in args:
        return subprocess.call([track] + args)
    xs, ys, sr, sb = (float(v) for v in os.environ["MTT_COV_RADAR"].split())
    k = args.index("--detections") + 1
    with tempfile.TemporaryDirectory() as d:
        dst = os.path.join(d, "cov.det.csv")
        with_cov(args[k], dst, xs, ys, sr, sb)
        args[k] = dst
        return subprocess.call([track] + args)


if __name__ == "__main__":
    sys.exit(main())
