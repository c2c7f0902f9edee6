#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""A fragility curve (`blockdyn fragility --plot`): the fraction of records that overturned at
each intensity level (multiple stripes) and the lognormal curve fitted by maximum likelihood with
its bootstrap 90 % band.

usage: plot_fragility.py RUNS.csv OUT.png --im IM --curve "im:p:p05:p95,..." [--title T]"""
import argparse
import math

from plotkit import plt, read_rows, save  # noqa: E402

UNITS = {"pga": "PGA [g]", "pgv": "PGV [m/s]", "pga-over-uplift": "PGA / (g tan alpha)"}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("csv")
    ap.add_argument("out")
    ap.add_argument("--im", default="pga")
    ap.add_argument("--curve", default="-")
    ap.add_argument("--title", default="")
    a = ap.parse_args()
    rows = read_rows(a.csv)
    levels = {}
    for r in rows:
        if r["overturned"] == "":  # the run left the model: not in the fractions
            continue
        n, k = levels.get(float(r["level"]), (0, 0))
        levels[float(r["level"])] = (n + 1, k + (r["overturned"] == "1"))
    xs = sorted(levels)
    fig, ax = plt.subplots(figsize=(7, 4.3), constrained_layout=True)
    ax.plot(xs, [levels[x][1] / levels[x][0] for x in xs], "o", color="k", ms=5,
            label=f"fraction overturned ({levels[xs[0]][0]} records per level)")
    if a.curve not in ("-", ""):
        pts = [tuple(float(v) for v in c.split(":")) for c in a.curve.strip(",").split(",")]
        im = [p[0] for p in pts]
        ax.plot(im, [p[1] for p in pts], color="C0", label="lognormal fit (maximum likelihood)")
        lo, hi = [p[2] for p in pts], [p[3] for p in pts]
        if not any(math.isnan(v) for v in lo):
            ax.fill_between(im, lo, hi, color="C0", alpha=0.2, label="90 % bootstrap band")
    label = UNITS.get(a.im, a.im.replace("sa:", "Sa(T = ") + " s) [g]" if a.im.startswith("sa:") else a.im)
    ax.set_xlabel(label)
    ax.set_ylabel("P(overturn | IM)")
    ax.set_ylim(-0.02, 1.02)
    ax.grid(True, alpha=0.3)
    # Lower right: a fragility curve rises from the lower left to the upper right, so this corner
    # holds no stripe (upper left hid a point).
    ax.legend(fontsize=8, loc="lower right")
    if a.title:
        ax.set_title(a.title, fontsize=9)
    save(fig, a.out)


if __name__ == "__main__":
    main()
