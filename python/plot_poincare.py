#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Poincare map through w = 0 (thesis Figs. 5.3-5.14): projections onto (y, y') and (y, w').

usage: plot_poincare.py CROSSINGS.csv OUT.png [TITLE]   (an SVG is written beside the PNG)
"""
import sys

from plotkit import col, plt, read_rows, save, split_args


def main(argv):
    (crossings,), out, title = split_args(argv, __doc__, 1)
    rows = read_rows(crossings)
    y, vy, vw, t = (col(rows, name) for name in ("y", "vy", "vw", "t"))
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
    save(fig, out, dpi=80, svg_dpi=80)


if __name__ == "__main__":
    main(sys.argv)
