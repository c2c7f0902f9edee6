# SPDX-License-Identifier: Apache-2.0
"""Overturning spectrum: the smallest overturning amplitude against the pulse duration, with the
linearised closed form for a rectangular pulse when present; with --map AMIN AMAX, the whole
overturn / survive picture of the scan over (duration, amplitude) instead (the scan's amplitudes
are geometric from AMIN to AMAX, one per character of the `scan` column).
Usage: plot_spectrum.py SPECTRUM.csv OUT.png [--title T] [--map AMIN AMAX]"""

from plotkit import cell_edges, read_rows, save, figure_parser, plt  # noqa: E402


def main():
    ap = figure_parser()
    ap.add_argument("--map", nargs=2, type=float, metavar=("AMIN", "AMAX"))
    a = ap.parse_args()
    rows = read_rows(a.csv)
    d = [float(r["duration"]) for r in rows]
    amin = [float(r["min_overturning_amplitude"]) if r["min_overturning_amplitude"] else float("nan") for r in rows]
    if a.map:
        return picture(rows, d, amin, a)
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
    save(fig, a.out, dpi=120)


def picture(rows, d, amin, a):
    import numpy as np
    from matplotlib.colors import ListedColormap
    n = len(rows[0]["scan"])
    amps = [a.map[0] * (a.map[1] / a.map[0]) ** (j / (n - 1)) for j in range(n)]
    order = sorted(range(len(d)), key=lambda i: d[i])
    z = np.array([[int(ch) for ch in rows[i]["scan"]] for i in order], dtype=float).T
    ds = [d[i] for i in order]
    fig, ax = plt.subplots(figsize=(9.5, 4.8))
    # Rasterized: 16,000 cells as SVG paths made a 3 MB file.
    ax.pcolormesh(cell_edges(ds, log=True), cell_edges(amps, log=True), z,
                  cmap=ListedColormap(["#cfe3f3", "#d9534f", "#9e9e9e"]), vmin=0, vmax=2, shading="flat",
                  rasterized=True)
    ax.plot(ds, [amin[i] for i in order], "k-", lw=1.2, label="smallest overturning amplitude (bisection)")
    if any(r["linearised_rect"] for r in rows):
        ax.plot(ds, [float(rows[i]["linearised_rect"]) if rows[i]["linearised_rect"] else float("nan")
                     for i in order], "k--", lw=1, label="linearised closed form (rect pulse)")
    from matplotlib.patches import Patch
    h, _ = ax.get_legend_handles_labels()
    h += [Patch(color="#d9534f", label="overturns"), Patch(color="#cfe3f3", label="survives")]
    if (z == 2).any():
        h.append(Patch(color="#9e9e9e", label="outside the model"))
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("pulse duration t_p [s]")
    ax.set_ylabel("amplitude [g]")
    ax.set_title(a.title, fontsize=9)
    # Beside the map: inside, it covered the overturning region it explains.
    ax.legend(handles=h, fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
    fig.tight_layout()
    save(fig, a.out, dpi=120)


if __name__ == "__main__":
    main()
