# SPDX-License-Identifier: BSD-3-Clause
"""mtt.stonesoup: the mtt tracker as a Stone Soup tracker (``pip install mtt[stonesoup]``).

    from mtt.stonesoup import MttTracker
    tracker = MttTracker(detector=reader, settings={"pd": 0.9, "clutter_density": 1e-4})
    for time, tracks in tracker:            # confirmed tracks
        ...

``MttTracker`` takes Stone Soup ``Detection``s whose ``state_vector`` is the
2-D position ``[x, y]`` (``metadata["amplitude"]``, if present, is the
detection's amplitude; a detection whose ``measurement_model`` has a 2 x 2
``covar()`` is tracked with that covariance, ALGORITHMS.md section 3.1,
the others with the settings' ``meas_sigma``; under the settings' ``measurement``
"polar", detections of a ``CartesianToBearingRange`` model, state_vector
``[bearing, range]``, or ``CartesianToBearingRangeRate``, ``[bearing, range,
range rate]``, whose noise is the settings' ``meas_sigma`` (and
``range_rate_sigma``) and whose ``translation_offset`` is ``sensor_xy``,
section 3.2) and gives Stone Soup ``Track``s of ``GaussianState``s
in Stone Soup's constant-velocity order ``[x, vx, y, vy]`` (the covariance
permuted the same way).  ``track.id`` is the mtt track id as a string, and
``track.metadata`` holds ``existence``, ``confirmed`` and ``age`` of the
last scan.  The same ``Track`` object grows by one state per scan for as
long as mtt keeps the track.  Times are the scans' timestamps in seconds
since the first scan's timestamp (a timestamp may also be a number).
"""

from __future__ import annotations

import datetime
import math

import numpy as np

try:
    from stonesoup.base import Property
    from stonesoup.reader.base import DetectionReader
    from stonesoup.tracker.base import Tracker as _SSTracker
    from stonesoup.types.state import GaussianState
    from stonesoup.types.track import Track as _SSTrack
except ImportError as e:  # the optional extra
    raise ImportError(f"mtt.stonesoup needs Stone Soup: pip install 'mtt[stonesoup]' ({e})") from e

from .tracker import Tracker

__all__ = ["MttTracker", "CV_ORDER"]

#: mtt's state order (x, y, vx, vy) indexed into Stone Soup's CV order (x, vx, y, vy).
CV_ORDER = (0, 2, 1, 3)


class MttTracker(_SSTracker):
    """Stone Soup tracker running mtt's LM-IHPDA (or any mode of the settings).

    Iterate over it (with a ``detector``) or call :meth:`update_tracker` per
    scan; both return ``(timestamp, tracks)``, the set of confirmed tracks.
    """

    detector: DetectionReader = Property(
        default=None, doc="Detection reader (or any iterable) giving (timestamp, Detections) per "
                          "scan; None when update_tracker is called directly")
    settings: object = Property(default=None, doc="mtt settings: a dict with the keys of "
                                "docs/FORMATS.md, a path to a settings JSON file, or None")

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self.detector_iter = None
        #: the mtt.Tracker underneath (its stats, its numpy tracks)
        self.mtt = Tracker(self.settings)
        self._t0 = None
        self._live: dict[int, _SSTrack] = {}

    # ------------------------------------------------------------ Stone Soup interface

    @property
    def tracks(self) -> set:
        """Confirmed tracks after the last scan."""
        return {t for t in self._live.values() if t.metadata.get("confirmed")}

    @property
    def tentative_tracks(self) -> set:
        """Tentative (not yet confirmed) tracks after the last scan."""
        return {t for t in self._live.values() if not t.metadata.get("confirmed")}

    def __iter__(self):
        if self.detector is None:
            raise AttributeError("Detector has not been set. A detector attribute is required to "
                                 "iterate over a tracker.")
        if self.detector_iter is None:
            self.detector_iter = iter(self.detector)
        return self

    def __next__(self):
        timestamp, detections = next(self.detector_iter)
        return self.update_tracker(timestamp, detections)

    def update_tracker(self, timestamp, detections):
        """Run one scan; returns (timestamp, confirmed tracks).  ``detections``:
        any iterable of Detections, a set included: mtt stores a scan's
        detections in a canonical order, so the tracks and their identities
        do not depend on the iteration order.  Raises ValueError
        (and changes nothing) for a timestamp not later than the last one or a
        detection that is not a 2-D position."""
        seconds = self._seconds(timestamp)
        detections = list(detections)
        if self.mtt.polar:
            z, cov = self._polar(detections), None
        else:
            z, cov = self._matrix(detections), self._covariances(detections)
        live = self.mtt.step(seconds, z, cov)
        if self._t0 is None:
            self._t0 = timestamp
        tracks = {}
        for t in live:
            sst = self._live.get(t.id)
            if sst is None:
                sst = _SSTrack(id=str(t.id))
            order = list(CV_ORDER)
            state = GaussianState(t.state[order].reshape(4, 1),
                                  t.covar[np.ix_(order, order)], timestamp=timestamp)
            sst.append(state)
            sst.metadata.update(existence=t.existence, confirmed=t.confirmed, age=t.age)
            tracks[t.id] = sst
        self._live = tracks
        return timestamp, self.tracks

    # ------------------------------------------------------------ conversions

    def _seconds(self, timestamp) -> float:
        """Seconds since the first scan's timestamp (a datetime or a number)."""
        t0 = timestamp if self._t0 is None else self._t0
        if isinstance(timestamp, datetime.datetime) or isinstance(t0, datetime.datetime):
            if not (isinstance(timestamp, datetime.datetime) and isinstance(t0, datetime.datetime)):
                raise ValueError(f"timestamp {timestamp!r} and the first scan's {t0!r} must both be "
                                 f"datetimes or both numbers")
            return (timestamp - t0).total_seconds()
        try:
            return float(timestamp) - float(t0)
        except (TypeError, ValueError):
            raise ValueError(f"timestamp must be a datetime or a number, got {timestamp!r}") from None

    def _polar(self, detections) -> np.ndarray:
        """Detections of a CartesianToBearingRange model (state_vector [bearing, range]) or
        CartesianToBearingRangeRate ([bearing, range, range rate]) as (n, 4) rows range,
        bearing, amplitude, range rate (NaN: none) for measurement polar (ALGORITHMS.md
        section 3.2); the model's noise and sensor position must be the settings'."""
        sig = np.asarray(self.mtt.param("meas_sigma"), dtype=float)
        sensor = np.asarray(self.mtt.param("sensor_xy"), dtype=float)
        srr = float(self.mtt.param("range_rate_sigma")[0])
        rows = []
        for d in detections:
            model = getattr(d, "measurement_model", None)
            name = type(model).__name__
            if name not in ("CartesianToBearingRange", "CartesianToBearingRangeRate"):
                raise ValueError(f"with measurement polar each detection's measurement_model must be "
                                 f"CartesianToBearingRange or CartesianToBearingRangeRate, got {name}")
            rate = name == "CartesianToBearingRangeRate"
            c = np.asarray(model.covar(), dtype=float)
            want = np.diag([sig[1] ** 2, sig[0] ** 2] + ([srr ** 2] if rate else []))
            what = "meas_sigma [sigma_range, sigma_bearing]" + (" and range_rate_sigma" if rate else "")
            if c.shape != want.shape or not np.allclose(c, want, rtol=1e-6, atol=0.0):
                raise ValueError(f"the measurement model's noise covariance {c.tolist()!r} (bearing, range"
                                 f"{', range rate' if rate else ''}) is not the settings' {what}: "
                                 f"diag({', '.join(repr(float(v)) for v in np.diag(want))})")
            off = np.asarray(model.translation_offset, dtype=float).ravel()[:2]
            if not np.allclose(off, sensor, rtol=1e-9, atol=1e-9):
                raise ValueError(f"the measurement model's translation_offset {off.tolist()!r} is not "
                                 f"the settings' sensor_xy {sensor.tolist()!r}")
            rot = np.asarray(getattr(model, "rotation_offset", np.zeros(3)), dtype=float).ravel()
            vel = np.asarray(getattr(model, "velocity", np.zeros(3)), dtype=float).ravel()
            if np.any(rot != 0.0) or np.any(vel != 0.0):
                raise ValueError("a measurement model with a rotation_offset or a sensor velocity is not "
                                 "supported: bearings are atan2(y - y_s, x - x_s) from a still sensor")
            sv = np.asarray(d.state_vector, dtype=float).ravel()
            if sv.shape != ((3,) if rate else (2,)):
                raise ValueError(f"a detection's state_vector must be [bearing, range"
                                 f"{', range_rate' if rate else ''}], got shape {sv.shape}")
            md = getattr(d, "metadata", None) or {}
            a = md.get("amplitude", None)
            rows.append((sv[1], sv[0], np.nan if a is None else float(a), sv[2] if rate else np.nan))
        return np.array(rows, dtype=float).reshape(-1, 4)

    @staticmethod
    def _covariances(detections):
        """Each detection's measurement-model covariance as (n, 3) rows (zeros where it has
        none), or None when no detection has one."""
        rows, any_cov = [], False
        for d in detections:
            model = getattr(d, "measurement_model", None)
            r = (0.0, 0.0, 0.0)
            if model is not None and hasattr(model, "covar"):
                c = np.asarray(model.covar(), dtype=float)
                if c.shape != (2, 2):
                    raise ValueError(f"a detection's measurement model must have a 2 x 2 covariance "
                                     f"(x, y), got shape {c.shape}")
                r = (c[0, 0], c[0, 1], c[1, 1])
                any_cov = True
            rows.append(r)
        return np.array(rows, dtype=float).reshape(-1, 3) if any_cov else None

    @staticmethod
    def _matrix(detections) -> np.ndarray:
        rows = []
        for d in detections:
            sv = np.asarray(getattr(d, "state_vector", None), dtype=float).ravel()
            if sv.shape != (2,):
                raise ValueError(f"a detection's state_vector must be [x, y] (2-D position), "
                                 f"got shape {sv.shape}")
            md = getattr(d, "metadata", None) or {}
            a = md.get("amplitude", None)
            if a is None or (isinstance(a, str) and a.strip() == ""):
                amp = math.nan
            else:
                try:
                    amp = float(a)
                except (TypeError, ValueError):
                    raise ValueError(f"metadata['amplitude'] must be a number, got {a!r}") from None
            rows.append((sv[0], sv[1], amp))
        return np.array(rows, dtype=float).reshape(-1, 3)
