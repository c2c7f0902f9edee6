#!/usr/bin/env python3
"""Poincare map through w = 0 (thesis Figs. 5.3-5.14): projections onto (y, y') and (y, w').

usage: plot_poincare.py CROSSINGS.csv OUT.png [TITLE]   (an SVG is written beside the PNG)
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main(argv):
    if len(argv) not in (3, 4):
        raise SystemExit(__doc__)
    with open(argv[1], newline="") as f:
        rows = list(csv.DictReader(f))
    out = argv[2]
    title = argv[3] if len(argv) == 4 else ""
    y = np.array([float(r["y"]) for r in rows])
    vy = np.array([float(r["vy"]) for r in rows])
    vw = np.array([float(r["vw"]) for r in rows])
    t = np.array([float(r["t"]) for r in rows])
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.8), constrained_layout=True)
    kw = dict(s=2, c=t, cmap="viridis", linewidths=0, rasterized=True)
    sc = ax[0].scatter(y, vy, **kw)
    ax[0].set_xlabel("y")
    ax[0].set_ylabel("y'")
    ax[1].scatter(y, vw, **kw)
    ax[1].set_xlabel("y")
    ax[1].set_ylabel("w'")
    if len(t):
        fig.colorbar(sc, ax=ax[1], label="time of crossing")
    fig.suptitle(f"{title}  ({len(t)} crossings)")
    fig.savefig(out, dpi=80)
    fig.savefig(os.path.splitext(out)[0] + ".svg", dpi=80)


if __name__ == "__main__":
    main(sys.argv)
