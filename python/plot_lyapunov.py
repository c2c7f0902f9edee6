#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Convergence of the largest Lyapunov exponent: running estimate against time.

usage: plot_lyapunov.py HISTORY.csv OUT.png [TITLE]   (an SVG is written beside the PNG)
"""
import textwrap
import sys

from plotkit import col, plt, read_rows, save, split_args


def main(argv):
    (history,), out, title = split_args(argv, __doc__, 1)
    rows = read_rows(history)
    t, est = col(rows, "t"), col(rows, "estimate")
    fig, ax = plt.subplots(figsize=(8, 4.5), constrained_layout=True)
    ax.plot(t, est, lw=1.0)
    ax.axhline(0.0, color="k", lw=0.5)
    ax.set_xlabel("time")
    ax.set_ylabel("running estimate of the largest exponent")
    ax.set_title(textwrap.fill(title, 90))  # wrapped: a long title was clipped
    ax.grid(alpha=0.3)
    save(fig, out, dpi=80, svg_dpi=80)


if __name__ == "__main__":
    main(sys.argv)
