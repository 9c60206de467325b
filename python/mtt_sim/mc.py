#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Monte Carlo runs of a scenario through the mtt tracker, with the papers' tables and plots.

    PYTHONPATH=python python3 -m mtt_sim.mc --scenario scenarios/crossing3.json --runs 500 --out out/crossing3 \
        --assoc lm-ipda lm-ihpda
    PYTHONPATH=python python3 -m mtt_sim.mc --scenario scenarios/formations.json --runs 10 --out out/formations

Run r uses seed SEED0 + r in every mode (identical detections across modes).
The tracker runs in-process through the mtt package when it is installed
(`pip install .`), else as one mtt-track process per run; --tracker forces
either (the scores are the same, in-process is faster: docs/PYTHON.md).
Prints the tables to stdout (also OUT/report.txt), writes OUT/summary.json,
OUT/*.png and the files of run 0 under OUT/run0/.  Progress goes to stderr.
With --scheduler tcp://HOST:8786 the runs are tasks of a running Dask
scheduler instead of local processes (docs/PYTHON.md "Monte Carlo on a
cluster"); the totals are the same.
Exit status: 0 if every run succeeded, 1 if some failed, 2 on bad arguments.

The runner: generate, run the tracker, score, aggregate.  Run r of mode m
uses seed ``seed0 + r`` for every mode, so the modes are compared on
identical detections (common random numbers), as S4 compares its two
methods.  Work items (mode, run) are spread over J worker processes (or
the workers of a Dask scheduler) and aggregated in run order;
each one generates its run in a private temporary directory, calls

    mtt-track --config S --detections D --tracks T

timing the call with a monotonic clock, reads T and scores it with
``metrics.score_run``.  The files of run 0 are kept under ``OUT/run0/`` for
the scene plot and for replotting.

The tracker runs in-process through the ``mtt`` package (``pip install .``)
when it is importable (``tracker="auto"``, or ``"in-process"`` to insist),
else as one ``mtt-track`` process per run (``"mtt-track"`` forces it).  The
in-process path hands the tracker the numbers exactly as mtt-track would read
them from the detections file and takes the tracks' numbers as mtt-track
prints them, so both paths give the same scores (python/tests/package).
"""

from __future__ import annotations

import argparse
import json
import math
import multiprocessing
import os
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

from . import csvio, gen, metrics, radar, report
from . import scenario as scnmod

__all__ = ["find_mtt_track", "find_tracker", "text_values", "in_process_available", "track_in_process", "IN_PROCESS",
           "TrackerError", "run_tracker", "one_run", "monte_carlo", "Aggregate", "build_summary",
           "add_run_arguments", "add_scheduler_argument", "check_scheduler", "dask_client", "main"]

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DEFAULT_BINARY = os.path.join(REPO, "build", "host-float", "tools", "track", "mtt-track")


class TrackerError(RuntimeError):
    """mtt-track failed (non-zero exit, time-out or unreadable output)."""


def find_mtt_track(explicit: str | None = None) -> str | None:
    """The mtt-track binary: ``explicit``, else $MTT_TRACK, else build/host-float/tools/track/mtt-track."""
    for cand in (explicit, os.environ.get("MTT_TRACK"), DEFAULT_BINARY):
        if cand and os.path.isfile(cand) and os.access(cand, os.X_OK):
            return os.path.abspath(cand)
    return None


IN_PROCESS = "in-process"


def in_process_available() -> bool:
    """True when the mtt package (with its compiled module) can be imported."""
    try:
        import mtt  # noqa: F401
        from mtt import _core  # noqa: F401
    except ImportError:
        return False
    return True


def find_tracker(choice: str = "auto", explicit: str | None = None) -> str | None:
    """The tracker to run: IN_PROCESS, or the path of mtt-track, or None.

    "in-process": the mtt package (None if it does not import); "mtt-track":
    find_mtt_track(explicit); "auto": an explicitly given binary, else the
    package when it imports, else find_mtt_track().
    """
    if choice not in ("auto", IN_PROCESS, "mtt-track"):
        raise ValueError(f"tracker must be auto, in-process or mtt-track, not {choice!r}")
    if choice == IN_PROCESS or (choice == "auto" and explicit is None):
        if in_process_available():
            return IN_PROCESS
        if choice == IN_PROCESS:
            return None
    return find_mtt_track(explicit)


def text_values(v, digits: int) -> np.ndarray:
    """v as it reads back from text written with %.<digits>g (NaN stays NaN).
    One format of the whole column, then one parse (the fastest way found)."""
    v = np.asarray(v, float).ravel()
    if len(v) == 0:
        return np.zeros(0)
    return np.array(((f"%.{digits}g," * len(v)) % tuple(v.tolist())).split(",")[:-1], dtype=float)


def track_in_process(run: dict, printed=("x", "y")) -> tuple[dict, float]:
    """Track a generated run with mtt.Tracker as mtt-track would track its files.

    The detections are the numbers of csvio.format_det's text (x, y, time
    %.10g, amplitude %.6g), each scan at its time minus the first scan's, in
    the file's row order.  The track columns named in ``printed`` (those that
    metrics.score_run reads, by default) are the numbers of mtt-track's text
    (%.9g of a float build, %.17g of a double one), the others the tracker's
    values (equal to the text to its printed digits).  Returns (tracks table
    as csvio.read_tracks gives it, seconds spent tracking)."""
    import mtt
    from mtt.tracker import TABLE_COLUMNS

    det = run["det"]
    if "range" in det:
        raise TrackerError("the mtt package does not take polar detections: --tracker mtt-track")
    times = text_values(run["times"], 10)
    order = np.argsort(np.asarray(det["scan"], int), kind="stable")
    scans = np.asarray(det["scan"], int)[order]
    z = np.column_stack([text_values(det["x"], 10)[order], text_values(det["y"], 10)[order],
                         text_values(det["amp"], 6)[order]])
    bounds = np.searchsorted(scans, np.arange(len(times) + 1))
    tables, scan_of = [], []
    t_start = time.perf_counter()
    try:
        trk = mtt.Tracker(run["settings"], interval=times[1] - times[0] if len(times) > 1 else None)
        for k in range(len(times)):
            trk.update(times[k] - times[0], z[bounds[k]:bounds[k + 1]])
            tab = trk.track_table()
            tables.append(tab)
            scan_of.append(np.full(len(tab), k, int))
    except ValueError as e:
        raise TrackerError(f"mtt.Tracker: {e}") from None
    elapsed = time.perf_counter() - t_start
    tab = np.concatenate(tables) if tables else np.zeros((0, len(TABLE_COLUMNS)))
    col = {name: tab[:, i] for i, name in enumerate(TABLE_COLUMNS)}
    digits = 9 if mtt.REAL == "float" else 17
    out = {"scan": np.concatenate(scan_of) if scan_of else np.zeros(0, int),
           "track": col["id"].astype(int), "confirmed": col["confirmed"] != 0.0}
    out["time"] = times[out["scan"]]
    for k, c in (("x", "x"), ("y", "y"), ("vx", "vx"), ("vy", "vy"), ("existence", "existence"),
                 ("pxx", "P00"), ("pxy", "P01"), ("pyy", "P11")):
        out[k] = text_values(col[c], digits) if k in printed else col[c].copy()
    if run["settings"].get("split"):
        out["p_split"] = col["p_split"].copy()
        out["parent"] = col["parent"].astype(int)
    return out, elapsed


def _tracks_text(tracks: dict) -> str:
    """A tracks CSV of a tracks table (the files kept of run 0)."""
    lines = [csvio.TRACKS_HEADER]
    for i in range(len(tracks["scan"])):
        lines.append(",".join([str(int(tracks["scan"][i])), repr(float(tracks["time"][i])),
                               str(int(tracks["track"][i])),
                               "confirmed" if tracks["confirmed"][i] else "tentative"]
                              + [repr(float(tracks[k][i])) for k in
                                 ("x", "y", "vx", "vy", "existence", "pxx", "pxy", "pyy")]))
    return "\n".join(lines) + "\n"


def run_tracker(exe: str, settings: str, det: str, tracks: str, timeout: float = 600.0) -> float:
    """Run mtt-track once; return its wall time in seconds; raise TrackerError on failure."""
    cmd = [exe, "--config", settings, "--detections", det, "--tracks", tracks]
    t0 = time.perf_counter()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        raise TrackerError(f"mtt-track timed out after {timeout:.0f} s") from None
    except OSError as e:  # binary missing, not executable, being rebuilt
        raise TrackerError(f"cannot run {exe}: {e}") from None
    elapsed = time.perf_counter() - t0
    if p.returncode != 0:
        msg = (p.stderr or "").strip().splitlines()
        raise TrackerError(f"mtt-track exit {p.returncode}: {msg[0] if msg else '(no message)'}")
    if not os.path.isfile(tracks):
        raise TrackerError("mtt-track exited 0 but wrote no tracks file")
    return elapsed


def _track_process(run: dict, mode: str, exe: str, keep_dir: str | None, timeout: float):
    """One mtt-track process on the run's files; returns (tracks table, wall seconds)."""
    with tempfile.TemporaryDirectory(prefix="mtt_mc_") as td:
        paths = gen.write_run(run, td, "run")
        tpath = os.path.join(td, "run.tracks.csv")
        elapsed = run_tracker(exe, paths["settings"], paths["det"], tpath, timeout)
        try:
            tracks = csvio.read_tracks(tpath)
        except csvio.FormatError as e:
            raise TrackerError(f"bad tracks file: {e}") from None
        if keep_dir:
            os.makedirs(keep_dir, exist_ok=True)
            name = run["name"]
            shutil.copyfile(paths["det"], os.path.join(keep_dir, f"{name}.det.csv"))
            shutil.copyfile(paths["truth"], os.path.join(keep_dir, f"{name}.truth.csv"))
            shutil.copyfile(paths["settings"], os.path.join(keep_dir, f"{name}.{mode}.settings.json"))
            shutil.copyfile(tpath, os.path.join(keep_dir, f"{name}.{mode}.tracks.csv"))
    return tracks, elapsed


def one_run(scn: dict, mode: str, run_index: int, seed: int, exe: str, keep_dir: str | None = None,
            timeout: float = 600.0) -> dict:
    """Generate, track and score one run; never raises for tracker failures.

    ``exe``: IN_PROCESS, the path of mtt-track, or a callable ``exe(run) ->
    (tracks table, seconds)`` (another tracker, e.g. mtt_sim.stonesoup_mc's).
    """
    res = {"mode": mode, "run": run_index, "seed": seed, "ok": False}
    try:
        # another tracker (a callable) ignores the association mode; the detections do not depend on it
        run = gen.generate(scn, seed, None if callable(exe) else mode)
        nscan = len(run["times"])
        if exe == IN_PROCESS or callable(exe):
            # run 0 is kept: every column as mtt-track would print it
            tracks, elapsed = (exe(run) if callable(exe) else
                               track_in_process(run, csvio.TRACKS_HEADER.split(",") if keep_dir else ("x", "y")))
            if keep_dir:
                name = run["name"]
                gen.write_run(run, keep_dir, name)
                os.replace(os.path.join(keep_dir, f"{name}.settings.json"),
                           os.path.join(keep_dir, f"{name}.{mode}.settings.json"))
                with open(os.path.join(keep_dir, f"{name}.{mode}.tracks.csv"), "w", encoding="utf-8") as f:
                    f.write(_tracks_text(tracks))
        else:
            tracks, elapsed = _track_process(run, mode, exe, keep_dir, timeout)
        if len(tracks["scan"]) and (tracks["scan"].min() < 0 or tracks["scan"].max() >= nscan):
            raise TrackerError("tracks file has a scan outside the detections' scans")
        met = scn.get("metrics", {})
        sc = metrics.score_run(run["truth"], tracks, nscan,
                               float(met.get("match_distance", 1.0)), float(met.get("gospa_c", met.get("match_distance", 1.0))),
                               run["seeded_targets"], int(met.get("seeded_eval_scan", -1)),
                               [(int(sp["child"]), int(sp["parent"]), int(sp["scan"])) for sp in scn.get("splits", [])])
        res.update(ok=True, elapsed=elapsed, time_per_frame=metrics.time_per_frame(elapsed, nscan), score=sc)
    except TrackerError as e:
        res["error"] = str(e)
    return res


# ------------------------------------------------------------------ aggregation


def _nan_to_none(x):
    if isinstance(x, dict):
        return {k: _nan_to_none(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_nan_to_none(v) for v in x]
    if isinstance(x, np.ndarray):
        return _nan_to_none(x.tolist())
    if isinstance(x, (np.floating, float)):
        return None if not math.isfinite(float(x)) else float(x)
    if isinstance(x, np.integer):
        return int(x)
    if isinstance(x, np.bool_):
        return bool(x)
    return x


class Aggregate:
    """Sums of the per-run scores of one mode."""

    PER_SCAN = ("n_truth", "conf_true", "conf_false", "n_tentative", "n_confirmed",
                "gospa", "gospa_loc", "gospa_missed", "gospa_false")

    def __init__(self, nscan: int, windows: dict | None = None):
        self.nscan = nscan
        self.windows = windows or {}  # manoeuvre windows: RMSE split into straight legs and turns
        self.ok = 0
        self.failures: list[dict] = []
        self.sums = {k: np.zeros(nscan) for k in self.PER_SCAN}
        self.sq = {}      # target id -> (sum of squared errors, count) per scan
        self.mot = {"gt": 0, "matches": 0, "fn": 0, "fp": 0, "idsw": 0, "swaps": 0, "dist": 0.0}
        self.hota: dict[int, dict] = {}  # run index -> metrics.hota, combined in run order
        self.times: list[float] = []
        self.seeded = {"runs": 0, "failed": 0, "coalescence": 0, "switch": 0, "lost": 0,
                       "coalescence_or_switch": 0}
        self.run0 = None
        self.split = {"runs": 0, "delays": [], "never": 0, "spawned": 0, "false_splits": 0}

    def add(self, res: dict) -> None:
        if not res["ok"]:
            self.failures.append({"run": res["run"], "seed": res["seed"], "error": res.get("error", "")})
            return
        sc = res["score"]
        self.ok += 1
        for k in self.PER_SCAN:
            self.sums[k] += sc[k]
        for tid, e in sc["sq_err"].items():
            s, c = self.sq.setdefault(int(tid), (np.zeros(self.nscan), np.zeros(self.nscan)))
            m = np.isfinite(e)
            s[m] += e[m]
            c[m] += 1
        for k in self.mot:
            self.mot[k] += sc["mot"][k]
        self.hota[int(res["run"])] = sc["hota"]
        self.times.append(res["time_per_frame"])
        if sc["seeded"] is not None:
            self.seeded["runs"] += 1
            for k in ("failed", "coalescence", "switch", "lost"):
                self.seeded[k] += int(bool(sc["seeded"][k]))
            self.seeded["coalescence_or_switch"] += int(sc["seeded"]["coalescence"] or sc["seeded"]["switch"])
        if sc.get("split") is not None:
            sp = self.split
            sp["runs"] += 1
            for d in sc["split"]["delays"]:
                if d is None:
                    sp["never"] += 1
                else:
                    sp["delays"].append(d)
            sp["spawned"] += sc["split"]["spawned"]
            sp["false_splits"] += sc["split"]["false_splits"]
        if res["run"] == 0:
            self.run0 = {"tentative": sc["n_tentative"].tolist(), "confirmed": sc["n_confirmed"].tolist(),
                         "seeded": sc["seeded"]}

    def result(self) -> dict:
        n = max(self.ok, 1)
        s = self.sums
        per_scan = {
            "n_truth_sum": s["n_truth"], "conf_true_sum": s["conf_true"], "conf_false_sum": s["conf_false"],
            "tentative_mean": s["n_tentative"] / n, "confirmed_mean": s["n_confirmed"] / n,
            "gospa_mean": s["gospa"] / n, "gospa_loc_mean": s["gospa_loc"] / n,
            "gospa_missed_mean": s["gospa_missed"] / n, "gospa_false_mean": s["gospa_false"] / n,
        }
        rmse, rmse_target = {}, {}
        tot_s = np.zeros(self.nscan)
        tot_c = np.zeros(self.nscan)
        for tid in sorted(self.sq):
            ss, cc = self.sq[tid]
            with np.errstate(invalid="ignore", divide="ignore"):
                rmse[str(tid)] = np.where(cc > 0, np.sqrt(ss / np.maximum(cc, 1)), np.nan)
            rmse_target[str(tid)] = math.sqrt(ss.sum() / cc.sum()) if cc.sum() else math.nan
            tot_s += ss
            tot_c += cc
        per_scan["rmse"] = rmse
        per_scan["rmse_all"] = np.where(tot_c > 0, np.sqrt(tot_s / np.maximum(tot_c, 1)), np.nan)
        total = s["n_tentative"] / n + s["n_confirmed"] / n
        peak = int(np.argmax(total)) if self.ok else 0
        mot = self.mot
        gt = mot["gt"]
        hota = metrics.hota_combine([self.hota[r] for r in sorted(self.hota)]) if self.hota else None
        totals = {
            "gospa_mean": float(s["gospa"].mean() / n) if self.ok else math.nan,
            "hota": hota["hota"] if hota else math.nan, "deta": hota["deta"] if hota else math.nan,
            "assa": hota["assa"] if hota else math.nan, "loca": hota["loca"] if hota else math.nan,
            "mota": (1.0 - (mot["fn"] + mot["fp"] + mot["idsw"]) / gt) if gt else math.nan,
            "motp": mot["dist"] / mot["matches"] if mot["matches"] else math.nan,
            "idsw": mot["idsw"], "idsw_per_run": mot["idsw"] / n,
            "swaps": mot["swaps"], "swaps_per_run": mot["swaps"] / n, "fn": mot["fn"], "fp": mot["fp"], "gt": gt,
            "confirmed_true_fraction": float(s["conf_true"].sum() / s["n_truth"].sum()) if s["n_truth"].sum() else math.nan,
            "confirmed_false_per_scan": float(s["conf_false"].mean() / n) if self.ok else math.nan,
            "rmse_per_target": rmse_target,
            "rmse_all": math.sqrt(tot_s.sum() / tot_c.sum()) if tot_c.sum() else math.nan,
            "time_per_frame_ms": {
                "mean": 1e3 * float(np.mean(self.times)) if self.times else math.nan,
                "median": 1e3 * float(np.median(self.times)) if self.times else math.nan,
                "max": 1e3 * float(np.max(self.times)) if self.times else math.nan,
            },
            "peak": {"scan": peak, "tentative_mean": float(s["n_tentative"][peak] / n),
                     "confirmed_mean": float(s["n_confirmed"][peak] / n)},
        }
        if self.windows:
            legs = metrics.rmse_legs(self.sq, self.windows, self.nscan)
            totals["rmse_straight"] = legs["straight"]
            totals["rmse_turn"] = legs["turn"]
        if self.run0 is not None:
            t0 = np.array(self.run0["tentative"]) + np.array(self.run0["confirmed"])
            k = int(np.argmax(t0))
            totals["peak_run0"] = {"scan": k, "tentative": int(self.run0["tentative"][k]),
                                   "confirmed": int(self.run0["confirmed"][k])}
        if self.split["runs"]:
            sp = self.split
            d = np.array(sp["delays"], float)
            n_split = len(d) + sp["never"]
            totals["split"] = {
                "children": n_split, "never": sp["never"],
                # delays of the children never confirmed count as infinite in the quantiles
                "delay_median": float(np.quantile(np.concatenate([d, np.full(sp["never"], np.inf)]), 0.5))
                if n_split else math.nan,
                "delay_p90": float(np.quantile(np.concatenate([d, np.full(sp["never"], np.inf)]), 0.9,
                                               method="inverted_cdf")) if n_split else math.nan,
                "within3": float((d <= 3).sum() / n_split) if n_split else math.nan,
                "spawned_per_run": sp["spawned"] / sp["runs"], "false_splits_per_run": sp["false_splits"] / sp["runs"],
            }
        seeded = None
        if self.seeded["runs"]:
            r = self.seeded["runs"]
            # rate: runs where some seeded track is not on its own target
            # (metrics.seeded_outcome "failed"); the others break it down.
            seeded = dict(self.seeded, rate=self.seeded["failed"] / r)
        return _nan_to_none({
            "runs_ok": self.ok, "runs_failed": len(self.failures), "failures": self.failures[:20],
            "per_scan": per_scan, "totals": totals, "seeded": seeded, "run0": self.run0,
        })


# ------------------------------------------------------------------ parallel driver

_G = {}


def _init_worker(scn, exe, keep_root, timeout):
    _G.update(scn=scn, exe=exe, keep_root=keep_root, timeout=timeout)


def _work(item):
    mode, r, seed = item
    keep = _G["keep_root"] if (r == 0 and _G["keep_root"]) else None
    return one_run(_G["scn"], mode, r, seed, _G["exe"], keep, _G["timeout"])


def _progress(done, total, t_start, stream, last=[0.0]):
    now = time.monotonic()
    if done < total and now - last[0] < 0.25:  # at most 4 updates a second
        return
    last[0] = now
    el = time.monotonic() - t_start
    rate = done / el if el > 0 else 0.0
    eta = (total - done) / rate if rate > 0 else float("nan")
    eta_s = f"{eta:.0f} s" if math.isfinite(eta) else "?"
    stream.write(f"\r[run {done}/{total}] {rate:.1f} runs/s, ETA {eta_s}   ")
    stream.flush()


def _in_order(results, index_of):
    """The results of ``results`` (in any order) in the order of ``index_of(res)``
    (0, 1, 2, ...): each one as soon as every earlier one has come.  Aggregate.add
    sums floats, so the order of the adds decides the last bits of the totals."""
    pending, nxt = {}, 0
    for res in results:
        pending[index_of(res)] = res
        while nxt in pending:
            yield pending.pop(nxt)
            nxt += 1


def dask_client(scheduler):
    """A distributed.Client for ``scheduler``: a Client (returned as is, not owned) or an
    address such as tcp://HOST:8786 (connected here, owned by the caller).  Returns
    (client, owned)."""
    if not isinstance(scheduler, str):
        return scheduler, False
    from distributed import Client  # dask[distributed], the sim extra

    return Client(scheduler, timeout="30s"), True


def _dask_runs(client, scn, exe, keep_root, timeout, items):
    """The results of ``items`` run as Dask tasks (one_run each), as they complete."""
    from distributed import as_completed

    scn_f = client.scatter(scn, broadcast=True)
    futs = [client.submit(one_run, scn_f, m, r, seed, exe, keep_root if (r == 0 and keep_root) else None,
                          timeout, pure=False)
            for m, r, seed in items]
    try:
        for f in as_completed(futs):
            yield f.result()
    finally:
        client.cancel(futs)


def monte_carlo(scn: dict, modes, runs: int, exe: str, jobs: int | None = None, seed0: int = 0,
                keep_root: str | None = None, timeout: float = 600.0, progress=sys.stderr,
                scheduler=None, first_run: int = 0, aggregates: dict | None = None) -> dict:
    """Run every (mode, run) and return {mode: Aggregate.result()} plus timing info.

    Runs first_run .. first_run + runs - 1 (run r: seed seed0 + r).  ``scheduler``:
    None or "local": ``jobs`` local processes; a Dask scheduler's address
    (tcp://HOST:8786) or a distributed.Client: every run is a Dask task (the
    workers need mtt_sim and ``exe`` at the same path).  The results are added
    to the aggregates in run order whatever the order they complete in, so
    the totals are the same bit for bit for any jobs and scheduler.
    ``aggregates``: {mode: Aggregate} to add to (a run split into chunks
    gives the totals of one call), else new ones."""
    nscan = int(scn["scans"]["count"])
    jobs = jobs or os.cpu_count() or 1
    items = [(m, r, seed0 + r) for r in range(first_run, first_run + runs) for m in modes]
    windows = scnmod.manoeuvre_windows(scn)
    aggs = aggregates if aggregates is not None else {m: Aggregate(nscan, windows) for m in modes}
    t0 = time.monotonic()
    done = 0
    pool = client = None
    owned = False
    if scheduler not in (None, "local"):
        client, owned = dask_client(scheduler)
        jobs = sum(client.nthreads().values())
        it = _dask_runs(client, scn, exe, keep_root, timeout, items)
    elif jobs <= 1:
        _init_worker(scn, exe, keep_root, timeout)
        it = map(_work, items)
    else:
        ctx = multiprocessing.get_context("fork")
        pool = ctx.Pool(jobs, initializer=_init_worker, initargs=(scn, exe, keep_root, timeout))
        it = pool.imap_unordered(_work, items, chunksize=1)
    if progress is not None:  # a long run (a recording) shows the line before its first result
        _progress(0, len(items), t0, progress)
    mode_index = {m: i for i, m in enumerate(modes)}

    def arrived(results):
        nonlocal done
        for res in results:
            done += 1
            if progress is not None:
                _progress(done, len(items), t0, progress)
            yield res

    try:
        for res in _in_order(arrived(it), lambda res: (res["run"] - first_run) * len(modes) + mode_index[res["mode"]]):
            aggs[res["mode"]].add(res)
    finally:
        if pool is not None:
            pool.close()
            pool.join()
        if owned:
            client.close()
    if progress is not None:
        progress.write("\n")
        progress.flush()
    wall = time.monotonic() - t0
    return {"results": {m: aggs[m].result() for m in modes}, "wall_s": wall, "jobs": jobs}


def build_summary(scn: dict, scenario_file: str, overrides, modes, runs, seed0, exe, mc: dict) -> dict:
    """The summary.json object (documented in scenarios/README.md)."""
    return _nan_to_none({
        "scenario": scn["name"],
        "scenario_file": scenario_file,
        "overrides": list(overrides or []),
        "units": scn.get("units", {}),
        "runs": runs, "seed0": seed0, "modes": list(modes), "mtt_track": exe,
        "jobs": mc["jobs"], "wall_s": mc["wall_s"],
        "scan_times": scnmod.scan_times(scn),
        "area": scn["area"],
        # a radar's: its range sigma on both axes (the plots' gate ellipses) and, for its polar
        # file, its position (the plots show the detections converted)
        "meas_sigma": scn.get("meas_sigma") or [radar.sensor(scn)["sr"]] * 2,
        **({"sensor_xy": [radar.sensor(scn)["xs"], radar.sensor(scn)["ys"]]}
           if radar.is_radar(scn) and radar.sensor(scn)["output"] == "polar" else {}),
        "metrics": {"match_distance": scn.get("metrics", {}).get("match_distance"),
                    "gospa_c": scn.get("metrics", {}).get("gospa_c"),
                    "gospa_p": 1, "gospa_alpha": 2},
        "report": scn.get("report", {}),
        "results": mc["results"],
    })


def add_run_arguments(ap: argparse.ArgumentParser, scenarios: bool = False, runs: int = 100,
                      per: str = "mode") -> None:
    """The options of every Monte Carlo command: scenario, runs, jobs, out, seed0, set.

    ``scenarios``: --scenario takes one or more files; ``runs``: the default
    of --runs; ``per``: what --runs counts runs of, in its help."""
    if scenarios:
        ap.add_argument("--scenario", nargs="+", required=True, help="scenario JSON file(s)")
    else:
        ap.add_argument("--scenario", required=True, help="scenario JSON file")
    ap.add_argument("--runs", type=int, default=runs, help=f"Monte Carlo runs per {per} (default {runs})")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1, help="worker processes (default: cores)")
    ap.add_argument("--out", required=True, help="output directory")
    ap.add_argument("--seed0", type=int, default=0, help="seed of run 0 (default 0)")
    ap.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                    help="override a scenario value by dotted path (repeatable)")


def add_scheduler_argument(ap: argparse.ArgumentParser) -> None:
    """--scheduler of mc and tune (monte_carlo's ``scheduler``)."""
    ap.add_argument("--scheduler", default="local", metavar="local|tcp://HOST:PORT",
                    help="local (default): --jobs local processes; tcp://HOST:8786: the runs are tasks of that "
                         "running Dask scheduler (dask[distributed]; the workers need mtt_sim and the same "
                         "mtt-track path, run 0's files are written by the worker that runs it); the totals "
                         "are the same as a serial run's")


def check_scheduler(value: str) -> str | None:
    """An error message for a bad --scheduler, else None."""
    if value == "local" or value.startswith(("tcp://", "tls://", "inproc://", "ucx://")):
        return None
    return f"--scheduler: '{value}' is neither local nor a scheduler address such as tcp://HOST:8786"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    add_run_arguments(ap)
    add_scheduler_argument(ap)
    ap.add_argument("--mtt-track", dest="mtt_track",
                    help="mtt-track binary (default: $MTT_TRACK, then build/host-float/tools/track/mtt-track)")
    ap.add_argument("--tracker", choices=("auto", "in-process", "mtt-track"), default="auto",
                    help="auto (default): the mtt package in-process when it is installed, else "
                         "mtt-track; in-process / mtt-track: that one only")
    ap.add_argument("--assoc", nargs="+", metavar="MODE",
                    help="association mode(s) to compare (default: the scenario's tracker.association)")
    ap.add_argument("--timeout", type=float, default=600.0, help="seconds allowed per mtt-track call")
    ap.add_argument("--no-plots", action="store_true", help="skip the PNG figures")
    a = ap.parse_args(argv)
    if a.runs < 1 or a.jobs < 1:
        ap.error("--runs and --jobs must be >= 1")
    bad = check_scheduler(a.scheduler)
    if bad:
        ap.error(bad)
    try:
        scn = scnmod.load(a.scenario, a.set)
        modes = a.assoc or [scnmod.tracker_value(scn, "association")]
        for m in modes:
            if m not in scnmod.ASSOC_MODES:
                raise scnmod.ScenarioError(f"--assoc: '{m}' is not one of {', '.join(scnmod.ASSOC_MODES)}")
    except (scnmod.ScenarioError, OSError) as e:
        print(f"mc.py: {e}", file=sys.stderr)
        return 2
    exe = find_tracker(a.tracker, a.mtt_track)
    if exe is None:
        if a.tracker == "in-process":
            print("mc.py: --tracker in-process: the mtt package is not installed (pip install .)",
                  file=sys.stderr)
        else:
            print("mc.py: no mtt-track binary (give --mtt-track, set MTT_TRACK, build build/host-float, "
                  "or pip install . for the in-process tracker)", file=sys.stderr)
        return 2
    os.makedirs(a.out, exist_ok=True)
    res = monte_carlo(scn, modes, a.runs, exe, a.jobs, a.seed0,
                      keep_root=os.path.join(a.out, "run0"), timeout=a.timeout, scheduler=a.scheduler)
    summary = build_summary(scn, a.scenario, a.set, modes, a.runs, a.seed0, exe, res)
    with open(os.path.join(a.out, "summary.json"), "w", encoding="utf-8") as f:
        json.dump(summary, f, indent=1)
        f.write("\n")
    text = report.full_report(summary)
    with open(os.path.join(a.out, "report.txt"), "w", encoding="utf-8") as f:
        f.write(text)
    sys.stdout.write(text)
    if not a.no_plots and any(summary["results"][m]["runs_ok"] for m in modes):
        from . import plot  # matplotlib, only when drawing

        paths = plot.plot_all(summary, a.out)
        print("plots: " + ", ".join(os.path.relpath(p, a.out) for p in paths))
    failed = sum(summary["results"][m]["runs_failed"] for m in modes)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
