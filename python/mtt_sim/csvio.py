# SPDX-License-Identifier: BSD-3-Clause
"""Readers and writers for the files of docs/FORMATS.md.

In memory, each file is a dict of equal-length numpy arrays (a "table"):

- detections: scan (int), time, x, y, amp (float; NaN = empty amplitude);
  a radar's polar detections have range, bearing (and range_rate) instead
  of x, y (header ``scan,time,range,bearing,amplitude[,range_rate]``)
  The table holds real detections only; the writer adds the single empty
  row ``scan,time,,,`` for every scan that has none, so it needs the times
  of all scans.
- truth: scan (int), time, target (int), x, y, vx, vy
- tracks: scan (int), time, track (int), confirmed (bool), x, y, vx, vy,
  existence (NaN = empty), pxx, pxy, pyy

Numbers are written with ``repr``-exact precision where it matters
(``%.10g``), never as nan or inf.
"""

from __future__ import annotations

import json
import math
import os

import numpy as np

DET_HEADER = "scan,time,x,y,amplitude"
POLAR_HEADER = "scan,time,range,bearing,amplitude"
RANGE_RATE_COLUMN = "range_rate"  # optional last column of a polar file
TRUTH_HEADER = "scan,time,target,x,y,vx,vy"
TRACKS_HEADER = "scan,time,track,status,x,y,vx,vy,existence,pxx,pxy,pyy"

__all__ = [
    "DET_HEADER", "POLAR_HEADER", "RANGE_RATE_COLUMN", "TRUTH_HEADER", "TRACKS_HEADER", "FormatError",
    "empty_det", "empty_truth", "empty_tracks",
    "write_det", "write_truth", "write_settings", "format_det", "format_truth",
    "read_det", "read_polar_det", "read_truth", "read_tracks", "parse_tracks",
]


class FormatError(ValueError):
    """A file does not follow docs/FORMATS.md; the message names file, line and field."""


def _f(v: float) -> str:
    v = float(v)
    if not math.isfinite(v):
        raise ValueError(f"non-finite value {v} cannot be written")
    s = f"{v:.10g}"
    return "0" if s == "-0" else s


def empty_det():
    return {"scan": np.zeros(0, int), "time": np.zeros(0), "x": np.zeros(0), "y": np.zeros(0), "amp": np.zeros(0)}


def empty_truth():
    z = np.zeros(0)
    return {"scan": np.zeros(0, int), "time": z, "target": np.zeros(0, int), "x": z, "y": z, "vx": z, "vy": z}


def empty_tracks():
    z = np.zeros(0)
    return {"scan": np.zeros(0, int), "time": z, "track": np.zeros(0, int), "confirmed": np.zeros(0, bool),
            "x": z, "y": z, "vx": z, "vy": z, "existence": z, "pxx": z, "pxy": z, "pyy": z}


# ------------------------------------------------------------------ writers


def format_det(det: dict, times) -> str:
    """Detections CSV text; ``times[k]`` is the time of scan k (all scans).

    A table with ``range`` and ``bearing`` (a radar's) gives the polar file,
    with its ``range_rate`` column when the table has one."""
    polar = "range" in det
    rate = polar and RANGE_RATE_COLUMN in det
    cols = ("range", "bearing") if polar else ("x", "y")
    lines = [POLAR_HEADER + ("," + RANGE_RATE_COLUMN if rate else "") if polar else DET_HEADER]
    empty = ",,," if rate else ",,"
    scans = np.asarray(det["scan"], int)
    order = np.argsort(scans, kind="stable")
    pos = 0
    n = len(order)
    for k, t in enumerate(times):
        ts = _f(t)
        if pos >= n or scans[order[pos]] != k:
            lines.append(f"{k},{ts},{empty}")
            continue
        while pos < n and scans[order[pos]] == k:
            i = order[pos]
            a = det["amp"][i]
            amp = "" if not np.isfinite(a) else f"{float(a):.6g}"
            rr = f",{_f(det[RANGE_RATE_COLUMN][i])}" if rate else ""
            lines.append(f"{k},{ts},{_f(det[cols[0]][i])},{_f(det[cols[1]][i])},{amp}{rr}")
            pos += 1
    if pos != n:
        raise ValueError("detections reference a scan beyond the scan times")
    return "\n".join(lines) + "\n"


def format_truth(truth: dict) -> str:
    """Ground-truth CSV text (rows in the table's order)."""
    lines = [TRUTH_HEADER]
    for i in range(len(truth["scan"])):
        lines.append(",".join([
            str(int(truth["scan"][i])), _f(truth["time"][i]), str(int(truth["target"][i])),
            _f(truth["x"][i]), _f(truth["y"][i]), _f(truth["vx"][i]), _f(truth["vy"][i])]))
    return "\n".join(lines) + "\n"


def _write_atomic(path: str, text: str) -> None:
    tmp = f"{path}.tmp{os.getpid()}"
    with open(tmp, "w", encoding="utf-8", newline="\n") as f:
        f.write(text)
    os.replace(tmp, path)


def write_det(path: str, det: dict, times) -> None:
    _write_atomic(path, format_det(det, times))


def write_truth(path: str, truth: dict) -> None:
    _write_atomic(path, format_truth(truth))


def write_settings(path: str, settings: dict) -> None:
    _write_atomic(path, json.dumps(settings, indent=2) + "\n")


# ------------------------------------------------------------------ readers


def _lines(path: str):
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            line = line.rstrip("\r\n")
            if not line.strip() or line.lstrip().startswith("#"):
                continue
            yield n, line


def _num(path, n, field, text, *, empty_ok=False, integer=False):
    if text == "":
        if empty_ok:
            return math.nan
        raise FormatError(f"{path}:{n}: field '{field}': empty")
    try:
        v = int(text) if integer else float(text)
    except ValueError:
        raise FormatError(f"{path}:{n}: field '{field}': not a number: '{text}'") from None
    if not integer and not math.isfinite(v):
        raise FormatError(f"{path}:{n}: field '{field}': nan or inf")
    return v


def _read(path, header, parse_row):
    """Rows of a CSV whose header is ``header`` (or one of the tuple ``header``; the first
    matching one's index then goes to parse_row as its last argument)."""
    rows = []
    it = _lines(path)
    try:
        n, first = next(it)
    except StopIteration:
        raise FormatError(f"{path}: empty file (no header)") from None
    several = isinstance(header, tuple)
    heads = header if several else (header,)
    if first.strip() not in heads:
        want = "' or '".join(heads)
        raise FormatError(f"{path}:{n}: header must be '{want}', got '{first.strip()}'")
    which = heads.index(first.strip())
    header = heads[which]
    ncol = header.count(",") + 1
    for n, line in it:
        f = line.split(",")
        if len(f) != ncol:
            raise FormatError(f"{path}:{n}: expected {ncol} fields, got {len(f)}")
        f = [a.strip() for a in f]
        rows.append(parse_row(path, n, f, which) if several else parse_row(path, n, f))
    return rows


def _det_rows(path, header, names):
    """(rows, times) of a detections file: rows (scan, time, a, b, amplitude, extra...) of the
    columns ``names`` after scan, time; a scan's empty row gives no row."""
    times = {}

    def row(p, n, f, which=0):
        scan = _num(p, n, "scan", f[0], integer=True)
        t = _num(p, n, "time", f[1])
        if scan < 0:
            raise FormatError(f"{p}:{n}: field 'scan': negative")
        if scan in times and times[scan] != t:
            raise FormatError(f"{p}:{n}: field 'time': differs within scan {scan}")
        times[scan] = t
        if f[2] == "" and f[3] == "":
            return None
        cols = names[:len(f) - 2]
        return (scan, t) + tuple(_num(p, n, c, v, empty_ok=(c == "amplitude")) for c, v in zip(cols, f[2:]))

    return [r for r in _read(path, header, row) if r is not None], times


def read_det(path: str):
    """Read a detections CSV; returns (table, times) where times maps scan -> time."""
    rows, times = _det_rows(path, DET_HEADER, ("x", "y", "amplitude"))
    det = empty_det()
    if rows:
        a = list(zip(*rows))
        det = {"scan": np.array(a[0], int), "time": np.array(a[1], float), "x": np.array(a[2], float),
               "y": np.array(a[3], float), "amp": np.array(a[4], float)}
    return det, times


def read_polar_det(path: str):
    """Read a polar detections CSV (a radar's); returns (table with range, bearing, amp and,
    when the file has the column, range_rate; times as read_det's)."""
    rows, times = _det_rows(path, (POLAR_HEADER, POLAR_HEADER + "," + RANGE_RATE_COLUMN),
                            ("range", "bearing", "amplitude", RANGE_RATE_COLUMN))
    with open(path, encoding="utf-8") as f:
        rate = RANGE_RATE_COLUMN in next((ln for ln in f if ln.strip() and not ln.lstrip().startswith("#")), "")
    a = list(zip(*rows)) if rows else [[] for _ in range(6 if rate else 5)]
    det = {"scan": np.array(a[0], int), "time": np.array(a[1], float), "range": np.array(a[2], float),
           "bearing": np.array(a[3], float), "amp": np.array(a[4], float)}
    if rate:
        det[RANGE_RATE_COLUMN] = np.array(a[5], float)
    return det, times


def read_truth(path: str) -> dict:
    def row(p, n, f):
        return (_num(p, n, "scan", f[0], integer=True), _num(p, n, "time", f[1]),
                _num(p, n, "target", f[2], integer=True), _num(p, n, "x", f[3]), _num(p, n, "y", f[4]),
                _num(p, n, "vx", f[5]), _num(p, n, "vy", f[6]))

    rows = _read(path, TRUTH_HEADER, row)
    if not rows:
        return empty_truth()
    a = list(zip(*rows))
    return {"scan": np.array(a[0], int), "time": np.array(a[1], float), "target": np.array(a[2], int),
            "x": np.array(a[3], float), "y": np.array(a[4], float),
            "vx": np.array(a[5], float), "vy": np.array(a[6], float)}


def _track_row(p, n, f):
    status = f[3]
    if status not in ("tentative", "confirmed"):
        raise FormatError(f"{p}:{n}: field 'status': must be 'tentative' or 'confirmed', got '{status}'")
    return (_num(p, n, "scan", f[0], integer=True), _num(p, n, "time", f[1]),
            _num(p, n, "track", f[2], integer=True), status == "confirmed",
            _num(p, n, "x", f[4]), _num(p, n, "y", f[5]), _num(p, n, "vx", f[6]), _num(p, n, "vy", f[7]),
            _num(p, n, "existence", f[8], empty_ok=True),
            _num(p, n, "pxx", f[9]), _num(p, n, "pxy", f[10]), _num(p, n, "pyy", f[11]),
            tuple(_num(p, n, f"mu_{j}", v) for j, v in enumerate(f[12:])))


SPLIT_COLUMNS = ["p_split", "parent"]  # split = true (docs/FORMATS.md), after the mu_j


def _tracks_header_models(name, header: str):
    """(r, split): the number r of trailing model-probability columns
    mu_0..mu_{r-1} (motion = imm, docs/FORMATS.md), 0 without them, and
    whether p_split, parent follow them (split = true)."""
    h = header.strip()
    if h == TRACKS_HEADER:
        return 0, False
    extra = h[len(TRACKS_HEADER):].split(",")[1:] if h.startswith(TRACKS_HEADER + ",") else None
    split = bool(extra) and extra[-2:] == SPLIT_COLUMNS
    mu = extra[:-2] if split else extra
    if not extra or not mu or mu != [f"mu_{j}" for j in range(len(mu))]:
        raise FormatError(f"{name}:1: header must be '{TRACKS_HEADER}' (with motion = imm followed by "
                          f"mu_0, mu_1, ..., and with split by p_split, parent), got '{h}'")
    return len(mu), split


def _tracks_table(rows, r: int = 0, split: bool = False):
    if not rows:
        out = empty_tracks()
        if r:
            out["mu"] = np.zeros((0, r))
        if split:
            out["p_split"] = np.zeros(0)
            out["parent"] = np.zeros(0, int)
        return out
    a = list(zip(*rows))
    keys = ["scan", "time", "track", "confirmed", "x", "y", "vx", "vy", "existence", "pxx", "pxy", "pyy"]
    out = {}
    for k, col in zip(keys, a):
        dt = int if k in ("scan", "track") else bool if k == "confirmed" else float
        out[k] = np.array(col, dt)
    if r:
        out["mu"] = np.array(a[12], float).reshape(len(rows), r)  # model probabilities per row
    if split:
        out["p_split"] = np.array(a[13], float)
        out["parent"] = np.array(a[14], int)  # -1: no parent
    return out


def _parse_track_lines(name, lines) -> dict:
    """lines: (line number, text) with the header first."""
    if not lines:
        raise FormatError(f"{name}: empty file (no header)")
    r, split = _tracks_header_models(name, lines[0][1])
    ncol = 12 + r + (2 if split else 0)
    rows = []
    for n, line in lines[1:]:
        f = [a.strip() for a in line.split(",")]
        if len(f) != ncol:
            raise FormatError(f"{name}:{n}: expected {ncol} fields, got {len(f)}")
        if split:
            row = _track_row(name, n, f[:12 + r])
            parent = -1 if f[-1] == "" else _num(name, n, "parent", f[-1], integer=True)
            rows.append(row + (_num(name, n, "p_split", f[-2]), parent))
        else:
            rows.append(_track_row(name, n, f))
    return _tracks_table(rows, r, split)


def read_tracks(path: str) -> dict:
    """Read a tracks CSV written by mtt-track (with motion = imm: its mu_j
    columns as out["mu"], rows x r)."""
    return _parse_track_lines(path, list(_lines(path)))


def parse_tracks(text: str, name: str = "<tracks>") -> dict:
    """Parse tracks CSV text (same rules as :func:`read_tracks`)."""
    lines = [(n, ln) for n, ln in enumerate(text.splitlines(), 1) if ln.strip() and not ln.lstrip().startswith("#")]
    return _parse_track_lines(name, lines)
