#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Figures of docs/reports/RESULTS.md: our Monte Carlo results beside the papers' numbers.

    PYTHONPATH=python python3 -m mtt_sim.plot_papers crossing3 out/crossing3/summary.json --out docs/img/crossing3_confirmed_true.png
    PYTHONPATH=python python3 -m mtt_sim.plot_papers rates --out docs/img/coalesce3_rates.png \\
        "Sw=1e-5, 1000 runs=out/coalesce3/summary.json" "Sw=1e-4, 200 runs=out/coalesce3_q1e-4/summary.json"
    PYTHONPATH=python python3 -m mtt_sim.plot_papers rmse out/s4fig4/summary.json --out docs/img/crossing3_rmse.png

crossing3: confirmed true tracks summed over runs per mode (mc.py summary),
with [S4] Table 1's LM-IPDAF and LM-IPDAF* values as markers.

rmse: [S4] Fig. 4, the position RMSE of each target per scan (over the runs
that hold a confirmed track on it), every mode of the summary in one plot;
prints each target's RMSE over the run per mode and the largest difference
between two modes at one scan.

rates: coalescence-or-switch rate per mode, one bar per LABEL=SUMMARY
argument (an mc.py summary.json of a seeded scenario), modes in the order of
the first summary; [S1] Table 5's rates as black diamonds on the modes
they correspond to (jpda, jpda-vg, nnjpda, adaptive-nnjpda, jpda-star,
adaptive-jpda-star, adaptive-jpda).
"""
import argparse
import json

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# [S4] Table 1 (references of docs/ALGORITHMS.md), confirmed true tracks of 1500
S4_TIMES = [52, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70]
S4_LMIPDAF = [1238, 1351, 1366, 1386, 1400, 1417, 1427, 1435, 1445, 1456, 1459, 1466, 1471, 1473]
S4_STAR = [v + 1 for v in S4_LMIPDAF]  # LM-IPDAF* is higher by exactly 1 at every listed time
# [S1] Table 5, coalescence-and-switch probability (%)
S1_RATES = {"jpda": 36.0, "jpda-vg": 20.6, "nnjpda": 47.4, "adaptive-nnjpda": 12.8, "jpda-star": 13.0,
            "adaptive-jpda-star": 8.0, "adaptive-jpda": 5.1}
S1_OTHER = [("JPDA, gate changed", 20.6), ("adaptive NNJPDA", 12.8), ("adaptive JPDA*", 8.0)]


def crossing3(a) -> None:
    with open(a.summary) as f:
        s = json.load(f)
    t = s["scan_times"]
    fig, ax = plt.subplots(figsize=(8.0, 3.8), dpi=90)
    for m in s["modes"]:
        ax.plot(t, s["results"][m]["per_scan"]["conf_true_sum"], label=f"mtt {m}")
    ax.plot(S4_TIMES, S4_LMIPDAF, "kD", ms=5, mfc="none", label="S4 LM-IPDAF")
    ax.plot(S4_TIMES, S4_STAR, "k+", ms=7, label="S4 LM-IPDAF* (= LM-IPDAF + 1)")
    ax.axhline(3 * s["runs"], color="k", ls=":", lw=1)
    ax.set_xlabel("time [s]")
    ax.set_ylabel(f"confirmed true tracks (sum over {s['runs']} runs)")
    ax.set_ylim(1000, 3 * s["runs"] + 30)
    ax.set_xlim(0, t[-1] + 1)
    ax.set_title("crossing3: confirmed true tracks, beside [S4] Table 1", fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="lower left")
    fig.tight_layout()
    fig.savefig(a.out)


def rmse(a) -> None:
    with open(a.summary) as f:
        s = json.load(f)
    t, modes = s["scan_times"], s["modes"]
    styles = ["-", "--", ":", "-."]
    fig, ax = plt.subplots(figsize=(8.0, 3.8), dpi=90)
    per = {m: s["results"][m]["per_scan"]["rmse"] for m in modes}
    for k, m in enumerate(modes):
        for i, tid in enumerate(sorted(per[m])):
            ax.plot(t, per[m][tid], styles[k % len(styles)], color=f"C{i}", lw=1.2,
                    label=f"{m}, target {tid}")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("position RMSE [m]")
    ax.set_xlim(0, t[-1] + 1)
    ax.set_title(f"{s['scenario']}: position RMSE per target, {s['runs']} runs ([S4] Fig. 4)", fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, ncol=len(modes), loc="upper left")
    fig.tight_layout()
    fig.savefig(a.out)
    print("target  " + "  ".join(f"{m:>12}" for m in modes) + "  largest |difference| at one scan (m)")
    for tid in sorted(per[modes[0]]):
        tot = [s["results"][m]["totals"]["rmse_per_target"][tid] for m in modes]
        diff = max((abs(x - y) for m in modes[1:] for x, y in zip(per[modes[0]][tid], per[m][tid])
                    if x is not None and y is not None and x == x and y == y), default=float("nan"))
        print(f"{tid:>6}  " + "  ".join(f"{v:12.4f}" for v in tot) + f"  {diff:.4f}")


def rates(a) -> None:
    series = []
    for arg in a.series:
        label, _, path = arg.rpartition("=")
        with open(path) as f:
            series.append((label, json.load(f)))
    modes = series[0][1]["modes"]
    width = 0.8 / len(series)
    fig, ax = plt.subplots(figsize=(10.0, 4.6), dpi=90)
    for i, (label, s) in enumerate(series):
        xs, ys = [], []
        for k, m in enumerate(modes):
            sd = s["results"].get(m, {}).get("seeded")
            if sd:
                xs.append(k - 0.4 + width * (i + 0.5))
                ys.append(100.0 * sd["rate"])
        ax.bar(xs, ys, width, label=label)
    px = [k for k, m in enumerate(modes) if m in S1_RATES]
    ax.plot(px, [S1_RATES[modes[k]] for k in px], "kD", ms=6, label="S1 Table 5")
    ax.axhline(5.1, color="k", ls=":", lw=1)
    ax.text(-0.45, 5.6, "S1 adaptive JPDA 5.1 %", ha="left", va="bottom", fontsize=7)
    fig.text(0.01, 0.01, "S1 variants without a mode here: " + ", ".join(f"{n} {v} %" for n, v in S1_OTHER),
             fontsize=8, va="bottom")
    ax.set_xticks(range(len(modes)))
    ax.set_xticklabels(modes, rotation=35, ha="right", fontsize=8)
    ax.set_ylabel("runs with a coalescence or switch [%]")
    ax.set_title(a.title, fontsize=10)
    ax.set_ylim(0, 125)
    ax.set_yticks(range(0, 101, 20))
    ax.grid(axis="y", alpha=0.3)
    ax.legend(fontsize=8, loc="upper left", ncol=3)
    fig.tight_layout(rect=(0, 0.03, 1, 1))
    fig.savefig(a.out)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    c = sub.add_parser("crossing3", help="confirmed true tracks beside S4 Table 1")
    c.add_argument("summary")
    c.add_argument("--out", required=True)
    e = sub.add_parser("rmse", help="RMSE per target over time, every mode (S4 Fig. 4)")
    e.add_argument("summary")
    e.add_argument("--out", required=True)
    r = sub.add_parser("rates", help="coalescence-or-switch rates beside S1 Table 5")
    r.add_argument("series", nargs="+", help="LABEL=summary.json")
    r.add_argument("--out", required=True)
    r.add_argument("--title", default="coalesce3: coalescence-or-switch rate per mode, beside [S1] Table 5")
    a = ap.parse_args()
    {"crossing3": crossing3, "rmse": rmse, "rates": rates}[a.cmd](a)


if __name__ == "__main__":
    main()
