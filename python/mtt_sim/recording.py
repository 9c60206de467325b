# SPDX-License-Identifier: BSD-3-Clause
"""Recorded trajectories as scenario truth (``"truth": {"recording": {...}}``).

A recording is a table of samples ``time, id, lat, lon`` (degrees, WGS84)
or ``time, id, x, y`` (already in the scenario's plane, metres).  Two
sources:

- a CSV file (``"source": "path/to/file.csv"``, relative to the scenario
  file's folder): a header row naming at least ``time``, ``id`` and either
  ``lat, lon`` or ``x, y``, optionally ``onground`` (true/false/1/0; other
  columns are ignored), ``#`` comment lines,
  ``time`` in seconds (any epoch) or an ISO 8601 date-time.  Read with the
  standard library: no pandas needed.
- a sample of the ``traffic`` package's wheel (``"source":
  "traffic:collections/quickstart"``: the path under
  ``traffic/data/samples/`` without ``.json.gz``).  The wheel is fetched at
  run time with ``pip download traffic==2.13 --no-deps`` into
  ``$MTT_SIM_CACHE`` (default ``~/.cache/mtt_sim``), or taken from
  ``$MTT_SIM_TRAFFIC_WHEEL``; its ``.json.gz`` sample is read with pandas
  (columns ``timestamp`` in ms, ``icao24`` or ``flight_id``, ``latitude``,
  ``longitude``, and ``onground`` where the sample has it).  With
  ``airborne_only`` the samples on the ground are left out (a landed
  aircraft ends there; one that takes off again is absent in between).  Nothing of it is ever written into the repository.

Projection (lat/lon only): the WGS84 local tangent plane at the origin,
h = 0: geodetic -> ECEF -> east, north (the up component is dropped; the
altitude is not used, so the plane holds the ground track).  Distances from
the origin are the chord's projection, short of the geodesic by R th^3 / 6:
13.8 m at 150 km (9e-5 relative), 0.1 m at 30 km.

Truth at the scans (:func:`truth_tracks`): the scenario's time t maps to
recording time ``first + start + (t - t0)``, ``first`` the earliest sample of
the recording.  Each target's samples are sorted (equal times averaged);
position is interpolated linearly between the two samples around the scan
time and the velocity is the slope of that interpolated track over
``velocity_window`` (default one scan period) centred on the scan time,
clipped to the samples around it without a gap longer than ``max_gap``: the
aircraft's mean velocity over the scan (a radar's range rate measures the
aircraft's velocity, not the recording's sampling noise).  A
recording's 1 s samples carry metres of position noise, so one segment's
slope is not the aircraft's velocity (traffic's collections/quickstart:
23.4 m per axis, and 130,589 of its 398,655 1 s steps above 2 g, ``python3
-m mtt_sim.recording traffic:collections/quickstart --origin 48.83 2.48
--dt 1``).  A window of 0, or one clipped to a single sample, gives the
segment's slope.  A target is present at a
scan only between its first and last sample and only when the segment
around the scan is no longer than ``max_gap`` (default 3 scan periods); the
generator then clips it to the scenario's ``area``.
"""

from __future__ import annotations

import csv
import datetime as _dt
import math
import os
import subprocess
import sys
import zipfile

import numpy as np

from .scenario import ScenarioError

__all__ = [
    "RecordingError", "TRAFFIC_VERSION", "TRAFFIC_PREFIX", "read", "project", "truth_tracks",
    "traffic_wheel", "traffic_samples", "scan_count", "main",
]

TRAFFIC_VERSION = "2.13"
TRAFFIC_PREFIX = "traffic:"
_SAMPLES = "traffic/data/samples/"

# WGS84
_A = 6378137.0
_F = 1.0 / 298.257223563
_E2 = _F * (2.0 - _F)


class RecordingError(ScenarioError):
    """A recording cannot be read; the message names the file, line and field."""


# ---------------------------------------------------------------- projection


def _ecef(lat, lon):
    la, lo = np.radians(lat), np.radians(lon)
    n = _A / np.sqrt(1.0 - _E2 * np.sin(la) ** 2)
    return n * np.cos(la) * np.cos(lo), n * np.cos(la) * np.sin(lo), n * (1.0 - _E2) * np.sin(la)


def project(lat, lon, origin):
    """East, north (metres) of lat/lon (degrees) in the local tangent plane at origin = (lat0, lon0)."""
    lat = np.asarray(lat, float)
    lon = np.asarray(lon, float)
    lat0, lon0 = float(origin[0]), float(origin[1])
    x, y, z = _ecef(lat, lon)
    x0, y0, z0 = _ecef(np.array(lat0), np.array(lon0))
    dx, dy, dz = x - x0, y - y0, z - z0
    sl, cl = math.sin(math.radians(lat0)), math.cos(math.radians(lat0))
    so, co = math.sin(math.radians(lon0)), math.cos(math.radians(lon0))
    east = -so * dx + co * dy
    north = -sl * co * dx - sl * so * dy + cl * dz
    return east, north


# ---------------------------------------------------------------- sources


def _cache_dir():
    return os.environ.get("MTT_SIM_CACHE") or os.path.join(os.path.expanduser("~"), ".cache", "mtt_sim")


def traffic_wheel() -> str:
    """Path of the traffic wheel: $MTT_SIM_TRAFFIC_WHEEL, else the cache, else pip download into it."""
    env = os.environ.get("MTT_SIM_TRAFFIC_WHEEL")
    if env:
        if not os.path.isfile(env):
            raise RecordingError(f"$MTT_SIM_TRAFFIC_WHEEL: {env}: no such file")
        return env
    cache = _cache_dir()
    name = f"traffic-{TRAFFIC_VERSION}-py3-none-any.whl"
    path = os.path.join(cache, name)
    if os.path.isfile(path):
        return path
    cmd = [sys.executable, "-m", "pip", "download", f"traffic=={TRAFFIC_VERSION}", "--no-deps",
           "--only-binary", ":all:", "-d", cache, "--quiet", "--disable-pip-version-check"]
    print(f"mtt_sim: fetching the traffic {TRAFFIC_VERSION} wheel (its sample recordings) into {cache}",
          file=sys.stderr)
    try:
        os.makedirs(cache, exist_ok=True)
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    except (OSError, subprocess.TimeoutExpired) as e:
        p = None
        err = str(e)
    else:
        err = (p.stderr or p.stdout or "").strip().splitlines()[-1:] or [""]
        err = err[0]
    if p is None or p.returncode != 0 or not os.path.isfile(path):
        raise RecordingError(
            f"could not fetch the traffic wheel ({err}); run\n"
            f"  python3 -m pip download traffic=={TRAFFIC_VERSION} --no-deps -d {cache}\n"
            f"on a machine with network access (or copy the wheel there), or set "
            f"MTT_SIM_TRAFFIC_WHEEL=/path/to/{name}")
    return path


def traffic_samples(wheel: str | None = None):
    """Sorted sample names in the wheel (``collections/quickstart``, ``calibration/ajaccio``, ...)."""
    wheel = wheel or traffic_wheel()
    try:
        with zipfile.ZipFile(wheel) as z:
            names = z.namelist()
    except (OSError, zipfile.BadZipFile) as e:
        raise RecordingError(f"{wheel}: not a readable wheel: {e}") from None
    return sorted(n[len(_SAMPLES):-len(".json.gz")] for n in names
                  if n.startswith(_SAMPLES) and n.endswith(".json.gz"))


def _read_traffic(name: str):
    wheel = traffic_wheel()
    member = f"{_SAMPLES}{name}.json.gz"
    src = f"{wheel}!{member}"
    avail = traffic_samples(wheel)
    if name not in avail:
        raise RecordingError(f"{TRAFFIC_PREFIX}{name}: no such sample in {os.path.basename(wheel)}; "
                             f"available: {', '.join(avail)}")
    try:
        import pandas as pd
    except ImportError:
        raise RecordingError(f"{TRAFFIC_PREFIX}{name}: reading a traffic sample needs pandas "
                             f"(python3 -m pip install pandas, or pip install '.[sim]')") from None
    with zipfile.ZipFile(wheel) as z:
        with z.open(member) as fh:
            try:
                df = pd.read_json(fh, compression="gzip", dtype={"icao24": str, "flight_id": str},
                                  precise_float=True)  # exact decimal parsing: the same bytes everywhere
            except ValueError as e:
                raise RecordingError(f"{src}: not a JSON records file: {e}") from None
    idcol = "flight_id" if "flight_id" in df.columns else "icao24"
    for c in ("timestamp", idcol, "latitude", "longitude"):
        if c not in df.columns:
            raise RecordingError(f"{src}: field '{c}': missing column (has {', '.join(map(str, df.columns))})")
    df = df.dropna(subset=["timestamp", "latitude", "longitude"])
    ts = df["timestamp"]
    if np.issubdtype(ts.dtype, np.number):
        t = ts.to_numpy(float) / 1000.0  # traffic writes epoch milliseconds
    else:  # pandas parses a 'timestamp' column into dates itself
        d = pd.to_datetime(ts, utc=True)
        t = (d - pd.Timestamp(0, tz="UTC")).dt.total_seconds().to_numpy(float)
    return {"source": src, "time": t, "id": df[idcol].astype(str).to_numpy(),
            "lat": df["latitude"].to_numpy(float), "lon": df["longitude"].to_numpy(float),
            **({"onground": df["onground"].fillna(False).astype(bool).to_numpy()} if "onground" in df.columns else {})}


def _parse_time(text):
    try:
        v = float(text)
    except ValueError:
        pass
    else:
        return v if math.isfinite(v) else None
    try:
        d = _dt.datetime.fromisoformat(text.replace("Z", "+00:00"))
    except ValueError:
        return None
    if d.tzinfo is None:
        d = d.replace(tzinfo=_dt.timezone.utc)
    return d.timestamp()


_BOOL = {"true": True, "1": True, "false": False, "0": False, "": False}


def _read_csv(path: str):
    try:
        f = open(path, encoding="utf-8", newline="")
    except OSError as e:
        raise RecordingError(f"{path}: {e.strerror or e}") from None
    with f:
        lines = [(n, line) for n, line in enumerate(f, 1) if line.strip() and not line.lstrip().startswith("#")]
    if not lines:
        raise RecordingError(f"{path}: empty file (a header row 'time,id,lat,lon' or 'time,id,x,y' is needed)")
    hn, head = lines[0]
    cols = [c.strip() for c in next(csv.reader([head]))]
    if "lat" in cols or "lon" in cols:
        pos = ("lat", "lon")
    else:
        pos = ("x", "y")
    for c in ("time", "id") + pos:
        if c not in cols:
            raise RecordingError(f"{path}:{hn}: field '{c}': missing column (the header must name time, id "
                                 f"and lat, lon or x, y; it has {', '.join(cols)})")
    idx = {c: cols.index(c) for c in ("time", "id") + pos}
    gnd = cols.index("onground") if "onground" in cols else None
    t, ids, a, b, g = [], [], [], [], []
    for n, row in zip((n for n, _ in lines[1:]), csv.reader([ln for _, ln in lines[1:]])):
        if len(row) != len(cols):
            raise RecordingError(f"{path}:{n}: {len(row)} fields, the header has {len(cols)}")
        tv = _parse_time(row[idx["time"]].strip())
        if tv is None:
            raise RecordingError(f"{path}:{n}: field 'time': '{row[idx['time']]}' is not seconds or an ISO 8601 time")
        tid = row[idx["id"]].strip()
        if not tid:
            raise RecordingError(f"{path}:{n}: field 'id': empty")
        vals = []
        for c in pos:
            s = row[idx[c]].strip()
            try:
                v = float(s)
            except ValueError:
                v = float("nan")
            if not math.isfinite(v):
                raise RecordingError(f"{path}:{n}: field '{c}': '{s}' is not a finite number")
            vals.append(v)
        if pos == ("lat", "lon") and not (-90.0 <= vals[0] <= 90.0 and -180.0 <= vals[1] <= 360.0):
            raise RecordingError(f"{path}:{n}: field 'lat'/'lon': {vals[0]}, {vals[1]} out of range")
        if gnd is not None:
            gs = row[gnd].strip().lower()
            if gs not in _BOOL:
                raise RecordingError(f"{path}:{n}: field 'onground': '{row[gnd]}' is not true/false/1/0/empty")
            g.append(_BOOL[gs])
        t.append(tv)
        ids.append(tid)
        a.append(vals[0])
        b.append(vals[1])
    if not t:
        raise RecordingError(f"{path}: no sample rows after the header")
    out = {"source": path, "time": np.array(t, float), "id": np.array(ids, dtype=object)}
    out[pos[0]] = np.array(a, float)
    out[pos[1]] = np.array(b, float)
    if gnd is not None:
        out["onground"] = np.array(g, bool)
    return out


_CACHE = {}


def read(source: str, base_dir: str = "."):
    """The recording's samples: dict source, time (s), id (str), and lat, lon or x, y (numpy arrays).

    Cached per process (a Monte Carlo run reads a recording once).
    """
    if source.startswith(TRAFFIC_PREFIX):
        key = ("traffic", source, os.environ.get("MTT_SIM_TRAFFIC_WHEEL"), _cache_dir())
        if key not in _CACHE:
            _CACHE[key] = _read_traffic(source[len(TRAFFIC_PREFIX):].strip("/"))
        return _CACHE[key]
    path = source if os.path.isabs(source) else os.path.join(base_dir, source)
    try:
        st = os.stat(path)
        key = ("csv", os.path.abspath(path), st.st_mtime_ns, st.st_size)
    except OSError:
        key = None
    if key is None or key not in _CACHE:
        rec = _read_csv(path)
        if key is None:
            return rec
        _CACHE[key] = rec
    return _CACHE[key]


# ---------------------------------------------------------------- truth


def _spec_dir(scn):
    src = scn.get("_source")
    return os.path.dirname(os.path.abspath(src)) if src and os.path.isfile(src) else "."


def _planar(rec, spec):
    """(time, id, x, y) arrays of the recording in the scenario's plane, after the ids and onground filters."""
    keep = np.ones(len(rec["time"]), bool)
    if spec.get("ids") is not None:
        want = {str(i) for i in spec["ids"]}
        keep = np.array([str(i) in want for i in rec["id"]], bool)
        missing = want - set(str(i) for i in rec["id"][keep])
        if missing:
            raise RecordingError(f"{rec['source']}: ids {', '.join(sorted(missing))} not in the recording")
    if spec.get("airborne_only"):
        if "onground" not in rec:
            raise RecordingError(f"{rec['source']}: 'airborne_only' needs an 'onground' column; "
                                 f"this recording has none")
        keep &= ~rec["onground"]
    if "lat" in rec:
        origin = spec.get("origin")
        if origin is None:
            origin = (float(np.mean(rec["lat"])), float(np.mean(rec["lon"])))
        x, y = project(rec["lat"][keep], rec["lon"][keep], origin)
    else:
        if spec.get("origin") is not None:
            raise RecordingError(f"{rec['source']}: 'origin' is for lat/lon recordings; this one has x, y")
        x, y = rec["x"][keep], rec["y"][keep]
    return rec["time"][keep], rec["id"][keep], np.asarray(x, float), np.asarray(y, float)


def sample_accelerations(t, ids, x, y, dt):
    """|second difference| / dt^2 of each id's track resampled every dt (linear interpolation).

    These are the accelerations that the truth itself has at a scan period dt,
    as the scenario's linear interpolation makes it: the recording's own
    noise and its gaps bridged by straight lines included."""
    out = []
    for u in sorted(set(ids)):
        m = ids == u
        o = np.argsort(t[m], kind="stable")
        tt, xx, yy = t[m][o], x[m][o], y[m][o]
        keep = np.concatenate([[True], np.diff(tt) > 0])
        tt, xx, yy = tt[keep], xx[keep], yy[keep]
        tau = np.arange(tt[0], tt[-1] + 1e-9, dt) if len(tt) else tt
        if len(tau) < 3:
            continue
        px, py = np.interp(tau, tt, xx), np.interp(tau, tt, yy)
        out.append(np.hypot(np.diff(px, 2), np.diff(py, 2)) / (dt * dt))
    return np.concatenate(out) if out else np.zeros(0)


def sample_jitter(t, ids, x, y, half=3):
    """Per-axis RMS of the samples about a local quadratic in time, over 2 half + 1 samples.

    A real aircraft's path is smooth over half a minute (a turn's cubic term
    cancels at the window's centre), so what the quadratic does not follow is
    the recording's own position noise: its reports' positions and times
    disagree. Each residual is scaled by 1/sqrt(1 - h), h the centre's
    leverage, so white noise of standard deviation s gives s. Windows that
    span a gap (more than twice the id's median interval per sample) are
    skipped. Returns (rms, number of residuals)."""
    res, lev = [], {}
    for u in sorted(set(ids)):
        m = ids == u
        o = np.argsort(t[m], kind="stable")
        tt, xx, yy = t[m][o], x[m][o], y[m][o]
        if len(tt) < 2 * half + 1:
            continue
        step = float(np.median(np.diff(tt)))
        for i in range(half, len(tt) - half):
            w = slice(i - half, i + half + 1)
            tc = tt[w] - tt[i]
            if step <= 0 or tc[-1] - tc[0] > 2.0 * 2 * half * step:
                continue
            a = np.vander(tc / step, 3)
            key = tuple(np.round(tc / step, 6))
            if key not in lev:  # the centre's hat value and the fit's weights
                pinv = np.linalg.pinv(a)
                lev[key] = (pinv[:, half] @ a[half], pinv)
            h, pinv = lev[key]
            if h >= 1.0 - 1e-9:
                continue
            for v in (xx[w], yy[w]):
                res.append((v[half] - a[half] @ (pinv @ v)) / math.sqrt(1.0 - h))
    r = np.asarray(res, float)
    return (float(np.sqrt(np.mean(r * r))) if len(r) else float("nan")), len(r)


def _int_ids(ids, first_id):
    """Target number of each distinct id: the id itself if all are integers >= 0, else first_id + sorted rank."""
    uniq = sorted(set(str(i) for i in ids))
    if first_id is None and all(u.isdigit() for u in uniq):
        return {u: int(u) for u in uniq}
    base = int(first_id or 0)
    if all(u.isdigit() for u in uniq):
        uniq.sort(key=int)
    return {u: base + j for j, u in enumerate(uniq)}


def scan_count(scn) -> int:
    """Number of scans that cover the recording (from ``start``, for ``duration`` if given)."""
    spec = scn["truth"]["recording"]
    rec = read(spec["source"], _spec_dir(scn))
    t = rec["time"]
    span = float(t.max() - t.min()) - float(spec.get("start", 0.0))
    if spec.get("duration") is not None:
        span = min(span, float(spec["duration"]))
    if span < 0:
        raise RecordingError(f"{rec['source']}: 'start' {spec.get('start')} s is after the recording's end "
                             f"({float(t.max() - t.min()):.1f} s)")
    return int(math.floor(span / float(scn["scans"]["dt"]) + 1e-9)) + 1


def truth_tracks(scn, times):
    """Per target id (ascending), the arrays (present, x, y, vx, vy) at the scan times.

    ``present`` is the boolean mask of the scans between the target's first and
    last samples (window restricted) whose segment is no longer than max_gap;
    the area clip is the generator's.
    """
    spec = scn["truth"]["recording"]
    rec = read(spec["source"], _spec_dir(scn))
    dt = float(scn["scans"]["dt"])
    t0 = float(scn["scans"].get("t0", 0.0))
    max_gap = float(spec.get("max_gap", 3.0 * dt))
    window = float(spec.get("velocity_window", dt))
    min_points = int(spec.get("min_points", 2))
    start = float(spec.get("start", 0.0))
    t, ids, x, y = _planar(rec, spec)
    first = float(rec["time"].min())
    lo = first + start
    hi = lo + float(spec["duration"]) if spec.get("duration") is not None else math.inf
    tau = first + start + (np.asarray(times, float) - t0)  # recording time of each scan
    num = _int_ids(ids, spec.get("first_id"))
    ids = np.array([str(i) for i in ids], dtype=object)
    out = {}
    for u, tid in sorted(num.items(), key=lambda kv: kv[1]):
        m = ids == u
        tt, xx, yy = t[m], x[m], y[m]
        o = np.argsort(tt, kind="stable")
        tt, xx, yy = tt[o], xx[o], yy[o]
        ut, inv = np.unique(tt, return_inverse=True)
        if len(ut) < len(tt):  # equal times: their mean position
            cnt = np.bincount(inv)
            xx = np.bincount(inv, xx) / cnt
            yy = np.bincount(inv, yy) / cnt
            tt = ut
        if len(tt) < max(2, min_points):  # distinct sample times over the whole recording
            continue
        present = (tau >= max(tt[0], lo)) & (tau <= min(tt[-1], hi))
        seg = np.clip(np.searchsorted(tt, tau, side="right") - 1, 0, len(tt) - 2)
        exact = np.isin(tau, tt)  # a scan at a sample's own time sees that sample
        long_gap = (tt[seg + 1] - tt[seg]) > max_gap
        present &= ~long_gap | exact
        # at a sample followed by a long gap, the velocity is the segment before it
        seg = np.where(exact & long_gap & (seg > 0), seg - 1, seg)
        ta, h = tt[seg], tt[seg + 1] - tt[seg]
        vx = (xx[seg + 1] - xx[seg]) / h
        vy = (yy[seg + 1] - yy[seg]) / h
        px = xx[seg] + vx * (tau - ta)
        py = yy[seg] + vy * (tau - ta)
        if window > 0:
            # the window within the gap-free run of samples of the sample at or before the scan
            run = np.concatenate(([0], np.cumsum(np.diff(tt) > max_gap)))
            k = np.clip(np.searchsorted(tt, tau, side="right") - 1, 0, len(tt) - 1)
            first_of = np.searchsorted(run, run, side="left")
            last_of = np.searchsorted(run, run, side="right") - 1
            a = np.maximum(tau - 0.5 * window, tt[first_of[k]])
            b = np.minimum(tau + 0.5 * window, tt[last_of[k]])
            wide = b > a
            h = np.where(wide, b - a, 1.0)
            vx = np.where(wide, (np.interp(b, tt, xx) - np.interp(a, tt, xx)) / h, vx)
            vy = np.where(wide, (np.interp(b, tt, yy) - np.interp(a, tt, yy)) / h, vy)
        if present.any():
            out[tid] = (present, px, py, vx, vy)
    return out


# ---------------------------------------------------------------- command line


def main(argv=None):
    """``python3 -m mtt_sim.recording [SOURCE ...]``: list traffic samples, or summarise recordings."""
    import argparse

    ap = argparse.ArgumentParser(description="List the traffic samples, or summarise recordings "
                                             "(extent in the local plane, targets, duration, sample interval, the "
                                             "truth's own accelerations between samples).")
    ap.add_argument("source", nargs="*", help="traffic:NAME or a CSV path; none: list the traffic samples")
    ap.add_argument("--origin", type=float, nargs=2, metavar=("LAT", "LON"), help="projection origin")
    ap.add_argument("--dt", type=float, help="period (s) of the truth's accelerations (default: the median "
                                             "sample interval; a scenario's scans.dt to see what its tracker meets)")
    a = ap.parse_args(argv)
    try:
        if not a.source:
            print("\n".join(TRAFFIC_PREFIX + s for s in traffic_samples()))
            return 0
        for s in a.source:
            rec = read(s)
            t, ids, x, y = _planar(rec, {"origin": a.origin})
            d = np.concatenate([np.diff(np.sort(t[ids == u])) for u in set(ids)])
            print(f"{s}: {len(t)} samples, {len(set(ids))} ids, {t.max() - t.min():.0f} s, "
                  f"sample interval median {np.median(d) if len(d) else float('nan'):.1f} s")
            if "lat" in rec:
                o = a.origin or (float(np.mean(rec['lat'])), float(np.mean(rec['lon'])))
                print(f"  origin (lat, lon) {o[0]:.6f}, {o[1]:.6f}")
            print(f"  x [{x.min():.0f}, {x.max():.0f}] m, y [{y.min():.0f}, {y.max():.0f}] m")
            step = a.dt or (float(np.median(d)) if len(d) else None)
            acc = sample_accelerations(t, ids, x, y, step) if step and step > 0 else np.zeros(0)
            if len(acc):
                q = np.quantile(acc, [0.5, 0.9, 0.99])
                print(f"  the truth's acceleration at a {step:g} s period: median {q[0]:.1f}, 90 % {q[1]:.1f}, "
                      f"99 % {q[2]:.1f}, max {acc.max():.1f} (length/time^2); {int((acc > 20.0).sum())} of "
                      f"{len(acc)} steps above 20 m/s^2 = 2 g, beyond an aircraft's (the recording's noise, "
                      f"or a gap bridged by a straight line)")
            jit, n = sample_jitter(t, ids, x, y)
            if n:
                print(f"  the recording's own position noise: {jit:.1f} per axis (RMS about a quadratic over 7 "
                      f"samples, {n} residuals), to set beside the sensor's sigma")
    except RecordingError as e:
        print(f"recording: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
