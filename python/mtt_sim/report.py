# SPDX-License-Identifier: BSD-3-Clause
"""Text tables from a summary (the object of summary.json), in the papers' formats.

* [S4] Table 1: confirmed true tracks summed over the runs at given
  times (maximum = targets x runs), one column per association mode.
* [S0] Fig. 5: tentative and confirmed track counts per frame (mean over
  runs, run 0 in brackets) and the peak frame.
* A summary of GOSPA, CLEAR-MOT, RMSE, false tracks and time per frame.
* [S1] Table 5: coalescence-or-switch rate, for seeded scenarios.
"""

from __future__ import annotations

import math

__all__ = ["time_to_scan", "table_confirmed_true", "table_counts", "table_summary", "table_seeded", "full_report"]


def time_to_scan(times, t):
    """Index of the scan whose time is within half an interval of t, or None."""
    if not times:
        return None
    dt = (times[1] - times[0]) if len(times) > 1 else 1.0
    k = int(round((t - times[0]) / dt))
    if 0 <= k < len(times) and abs(times[k] - t) <= dt / 2:
        return k
    return None


def _fmt(v, nd=3):
    if v is None or (isinstance(v, float) and not math.isfinite(v)):
        return "-"
    if isinstance(v, int):
        return str(v)
    return f"{v:.{nd}f}"


def _table(header, rows):
    cols = [header] + rows
    w = [max(len(str(r[i])) for r in cols) for i in range(len(header))]
    line = "  ".join(str(h).rjust(w[i]) for i, h in enumerate(header))
    out = [line, "  ".join("-" * x for x in w)]
    for r in rows:
        out.append("  ".join(str(c).rjust(w[i]) for i, c in enumerate(r)))
    return "\n".join(out)


def _default_scans(n, want=12):
    step = max(1, n // want)
    return list(range(0, n, step))


def table_confirmed_true(s: dict) -> str:
    times = s["scan_times"]
    modes = s["modes"]
    rep = s.get("report", {})
    if rep.get("table_times"):
        ks = [(t, time_to_scan(times, t)) for t in rep["table_times"]]
    else:
        ks = [(times[k], k) for k in _default_scans(len(times))]
    okm = [m for m in modes if s["results"][m]["runs_ok"]] or modes
    first = s["results"][okm[0]]["per_scan"]
    rows = []
    for t, k in ks:
        if k is None:
            continue
        row = [f"{t:g}", str(int(first["n_truth_sum"][k]))]
        for m in modes:
            ok = s["results"][m]["runs_ok"] > 0
            row.append(str(int(s["results"][m]["per_scan"]["conf_true_sum"][k])) if ok else "-")
        rows.append(row)
    runs_ok = ", ".join(f"{m}: {s['results'][m]['runs_ok']}" for m in modes)
    title = (f"Confirmed true tracks, summed over runs (runs ok: {runs_ok}); "
             f"max = targets present x runs; match distance {s['metrics']['match_distance']:g}")
    return title + "\n" + _table(["time", "max"] + modes, rows)


def table_counts(s: dict) -> str:
    times = s["scan_times"]
    modes = s["modes"]
    rep = s.get("report", {})
    scans = [int(k) for k in rep["count_frames"]] if rep.get("count_frames") else _default_scans(len(times), 20)
    scans = [k for k in scans if 0 <= k < len(times)]
    header = ["scan", "time"]
    for m in modes:
        header += [f"{m} tent", f"{m} conf"]
    rows = []
    for k in scans:
        row = [str(k), f"{times[k]:g}"]
        for m in modes:
            r = s["results"][m]
            ps = r["per_scan"]
            r0 = r.get("run0")
            if not r["runs_ok"]:
                row += ["-", "-"]
                continue
            t0 = f" [{r0['tentative'][k]}]" if r0 else ""
            c0 = f" [{r0['confirmed'][k]}]" if r0 else ""
            row += [f"{ps['tentative_mean'][k]:.1f}{t0}", f"{ps['confirmed_mean'][k]:.1f}{c0}"]
        rows.append(row)
    out = ["Tentative and confirmed tracks per scan: mean over runs [run 0]", _table(header, rows)]
    for m in modes:
        if not s["results"][m]["runs_ok"]:
            out.append(f"peak {m}: no successful run")
            continue
        tt = s["results"][m]["totals"]
        p = tt["peak"]
        line = (f"peak {m}: scan {p['scan']} (t = {times[p['scan']]:g}), mean {p['tentative_mean'] + p['confirmed_mean']:.1f} "
                f"tracks ({p['confirmed_mean']:.1f} confirmed, {p['tentative_mean']:.1f} tentative)")
        if tt.get("peak_run0"):
            q = tt["peak_run0"]
            line += (f"; run 0: scan {q['scan']}, {q['tentative'] + q['confirmed']} tracks "
                     f"({q['confirmed']} confirmed, {q['tentative']} tentative)")
        out.append(line)
    return "\n".join(out)


def table_summary(s: dict) -> str:
    modes = s["modes"]
    R = {m: s["results"][m] for m in modes}
    c = s["metrics"]["gospa_c"]
    rows = [
        ["runs ok / failed"] + [f"{R[m]['runs_ok']} / {R[m]['runs_failed']}" for m in modes],
        [f"GOSPA mean per scan (p=1, a=2, c={c:g})"] + [_fmt(R[m]["totals"]["gospa_mean"]) for m in modes],
        ["  of which missed / false (mean per scan)"] + [
            f"{_fmt(_mean(R[m]['per_scan']['gospa_missed_mean']))} / {_fmt(_mean(R[m]['per_scan']['gospa_false_mean']))}"
            for m in modes],
        ["MOTA"] + [_fmt(R[m]["totals"]["mota"]) for m in modes],
        ["MOTP (mean matched distance)"] + [_fmt(R[m]["totals"]["motp"]) for m in modes],
        ["HOTA (similarity 1 - d / match distance)"] + [_fmt(R[m]["totals"].get("hota")) for m in modes],
        ["  detection DetA / association AssA"] + [
            f"{_fmt(R[m]['totals'].get('deta'))} / {_fmt(R[m]['totals'].get('assa'))}" for m in modes],
        ["  localisation LocA"] + [_fmt(R[m]["totals"].get("loca")) for m in modes],
        ["ID switches (total / per run)"] + [
            f"{R[m]['totals']['idsw']} / {_fmt(R[m]['totals']['idsw_per_run'], 2)}" for m in modes],
        ["track swaps: a track moves to another target (total / per run)"] + [
            (f"{R[m]['totals']['swaps']} / {_fmt(R[m]['totals']['swaps_per_run'], 2)}"
             if "swaps" in R[m]["totals"] else "-") for m in modes],
        ["misses FN / false FP (total)"] + [f"{R[m]['totals']['fn']} / {R[m]['totals']['fp']}" for m in modes],
        ["confirmed true / targets present"] + [_fmt(R[m]["totals"]["confirmed_true_fraction"]) for m in modes],
        ["confirmed false tracks per scan"] + [_fmt(R[m]["totals"]["confirmed_false_per_scan"]) for m in modes],
        ["position RMSE, all targets"] + [_fmt(R[m]["totals"]["rmse_all"]) for m in modes],
    ]
    if any("rmse_turn" in R[m]["totals"] for m in modes):  # scenarios with manoeuvres only
        rows.append(["  on straight legs"] + [_fmt(R[m]["totals"].get("rmse_straight")) for m in modes])
        rows.append(["  in turns"] + [_fmt(R[m]["totals"].get("rmse_turn")) for m in modes])
    if any(R[m]["totals"].get("split") for m in modes):  # scenarios with splits only (metrics.split_outcome)
        sp = {m: R[m]["totals"].get("split") or {} for m in modes}
        rows.append(["scans split -> child confirmed (median / p90)"] + [
            f"{_fmt(sp[m].get('delay_median'), 1)} / {_fmt(sp[m].get('delay_p90'), 1)}" for m in modes])
        rows.append(["  child confirmed within 3 scans (runs)"] + [_fmt(sp[m].get("within3")) for m in modes])
        rows.append(["  child never confirmed (runs)"] + [str(sp[m].get("never", "-")) for m in modes])
        rows.append(["tracks split off / false splits per run"] + [
            f"{_fmt(sp[m].get('spawned_per_run'), 2)} / {_fmt(sp[m].get('false_splits_per_run'), 2)}" for m in modes])
    tids = sorted({t for m in modes for t in R[m]["totals"]["rmse_per_target"]}, key=int)
    if len(tids) <= 16:
        for t in tids:
            rows.append([f"  RMSE target {t}"] + [_fmt(R[m]["totals"]["rmse_per_target"].get(t)) for m in modes])
    rows.append(["time per frame ms (mean / median)"] + [
        f"{_fmt(R[m]['totals']['time_per_frame_ms']['mean'])} / {_fmt(R[m]['totals']['time_per_frame_ms']['median'])}"
        for m in modes])
    return "Summary (confirmed tracks only)\n" + _table(["metric"] + modes, rows)


def _mean(v):
    v = [a for a in v if a is not None]
    return sum(v) / len(v) if v else None


def table_seeded(s: dict) -> str | None:
    modes = s["modes"]
    if not any(s["results"][m].get("seeded") for m in modes):
        return None
    rows = []
    for m in modes:
        sd = s["results"][m].get("seeded")
        if not sd:
            rows.append([m, "-", "-", "-", "-", "-"])
            continue
        r = sd["runs"]
        rows.append([m, str(r), f"{100 * sd['rate']:.1f} %", f"{100 * sd['coalescence'] / r:.1f} %",
                     f"{100 * sd['switch'] / r:.1f} %", f"{100 * sd['lost'] / r:.1f} %"])
    return ("Seeded tracks at the evaluation scan: coalescence-or-switch rate (a run counts if any seeded track "
            "is not on its own target)\n" + _table(["mode", "runs", "rate", "coalescence", "switch", "lost"], rows))


def full_report(s: dict) -> str:
    parts = [f"scenario {s['scenario']} ({s['scenario_file']}), {s['runs']} runs from seed {s['seed0']}, "
             f"modes {', '.join(s['modes'])}, {s['jobs']} jobs, {s['wall_s']:.1f} s wall"]
    for m in s["modes"]:
        for f in s["results"][m]["failures"][:3]:
            parts.append(f"FAILED {m} run {f['run']} (seed {f['seed']}): {f['error']}")
    parts += ["", table_confirmed_true(s), "", table_counts(s), "", table_summary(s)]
    sd = table_seeded(s)
    if sd:
        parts += ["", sd]
    return "\n".join(parts) + "\n"
