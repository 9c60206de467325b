# SPDX-License-Identifier: BSD-3-Clause
"""mtt.Tracker and mtt.Track: the C tracker (include/mtt/mtt.h) with numpy in and out.

    import numpy as np, mtt
    trk = mtt.Tracker({"pd": 0.9, "clutter_density": 1e-4})
    for t, z in enumerate(scans):           # z: (n, 2) [x, y] or (n, 3) [x, y, amplitude]
        for track in trk.step(float(t), z):
            print(track.id, track.confirmed, track.state)

Every error raises and changes nothing: the input is validated before the C
library sees it, and the library itself leaves the tracker unchanged on error.
"""

from __future__ import annotations

import math
import os

import numpy as np

from . import _core
from .settings import SettingsError, apply_settings, load_settings

__all__ = ["Tracker", "Track", "SettingsError", "TABLE_COLUMNS"]

#: Columns of Tracker.track_table(): one row per live track.
TABLE_COLUMNS = ("id", "confirmed", "x", "y", "vx", "vy", "existence", "age", "detection",
                 *(f"P{i}{j}" for i in range(4) for j in range(4)), "n_models",
                 *(f"mu{j}" for j in range(_core.MAX_MODELS)), "p_split", "parent")


class Track:
    """One live track after a step (a snapshot: later steps do not change it).

    Attributes: ``id`` (int, never reused), ``confirmed`` (bool), ``state``
    (numpy (4,): x, y, vx, vy), ``covar`` (numpy (4, 4)), ``existence``
    (float in [0, 1]), ``age`` (scans since birth), ``detection`` (index of
    the detection of this step that updated it, or -1), and
    ``model_probabilities``: None with ``motion`` = ``cv``; with ``imm`` a
    read-only array of the r model probabilities after this step, in
    ``imm_models`` order (summing to 1; ALGORITHMS.md §14.1).
    """

    __slots__ = ("id", "confirmed", "state", "covar", "existence", "age", "detection",
                 "model_probabilities")

    def __init__(self, id, confirmed, state, covar, existence, age, detection=-1,
                 model_probabilities=None):
        self.id = int(id)
        self.confirmed = bool(confirmed)
        self.state = state
        self.covar = covar
        self.existence = float(existence)
        self.age = int(age)
        self.detection = int(detection)
        self.model_probabilities = model_probabilities

    @classmethod
    def _from_row(cls, r) -> "Track":
        """A row of Tracker.track_table()."""
        state = r[2:6].copy()
        covar = r[9:25].reshape(4, 4).copy()
        state.flags.writeable = False
        covar.flags.writeable = False
        mu = None
        nm = int(r[25])
        if nm > 1:
            mu = r[26:26 + nm].copy()
            mu.flags.writeable = False
        return cls(r[0], r[1] != 0.0, state, covar, r[6], r[7], r[8], mu)

    def __repr__(self) -> str:
        x, y, vx, vy = (float(v) for v in self.state)
        return (f"Track(id={self.id}, {'confirmed' if self.confirmed else 'tentative'}, "
                f"x={x:.6g}, y={y:.6g}, vx={vx:.6g}, vy={vy:.6g}, existence={self.existence:.4g}, "
                f"age={self.age})")


def _detections(detections, polar: bool = False) -> np.ndarray:
    """(n, 2) or (n, 3) array-like into validated (n, 3) float64 rows, NaN = no amplitude;
    polar: (n, 2) to (n, 4) [range, bearing, amplitude, range rate] into (n, 4) rows, NaN
    amplitude or range rate = none."""
    width = 4 if polar else 3
    if detections is None:
        return np.zeros((0, width))
    try:
        z = np.asarray(detections, dtype=float)
    except (TypeError, ValueError) as e:
        raise ValueError(f"detections must be numbers: {e}") from None
    if z.size == 0 and z.ndim <= 2:
        return np.zeros((0, width))
    names = ("range", "bearing") if polar else ("x", "y")
    if z.ndim != 2 or not 2 <= z.shape[1] <= width:
        more = " or (n, 4) [range, bearing, amplitude, range_rate]" if polar else ""
        raise ValueError(f"detections must have shape (n, 2) [{names[0]}, {names[1]}] or (n, 3) "
                         f"[{names[0]}, {names[1]}, amplitude]{more}, got {z.shape}")
    if z.shape[1] < width:
        z = np.column_stack([z, np.full((len(z), width - z.shape[1]), np.nan)])
    xy = z[:, :2]
    bad = ~np.isfinite(xy) | (np.abs(xy) > _core.REAL_MAX)
    if bad.any():
        i, j = np.argwhere(bad)[0]
        raise ValueError(f"detection {i}: {names[j]} = {z[i, j]!r} is not a finite number that "
                         f"mtt_real ({_core.REAL}) holds")
    if polar and not (xy[:, 0] > 0).all():
        i = int(np.argwhere(~(xy[:, 0] > 0))[0][0])
        raise ValueError(f"detection {i}: range = {float(z[i, 0])!r} must be > 0")
    a = z[:, 2]
    bad = ~np.isnan(a) & ~((a >= 0) & (a <= _core.REAL_MAX))
    if bad.any():
        i = int(np.argwhere(bad)[0][0])
        raise ValueError(f"detection {i}: amplitude = {a[i]!r} must be >= 0 and finite "
                         f"(NaN: unknown)")
    if polar:
        rr = z[:, 3]
        bad = ~np.isnan(rr) & ~(np.abs(rr) <= _core.REAL_MAX)
        if bad.any():
            i = int(np.argwhere(bad)[0][0])
            raise ValueError(f"detection {i}: range_rate = {float(rr[i])!r} must be finite (NaN: none)")
    return np.ascontiguousarray(z)


def _covariances(cov, n: int) -> np.ndarray:
    """(n, 3) [r_xx, r_xy, r_yy] or (n, 2, 2) array-like into validated (n, 3) float64 rows.

    A row of zeros is "meas_sigma's covariance"; any other must be finite and
    positive definite (ALGORITHMS.md section 3.1)."""
    try:
        c = np.asarray(cov, dtype=float)
    except (TypeError, ValueError) as e:
        raise ValueError(f"cov must be numbers: {e}") from None
    if c.ndim == 3 and c.shape[1:] == (2, 2):
        if not np.array_equal(c[:, 0, 1], c[:, 1, 0]):
            i = int(np.argwhere(c[:, 0, 1] != c[:, 1, 0])[0][0])
            raise ValueError(f"cov {i}: not symmetric ({c[i, 0, 1]!r} against {c[i, 1, 0]!r})")
        c = np.column_stack([c[:, 0, 0], c[:, 0, 1], c[:, 1, 1]]) if len(c) else np.zeros((0, 3))
    if c.size == 0 and n == 0:
        return np.zeros((0, 3))
    if c.ndim != 2 or c.shape != (n, 3):
        raise ValueError(f"cov must have shape ({n}, 3) [r_xx, r_xy, r_yy] or ({n}, 2, 2), one per "
                         f"detection, got {c.shape}")
    zero = ~c.any(axis=1)
    ok = np.isfinite(c).all(axis=1) & (np.abs(c) <= _core.REAL_MAX).all(axis=1) & \
        (c[:, 0] > 0) & (c[:, 2] > 0) & (c[:, 0] * c[:, 2] > c[:, 1] ** 2)
    bad = ~(zero | ok)
    if bad.any():
        i = int(np.argwhere(bad)[0][0])
        raise ValueError(f"cov {i}: {c[i].tolist()!r} is not a covariance (finite, r_xx > 0, r_yy > 0, "
                         f"r_xx r_yy > r_xy^2; all 0: meas_sigma's)")
    return np.ascontiguousarray(c)


class Tracker:
    """A multi-target tracker: ``Tracker(settings=None)``.

    ``settings``: a dict with the keys of docs/FORMATS.md ("Settings"), a path
    to a settings JSON file, or None for the defaults.  ``initial_tracks``
    entries start as confirmed tracks (identities 0, 1, ...); one without "P"
    gets the two-point covariance of the scan interval ``interval`` (keyword,
    default 1: mtt-track uses its detections' first scan interval).  Bad
    settings raise ``ValueError`` (:class:`mtt.SettingsError`) naming the key
    as mtt-track does.
    """

    def __init__(self, settings=None, *, interval: float | None = None):
        if settings is None:
            settings, source = {}, "settings"
        elif isinstance(settings, (str, bytes, os.PathLike)):
            source = os.fsdecode(settings)
            settings = load_settings(source)
        elif isinstance(settings, dict):
            source = "settings"
        else:
            raise TypeError(f"settings must be a dict, a path or None, not {type(settings).__name__}")
        core = _core.Tracker()
        seeds = apply_settings(core, settings, source)
        st = core.init()
        if st != 0:  # mtt_params_check passed: not the settings' fault
            raise RuntimeError(f"mtt_tracker_init failed: {_core.status_text(st)}")
        self._core = core
        self._time = None
        if seeds:
            self._add_seeds(seeds, source, 1.0 if interval is None else interval)
        self._tracks = None

    def _add_seeds(self, seeds, source, interval):
        st, P2 = _core.two_point_cov(*self.param("meas_sigma"), float(interval))
        if st != 0:
            raise ValueError(f"two-point covariance for the initial tracks failed (scan interval "
                             f"{interval:g}): {_core.status_text(st)}")
        for i, s in enumerate(seeds):
            st, _ = self._core.add_track(s.x, s.P if s.P is not None else P2)
            if st == 0:
                continue
            if st == _core.ERR_VALUE:
                key = f"initial_tracks[{i}]" + (".P" if s.P is not None else "")
                msg = ("must be a symmetric positive definite covariance" if s.P is not None
                       else "rejected: state not finite")
            elif st == _core.ERR_FULL:
                key = f"initial_tracks[{i}]"
                msg = f"too many initial tracks: the track table holds {_core.MAX_TRACKS} (MTT_MAX_TRACKS)"
            else:
                raise RuntimeError(f"mtt_tracker_add_track failed: {_core.status_text(st)}")
            raise SettingsError(source, key, msg)

    # ------------------------------------------------------------ queries

    @property
    def polar(self) -> bool:
        """True under ``measurement`` "polar": ``step`` takes range, bearing (ALGORITHMS.md section 3.2)."""
        return int(self.param("measurement")[0]) == 1

    def param(self, key: str):
        """The value of a settings key as the tracker holds it (tuple of floats;
        an enum as its index, a boolean as 0 / 1; imm_models as r, then a
        model index and a psd per slot; the per-model keys in their
        MTT_MAX_MODELS slots)."""
        from .settings import n_values, params_table
        row = next((r for r in params_table() if r.key == key), None)
        if row is None:
            raise KeyError(key)
        _, v = self._core.get_param(key, n_values(row))
        return v

    @property
    def tracks(self) -> list:
        """The live tracks after the last step (ascending id), as ``step`` returned them."""
        if self._tracks is None:
            self._tracks = [Track._from_row(r) for r in self.track_table()]
        return list(self._tracks)

    def track_table(self) -> np.ndarray:
        """The live tracks as one float64 array (n, 28 + MAX_MODELS), ascending id;
        the columns are ``mtt.tracker.TABLE_COLUMNS``: id, confirmed (0/1), x, y,
        vx, vy, existence, age, detection (-1: none), the covariance row-major,
        n_models (1 with motion = cv), the model probabilities mu0, mu1, ...,
        p_split and parent (split = true: P(split) and the id of the track this
        one split off from, -1 for none; docs/FORMATS.md).
        Cheaper than ``tracks`` for many steps (no object per track)."""
        a = np.frombuffer(self._core.table(), dtype=np.float64).reshape(-1, _core.TABLE_COLUMNS)
        return a

    @property
    def stats(self) -> dict:
        """{"last": counters of the last step, "total": since the start}, named as mtt_counts' fields."""
        last, total, _ = self._core.stats()
        return {"last": last, "total": total}

    @property
    def time(self) -> float | None:
        """Time of the last step, or None."""
        return self._time

    # ------------------------------------------------------------ stepping

    def step(self, time: float, detections=(), cov=None) -> list:
        """Run one scan (see :meth:`update`) and return the live tracks after it,
        a list of :class:`Track` in ascending id."""
        self.update(time, detections, cov)
        return self.tracks

    def update(self, time: float, detections=(), cov=None) -> None:
        """Run one scan at ``time`` (greater than the last step's) with ``detections``:
        array-like (n, 2) [x, y] or (n, 3) [x, y, amplitude] (NaN amplitude: unknown;
        n may be 0), without building Track objects (``tracks`` and
        ``track_table()`` give the result).  ``cov``: each detection's own
        covariance, (n, 3) [r_xx, r_xy, r_yy] or (n, 2, 2); a row of zeros
        (or ``cov`` None) is meas_sigma's (ALGORITHMS.md section 3.1).
        Under ``measurement`` "polar" the detections are (n, 2) [range,
        bearing], (n, 3) [range, bearing, amplitude] or (n, 4) [range,
        bearing, amplitude, range_rate] from ``sensor_xy`` (bearing in
        radians, atan2(y - y_s, x - x_s); range > 0; NaN range rate: none;
        a range rate needs ``range_rate_sigma``), each converted with its own
        covariance (ALGORITHMS.md section 3.2), and ``cov`` must be None.

        Raises ValueError for a time that is not finite, not representable or
        not later than the last one, for detections of the wrong shape or
        with non-finite coordinates or negative amplitudes, and for a ``cov``
        row that is not a covariance; the tracker is then unchanged.  A ``cov``
        where the library has no covariance per detection (a build without
        MTT_WITH_MEAS_COV) raises ValueError too.
        """
        try:
            t = float(time)
        except (TypeError, ValueError):
            raise ValueError(f"time must be a number, got {time!r}") from None
        if not math.isfinite(t) or abs(t) > _core.REAL_MAX:
            raise ValueError(f"time {t!r} is not a finite number that mtt_real ({_core.REAL}) holds")
        polar = self.polar
        z = _detections(detections, polar)
        if polar and cov is not None:
            raise ValueError("cov: under measurement polar each detection's covariance comes from "
                             "meas_sigma [sigma_range, sigma_bearing] (ALGORITHMS.md section 3.2)")
        c = None if cov is None else _covariances(cov, len(z)).tobytes()
        st = self._core.step(t, z.tobytes(), c, 1 if polar else 0)
        if polar and st == _core.ERR_PARAM:
            raise ValueError("a detection has a range rate but the settings' range_rate_sigma is 0")
        if st == _core.ERR_UNSUPPORTED and c is not None:
            raise ValueError("a covariance per detection is not available here: the library was built "
                             "without MTT_WITH_MEAS_COV")
        if st == _core.ERR_TIME:
            raise ValueError(f"time {t!r} is not later than the last step's time {self._time!r} "
                             f"in the tracker's precision (mtt_real={_core.REAL})")
        if st != 0:
            raise RuntimeError(f"mtt_tracker_step failed: {_core.status_text(st)}")
        self._time = t
        self._tracks = None

    def __repr__(self) -> str:
        tab = self.track_table()
        n, c = len(tab), int(tab[:, 1].sum())
        return f"<mtt.Tracker time={self._time!r}: {n} tracks, {c} confirmed>"
