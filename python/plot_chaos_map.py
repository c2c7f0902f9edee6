# SPDX-License-Identifier: Apache-2.0
"""Chaos map over (omega, beta): the largest Lyapunov exponent / p as a colour (diverging, zero
white: blue attracting orbits, red chaos) where the motion lasted, collapse points as black
crosses, rest as grey dots, superstable (came to rest: exponent -infinity) as blue squares.
Usage: plot_chaos_map.py POINTS.csv OUT.png [--title T] [--threshold X]"""
import csv

import numpy as np  # noqa: E402
from matplotlib.colors import TwoSlopeNorm  # noqa: E402
from plotkit import cell_edges, save, figure_parser, plt  # noqa: E402


def main():
    ap = figure_parser()
    ap.add_argument("--threshold", type=float, default=0.01)
    a = ap.parse_args()
    with open(a.csv, newline="") as f:
        rows = list(csv.DictReader(f))
    omegas = sorted({float(r["omega"]) for r in rows})
    betas = sorted({float(r["beta"]) for r in rows})
    grid = np.full((len(betas), len(omegas)), np.nan)
    fig, ax = plt.subplots(figsize=(8, 5.2))
    marks = {}

    def put(x, y, label, **kw):
        marks.setdefault(label, ([], [], kw))
        marks[label][0].append(x)
        marks[label][1].append(y)

    for r in rows:
        w, b, m = float(r["omega"]), float(r["beta"]), r["motion"]
        if m in ("periodic", "neutral", "chaotic"):
            grid[betas.index(b), omegas.index(w)] = float(r["exponent_nondim"])
        elif m == "collapse":
            put(w, b, "collapse", marker="x", color="k", s=18)
        elif m == "superstable":
            put(w, b, "superstable (comes to rest)", marker="s", color="tab:blue", s=12)
        elif m == "rest":
            put(w, b, "rest", marker=".", color="0.6", s=10)
        else:
            put(w, b, "failed", marker="$?$", color="tab:red", s=20)
    finite = grid[np.isfinite(grid)]
    if finite.size:
        lo = min(float(finite.min()), -a.threshold)
        hi = max(float(finite.max()), a.threshold)
        norm = TwoSlopeNorm(vmin=lo, vcenter=0.0, vmax=hi)

        pc = ax.pcolormesh(cell_edges(omegas), cell_edges(betas), np.ma.masked_invalid(grid), cmap="RdBu_r", norm=norm,
                           shading="flat")
        cb = fig.colorbar(pc, ax=ax)
        cb.set_label("largest Lyapunov exponent / p")
    for label, (xs, ys, kw) in marks.items():
        ax.scatter(xs, ys, label=label, **kw)
    ax.set_xlabel("omega = Omega / p")
    ax.set_ylabel("beta")
    ax.set_title(a.title, fontsize=9)
    if marks:
        ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.25, 1.0))
    fig.tight_layout()
    save(fig, a.out, dpi=120)


if __name__ == "__main__":
    main()
