#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The rocking spectrum of `blockdyn rocking-spectrum`: theta_max / alpha versus the frequency
parameter p (one curve per record scale), overturned points at the top.

usage: plot_rocking_spectrum.py TABLE.csv OUT.png [--alpha A]"""
import argparse

from plotkit import legend_outside, plt, read_rows, save  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("table")
    ap.add_argument("out")
    ap.add_argument("--alpha", type=float, default=None)
    ap.add_argument("--title", default="")
    a = ap.parse_args()
    rows = read_rows(a.table)
    fig, ax = plt.subplots(figsize=(7, 4.2))
    scales = sorted({float(r["scale"]) for r in rows})
    for k, s in enumerate(scales):
        pts = sorted((float(r["p"]), float(r["max_abs_rotation_over_alpha"]), r["overturned"] == "1")
                     for r in rows if float(r["scale"]) == s)
        label = f"scale {s:g}" if len(scales) > 1 else "record"
        line, = ax.plot([p for p, _, o in pts if not o], [m for _, m, o in pts if not o], "o-", ms=3, label=label)
        over = [p for p, _, o in pts if o]
        if over:  # overturned: a cross per scale in its colour, above the axis' 1
            ax.plot(over, [1.03 + 0.03 * k] * len(over), "x", color=line.get_color(), ms=5)
    ax.axhline(1.0, color="0.5", lw=0.6)
    ax.text(0.01, 0.98, "x: overturned", transform=ax.transAxes, va="top", fontsize=8)
    ax.set_xscale("log")
    ax.set_ylim(0, 1.06 + 0.03 * len(scales))
    ax.set_xlabel("p [rad/s]  (larger blocks to the left)")
    ax.set_ylabel(r"$\theta_{max} / \alpha$")
    title = "rocking spectrum: " + a.title if a.title else "rocking spectrum" + (f", alpha = {a.alpha:.4g} rad" if a.alpha else "")
    ax.set_title(title)
    ax.grid(True, alpha=0.3)
    legend_outside(ax)
    save(fig, a.out)


if __name__ == "__main__":
    main()
