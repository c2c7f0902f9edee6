# SPDX-License-Identifier: Apache-2.0
"""Equilibrium bifurcation diagram w vs k for one aspect ratio (thesis Figs 4.37-4.39).

Usage: plot_bifurcation.py DIAGRAM.csv OUT.png  (reads DIAGRAM.csv.json for k_os, k_uns, ...)
Left: window around k_uns, k_os (linear k); right: the requested range. Stable branches solid,
unstable dashed, w = alpha dotted. Writes OUT.png and OUT.svg.
"""
from collections import defaultdict

from plotkit import load_meta, plt, read_rows, run_in_out, save, stem


def runs(points):
    """Split (index, k, w) points into runs of consecutive k indices (a branch may vanish)."""
    out, cur = [], []
    for p in sorted(points):
        if cur and p[0] != cur[-1][0] + 1:
            out.append(cur)
            cur = []
        cur.append(p)
    if cur:
        out.append(cur)
    return out


def draw(ax, rows, meta, logx):
    groups = defaultdict(list)
    for row in rows:
        # The tilted equilibria at one k are one stable and one unstable point: stability
        # separates the two branches; the upright branch changes style at k_os.
        groups[(row["branch"], row["stable"])].append((row["index"], row["k"], row["w"]))
    for (branch, stable), pts in groups.items():
        style = "-" if stable else "--"
        for run in runs(pts):
            ks = [p[1] for p in run]
            ws = [p[2] for p in run]
            if len(run) == 1:
                ax.plot(ks, ws, "k." if stable else "kx", ms=3)
            else:
                ax.plot(ks, ws, "k" + style, lw=1.3 if stable else 1.0)
    ax.axhline(meta["alpha"], color="0.4", ls=":", lw=1.0)
    for key in ("k_os", "k_uns"):
        ax.axvline(meta[key], color="C0", lw=0.6, alpha=0.5)
    ax.plot([meta["k_uns"]], [meta["fold_w_one_corner"]], "o", color="C3", ms=4)
    if logx:
        ax.set_xscale("log")
    ax.set_xlabel("k")
    ax.set_ylabel("w")
    ax.set_ylim(-0.03 * meta["alpha"], 1.1 * meta["alpha"])


def main(csv_path, out_png):
    meta = load_meta(csv_path)
    panels = defaultdict(list)
    for row in read_rows(csv_path):
        panels[row["panel"]].append(
            {"index": int(row["index"]), "k": float(row["k"]), "w": float(row["w"]),
             "stable": row["stable"] == "1", "branch": row["branch"]})
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    draw(ax1, panels["zoom"], meta, False)
    draw(ax2, panels["range"], meta, meta["range"]["spacing"] == "log")
    r = meta["r"]
    ax1.set_title(f"r = {r:g}: k_uns = {meta['k_uns']:.4f}, k_os = {meta['k_os']:.4f}", fontsize=10)
    ax2.set_title(f"r = {r:g}", fontsize=10)
    ax2.plot([], [], "k-", label="stable")
    ax2.plot([], [], "k--", label="unstable")
    ax2.plot([], [], color="0.4", ls=":", label="w = alpha")
    ax2.plot([], [], "o", color="C3", ms=4, label="fold (k_uns)")
    ax2.legend(fontsize=8, loc="center right")
    fig.tight_layout()
    save(fig, stem(out_png) + ".png")


if __name__ == "__main__":
    run_in_out(main, __doc__)
