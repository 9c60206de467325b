#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Figures (matplotlib, Agg backend, PNG), and the command that replots them from a
Monte Carlo summary or draws one run's scene, model probabilities or split.

    PYTHONPATH=python python3 -m mtt_sim.plot summary out/crossing3/summary.json [--out DIR]
    PYTHONPATH=python python3 -m mtt_sim.plot scene --det D.det.csv --truth D.truth.csv --tracks D.tracks.csv \
        [--scenario scenarios/crossing3.json] [--settings D.settings.json] \
        [--scans 12 13 14 15] --out scene.png
    PYTHONPATH=python python3 -m mtt_sim.plot models --truth D.truth.csv --tracks D.tracks.csv \
        --scenario scenarios/manoeuvre.json --out models.png     # IMM: model probabilities
    PYTHONPATH=python python3 -m mtt_sim.plot split --truth D.truth.csv --tracks D.tracks.csv \
        --scenario scenarios/split_fast.json --out split.png       # split = true: P(split) over time

* :func:`scene`: one run like [S0] Fig. 4: truth trajectories, all
  detections, confirmed tracks, and zoomed panels at a few scans with each
  confirmed track's 3-sigma position gate (ellipse of P_pos + R) and the
  detections of that scan.
* :func:`curves`: metric curves from a summary: confirmed true tracks per
  scan (S4 Fig. 5), tentative and confirmed counts (S0 Fig. 5), GOSPA per
  scan, position RMSE per target (S4 Fig. 4).
"""

from __future__ import annotations

import argparse
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.patches import Ellipse, Rectangle  # noqa: E402

from . import csvio, report, scenario  # noqa: E402

__all__ = ["scene", "curves", "gate_ellipse", "plot_all", "model_probabilities", "split_probability", "main"]

_COLORS = plt.get_cmap("tab10").colors


def gate_ellipse(pxx, pxy, pyy, sx, sy, k=3.0):
    """(width, height, angle_deg) of the k-sigma ellipse of S = P_pos + diag(sx^2, sy^2)."""
    S = np.array([[pxx + sx * sx, pxy], [pxy, pyy + sy * sy]])
    w, v = np.linalg.eigh(S)
    w = np.maximum(w, 0.0)
    ang = np.degrees(np.arctan2(v[1, 1], v[0, 1]))
    return 2 * k * np.sqrt(w[1]), 2 * k * np.sqrt(w[0]), ang


def _color(tid):
    return _COLORS[int(tid) % len(_COLORS)]


def _auto_zoom(truth, k, area):
    m = truth["scan"] == k
    if not m.any():
        return [area["x"], area["y"]]
    x, y = truth["x"][m], truth["y"][m]
    span = max(x.max() - x.min(), y.max() - y.min(), 1e-9)
    pad = 0.3 * span + 0.02 * max(area["x"][1] - area["x"][0], area["y"][1] - area["y"][0])
    return [[x.min() - pad, x.max() + pad], [y.min() - pad, y.max() + pad]]


def scene(det, truth, tracks, out_png, *, area, meas_sigma, times=None, gate_scans=(), zoom=None,
          title="", units=None, sigma_k=3.0):
    """Draw the scene of one run to ``out_png`` (tables as in csvio)."""
    sx, sy = float(meas_sigma[0]), float(meas_sigma[1])
    gate_scans = [int(k) for k in gate_scans][:4]
    ncol = max(len(gate_scans), 1)
    width = max(4.2 * ncol, 8.0)
    aspect = (area["y"][1] - area["y"][0]) / (area["x"][1] - area["x"][0])
    h_main = float(np.clip(width * aspect, 2.6, 6.0)) + 0.9
    h_zoom = 3.4 if gate_scans else 0.0
    fig = plt.figure(figsize=(width, h_main + h_zoom + 0.3), dpi=110)
    gs = fig.add_gridspec(2 if gate_scans else 1, ncol, height_ratios=[h_main, h_zoom] if gate_scans else [1])
    ax = fig.add_subplot(gs[0, :])
    ax.scatter(det["x"], det["y"], s=1.5, c="0.72", marker=".", linewidths=0, label="detections", rasterized=True)
    for tid in np.unique(truth["target"]):
        m = truth["target"] == tid
        ax.plot(truth["x"][m], truth["y"][m], "-", color="k", lw=0.9, alpha=0.8)
    ax.plot([], [], "-", color="k", lw=0.9, label="truth")
    conf = tracks["confirmed"]
    for tid in np.unique(tracks["track"][conf]):
        m = conf & (tracks["track"] == tid)
        ax.plot(tracks["x"][m], tracks["y"][m], "-", color=_color(tid), lw=1.6, alpha=0.85)
    ax.plot([], [], "-", color=_color(0), lw=1.6, label="confirmed tracks")
    if zoom:
        ax.add_patch(Rectangle((zoom[0][0], zoom[1][0]), zoom[0][1] - zoom[0][0], zoom[1][1] - zoom[1][0],
                               fill=False, ls="--", lw=0.8, ec="tab:red"))
    ax.set_xlim(area["x"])
    ax.set_ylim(area["y"])
    if _aspect_ok(area):
        ax.set_aspect("equal", adjustable="box")
    u = f" [{units.get('length')}]" if units and units.get("length") else ""
    ax.set_xlabel("x" + u)
    ax.set_ylabel("y" + u)
    ax.set_title(title or "scene")
    ax.legend(loc="upper right", fontsize=7, markerscale=4)
    for i, k in enumerate(gate_scans):
        a = fig.add_subplot(gs[1, i])
        z = zoom or _auto_zoom(truth, k, area)
        md = det["scan"] == k
        a.scatter(det["x"][md], det["y"][md], s=14, c="0.4", marker="x", linewidths=0.8, label="detections")
        for tid in np.unique(truth["target"]):
            m = (truth["target"] == tid) & (truth["scan"] <= k) & (truth["scan"] >= k - 5)
            a.plot(truth["x"][m], truth["y"][m], "-", color="k", lw=0.7, alpha=0.6)
        mt = truth["scan"] == k
        a.plot(truth["x"][mt], truth["y"][mt], "+", color="k", ms=7, mew=1.2, label="targets")
        mk = tracks["scan"] == k
        for j in np.nonzero(mk)[0]:
            c = bool(tracks["confirmed"][j])
            w, h, ang = gate_ellipse(tracks["pxx"][j], tracks["pxy"][j], tracks["pyy"][j], sx, sy, sigma_k)
            col = _color(tracks["track"][j]) if c else "0.6"
            a.add_patch(Ellipse((tracks["x"][j], tracks["y"][j]), w, h, angle=ang, fill=False,
                                ec=col, lw=1.3 if c else 0.6, ls="-" if c else ":"))
            if c:
                a.plot(tracks["x"][j], tracks["y"][j], "o", color=col, ms=2.5)
        a.set_xlim(z[0])
        a.set_ylim(z[1])
        a.set_aspect("equal", adjustable="box")
        ts = f", t = {times[k]:g}" if times is not None and k < len(times) else ""
        a.set_title(f"scan {k}{ts}", fontsize=9)
        a.tick_params(labelsize=7)
    if gate_scans:
        fig.text(0.5, 0.005, f"zoom: confirmed tracks with {sigma_k:g}-sigma gates (P_pos + R), "
                 "tentative dotted grey; x = detections of the scan, + = targets", ha="center", fontsize=8)
    fig.tight_layout(rect=(0, 0.02, 1, 1))
    fig.savefig(out_png)
    plt.close(fig)


def _aspect_ok(area):
    w = area["x"][1] - area["x"][0]
    h = area["y"][1] - area["y"][0]
    return 0.05 < h / w < 20


def _arr(v):
    return np.array([np.nan if a is None else a for a in v], float)


def curves(summary: dict, out_dir: str) -> list[str]:
    """Write the metric curve PNGs; return their paths."""
    os.makedirs(out_dir, exist_ok=True)
    t = np.array(summary["scan_times"], float)
    modes = [m for m in summary["modes"] if summary["results"][m]["runs_ok"]] or summary["modes"][:1]
    R = summary["results"]
    tu = summary.get("units", {}).get("time", "")
    xl = f"time [{tu}]" if tu else "time"
    name = summary["scenario"]
    paths = []

    fig, ax = plt.subplots(figsize=(7, 4), dpi=110)
    ax.plot(t, _arr(R[modes[0]]["per_scan"]["n_truth_sum"]), "k--", lw=1, label="max (targets x runs)")
    for i, m in enumerate(modes):
        ax.plot(t, _arr(R[m]["per_scan"]["conf_true_sum"]), "-", color=_COLORS[i % 10], lw=1.4, label=m)
    ax.set_xlabel(xl)
    ax.set_ylabel("confirmed true tracks (sum over runs)")
    ax.set_title(f"{name}: confirmed true tracks, {summary['runs']} runs")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    p = os.path.join(out_dir, "confirmed_true.png")
    fig.savefig(p)
    plt.close(fig)
    paths.append(p)

    fig, axs = plt.subplots(1, 2, figsize=(11, 4), dpi=110, sharex=True)
    for i, m in enumerate(modes):
        ps = R[m]["per_scan"]
        col = _COLORS[i % 10]
        axs[0].plot(t, _arr(ps["tentative_mean"]), "-", color=col, lw=1.4, label=f"{m} mean")
        axs[1].plot(t, _arr(ps["confirmed_mean"]), "-", color=col, lw=1.4, label=f"{m} mean")
        r0 = R[m].get("run0")
        if r0:
            axs[0].step(t, r0["tentative"], where="mid", color=col, lw=0.8, ls="--", label=f"{m} run 0")
            axs[1].step(t, r0["confirmed"], where="mid", color=col, lw=0.8, ls="--", label=f"{m} run 0")
    axs[1].plot(t, _arr(R[modes[0]]["per_scan"]["n_truth_sum"]) / max(summary["runs"], 1), "k:", lw=1,
                label="targets present")
    axs[0].set_title("tentative tracks per scan")
    axs[1].set_title("confirmed tracks per scan")
    for a in axs:
        a.set_xlabel(xl)
        a.grid(alpha=0.3)
        a.legend(fontsize=7)
    fig.suptitle(f"{name}: track counts")
    fig.tight_layout()
    p = os.path.join(out_dir, "counts.png")
    fig.savefig(p)
    plt.close(fig)
    paths.append(p)

    fig, ax = plt.subplots(figsize=(7, 4), dpi=110)
    for i, m in enumerate(modes):
        ps = R[m]["per_scan"]
        col = _COLORS[i % 10]
        ax.plot(t, _arr(ps["gospa_mean"]), "-", color=col, lw=1.4, label=f"{m} GOSPA")
        ax.plot(t, _arr(ps["gospa_missed_mean"]), ":", color=col, lw=1, label=f"{m} missed part")
        ax.plot(t, _arr(ps["gospa_false_mean"]), "--", color=col, lw=1, label=f"{m} false part")
    c = summary["metrics"]["gospa_c"]
    ax.set_xlabel(xl)
    ax.set_ylabel("mean GOSPA per scan")
    ax.set_title(f"{name}: GOSPA (p = 1, alpha = 2, c = {c:g})")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    p = os.path.join(out_dir, "gospa.png")
    fig.savefig(p)
    plt.close(fig)
    paths.append(p)

    tids = sorted({k for m in modes for k in R[m]["per_scan"]["rmse"]}, key=int)
    per = tids if 0 < len(tids) <= 6 else []
    n = len(per) + 1
    ncol = min(n, 3)
    nrow = (n + ncol - 1) // ncol
    fig, axs = plt.subplots(nrow, ncol, figsize=(4.2 * ncol, 3.3 * nrow), dpi=110, squeeze=False)
    panels = [("all targets", None)] + [(f"target {k}", k) for k in per]
    for idx, (label, k) in enumerate(panels):
        a = axs[idx // ncol][idx % ncol]
        for i, m in enumerate(modes):
            ps = R[m]["per_scan"]
            y = _arr(ps["rmse_all"] if k is None else ps["rmse"].get(k, [None] * len(t)))
            a.plot(t, y, "-", color=_COLORS[i % 10], lw=1.2, label=m)
        a.set_title(f"position RMSE, {label}", fontsize=9)
        a.set_xlabel(xl)
        a.grid(alpha=0.3)
        a.legend(fontsize=7)
    for idx in range(len(panels), nrow * ncol):
        axs[idx // ncol][idx % ncol].axis("off")
    fig.suptitle(f"{name}: position RMSE of matched confirmed tracks")
    fig.tight_layout()
    p = os.path.join(out_dir, "rmse.png")
    fig.savefig(p)
    plt.close(fig)
    paths.append(p)
    return paths


def plot_all(summary: dict, base_dir: str, out_dir: str | None = None) -> list[str]:
    """Curves plus a scene per mode from ``base_dir/run0`` (as written by mc.py)."""
    out_dir = out_dir or base_dir
    paths = curves(summary, out_dir)
    name = summary["scenario"]
    run0 = os.path.join(base_dir, "run0")
    det_p = os.path.join(run0, f"{name}.det.csv")
    truth_p = os.path.join(run0, f"{name}.truth.csv")
    if not (os.path.isfile(det_p) and os.path.isfile(truth_p)):
        return paths
    if "sensor_xy" in summary:  # a radar's polar detections, shown where the user's conversion puts them
        from . import radar  # noqa: PLC0415

        det = radar.converted(csvio.read_polar_det(det_p)[0], *summary["sensor_xy"])
    else:
        det, _ = csvio.read_det(det_p)
    truth = csvio.read_truth(truth_p)
    rep = summary.get("report", {})
    for m in summary["modes"]:
        tp = os.path.join(run0, f"{name}.{m}.tracks.csv")
        if not os.path.isfile(tp):
            continue
        tracks = csvio.read_tracks(tp)
        p = os.path.join(out_dir, f"scene_{m}.png")
        scene(det, truth, tracks, p, area=summary["area"], meas_sigma=summary["meas_sigma"],
              times=summary["scan_times"], gate_scans=rep.get("gate_scans", []), zoom=rep.get("zoom"),
              title=f"{name}, run 0 (seed {summary['seed0']}), {m}", units=summary.get("units"))
        paths.append(p)
    return paths


def model_probabilities(tracks: dict, truth: dict, windows: dict, out_png: str, *, names=None,
                        match_distance: float = 75.0, title: str = ""):
    """One run of an IMM tracker: per target, the model probabilities over
    time of the confirmed track that follows it (the track nearest to the
    target in most scans, within match_distance), with the target's turn
    windows shaded (scenario manoeuvres).  ``tracks`` needs the mu columns
    (motion = imm)."""
    import matplotlib.pyplot as plt

    if "mu" not in tracks:
        raise ValueError("the tracks file has no model probabilities (motion = imm writes mu_0, mu_1, ...)")
    r = tracks["mu"].shape[1]
    names = names or [f"model {j}" for j in range(r)]
    targets = sorted(set(int(t) for t in truth["target"]))
    fig, axes = plt.subplots(len(targets), 1, figsize=(8, 1.9 * len(targets) + 0.6), sharex=True, squeeze=False)
    conf = tracks["confirmed"]
    for ax, tid in zip(axes[:, 0], targets):
        sel = truth["target"] == tid
        best = {}
        for k, x, y in zip(truth["scan"][sel], truth["x"][sel], truth["y"][sel]):
            m = conf & (tracks["scan"] == k)
            if not m.any():
                continue
            d = np.hypot(tracks["x"][m] - x, tracks["y"][m] - y)
            i = int(np.argmin(d))
            if d[i] <= match_distance:
                t = int(tracks["track"][m][i])
                best[t] = best.get(t, 0) + 1
        for a, b in windows.get(tid, []):
            ax.axvspan(a - 0.5, b + 0.5, color="0.85", lw=0)
        if best:
            t = max(best, key=best.get)
            m = conf & (tracks["track"] == t)
            for j in range(r):
                ax.plot(tracks["scan"][m], tracks["mu"][m, j], lw=1.2, label=names[j])
            ax.set_ylabel(f"target {tid}\ntrack {t}", fontsize=8)
        ax.set_ylim(-0.02, 1.02)
        ax.grid(alpha=0.3)
    axes[0, 0].legend(loc="upper right", fontsize=8, ncol=r)
    axes[-1, 0].set_xlabel("scan (grey: the target turns)")
    fig.suptitle(title or "model probabilities of the confirmed tracks", fontsize=10)
    fig.tight_layout()
    fig.savefig(out_png, dpi=110)
    plt.close(fig)
    return out_png


def split_probability(tracks: dict, truth: dict, splits, out_png: str, *, title: str = "", units=None):
    """One run with split detection (split = true): above, the x-y plane
    with the true paths and the confirmed tracks (a split-off track drawn
    from its first scan, joined by a dashed line to its parent's position
    there); below, P(split) (the tracks file's p_split) over the scans of
    every track that ever had one above 1 %, with the true split scans
    (dotted) and the decouplings (solid) marked.  ``splits``: the
    scenario's splits list."""
    import matplotlib.pyplot as plt

    if "p_split" not in tracks:
        raise ValueError("the tracks file has no p_split column (written with split = true)")
    fig, (ax, bx) = plt.subplots(2, 1, figsize=(8, 7.5), gridspec_kw={"height_ratios": [3, 2]})
    for tid in sorted(set(int(t) for t in truth["target"])):
        m = truth["target"] == tid
        ax.plot(truth["x"][m], truth["y"][m], "-", color="0.6", lw=3, alpha=0.6, zorder=1)
        ax.annotate(f"target {tid}", (truth["x"][m][-1], truth["y"][m][-1]), fontsize=7, color="0.4")
    conf = np.asarray(tracks["confirmed"], bool)
    scan = np.asarray(tracks["scan"], int)
    ids = np.asarray(tracks["track"], int)
    par = np.asarray(tracks["parent"], int)
    births = []
    order = sorted(set(ids[conf].tolist()) | set(ids[np.asarray(tracks["p_split"], float) > 0.01].tolist()))
    col = {t: _COLORS[i % len(_COLORS)] for i, t in enumerate(order)}  # distinct in this plot
    for tid in sorted(set(ids[conf].tolist())):
        m = conf & (ids == tid)
        ax.plot(tracks["x"][m], tracks["y"][m], ".-", color=col.get(tid, "k"), ms=3, lw=1, label=f"track {tid}", zorder=2)
    for tid in sorted(set(ids[par >= 0].tolist())):
        m = ids == tid
        k0 = int(scan[m].min())
        p = int(par[m][0])
        births.append((k0, tid, p))
        i = np.nonzero(m & (scan == k0))[0][0]
        j = np.nonzero((ids == p) & (scan == k0))[0]
        if len(j):
            ax.plot([tracks["x"][j[0]], tracks["x"][i]], [tracks["y"][j[0]], tracks["y"][i]], "k--", lw=1, zorder=3)
        ax.plot(tracks["x"][i], tracks["y"][i], "k*", ms=9, zorder=4)
    u = (units or {}).get("length", "")
    ax.set_xlabel(f"x {u}".strip())
    ax.set_ylabel(f"y {u}".strip())
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="best", ncol=2)
    ax.set_title("confirmed tracks (star: a track split off its parent, dashed to the parent)", fontsize=9)
    ps = np.asarray(tracks["p_split"], float)
    for tid in sorted(set(ids[ps > 0.01].tolist())):
        m = ids == tid
        bx.plot(scan[m], ps[m], ".-", color=col.get(tid, "k"), lw=1.2, ms=3, label=f"track {tid}")
    for sp in splits:
        bx.axvline(int(sp["scan"]), color="0.3", ls=":", lw=1.2)
    for k0, tid, p in births:
        bx.axvline(k0, color=col.get(tid, "k"), ls="-", lw=1)
    bx.set_ylim(-0.02, 1.02)
    bx.set_xlim(0, int(scan.max()) if len(scan) else 1)
    bx.set_xlabel("scan (dotted: the true split; solid: decoupling, a track split off)")
    bx.set_ylabel("P(split)")
    bx.grid(alpha=0.3)
    if bx.lines:
        bx.legend(fontsize=7, loc="upper left")
    fig.suptitle(title or "split probability of one run", fontsize=10)
    fig.tight_layout()
    fig.savefig(out_png, dpi=110)
    plt.close(fig)
    return out_png


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    s = sub.add_parser("summary", help="curves and run-0 scenes from summary.json")
    s.add_argument("summary")
    s.add_argument("--out", help="output directory (default: the summary's directory)")
    s.add_argument("--print", action="store_true", help="also print the tables")
    c = sub.add_parser("scene", help="scene of one run")
    c.add_argument("--det", required=True)
    c.add_argument("--truth", required=True)
    c.add_argument("--tracks", required=True)
    c.add_argument("--scenario", help="scenario JSON (area, zoom, gate scans, units)")
    c.add_argument("--settings", help="tracker settings JSON (meas_sigma for the gates)")
    c.add_argument("--scans", type=int, nargs="*", help="scans for the zoomed gate panels")
    c.add_argument("--title", default="")
    c.add_argument("--out", required=True)
    mo = sub.add_parser("models", help="IMM: model probabilities of one run over time")
    mo.add_argument("--truth", required=True)
    mo.add_argument("--tracks", required=True)
    mo.add_argument("--scenario", required=True, help="scenario JSON (turn windows, match distance)")
    mo.add_argument("--names", nargs="*", help="model names (default: imm_models of the scenario)")
    mo.add_argument("--title", default="")
    mo.add_argument("--out", required=True)
    sp = sub.add_parser("split", help="split = true: P(split) of one run over time, and the split-off tracks")
    sp.add_argument("--truth", required=True)
    sp.add_argument("--tracks", required=True)
    sp.add_argument("--scenario", required=True, help="scenario JSON (its splits, units)")
    sp.add_argument("--title", default="")
    sp.add_argument("--out", required=True)
    a = ap.parse_args(argv)
    try:
        if a.cmd == "split":
            scn = scenario.load(a.scenario)
            split_probability(csvio.read_tracks(a.tracks), csvio.read_truth(a.truth), scn.get("splits", []),
                                    a.out, title=a.title, units=scn.get("units"))
            print(a.out)
            return 0
        if a.cmd == "models":
            scn = scenario.load(a.scenario)
            models = scn["tracker"].get("imm_models") or []
            names = a.names or [f"{m['model']} (q {m['process_psd']:g})" for m in models] or None
            model_probabilities(csvio.read_tracks(a.tracks), csvio.read_truth(a.truth),
                                      scenario.manoeuvre_windows(scn), a.out, names=names,
                                      match_distance=scn.get("metrics", {}).get("match_distance", 75.0),
                                      title=a.title)
            print(a.out)
            return 0
        if a.cmd == "summary":
            with open(a.summary, encoding="utf-8") as f:
                summ = json.load(f)
            base = os.path.dirname(os.path.abspath(a.summary))
            paths = plot_all(summ, base, a.out)
            if a.print:
                sys.stdout.write(report.full_report(summ))
            print("\n".join(paths))
            return 0
        det, times_map = csvio.read_det(a.det)
        truth = csvio.read_truth(a.truth)
        tracks = csvio.read_tracks(a.tracks)
        times = [times_map[k] for k in sorted(times_map)]
        area, zoom, scans, units = None, None, a.scans, None
        sigma = [1.0, 1.0]
        if a.scenario:
            scn = scenario.load(a.scenario)
            area, units = scn["area"], scn.get("units")
            zoom = scn.get("report", {}).get("zoom")
            scans = scans if scans is not None else scn.get("report", {}).get("gate_scans", [])
            sigma = scenario.tracker_value(scn, "meas_sigma")
        if a.settings:
            with open(a.settings, encoding="utf-8") as f:
                sigma = json.load(f).get("meas_sigma", sigma)
        if area is None:
            xs = list(det["x"]) + list(truth["x"])
            ys = list(det["y"]) + list(truth["y"])
            area = {"x": [min(xs), max(xs)], "y": [min(ys), max(ys)]}
        scene(det, truth, tracks, a.out, area=area, meas_sigma=sigma, times=times,
                    gate_scans=scans or [], zoom=zoom, title=a.title or os.path.basename(a.tracks), units=units)
        print(a.out)
        return 0
    except (OSError, ValueError, KeyError) as e:
        print(f"plot.py: {e}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
