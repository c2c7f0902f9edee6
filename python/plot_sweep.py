# SPDX-License-Identifier: Apache-2.0
"""Plot a `blockdyn sweep` CSV: a line over one axis or a map over two axes.

Usage: plot_sweep.py SWEEP.csv OUT.png --x AXIS [--y AXIS] [--column COL] [--logx] [--logy]
                     [--where COL=VALUE ...] [--t-end T]
1-D: COL versus AXIS. For first_flight_time, points without flight are drawn at t_final with a
separate marker (as in the thesis's time-to-flight plots).
2-D: cells coloured by COL; empty cells (e.g. no flight by t_end) grey. A text column (status,
ic, a classifier's label) gives a categorical map with a legend.
--where keeps rows whose COL equals VALUE exactly (as written in the CSV).
Writes OUT.png and OUT.svg (same stem).
"""
import argparse
import math

from matplotlib.colors import BoundaryNorm, ListedColormap
from matplotlib.patches import Patch

from plotkit import cell_edges, np, plt, read_rows, save

LABELS = {"k": "k = k_phys a b / (m g)", "r": "r = b / a", "inv_r": "1/r = a / b", "mu": "mu"}


def number(text):
    try:
        v = float(text)
    except ValueError:
        return None
    return v if math.isfinite(v) else None


def short(cond):
    """'mu=0.20000000000000001' -> 'mu = 0.2' for titles."""
    col, _, val = cond.partition("=")
    v = number(val)
    return "%s = %s" % (col, ("%.6g" % v) if v is not None else val)


def filtered_rows(path, where):
    rows = read_rows(path)
    for cond in where:
        col, _, val = cond.partition("=")
        rows = [r for r in rows if r.get(col) == val]
    return rows


def is_numeric(rows, column):
    vals = [r[column] for r in rows if r[column] != ""]
    return all(number(v) is not None for v in vals)


def plot_line(ax, rows, a):
    xs = [float(r[a.x]) for r in rows]
    order = np.argsort(xs)
    if a.column == "first_flight_time":
        fx, fy, nx, ny = [], [], [], []
        for i in order:
            r = rows[i]
            if r["first_flight_time"] != "":
                fx.append(xs[i])
                fy.append(float(r["first_flight_time"]))
            else:
                nx.append(xs[i])
                ny.append(float(r["t_final"]))
        ax.plot(fx, fy, "o", ms=3, color="C0", label="first flight")
        ax.plot(nx, ny, "x", ms=4, color="C3", label="no flight (t_final)")
        ax.set_ylabel("time to first flight")
        ax.legend(loc="best", fontsize=8)
    elif is_numeric(rows, a.column):
        px = [xs[i] for i in order if rows[i][a.column] != ""]
        py = [float(rows[i][a.column]) for i in order if rows[i][a.column] != ""]
        ax.plot(px, py, "o-", ms=3, lw=0.8)
        ax.set_ylabel(a.column)
    else:
        cats = sorted({r[a.column] for r in rows})
        ax.plot([xs[i] for i in order], [cats.index(rows[i][a.column]) for i in order], "o", ms=3)
        ax.set_yticks(range(len(cats)))
        ax.set_yticklabels(cats)
        ax.set_ylabel(a.column)
    ax.set_xlabel(LABELS.get(a.x, a.x))
    if a.logx:
        ax.set_xscale("log")
    if a.logy:
        ax.set_yscale("log")
    ax.grid(True, which="both", lw=0.3, alpha=0.5)


def plot_map(fig, ax, rows, a):
    xv = sorted({float(r[a.x]) for r in rows})
    yv = sorted({float(r[a.y]) for r in rows})
    xi = {v: i for i, v in enumerate(xv)}
    yi = {v: i for i, v in enumerate(yv)}
    grid = np.full((len(yv), len(xv)), np.nan)
    numeric = is_numeric(rows, a.column)
    cats = sorted({r[a.column] for r in rows}) if not numeric else []
    for r in rows:
        v = r[a.column]
        if v == "":
            continue
        grid[yi[float(r[a.y])], xi[float(r[a.x])]] = float(v) if numeric else cats.index(v)
    masked = np.ma.masked_invalid(grid)
    xe, ye = cell_edges(xv, a.logx), cell_edges(yv, a.logy)
    if numeric:
        cmap = plt.get_cmap("viridis").copy()
        cmap.set_bad("0.8")
        mesh = ax.pcolormesh(xe, ye, masked, cmap=cmap, shading="flat")
        fig.colorbar(mesh, ax=ax, label=a.column)
    else:
        colours = plt.get_cmap("tab10").colors
        cmap = ListedColormap([colours[i % 10] for i in range(len(cats))])
        cmap.set_bad("0.8")
        norm = BoundaryNorm(np.arange(len(cats) + 1) - 0.5, len(cats))
        ax.pcolormesh(xe, ye, masked, cmap=cmap, norm=norm, shading="flat")
        ax.legend(handles=[Patch(color=cmap(i), label=c) for i, c in enumerate(cats)], fontsize=7,
                  loc="upper left", bbox_to_anchor=(1.01, 1.0), title=a.column)
    if a.logx:
        ax.set_xscale("log")
    if a.logy:
        ax.set_yscale("log")
    ax.set_xlabel(LABELS.get(a.x, a.x))
    ax.set_ylabel(LABELS.get(a.y, a.y))
    if np.isnan(grid).any():
        ax.text(0.0, -0.14, "grey: no value (e.g. no flight by t_end)", transform=ax.transAxes, fontsize=7)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("csv")
    p.add_argument("out")
    p.add_argument("--x", required=True)
    p.add_argument("--y")
    p.add_argument("--column", default="first_flight_time")
    p.add_argument("--logx", action="store_true")
    p.add_argument("--logy", action="store_true")
    p.add_argument("--where", action="append", default=[])
    p.add_argument("--t-end", dest="t_end")
    a = p.parse_args()

    rows = filtered_rows(a.csv, a.where)
    if not rows:
        raise SystemExit("plot_sweep.py: no rows to plot (after --where filters)")
    for col in [a.x, a.y, a.column]:
        if col and col not in rows[0]:
            raise SystemExit("plot_sweep.py: column '%s' is not in %s" % (col, a.csv))
    fig, ax = plt.subplots(figsize=(7.5, 5.0) if a.y else (7.0, 4.5))
    if a.y:
        plot_map(fig, ax, rows, a)
    else:
        plot_line(ax, rows, a)
    fixed = ", ".join(short(w) for w in a.where)
    title = "%s  (%s%s)" % (a.column, "t_end = %s" % a.t_end if a.t_end else "",
                            (", " + fixed) if fixed else "")
    ax.set_title(title, fontsize=9)
    fig.tight_layout()
    save(fig, a.out, dpi=150)


if __name__ == "__main__":
    main()
