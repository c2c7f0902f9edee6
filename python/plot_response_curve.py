# SPDX-License-Identifier: Apache-2.0
"""theta_MAX / alpha versus omega, one curve per beta (collapsed points marked), and the largest
slip between blocks over b when any. Usage: plot_response_curve.py POINTS.csv OUT.png [--title T]"""
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
    betas = sorted({float(r["beta"]) for r in rows})
    sliding = any(float(r["max_sliding_over_b"]) > 0 for r in rows)
    fig, axes = plt.subplots(2 if sliding else 1, 1, figsize=(8, 7 if sliding else 4.5), sharex=True, squeeze=False)
    ax = axes[0][0]
    for b in betas:
        rs = [r for r in rows if float(r["beta"]) == b]
        w = [float(r["omega"]) for r in rs]
        th = [float(r["theta_max_over_alpha"]) for r in rs]
        line, = ax.plot(w, th, "o-", ms=3, label=f"beta = {b:g}")
        col = [(x, y) for x, y, r in zip(w, th, rs) if r["motion"] == "collapse"]
        if col:
            ax.plot(*zip(*col), "x", color=line.get_color(), ms=8)
        if sliding:
            axes[1][0].plot(w, [float(r["max_sliding_over_b"]) for r in rs], "o-", ms=3, color=line.get_color())
    ax.axhline(1.0, color="0.5", lw=0.8, ls="--")
    ax.set_ylabel("theta_MAX / alpha (x: collapsed)")
    ax.set_title(a.title, fontsize=9)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    ax.grid(alpha=0.3)
    if sliding:
        axes[1][0].set_ylabel("max slip between blocks / b")
        axes[1][0].grid(alpha=0.3)
    axes[-1][0].set_xlabel("omega = Omega / p")
    fig.tight_layout()
    fig.savefig(a.out, dpi=120)
    fig.savefig(os.path.splitext(a.out)[0] + ".svg")


if __name__ == "__main__":
    main()
