# SPDX-License-Identifier: BSD-3-Clause
"""The settings of docs/FORMATS.md (a dict, or a JSON file) into a parameter set.

The rules and the messages are mtt-track's (tools/io/settings.c): every key is a
row of the library's parameter table (``mtt_params_info``), type-checked
here and range-checked by ``mtt_params_set``; ``mtt_params_check`` judges the
keys together at the end; ``initial_tracks`` is read as mtt-track reads it.
A bad setting raises :class:`SettingsError` (a ``ValueError``) whose message
is mtt-track's line without the program name::

    settings.json: key 'pd': must be in (0, 1], found 1.5

No JSON library of C is needed: Python's ``json`` reads the file.
"""

from __future__ import annotations

import json
import math
import numbers
import os
import re

import numpy as np

from . import _core

__all__ = ["SettingsError", "Seed", "apply_settings", "load_settings", "n_values", "params_table"]

SEEDS_KEY = "initial_tracks"
SEED_KEYS = ("x", "y", "vx", "vy", "P")

# mtt_param_type
REAL, BOOL, ENUM, MODELS = 0, 1, 2, 3


class SettingsError(ValueError):
    """A setting is unknown, of the wrong type or out of range.

    ``key`` is the settings key path ("meas_sigma[1]", "initial_tracks[0].P"),
    or None when the whole input is at fault (malformed JSON).
    """

    def __init__(self, source: str, key: str | None, message: str, line: int = 0):
        self.source, self.key, self.reason = source, key, message
        where = f"{source}:{line}:" if line > 0 else f"{source}:"
        text = f"{where} key '{key}': {message}" if key is not None else f"{where} {message}"
        super().__init__(text)


class _Row:
    __slots__ = ("key", "type", "count", "lo", "hi", "lo_open", "hi_open", "names", "cross", "text",
                 "per_model")

    def __init__(self, t):
        for name, v in zip(self.__slots__, t):
            setattr(self, name, v)


_TABLE: list[_Row] | None = None


def params_table() -> list:
    """The library's settings keys (mtt_params_info), in docs/FORMATS.md order."""
    global _TABLE
    if _TABLE is None:
        _TABLE = [_Row(t) for t in _core.params_info()]
    return _TABLE


def n_values(r) -> int:
    """Values of a key through set_param / get_param (imm_models: r, then a
    model, a psd and a turn psd per slot)."""
    return 1 + _core.MODEL_VALUES * r.count if r.type == MODELS else r.count


class Seed:
    """One entry of ``initial_tracks``: x = [x, y, vx, vy], P (16 values) or None."""

    __slots__ = ("x", "P")

    def __init__(self, x, P):
        self.x, self.P = x, P


# ---------------------------------------------------------------- messages

def _is_bool(v) -> bool:
    return isinstance(v, (bool, np.bool_))


def _json_type(v) -> str:
    if _is_bool(v):
        return "a boolean"
    if isinstance(v, numbers.Number) or _is_np_number(v):
        return "a number"
    if isinstance(v, str):
        return "a string"
    if v is None:
        return "null"
    if isinstance(v, dict):
        return "an object"
    if _is_sequence(v):
        return "an array"
    return "an unknown value"


def _is_np_number(v) -> bool:
    return isinstance(v, np.number)


def _is_sequence(v) -> bool:
    """A JSON array: list, tuple or numpy array."""
    return isinstance(v, (list, tuple)) or (isinstance(v, np.ndarray) and v.ndim >= 1)


def _c_g(v: float, prec: int = 6) -> str:
    """C's %.<prec>g (Python's differs only in spelling inf/nan)."""
    return f"{v:.{prec}g}"


def _format_bound(v: float) -> str:
    """A bound as a person writes it: "0", "1e-9", "1e6" (tools/io/settings.c format_bound)."""
    s = _c_g(v)
    m = re.match(r"^(.*e)([+-]?)0*(\d+)$", s)
    if m:
        s = m.group(1) + ("-" if m.group(2) == "-" else "") + m.group(3)
    return s


def _range_text(r: _Row) -> str:
    rmax = _core.REAL_MAX
    has_lo, has_hi = r.lo > -rmax, r.hi < rmax
    lo, hi = _format_bound(r.lo), _format_bound(r.hi)
    if has_lo and has_hi:
        return f"in {'(' if r.lo_open else '['}{lo}, {hi}{')' if r.hi_open else ']'}"
    if has_lo:
        return f"{'>' if r.lo_open else '>='} {lo}"
    if has_hi:
        return f"{'<' if r.hi_open else '<='} {hi}"
    return "finite"


def _values_text(v) -> str:
    if len(v) == 1:
        return _format_bound(v[0])
    return "[" + ", ".join(_format_bound(x) for x in v) + "]"


def _edit_distance(a: str, b: str) -> int:
    if len(a) >= 64 or len(b) >= 64:
        return 1 << 30
    row = list(range(len(b) + 1))
    for i in range(1, len(a) + 1):
        prev_diag, row[0] = row[0], i
        for j in range(1, len(b) + 1):
            best = min(prev_diag + (a[i - 1] != b[j - 1]), row[j] + 1, row[j - 1] + 1)
            prev_diag, row[j] = row[j], best
    return row[len(b)]


class _Suggestion:
    def __init__(self, name: str):
        self.name, self.best_d, self.best = name, 1 << 30, ""

    def consider(self, cand: str):
        d = _edit_distance(self.name, cand)
        if d < self.best_d and 2 * d < len(self.name):
            self.best_d, self.best = d, cand


# ---------------------------------------------------------------- reading

class _Reader:
    def __init__(self, source: str, core):
        self.source, self.core = source, core
        self.seeds: list[Seed] = []

    def fail(self, key, message):
        raise SettingsError(self.source, key, message)

    def unknown(self, key, sg: _Suggestion):
        if sg.best_d <= 2:
            self.fail(key, f"unknown key (did you mean '{sg.best}'?)")
        self.fail(key, "unknown key")

    def number(self, v, key) -> float:
        if _is_bool(v) or not (isinstance(v, numbers.Real) or _is_np_number(v)):
            self.fail(key, f"must be a number, found {_json_type(v)}")
        try:
            x = float(v)
        except (TypeError, ValueError):
            self.fail(key, f"must be a number, found {_json_type(v)}")
        if not math.isfinite(x):
            self.fail(key, "must be a finite number")
        if abs(x) > _core.REAL_MAX:
            self.fail(key, f"{_c_g(x)} does not fit the tracker's real type (mtt_real={_core.REAL})")
        return x

    def numbers(self, v, key, n) -> list:
        if not _is_sequence(v):
            self.fail(key, f"must be an array of {n} numbers, found {_json_type(v)}")
        if len(v) != n:
            self.fail(key, f"must be an array of {n} numbers, found {len(v)} elements")
        return [self.number(e, f"{key}[{i}]") for i, e in enumerate(v)]

    def classify(self, prefix, name, sg=None):
        """('key', row) | ('group', None) | (None, None); with sg, collects the
        closest name at that level (for the message of an unknown key)."""
        kind, row = None, None
        for r in params_table():
            if not r.key.startswith(prefix):
                continue
            rest = r.key[len(prefix):]
            head, dot, _ = rest.partition(".")
            if not dot and rest == name:
                kind, row = "key", r
            elif dot and head == name and kind != "key":
                kind = "group"
            if sg is not None:
                sg.consider(head)
        if prefix == "" and sg is not None:
            sg.consider(SEEDS_KEY)
        return kind, row

    def name_list(self, r: _Row, implemented_only: bool) -> str:
        out = []
        for a, name in enumerate(r.names):
            if implemented_only:
                q = _core.Tracker()
                if q.set_param(r.key, (float(a),)) != 0 or q.check()[0] != 0:
                    continue
            out.append(name)
        return ", ".join(out)

    def models(self, r: _Row, v, key) -> list:
        """imm_models: 2 to count objects {"model": M, "process_psd": q}, with "turn_psd": w
        for M = ct and for ct only (tools/io/settings.c parse_models)."""
        n = len(v) if _is_sequence(v) else -1
        if n < 2 or n > r.count:
            found = _json_type(v) if n < 0 else ("fewer" if n < 2 else "more")
            self.fail(key, f'must be a list of 2 to {r.count} objects {{"model": M, "process_psd": q}}, '
                      f"found {found}")
        vals = [0.0] * n_values(r)
        vals[0] = float(n)
        names = ", ".join(r.names)
        for i, e in enumerate(v):
            sub = f"{key}[{i}]"
            if not isinstance(e, dict):
                self.fail(sub, f'must be an object {{"model": M, "process_psd": q}}, found {_json_type(e)}')
            for m in e:
                if m not in ("model", "process_psd", "turn_psd"):
                    self.fail(f"{sub}.{m}", "unknown key (expected model, process_psd, turn_psd)")
            m = e.get("model")
            if not isinstance(m, str):
                self.fail(f"{sub}.model", f"must be one of: {names}")
            if m not in r.names:
                self.fail(f"{sub}.model", f"unknown model '{m}' (expected one of: {names})")
            s = 1 + _core.MODEL_VALUES * i
            vals[s] = float(r.names.index(m))
            if "process_psd" not in e:
                self.fail(f"{sub}.process_psd", "missing")
            q = self.number(e["process_psd"], f"{sub}.process_psd")
            if not q > 0.0:
                self.fail(f"{sub}.process_psd", f"must be > 0, found {_c_g(q)}")
            vals[s + 1] = q
            ct = m == "ct"
            if "turn_psd" not in e and ct:
                self.fail(f"{sub}.turn_psd", "missing (model ct needs its turn-rate noise)")
            if "turn_psd" in e and not ct:
                self.fail(f"{sub}.turn_psd", "only model ct has a turn rate")
            if ct:
                w = self.number(e["turn_psd"], f"{sub}.turn_psd")
                if not w > 0.0:
                    self.fail(f"{sub}.turn_psd", f"must be > 0, found {_c_g(w)}")
                vals[s + 2] = w
        return vals

    def per_model(self, r: _Row, v, key) -> list:
        """r numbers, or r rows of r numbers, into the MAX_MODELS slots (tools/io/settings.c parse_per_model)."""
        mm = _core.MAX_MODELS
        n = len(v) if _is_sequence(v) else -1
        if n < 1 or n > mm:
            what = "an array of rows" if r.per_model == 2 else "an array of numbers"
            found = _json_type(v) if n < 0 else "more"
            self.fail(key, f"must be {what}, one per model of imm_models (at most {mm}), found {found}")
        vals = [0.0] * r.count
        if r.per_model == 1:
            vals[:n] = self.numbers(v, key, n)
        else:
            for i, row in enumerate(v):
                vals[i * mm:i * mm + n] = self.numbers(row, f"{key}[{i}]", n)
        return vals

    def param(self, r: _Row, v, key):
        if r.type == MODELS:
            vals = self.models(r, v, key)
        elif r.type == REAL and r.per_model:
            vals = self.per_model(r, v, key)
        elif r.type == REAL:
            vals = [self.number(v, key)] if r.count == 1 else self.numbers(v, key, r.count)
        elif r.type == BOOL:
            if not _is_bool(v):
                self.fail(key, f"must be true or false, found {_json_type(v)}")
            vals = [1.0 if v else 0.0]
        else:
            if not isinstance(v, str):
                self.fail(key, f"must be a string, found {_json_type(v)}")
            if v not in r.names:
                self.fail(key, f"unknown {key} '{v}' (expected one of: {self.name_list(r, False)})")
            vals = [float(r.names.index(v))]
        if self.core.set_param(r.key, tuple(vals)) != 0:
            self.report_range(r, key, vals)

    def report_range(self, r: _Row, key, vals):
        """mtt_params_set refused vals: name the element that is out of range
        on its own (the others as they are), and the range."""
        rng = _range_text(r)
        if r.type == MODELS:
            self.fail(key, f"must be {rng}, found a model out of range")
        if r.count > 1:
            _, cur = self.core.get_param(r.key, r.count)
            for e in range(r.count):
                w = list(cur)
                w[e] = vals[e]
                if self._copy().set_param(r.key, tuple(w)) != 0:
                    self.fail(f"{key}[{e}]", f"must be {rng}, found {_format_bound(vals[e])}")
        self.fail(key, f"must be {rng}, found {_values_text(vals)}")

    def _copy(self):
        """A _core.Tracker with the parameters set so far."""
        q = _core.Tracker()
        for row in params_table():
            _, cur = self.core.get_param(row.key, n_values(row))
            q.set_param(row.key, cur)
        return q

    def obj(self, d: dict, prefix: str):
        if prefix == "" and "imm_models" in d:
            # first, whatever the key order: it sets r and resets imm_transition, imm_initial
            kind, row = self.classify("", "imm_models")
            if kind == "key":
                self.param(row, d["imm_models"], "imm_models")
        for name, v in d.items():
            if prefix == "" and name == "imm_models" and self.classify("", name)[0] == "key":
                continue
            if not isinstance(name, str):
                self.fail(repr(name), "keys must be strings")
            kind, row = self.classify(prefix, name)
            seeds = prefix == "" and name == SEEDS_KEY
            key = prefix + name
            if kind is None and not seeds:
                sg = _Suggestion(name)
                self.classify(prefix, name, sg)
                self.unknown(key, sg)
            if seeds:
                self.tracks(v, key)
            elif kind == "key":
                self.param(row, v, key)
            else:
                sub = key + "."
                if not isinstance(v, dict):
                    keys = ", ".join(r.key[len(sub):] for r in params_table() if r.key.startswith(sub))
                    self.fail(key, f"must be an object with the keys {keys}, found {_json_type(v)}")
                self.obj(v, sub)

    def cov(self, v, key) -> list:
        if _is_sequence(v) and len(v) == 16:
            return self.numbers(v, key, 16)
        if not _is_sequence(v) or len(v) != 4:
            found = f"{len(v)} elements" if _is_sequence(v) else _json_type(v)
            self.fail(key, "must be a 4x4 covariance: 16 numbers row-major (or 4 rows of 4), "
                      f"found {found}")
        out = []
        for r, row in enumerate(v):
            out += self.numbers(row, f"{key}[{r}]", 4)
        return out

    def tracks(self, v, key):
        if not _is_sequence(v):
            self.fail(key, f"must be an array of track objects, found {_json_type(v)}")
        self.seeds = []
        for i, t in enumerate(v):
            tkey = f"{SEEDS_KEY}[{i}]"
            if not isinstance(t, dict):
                self.fail(tkey, 'must be an object {"x", "y", "vx", "vy"[, "P"]}, found '
                          + _json_type(t))
            x, P = [None] * 4, None
            for m, mv in t.items():
                mkey = f"{tkey}.{m}"
                if m not in SEED_KEYS:
                    sg = _Suggestion(str(m))
                    for k in SEED_KEYS:
                        sg.consider(k)
                    self.unknown(mkey, sg)
                k = SEED_KEYS.index(m)
                if k < 4:
                    x[k] = self.number(mv, mkey)
                else:
                    P = self.cov(mv, mkey)
            for k in range(4):
                if x[k] is None:
                    self.fail(f"{tkey}.{SEED_KEYS[k]}", "missing: every initial track needs x, y, vx and vy")
            self.seeds.append(Seed(x, P))

    @staticmethod
    def _row(key):
        return next(r for r in params_table() if r.key == key)

    def check(self):
        st, bad = self.core.check()
        if st == 0:
            return
        row = next((r for r in params_table() if r.key == bad), None)
        if st == _core.ERR_PARAM:
            if row is None:
                self.fail(bad or "?", "rejected by mtt_params_check")
            if row.type == MODELS or row.per_model:
                _, v = self.core.get_param("imm_models", n_values(self._row("imm_models")))
                what = row.cross if row.cross else "2 or more models"
                self.fail(bad, f"must be {what} (with {int(v[0])} models in imm_models)")
            _, v = self.core.get_param(bad, row.count)
            val = _values_text(v)
            self.fail(bad, f"must be {row.cross if row.cross else _range_text(row)}, found {val}")
        if st == _core.ERR_UNSUPPORTED and bad == "motion":
            assoc = self._row("association")
            _, a = self.core.get_param("association", 1)
            self.fail(bad, "motion = imm needs an association other than ihpda-2d and lm-ipda-all, and a "
                      f"build with MTT_WITH_IMM (association is {assoc.names[int(a[0])]})")
        if st == _core.ERR_UNSUPPORTED and bad == "split":
            _, m = self.core.get_param("motion", 1)
            self.fail(bad, "split = true needs motion = imm with a cv model in imm_models, and a build with "
                      f"MTT_WITH_SPLIT (motion is {self._row('motion').names[int(m[0])]})")
        if st == _core.ERR_UNSUPPORTED and row is not None and row.type == ENUM:
            _, v = self.core.get_param(bad, 1)
            self.fail(bad, f"{bad} '{row.names[int(v[0])]}' is not implemented in this version "
                      f"(available: {self.name_list(row, True)})")
        self.fail(bad or "?", "not supported by this version")


def _pairs_no_duplicates(source):
    def hook(pairs):
        seen = set()
        for k, _ in pairs:
            if k in seen:
                raise SettingsError(source, k, "given twice")
            seen.add(k)
        return dict(pairs)
    return hook


def _reject_constant(name):
    raise ValueError(f"{name} is not JSON")


def load_settings(path) -> dict:
    """Read a settings JSON file (one object) as mtt-track does: UTF-8 with an
    optional byte order mark, no duplicate keys, no NaN/Infinity."""
    source = os.fspath(path)
    try:
        with open(source, "rb") as f:
            data = f.read()
    except OSError as e:
        raise SettingsError(source, None, f"cannot read: {e.strerror or e}") from None
    if b"\0" in data:
        raise SettingsError(source, None, "contains a NUL byte: not a text file")
    text = data.decode("utf-8-sig", errors="replace")
    if not text.strip():
        raise SettingsError(source, None, "empty file: expected a JSON object")
    try:
        d = json.loads(text, object_pairs_hook=_pairs_no_duplicates(source),
                       parse_constant=_reject_constant)
    except SettingsError:
        raise
    except ValueError as e:
        line = getattr(e, "lineno", 0) or 0
        lines = text.splitlines()
        near = lines[line - 1].strip()[:40] if 0 < line <= len(lines) else ""
        raise SettingsError(source, None, f"malformed JSON near '{near}'", line) from None
    if not isinstance(d, dict):
        raise SettingsError(source, None, f"the settings must be a JSON object, found {_json_type(d)}")
    return d


def apply_settings(core, settings, source: str = "settings") -> list:
    """Set every key of the dict ``settings`` on the _core.Tracker ``core``
    (not initialised yet), then mtt_params_check; returns the seeds
    (``initial_tracks``).  Raises SettingsError; ``core`` may then be half set."""
    if not isinstance(settings, dict):
        raise SettingsError(source, None, f"the settings must be a JSON object, found {_json_type(settings)}")
    r = _Reader(source, core)
    r.obj(settings, "")
    r.check()
    return r.seeds
