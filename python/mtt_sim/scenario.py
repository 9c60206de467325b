# SPDX-License-Identifier: BSD-3-Clause
"""Scenario files: load, apply overrides, validate, expand.

The schema is documented in ``scenarios/README.md``.  In short, a scenario is
one JSON object describing the sensor (area, scans, PD, noise, clutter,
amplitudes), the targets (explicit, grouped formations, random, splits, or
a recording: ``truth.recording``, mtt_sim/recording.py), the
tracker settings object passed verbatim to ``mtt-track`` (key ``tracker``),
and scoring / reporting parameters (``metrics``, ``report``).

Any key whose name starts with ``_comment`` is a note and is ignored, except
inside ``tracker``, which must be exactly a docs/FORMATS.md settings object (the
tracker rejects unknown keys).  Every other unknown key is an error, so a typo
never silently falls back to a default.
"""

from __future__ import annotations

import copy
import json
import math
import re

__all__ = [
    "ScenarioError",
    "TRACKER_KEYS",
    "ASSOC_MODES",
    "load",
    "loads",
    "apply_overrides",
    "validate",
    "expand_targets",
    "manoeuvre_windows",
    "scan_times",
    "area_size",
    "clutter_measure",
    "seeded_targets",
    "tracker_settings",
    "tracker_value",
]


class ScenarioError(ValueError):
    """A scenario file is malformed; the message names the file and key."""


# docs/FORMATS.md "Tracker settings" keys.
TRACKER_KEYS = {
    "association", "lm_ihpda_variant", "contest_beta", "process_psd", "max_accel", "meas_sigma", "pd",
    "pg", "clutter_density", "snr_rho", "amplitude_eta", "adapt_s_min", "adapt_index", "adapt_memory", "adapt_gain", "adapt_reset_nis", "adapt_s_max", "markov_p11", "markov_p21",
    "existence_init", "confirm_threshold", "terminate_threshold", "merge_threshold", "initiate", "vmax", "init_gate",
    "intensity_gate", "jpda_bias", "subopt_jpda_constant_b", "jpda_star_threshold", "nnjpda_threshold",
    "adaptive_jpda_distance", "adaptive_jpda_shrink", "motion", "imm_models", "imm_transition",
    "imm_initial", "split", "split_p25", "split_p52", "split_p62", "split_dv", "split_confirm", "split_decide", "split_provisional_exist", "split_provisional_scans", "split_across", "split_known_speed", "split_decouple_r", "initial_tracks",
    "measurement", "sensor_xy", "range_rate_sigma",
}

ASSOC_MODES = (
    "lm-ihpda", "ihpda", "lm-ipda", "ipda", "ihpda-2d", "jipda", "jpda",
    "cheap-jpda", "suboptimal-jpda", "nnjpda", "jpda-star", "adaptive-jpda",
    "lm-ipda-all", "jpda-vg", "adaptive-nnjpda", "adaptive-jpda-star",
)

# docs/FORMATS.md defaults that the harness itself needs (plots, gates).
TRACKER_DEFAULTS = {"meas_sigma": [1.0, 1.0], "pg": 0.999, "association": "lm-ihpda"}

_TOP_KEYS = {
    "name", "description", "source", "units", "area", "scans", "sensor", "pd", "meas_sigma",
    "clutter", "amplitude", "truth_process_psd", "resolution", "targets", "groups",
    "random_targets", "splits", "truth", "tracker", "tracker_notes", "metrics", "report",
}
_TRUTH_KEYS = {"recording"}
_RECORDING_KEYS = {"source", "origin", "start", "duration", "ids", "min_points", "max_gap", "first_id",
                   "airborne_only", "velocity_window"}
_AREA_KEYS = {"x", "y"}
_SCAN_KEYS = {"count", "dt", "t0"}
_CLUTTER_KEYS = {"model", "density", "mean", "n", "p"}
_AMP_KEYS = {"rho"}
_TARGET_KEYS = {"id", "x", "y", "vx", "vy", "t_ref", "first_scan", "last_scan", "pd", "rho", "manoeuvres"}
_MANOEUVRE_KEYS = {"scan", "scans", "g", "turn_rate"}
G0 = 9.80665  # standard gravity, m/s^2: a manoeuvre's "g" assumes metres and seconds
_GROUP_KEYS = {"first_id", "x", "y", "vx", "vy", "t_ref", "first_scan", "last_scan", "pd", "offsets"}
_RANDOM_KEYS = {"count", "first_id", "speed", "margin", "first_scan", "last_scan", "pd"}
_SPLIT_KEYS = {"parent", "child", "scan", "dv_parent", "dv_child"}
_METRIC_KEYS = {"match_distance", "gospa_c", "seeded_targets", "seeded_eval_scan"}
_REPORT_KEYS = {"table_times", "count_frames", "gate_scans", "zoom", "curve_stride"}

_NAME_RE = re.compile(r"^[A-Za-z0-9_.-]+$")


def _is_comment(key: str) -> bool:
    return key.startswith("_comment")


def _strip_comments(obj):
    """Return a deep copy of obj without ``_comment*`` keys (not inside tracker)."""
    if isinstance(obj, dict):
        out = {}
        for k, v in obj.items():
            if _is_comment(k):
                continue
            out[k] = v if k == "tracker" else _strip_comments(v)
        return out
    if isinstance(obj, list):
        return [_strip_comments(v) for v in obj]
    return obj


def loads(text: str, source: str = "<string>", overrides=None) -> dict:
    """Parse, override (``["key.path=value", ...]``), validate and return a scenario."""
    try:
        raw = json.loads(text)
    except json.JSONDecodeError as e:
        raise ScenarioError(f"{source}: invalid JSON: {e}") from None
    if not isinstance(raw, dict):
        raise ScenarioError(f"{source}: top level must be a JSON object")
    scn = _strip_comments(raw)
    if overrides:
        apply_overrides(scn, overrides, source)
    validate(scn, source)
    scn["_source"] = source
    if "truth" in scn and "count" not in scn["scans"]:
        from . import recording  # noqa: PLC0415 (reads a file: only for a recording)

        scn["scans"]["count"] = recording.scan_count(scn)
    return scn


def load(path: str, overrides=None) -> dict:
    """Load a scenario file (see :func:`loads`)."""
    with open(path, encoding="utf-8") as f:
        return loads(f.read(), path, overrides)


def apply_overrides(scn: dict, overrides, source: str = "<string>") -> None:
    """Set values in place from ``"dotted.path=value"`` strings.

    The value is parsed as JSON when possible (numbers, lists, true/false,
    null), else taken as a string.  List elements are addressed by integer
    path components (``targets.0.pd=0.5``).  Missing dict keys are created.
    """
    for item in overrides:
        if "=" not in item:
            raise ScenarioError(f"{source}: override '{item}' is not KEY=VALUE")
        path, text = item.split("=", 1)
        try:
            value = json.loads(text)
        except json.JSONDecodeError:
            value = text
        parts = path.strip().split(".")
        node = scn
        for i, part in enumerate(parts):
            last = i == len(parts) - 1
            if isinstance(node, list):
                try:
                    idx = int(part)
                    node[idx]  # noqa: B018 (bounds check)
                except (ValueError, IndexError):
                    raise ScenarioError(f"{source}: override '{path}': bad list index '{part}'") from None
                if last:
                    node[idx] = value
                else:
                    node = node[idx]
            elif isinstance(node, dict):
                if last:
                    node[part] = value
                else:
                    node = node.setdefault(part, {})
            else:
                raise ScenarioError(f"{source}: override '{path}': '{part}' is inside a non-container")


# ---------------------------------------------------------------- validation


def _err(source, key, msg):
    raise ScenarioError(f"{source}: key '{key}': {msg}")


def _check_keys(obj, allowed, source, where):
    if not isinstance(obj, dict):
        _err(source, where, "must be an object")
    for k in obj:
        if k not in allowed:
            _err(source, f"{where}.{k}" if where else k, "unknown key")


_ABSENT = object()


def _lookup(obj, key, source, where, required):
    """(full key path, value); value _ABSENT when the key is absent and optional."""
    full = f"{where}.{key}" if where else key
    if key not in obj:
        if required:
            _err(source, full, "missing")
        return full, _ABSENT
    return full, obj[key]


def _num(obj, key, source, where, *, lo=None, hi=None, lo_open=False, required=True, integer=False):
    full, v = _lookup(obj, key, source, where, required)
    if v is _ABSENT:
        return None
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        _err(source, full, "must be a number")
    if integer and (not isinstance(v, int) and not float(v).is_integer()):
        _err(source, full, "must be an integer")
    if not math.isfinite(v):
        _err(source, full, "must be finite")
    if lo is not None and (v < lo or (lo_open and v == lo)):
        _err(source, full, f"must be {'>' if lo_open else '>='} {lo}")
    if hi is not None and v > hi:
        _err(source, full, f"must be <= {hi}")
    return v


def _pair(obj, key, source, where, *, increasing=False, positive=False, required=True):
    full, v = _lookup(obj, key, source, where, required)
    if v is _ABSENT:
        return None
    if (not isinstance(v, list) or len(v) != 2
            or any(isinstance(a, bool) or not isinstance(a, (int, float)) or not math.isfinite(a) for a in v)):
        _err(source, full, "must be a list of two finite numbers")
    if increasing and not v[0] < v[1]:
        _err(source, full, "must be increasing")
    if positive and not (v[0] > 0 and v[1] > 0):
        _err(source, full, "must be positive")
    return v


def _kinematics(obj, source, where):
    for k in ("x", "y", "vx", "vy"):
        _num(obj, k, source, where)
    _num(obj, "t_ref", source, where, required=False)
    _num(obj, "first_scan", source, where, lo=0, integer=True, required=False)
    _num(obj, "last_scan", source, where, lo=0, integer=True, required=False)
    _num(obj, "pd", source, where, lo=0, hi=1, required=False)
    _num(obj, "rho", source, where, lo=0, required=False)


def _manoeuvres(t, source, where):
    """``manoeuvres``: coordinated turns, each {"scan", "scans", "g" | "turn_rate"}, not overlapping."""
    mans = t.get("manoeuvres")
    if mans is None:
        return
    if not isinstance(mans, list):
        _err(source, where + ".manoeuvres", "must be a list")
    end = -1
    for j, m in enumerate(mans):
        w = f"{where}.manoeuvres[{j}]"
        _check_keys(m, _MANOEUVRE_KEYS, source, w)
        k0 = _num(m, "scan", source, w, lo=0, integer=True)
        _num(m, "scans", source, w, lo=1, integer=True)
        if ("g" in m) == ("turn_rate" in m):
            _err(source, w, "needs exactly one of 'g' (lateral acceleration) or 'turn_rate' (rad per time unit)")
        _num(m, "g", source, w, lo=-100, hi=100, required=False)
        _num(m, "turn_rate", source, w, required=False)
        if k0 < end:
            _err(source, w + ".scan", "manoeuvres must be in scan order and must not overlap")
        end = int(k0) + int(m["scans"])


def _recording(scn, ids, source):
    """``truth``: {"recording": {...}}, the truth from a recording (mtt_sim/recording.py)."""
    tr = scn["truth"]
    _check_keys(tr, _TRUTH_KEYS, source, "truth")
    if "recording" not in tr:
        _err(source, "truth.recording", "missing")
    w = "truth.recording"
    rec = tr["recording"]
    _check_keys(rec, _RECORDING_KEYS, source, w)
    src = rec.get("source")
    if not isinstance(src, str) or not src.strip():
        _err(source, w + ".source", "must be 'traffic:NAME' or a CSV path (columns time,id,lat,lon or time,id,x,y)")
    if rec.get("origin") is not None:
        o = _pair(rec, "origin", source, w)
        if not (-90 <= o[0] <= 90 and -180 <= o[1] <= 360):
            _err(source, w + ".origin", "must be [lat, lon] in degrees")
    _num(rec, "start", source, w, lo=0, required=False)
    _num(rec, "duration", source, w, lo=0, lo_open=True, required=False)
    _num(rec, "min_points", source, w, lo=2, integer=True, required=False)
    _num(rec, "max_gap", source, w, lo=0, lo_open=True, required=False)
    _num(rec, "velocity_window", source, w, lo=0, required=False)
    _num(rec, "first_id", source, w, lo=0, integer=True, required=False)
    if rec.get("ids") is not None:
        v = rec["ids"]
        if (not isinstance(v, list) or not v
                or any(isinstance(a, bool) or not isinstance(a, (str, int)) for a in v)):
            _err(source, w + ".ids", "must be a non-empty list of the recording's ids (strings or integers)")
    if "airborne_only" in rec and not isinstance(rec["airborne_only"], bool):
        _err(source, w + ".airborne_only", "must be true or false")
    for k in ("targets", "groups", "random_targets", "splits", "truth_process_psd"):
        if k in scn:
            _err(source, k, "not with truth.recording (the recording is the whole truth)")
    if scn["tracker"].get("initial_tracks") if isinstance(scn.get("tracker"), dict) else False:
        _err(source, "tracker.initial_tracks", "not with truth.recording (no seeded targets)")


def validate(scn: dict, source: str = "<string>") -> None:
    """Raise ScenarioError naming the first bad key; return None if valid."""
    _check_keys(scn, _TOP_KEYS, source, "")
    name = scn.get("name")
    if not isinstance(name, str) or not _NAME_RE.match(name):
        _err(source, "name", "must be a string of letters, digits, '_', '-', '.'")
    _check_keys(scn.get("area"), _AREA_KEYS, source, "area")
    _pair(scn["area"], "x", source, "area", increasing=True)
    _pair(scn["area"], "y", source, "area", increasing=True)
    _check_keys(scn.get("scans"), _SCAN_KEYS, source, "scans")
    _num(scn["scans"], "count", source, "scans", lo=1, integer=True, required="truth" not in scn)
    _num(scn["scans"], "dt", source, "scans", lo=0, lo_open=True)
    _num(scn["scans"], "t0", source, "scans", required=False)
    _num(scn, "pd", source, "", lo=0, hi=1)
    if "sensor" in scn:
        from . import radar  # noqa: PLC0415

        radar.validate(scn, source, _num, _pair, _check_keys, _err)
    else:
        _pair(scn, "meas_sigma", source, "", positive=True)
    _num(scn, "truth_process_psd", source, "", lo=0, required=False)
    _num(scn, "resolution", source, "", lo=0, required=False)

    cl = scn.get("clutter", {"model": "none"})
    _check_keys(cl, _CLUTTER_KEYS, source, "clutter")
    model = cl.get("model")
    if model == "poisson":
        if ("density" in cl) == ("mean" in cl):
            _err(source, "clutter", "poisson needs exactly one of 'density' (per unit area; a radar's: per unit "
                                    "of range x bearing) or 'mean' (per scan)")
        _num(cl, "density", source, "clutter", lo=0, required=False)
        _num(cl, "mean", source, "clutter", lo=0, required=False)
    elif model == "binomial":
        _num(cl, "n", source, "clutter", lo=0, integer=True)
        _num(cl, "p", source, "clutter", lo=0, hi=1)
    elif model != "none":
        _err(source, "clutter.model", "must be 'poisson', 'binomial' or 'none'")

    amp = scn.get("amplitude")
    if amp is not None:
        _check_keys(amp, _AMP_KEYS, source, "amplitude")
        _num(amp, "rho", source, "amplitude", lo=0)

    ids = set()
    for i, t in enumerate(scn.get("targets", [])):
        w = f"targets[{i}]"
        _check_keys(t, _TARGET_KEYS, source, w)
        _num(t, "id", source, w, lo=0, integer=True)
        _kinematics(t, source, w)
        _manoeuvres(t, source, w)
        if t["id"] in ids:
            _err(source, w + ".id", "duplicate target id")
        ids.add(int(t["id"]))
    for i, g in enumerate(scn.get("groups", [])):
        w = f"groups[{i}]"
        _check_keys(g, _GROUP_KEYS, source, w)
        _num(g, "first_id", source, w, lo=0, integer=True)
        _kinematics(g, source, w)
        offs = g.get("offsets")
        if not isinstance(offs, list) or not offs:
            _err(source, w + ".offsets", "must be a non-empty list of [dx, dy]")
        for j in range(len(offs)):
            _pair({"o": offs[j]}, "o", source, f"{w}.offsets[{j}]")
            tid = int(g["first_id"]) + j
            if tid in ids:
                _err(source, w, f"target id {tid} already used")
            ids.add(tid)
    rt = scn.get("random_targets")
    if rt is not None:
        w = "random_targets"
        _check_keys(rt, _RANDOM_KEYS, source, w)
        n = _num(rt, "count", source, w, lo=0, integer=True)
        first = _num(rt, "first_id", source, w, lo=0, integer=True, required=False) or 0
        _pair(rt, "speed", source, w)
        if not 0 <= rt["speed"][0] <= rt["speed"][1]:
            _err(source, w + ".speed", "must be [lo, hi] with 0 <= lo <= hi")
        _num(rt, "margin", source, w, lo=0, required=False)
        _num(rt, "first_scan", source, w, lo=0, integer=True, required=False)
        _num(rt, "last_scan", source, w, lo=0, integer=True, required=False)
        _num(rt, "pd", source, w, lo=0, hi=1, required=False)
        for tid in range(int(first), int(first) + int(n)):
            if tid in ids:
                _err(source, w, f"target id {tid} already used")
            ids.add(tid)
    for i, s in enumerate(scn.get("splits", [])):
        w = f"splits[{i}]"
        _check_keys(s, _SPLIT_KEYS, source, w)
        _num(s, "parent", source, w, lo=0, integer=True)
        _num(s, "child", source, w, lo=0, integer=True)
        _num(s, "scan", source, w, lo=1, integer=True)
        _pair(s, "dv_parent", source, w)
        _pair(s, "dv_child", source, w)
        if s["parent"] not in ids:
            _err(source, w + ".parent", "no such target")
        if s["child"] in ids:
            _err(source, w + ".child", "target id already used")
        ids.add(int(s["child"]))
    if "truth" in scn:
        _recording(scn, ids, source)
    elif not ids:
        _err(source, "targets", "the scenario has no target")

    trk = scn.get("tracker")
    if not isinstance(trk, dict):
        _err(source, "tracker", "must be an object (a docs/FORMATS.md settings object)")
    for k in trk:
        if k not in TRACKER_KEYS:
            _err(source, f"tracker.{k}", "not a docs/FORMATS.md settings key (mtt-track would reject it)")
    if "association" in trk and trk["association"] not in ASSOC_MODES:
        _err(source, "tracker.association", f"must be one of {', '.join(ASSOC_MODES)}")
    if "tracker_notes" in scn and not isinstance(scn["tracker_notes"], dict):
        _err(source, "tracker_notes", "must be an object")

    met = scn.get("metrics", {})
    _check_keys(met, _METRIC_KEYS, source, "metrics")
    _num(met, "match_distance", source, "metrics", lo=0, lo_open=True, required=False)
    _num(met, "gospa_c", source, "metrics", lo=0, lo_open=True, required=False)
    _num(met, "seeded_eval_scan", source, "metrics", integer=True, required=False)
    if "seeded_targets" in met:
        st = met["seeded_targets"]
        if not isinstance(st, list) or any(not isinstance(a, int) or a not in ids for a in st):
            _err(source, "metrics.seeded_targets", "must be a list of target ids")
        if len(st) != len(trk.get("initial_tracks", [])):
            _err(source, "metrics.seeded_targets", "must have one target per tracker.initial_tracks entry")
    rep = scn.get("report", {})
    _check_keys(rep, _REPORT_KEYS, source, "report")
    for k in ("table_times", "count_frames", "gate_scans"):
        if k in rep and (not isinstance(rep[k], list)
                         or any(isinstance(a, bool) or not isinstance(a, (int, float)) for a in rep[k])):
            _err(source, f"report.{k}", "must be a list of numbers")
    if "zoom" in rep and rep["zoom"] is not None:
        z = rep["zoom"]
        if not (isinstance(z, list) and len(z) == 2):
            _err(source, "report.zoom", "must be [[x0, x1], [y0, y1]] or null")
        _pair({"x": z[0]}, "x", source, "report.zoom[0]", increasing=True)
        _pair({"y": z[1]}, "y", source, "report.zoom[1]", increasing=True)


# ---------------------------------------------------------------- helpers


def scan_times(scn: dict):
    """Times of every scan: t0 + k * dt, k = 0 .. count-1 (a Python list)."""
    s = scn["scans"]
    t0 = float(s.get("t0", 0.0))
    return [t0 + k * float(s["dt"]) for k in range(int(s["count"]))]


def area_size(scn: dict) -> float:
    """Area of the surveillance region in the scenario's length unit squared."""
    a = scn["area"]
    return (a["x"][1] - a["x"][0]) * (a["y"][1] - a["y"][0])


def clutter_measure(scn: dict) -> float:
    """The measure over which the clutter is uniform, a clutter density's unit: the area, or
    a radar's range span x bearing span (length x radian)."""
    if "sensor" in scn:
        from . import radar  # noqa: PLC0415

        return radar.clutter_measure(radar.sensor(scn))
    return area_size(scn)


def expand_targets(scn: dict):
    """Deterministic targets (explicit and grouped) as a list of dicts.

    Each dict has id, x, y, vx, vy (state at time t_ref), t_ref, first_scan,
    last_scan (inclusive), pd.  Random targets and split children are drawn
    or derived by the generator, not here.
    """
    nscan = int(scn["scans"]["count"])
    t0 = float(scn["scans"].get("t0", 0.0))
    pd = float(scn["pd"])
    out = []

    def one(tid, src, dx=0.0, dy=0.0):
        return {
            "id": int(tid),
            "x": float(src["x"]) + dx, "y": float(src["y"]) + dy,
            "vx": float(src["vx"]), "vy": float(src["vy"]),
            "t_ref": float(src.get("t_ref", t0)),
            "first_scan": int(src.get("first_scan", 0)),
            "last_scan": int(src.get("last_scan", nscan - 1)),
            "pd": float(src.get("pd", pd)),
            "rho": (float(src["rho"]) if "rho" in src else None),
            "manoeuvres": [dict(m) for m in src.get("manoeuvres", [])],
        }

    for t in scn.get("targets", []):
        out.append(one(t["id"], t))
    for g in scn.get("groups", []):
        for j, (dx, dy) in enumerate(g["offsets"]):
            out.append(one(int(g["first_id"]) + j, g, float(dx), float(dy)))
    out.sort(key=lambda d: d["id"])
    return out


def manoeuvre_windows(scn: dict):
    """Turn windows of the explicit targets: {target id: [(first, last) scan, ...]}.

    A manoeuvre {"scan": k0, "scans": n} turns the motion from scan k0 to
    scan k0 + n, so the scans whose true state it changes while it lasts are
    k0 + 1 .. k0 + n (inclusive); the window is that range.
    """
    out = {}
    for t in scn.get("targets", []):
        w = [(int(m["scan"]) + 1, int(m["scan"]) + int(m["scans"])) for m in t.get("manoeuvres", [])]
        if w:
            out[int(t["id"])] = w
    return out


def seeded_targets(scn: dict):
    """Target ids that the tracker's ``initial_tracks`` follow, in list order.

    ``metrics.seeded_targets`` if given, else the targets present at scan 0 in
    ascending id (only when their number equals the number of initial tracks).
    Empty list when there are no initial tracks.
    """
    init = scn["tracker"].get("initial_tracks") or []
    if not init:
        return []
    met = scn.get("metrics", {})
    if "seeded_targets" in met:
        return [int(a) for a in met["seeded_targets"]]
    present = [t["id"] for t in expand_targets(scn) if t["first_scan"] == 0]
    if len(present) != len(init):
        raise ScenarioError(
            f"{scn.get('_source', '<scenario>')}: key 'metrics.seeded_targets': needed "
            f"({len(init)} initial tracks, {len(present)} targets at scan 0)")
    return present


def tracker_settings(scn: dict, association: str | None = None) -> dict:
    """The settings object to hand to mtt-track (a copy), optionally with another mode.

    A key whose value is null is left out (``--set tracker.process_psd=null``
    removes the scenario's process_psd: the tracker's default applies)."""
    trk = {k: v for k, v in copy.deepcopy(scn["tracker"]).items() if v is not None}
    if association is not None:
        if association not in ASSOC_MODES:
            raise ScenarioError(f"association '{association}' is not one of {', '.join(ASSOC_MODES)}")
        trk["association"] = association
    return trk


def tracker_value(scn: dict, key: str):
    """A tracker setting with the docs/FORMATS.md default when absent."""
    return scn["tracker"].get(key, TRACKER_DEFAULTS.get(key))
