#!/usr/bin/env python3
"""Convergence of the largest Lyapunov exponent: running estimate against time.

usage: plot_lyapunov.py HISTORY.csv OUT.png [TITLE]   (an SVG is written beside the PNG)
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
    t = np.array([float(r["t"]) for r in rows])
    est = np.array([float(r["estimate"]) for r in rows])
    fig, ax = plt.subplots(figsize=(8, 4.5), constrained_layout=True)
    ax.plot(t, est, lw=1.0)
    ax.axhline(0.0, color="k", lw=0.5)
    ax.set_xlabel("time")
    ax.set_ylabel("running estimate of the largest exponent")
    ax.set_title(title)
    ax.grid(alpha=0.3)
    fig.savefig(out, dpi=80)
    fig.savefig(os.path.splitext(out)[0] + ".svg", dpi=80)


if __name__ == "__main__":
    main(sys.argv)
