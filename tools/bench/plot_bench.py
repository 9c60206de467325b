#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Tables and the cost-against-load plot of tools/bench/bench.sh (docs/PERFORMANCE.md).

usage: tools/bench/plot_bench.py OUT_DIR

Reads OUT_DIR/wall.json (mtt-bench --json) and OUT_DIR/instructions.tsv
(mode, workload, Ir per frame of mtt_tracker_step, Ir per frame of the
floor), writes OUT_DIR/bench.md and OUT_DIR/cost_vs_n.png, and prints the
tables and the check of the issue's targets.
"""
import json
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def load(out):
    wall = json.loads((out / "wall.json").read_text())["results"]
    ins = {}
    for line in (out / "instructions.tsv").read_text().splitlines():
        mode, work, step, fl = line.split("\t")
        key = work if work == "formations" else f"dense-{work}"
        ins[(mode, key)] = (float(step), float(fl))
    return wall, ins


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    out = Path(sys.argv[1])
    wall, ins = load(out)
    modes = list(dict.fromkeys(r["mode"] for r in wall))
    works = list(dict.fromkeys("formations" if r["workload"].startswith("scan-") else r["workload"]
                               for r in wall))
    byk = {}
    for r in wall:
        w = "formations" if r["workload"].startswith("scan-") else r["workload"]
        byk[(r["mode"], w)] = r
    dense_n = [int(w.split("-")[1]) for w in works if w.startswith("dense-")]

    lines = []
    lines.append("### Wall time per frame (median and worst over the timed frames; us)\n")
    lines.append("| workload | mode | tracks | pairs | median | worst | floor | ratio | ns/(track+pair) |")
    lines.append("|---|---|---|---|---|---|---|---|---|")
    for w in works:
        for m in modes:
            r = byk.get((m, w))
            if r:
                lines.append(f"| {w} | {m} | {r['tracks']:.1f} | {r['pairs']:.1f} | {r['median_us']:.2f} | "
                             f"{r['worst_us']:.1f} | {r['floor_median_us']:.2f} | {r['ratio_to_floor']:.2f}x | "
                             f"{r['ns_per_track_plus_pair']:.0f} |")
    lines.append("\n### Instructions per frame (callgrind; repeatable)\n")
    lines.append("| mode | " + " | ".join(works) + " |")
    lines.append("|---|" + "---|" * len(works))
    for m in modes:
        cells = []
        for w in works:
            v = ins.get((m, w))
            r = byk.get((m, w))
            if v and r:
                per = v[0] / max(r["tracks"] + r["pairs"], 1e-9)
                cells.append(f"{v[0]:,.0f} ({v[0] / v[1]:.2f}x floor, {per:.0f}/(t+p))")
            else:
                cells.append("-")
        lines.append(f"| {m} | " + " | ".join(cells) + " |")
    fl = [f"{w}: {ins[(modes[0], w)][1]:,.0f}" for w in works if (modes[0], w) in ins]
    lines.append("\nFloor (Kalman predict + one-measurement update per track), instructions per frame: "
                 + ", ".join(fl) + ".\n")

    # targets
    t = []
    m0 = "lm-ihpda"
    if (m0, "formations") in ins:
        s, f = ins[(m0, "formations")]
        r = byk[(m0, "formations")]
        t.append(f"- lm-ihpda at the formations peak ({r['workload']}, {r['tracks']:.0f} tracks): "
                 f"{s / f:.2f}x the floor in instructions, {r['ratio_to_floor']:.2f}x in wall time "
                 f"(target <= 3x): {'met' if s / f <= 3 and r['ratio_to_floor'] <= 3 else 'MISSED'}")
    if dense_n:
        lo, hi = f"dense-{min(dense_n)}", f"dense-{max(dense_n)}"
        def per_ir(w):
            return ins[(m0, w)][0] / (byk[(m0, w)]["tracks"] + byk[(m0, w)]["pairs"])
        pi = [per_ir(f"dense-{n}") for n in dense_n]
        pw = [byk[(m0, f"dense-{n}")]["ns_per_track_plus_pair"] for n in dense_n]
        gi, gw = max(pi) / min(pi), max(pw) / min(pw)
        t.append(f"- lm-ihpda cost per (track + pair), N = {min(dense_n)}..{max(dense_n)}: "
                 f"instructions {', '.join(f'{v:.0f}' for v in pi)} (spread {gi:.2f}x); "
                 f"wall ns {', '.join(f'{v:.0f}' for v in pw)} (spread {gw:.2f}x) (target within 1.5x): "
                 f"{'met' if gi <= 1.5 else 'MISSED'} in instructions, {'met' if gw <= 1.5 else 'missed'} in wall time")
        for other in ("ihpda-2d", "jipda"):
            if (other, lo) not in ins:
                continue
            rows = []
            ok_i = ok_w = True
            for n in dense_n:
                if n < 16:
                    continue
                w = f"dense-{n}"
                a, b = ins[(m0, w)][0], ins[(other, w)][0]
                aw, bw = byk[(m0, w)]["median_us"], byk[(other, w)]["median_us"]
                ok_i &= a < b
                ok_w &= aw < bw
                rows.append(f"N={n}: {a:,.0f} vs {b:,.0f} Ir, {aw:.1f} vs {bw:.1f} us")
            t.append(f"- lm-ihpda faster than {other} at every N >= 16 ({'; '.join(rows)}): "
                     f"{'met' if ok_i else 'MISSED'} in instructions, {'met' if ok_w else 'missed'} in wall time")
    lines.append("### Targets\n")
    lines.extend(t)
    text = "\n".join(lines) + "\n"
    (out / "bench.md").write_text(text)
    print(text)

    fig, ax = plt.subplots(1, 2, figsize=(12, 5))
    cmap = plt.get_cmap("tab20")
    markers = "osD^v<>phX*d"
    xs = dense_n
    for idx, m in enumerate(modes):
        ok = [n for n in xs if (m, f"dense-{n}") in byk and (m, f"dense-{n}") in ins]
        per = [ins[(m, f"dense-{n}")][0] / (byk[(m, f"dense-{n}")]["tracks"] + byk[(m, f"dense-{n}")]["pairs"])
               for n in ok]
        style = dict(color="k", lw=2.2, zorder=4) if m == m0 else dict(color=cmap(idx % 20), lw=1.1, zorder=3)
        ax[0].plot(ok, per, marker=markers[idx % len(markers)], label=m, **style)
        ax[1].plot(ok, [byk[(m, f"dense-{n}")]["median_us"] for n in ok], marker=markers[idx % len(markers)],
                   label=m, **style)
    ax[0].plot(xs, [ins[(modes[0], f"dense-{n}")][1] / (byk[(modes[0], f"dense-{n}")]["tracks"]
                                                       + byk[(modes[0], f"dense-{n}")]["pairs"]) for n in xs],
               ls="--", color="grey", label="floor (Kalman only)")
    ax[1].plot(xs, [byk[(modes[0], f"dense-{n}")]["floor_median_us"] for n in xs], ls="--", color="grey",
               label="floor (Kalman only)")
    ax[0].set_title("instructions per (track + gated pair), callgrind")
    ax[0].set_ylabel("instructions")
    ax[0].set_ylim(bottom=0)
    ax[1].set_title("median wall time per frame")
    ax[1].set_ylabel("us")
    ax[1].set_yscale("log")
    for a_ in ax:
        a_.set_xscale("log", base=2)
        a_.set_xlabel("targets N (2 clutter points per target per frame)")
        a_.grid(True, which="both", alpha=0.3)
    ax[0].legend(fontsize=7, ncol=3, loc="lower right")
    fig.suptitle("mtt: per-frame cost against load, every association mode (tools/bench/bench.sh)")
    fig.tight_layout()
    fig.savefig(out / "cost_vs_n.png", dpi=90)
    print(f"plot: {out / 'cost_vs_n.png'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
