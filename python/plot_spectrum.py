# SPDX-License-Identifier: Apache-2.0
"""Overturning spectrum: the smallest overturning amplitude against the pulse duration, with the
linearised closed form for a rectangular pulse when present.
Usage: plot_spectrum.py SPECTRUM.csv OUT.png [--title T]"""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("csv")
    ap.add_argument("out")
    ap.add_argument("--title", default="")
    a = ap.parse_args()
    with open(a.csv, newline="") as f:
        rows = list(csv.DictReader(f))
    d = [float(r["duration"]) for r in rows]
    amin = [float(r["min_overturning_amplitude"]) if r["min_overturning_amplitude"] else float("nan") for r in rows]
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.plot(d, amin, "o-", ms=3, label="blockdyn: smallest overturning amplitude")
    if any(r["linearised_rect"] for r in rows):
        lin = [float(r["linearised_rect"]) if r["linearised_rect"] else float("nan") for r in rows]
        ax.plot(d, lin, "--", label="linearised closed form (rect pulse)")
    isl = [x for x, r in zip(d, rows) if int(r["safe_islands"]) > 0]
    if isl:
        ax.plot(isl, [amin[d.index(x)] for x in isl], "^", color="tab:green", ms=6,
                label="safe islands above the minimum")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("pulse duration t_p [s]")
    ax.set_ylabel("amplitude [g]")
    ax.set_title(a.title, fontsize=9)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8, loc="upper right")
    fig.tight_layout()
    fig.savefig(a.out, dpi=120)
    fig.savefig(os.path.splitext(a.out)[0] + ".svg")


if __name__ == "__main__":
    main()
