# SPDX-License-Identifier: Apache-2.0
"""Stroboscopic samples and cycles (seed 002 Figs. 12-14): theta of the block at t = k T coloured by
the cycle found there, and the (theta, theta') phase portrait of each periodic segment (the whole
segment faint, its last two cycles bold, the strobe samples as dots).
Usage: plot_cycles.py STROBE.csv OUT.png --trace TRACE.csv --block B --period T [--title T]"""
import csv
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from plotkit import figure_parser, save  # noqa: E402


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return rows


def column(rows, name):
    return np.array([float(r[name]) for r in rows])


def segments(t, labels):
    """Contiguous runs of one label: [(label, t_start, t_end, first_index, last_index)]."""
    out = []
    for i, lab in enumerate(labels):
        if out and out[-1][0] == lab:
            out[-1][2] = t[i]
            out[-1][4] = i
        else:
            out.append([lab, t[i], t[i], i, i])
    return out


def main():
    ap = figure_parser()
    ap.add_argument("--trace", required=True)
    ap.add_argument("--block", type=int, default=0)
    ap.add_argument("--period", type=float, required=True)
    a = ap.parse_args()
    b = a.block
    rows = read(a.csv)
    t = column(rows, "t")
    th = column(rows, f"theta_{b}")
    om = column(rows, f"omega_{b}")
    labels = [r["cycle"] for r in rows]
    segs = segments(t, labels)
    periodic = [s for s in segs if s[0].startswith("(") and s[2] > s[1]]
    shown = sorted(sorted(periodic, key=lambda s: s[1] - s[2])[:3], key=lambda s: s[1])
    trace = read(a.trace)
    tt = column(trace, "t") if trace else np.array([])
    tth = column(trace, f"theta_{b}") if trace else np.array([])
    tom = column(trace, f"omega_{b}") if trace else np.array([])

    if not shown and len(tt):
        # No cycle: the trajectory of the last 10 periods instead.
        shown = [["last 10 periods (no cycle)", max(tt[0], tt[-1] - 10 * a.period), tt[-1], 0, 0]]
    ncol = max(1, len(shown))
    fig = plt.figure(figsize=(max(8.0, 4.0 * ncol), 7.5))
    ax = fig.add_subplot(2, 1, 1)
    names = list(dict.fromkeys(labels))
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for i, lab in enumerate(names):
        sel = np.array([x == lab for x in labels])
        ax.plot(t[sel], th[sel], ".", ms=3, color=colours[i % len(colours)] if lab != "non-periodic" else "0.5",
                label=lab or "unclassified")
    for s in segs[1:]:
        ax.axvline(s[1], color="0.6", lw=0.6, ls="--")
    ax.set_xlabel("t [s]")
    ax.set_ylabel(f"theta_{b}(k T) [rad]")
    ax.set_title((a.title + "\n" if a.title else "") + "stroboscopic samples at t = k T", fontsize=9)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), markerscale=3)
    ax.grid(alpha=0.3)
    for i, s in enumerate(shown):
        axp = fig.add_subplot(2, ncol, ncol + i + 1)
        lab, t0, t1 = s[0], s[1], s[2]
        m = re.match(r"\(([\d.]+),(\d+)\)", lab)
        n = int(m.group(2)) if m else 5
        sel = (tt >= t0) & (tt <= t1)
        axp.plot(tth[sel], tom[sel], color="0.75", lw=0.5)
        last = sel & (tt >= t1 - 2 * n * a.period)
        axp.plot(tth[last], tom[last], color="C0", lw=1.2)
        ss = (t >= t0) & (t <= t1)
        axp.plot(th[ss], om[ss], ".", color="C3", ms=4)
        axp.set_xlabel(f"theta_{b} [rad]")
        axp.set_ylabel(f"theta'_{b} [rad/s]")
        axp.set_title(f"{'cycle ' if m else ''}{lab}, {t0:.4g} <= t <= {t1:.4g} s", fontsize=9)
        axp.grid(alpha=0.3)
    fig.tight_layout()
    save(fig, a.out, dpi=120)


if __name__ == "__main__":
    main()
