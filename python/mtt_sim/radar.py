#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""A radar sensor for scenarios (``"sensor": {"kind": "radar", ...}``), and the user's polar to x, y converter.

    PYTHONPATH=python python3 -m mtt_sim.radar convert RUN.det.csv RUN.xy.det.csv --sensor-xy 0 0

The radar at ``position`` (x_s, y_s) reports each target in its coverage
with the scenario's PD as

    range   r = |p - s| + N(0, sigma_range^2)
    bearing b = atan2(y - y_s, x - x_s) + N(0, sigma_bearing^2), radians, wrapped into [-pi, pi)
    range rate = (p - s) . v / |p - s| + N(0, sigma_range_rate^2)   (only with sigma_range_rate)

p, v the truth's position and velocity at the scan (a recording's: the
interpolated positions and their slope over one scan period,
``velocity_window``, mtt_sim/recording.py).
The coverage is the annulus sector range_min <= r <= range_max, bearing in
[b0, b1] (default the full circle); a target outside it (or outside the
scenario's area) is not in the truth, and a detection whose measured range
or bearing falls outside it is not reported.  Clutter: the scenario's
``clutter`` count (Poisson ``mean`` per scan, or ``density`` per unit of
range x bearing, length x radian, as the tracker's polar clutter_density),
uniform in range and in bearing over the coverage, range rate uniform in
[-range_rate_max, range_rate_max].  Amplitudes as the Cartesian sensor's.

The detections file is docs/FORMATS.md's polar one, ``scan,time,range,
bearing,amplitude`` (plus ``,range_rate`` with sigma_range_rate).  With
``"output": "xy"`` the generator writes instead what a user who converts the
same detections to x, y writes (``convert``): x = x_s + r cos b,
y = y_s + r sin b of the numbers as the polar file holds them.

Random numbers: the target stream draws (u, three normals, amplitude) per
present target and the clutter stream (range, bearing, rate, amplitude) per
clutter point whatever the options, so that range rate on or off and output
polar or xy leave every other number of a seed unchanged: the rows of a
comparison see the same detections.
"""

from __future__ import annotations

import argparse
import math
import sys

import numpy as np

__all__ = ["SENSOR_KEYS", "is_radar", "validate", "sensor", "clutter_measure", "coverage_area", "in_coverage",
           "wrap", "to_xy", "polar_of", "measure", "clutter", "converted", "convert_file", "main"]

SENSOR_KEYS = {"kind", "position", "sigma_range", "sigma_bearing", "sigma_range_rate", "range_min", "range_max",
               "bearing", "range_rate_max", "output"}
TWO_PI = 2.0 * math.pi


def is_radar(scn: dict) -> bool:
    return isinstance(scn.get("sensor"), dict) and scn["sensor"].get("kind") == "radar"


def validate(scn: dict, source: str, num, pair, check_keys, err) -> None:
    """Check ``sensor`` with scenario.py's helpers (they name the file and key)."""
    s = scn["sensor"]
    check_keys(s, SENSOR_KEYS, source, "sensor")
    if s.get("kind") != "radar":
        err(source, "sensor.kind", "must be 'radar' (without a sensor object the sensor is the x, y one of "
                                   "meas_sigma)")
    if s.get("position") is not None:
        pair(s, "position", source, "sensor")
    num(s, "sigma_range", source, "sensor", lo=0, lo_open=True)
    num(s, "sigma_bearing", source, "sensor", lo=0, lo_open=True, hi=math.pi)
    num(s, "sigma_range_rate", source, "sensor", lo=0, lo_open=True, required=False)
    rmin = num(s, "range_min", source, "sensor", lo=0, required=False) or 0.0
    num(s, "range_max", source, "sensor", lo=rmin, lo_open=True)
    if s.get("bearing") is not None:
        b = pair(s, "bearing", source, "sensor", increasing=True)
        if b[1] - b[0] > TWO_PI + 1e-12:
            err(source, "sensor.bearing", "must span at most 2 pi")
    num(s, "range_rate_max", source, "sensor", lo=0, lo_open=True, required="sigma_range_rate" in s)
    if s.get("output", "polar") not in ("polar", "xy"):
        err(source, "sensor.output", "must be 'polar' or 'xy'")
    if "meas_sigma" in scn:
        err(source, "meas_sigma", "not with a radar sensor (its noise is sensor.sigma_range, sigma_bearing)")
    if float(scn.get("resolution", 0.0)) > 0.0:
        err(source, "resolution", "not with a radar sensor")


def sensor(scn: dict) -> dict:
    """The radar's numbers with the defaults filled in: xs, ys, sr, sb, srr (None), rmin, rmax, b0, b1, rrmax, output."""
    s = scn["sensor"]
    a = scn["area"]
    pos = s.get("position") or [0.5 * (a["x"][0] + a["x"][1]), 0.5 * (a["y"][0] + a["y"][1])]
    b = s.get("bearing") or [-math.pi, math.pi]
    return {"xs": float(pos[0]), "ys": float(pos[1]), "sr": float(s["sigma_range"]),
            "sb": float(s["sigma_bearing"]),
            "srr": float(s["sigma_range_rate"]) if s.get("sigma_range_rate") is not None else None,
            "rmin": float(s.get("range_min", 0.0)), "rmax": float(s["range_max"]),
            "b0": float(b[0]), "b1": float(b[1]), "rrmax": float(s.get("range_rate_max", 1.0)),
            "output": s.get("output", "polar")}


def clutter_measure(r: dict) -> float:
    """Range span x bearing span of the coverage (length x radian): a polar clutter density's unit."""
    return (r["rmax"] - r["rmin"]) * (r["b1"] - r["b0"])


def coverage_area(r: dict) -> float:
    """Area of the coverage in the plane (length^2): the converted detections' clutter density's unit."""
    return 0.5 * (r["b1"] - r["b0"]) * (r["rmax"] ** 2 - r["rmin"] ** 2)


def wrap(b):
    """Angles into [-pi, pi)."""
    return np.mod(np.asarray(b, float) + math.pi, TWO_PI) - math.pi


def in_coverage(r: dict, rng, brg):
    """Mask of the (range, bearing) pairs inside the coverage (bounds inclusive)."""
    rng = np.asarray(rng, float)
    d = np.mod(np.asarray(brg, float) - r["b0"], TWO_PI)
    width = r["b1"] - r["b0"]
    inside = (d <= width) if width < TWO_PI else np.ones(len(rng), bool)
    return inside & (rng >= r["rmin"]) & (rng <= r["rmax"])


def polar_of(r: dict, x, y, vx, vy):
    """True range, bearing (wrapped) and range rate of positions x, y with velocities vx, vy."""
    dx, dy = np.asarray(x, float) - r["xs"], np.asarray(y, float) - r["ys"]
    rng = np.hypot(dx, dy)
    with np.errstate(invalid="ignore", divide="ignore"):
        rr = np.where(rng > 0, (dx * np.asarray(vx, float) + dy * np.asarray(vy, float)) / rng, 0.0)
    return rng, wrap(np.arctan2(dy, dx)), rr


def to_xy(rng, brg, xs: float, ys: float):
    """The user's conversion: x = xs + r cos b, y = ys + r sin b."""
    rng, brg = np.asarray(rng, float), np.asarray(brg, float)
    return xs + rng * np.cos(brg), ys + rng * np.sin(brg)


def measure(r: dict, pres, rng_det, rho: float):
    """One scan's target detections of the present targets ``pres`` (id, x, y, pd, rho, vx, vy).

    Returns (range, bearing, range rate, amplitude, target id) of the
    reported ones (detected and measured inside the coverage)."""
    n = len(pres)
    u = rng_det.random(n)
    noise = rng_det.standard_normal((n, 3)) * np.array([r["sr"], r["sb"], r["srr"] or 0.0])
    tamp = rng_det.exponential(1.0 + np.array([rho if p[4] is None else p[4] for p in pres], float), n)
    if not n:
        z = np.zeros(0)
        return z, z, z, z, np.zeros(0, int)
    rng0, b0, rr0 = polar_of(r, [p[1] for p in pres], [p[2] for p in pres], [p[5] for p in pres],
                             [p[6] for p in pres])
    rng = rng0 + noise[:, 0]
    brg = wrap(b0 + noise[:, 1])
    rr = rr0 + noise[:, 2]
    keep = (u < np.array([p[3] for p in pres], float)) & in_coverage(r, rng, brg)
    return rng[keep], brg[keep], rr[keep], tamp[keep], np.array([p[0] for p in pres], int)[keep]


def clutter(r: dict, m: int, rng_clut):
    """m clutter points uniform in range and bearing over the coverage: (range, bearing, range rate, amplitude)."""
    rng = rng_clut.uniform(r["rmin"], r["rmax"], m)
    brg = wrap(rng_clut.uniform(r["b0"], r["b1"], m))
    rr = r["rrmax"] * (2.0 * rng_clut.random(m) - 1.0)
    amp = rng_clut.exponential(1.0, m)
    return rng, brg, rr, amp


def converted(det: dict, xs: float, ys: float) -> dict:
    """A polar detections table as the x, y table that the user's conversion of its file gives."""
    from .mc import text_values  # noqa: PLC0415 (the numbers as the polar file holds them)

    x, y = to_xy(text_values(det["range"], 10), text_values(det["bearing"], 10), xs, ys)
    out = {k: v for k, v in det.items() if k not in ("range", "bearing", "range_rate")}
    out["x"], out["y"] = x, y
    return out


def convert_file(src: str, dst: str, xs: float, ys: float) -> int:
    """Polar detections CSV -> x, y detections CSV (range rate dropped); returns the number of detections."""
    from . import csvio  # noqa: PLC0415

    det, times = csvio.read_polar_det(src)
    xy = converted(det, xs, ys)
    scans = sorted(times)
    if scans != list(range(len(scans))):
        raise csvio.FormatError(f"{src}: scans must be 0, 1, 2, ... without a gap to be converted")
    csvio.write_det(dst, xy, [times[k] for k in scans])
    return len(xy["x"])


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    c = sub.add_parser("convert", help="polar detections CSV -> x, y detections CSV (x = xs + r cos b, "
                                       "y = ys + r sin b; range rate dropped)")
    c.add_argument("src", help="polar detections CSV (scan,time,range,bearing,amplitude[,range_rate])")
    c.add_argument("dst", help="x, y detections CSV to write (scan,time,x,y,amplitude)")
    c.add_argument("--sensor-xy", type=float, nargs=2, required=True, metavar=("XS", "YS"),
                   help="the radar's position (the settings' sensor_xy)")
    a = ap.parse_args(argv)
    from . import csvio  # noqa: PLC0415

    try:
        n = convert_file(a.src, a.dst, a.sensor_xy[0], a.sensor_xy[1])
    except (csvio.FormatError, OSError, ValueError) as e:
        print(f"radar.py: {e}", file=sys.stderr)
        return 2
    print(f"{a.dst}: {n} detections")
    return 0


if __name__ == "__main__":
    sys.exit(main())
