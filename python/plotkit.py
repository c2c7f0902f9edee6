# SPDX-License-Identifier: Apache-2.0
"""Shared helpers for the blockdyn plotting scripts (python/plot_*.py).

Importing this module selects the non-interactive Agg backend; the scripts take `plt` and `np`
from here. Every plot is written as OUT.png plus an SVG with the same stem (see `save`).
"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402,F401
import numpy as np  # noqa: E402

__all__ = ["plt", "np", "figure_parser", "read_rows", "load_meta", "load_table", "load_columns", "load_named", "col",
           "save", "stem", "split_args", "run_in_out", "run_modes", "t_end", "run_title", "k_scan_figure",
           "finish_k_scan", "log_axes", "read_table", "Cli", "legend_outside",
           "legend_below"]


def figure_parser():
    """The arguments every figure script takes: the table it draws (CSV), the figure (OUT.png) and
    --title; a script adds its own."""
    import argparse
    ap = argparse.ArgumentParser()
    ap.add_argument("csv")
    ap.add_argument("out")
    ap.add_argument("--title", default="")
    return ap


# ----------------------------------------------------------------------------- loading

def read_rows(path):
    """All rows of a CSV file as dicts (column name -> text)."""
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def cell_edges(centres, log=False):
    """Cell edges around sorted centres, for pcolormesh: half-way between neighbours (geometric
    means on a log axis), the outer cells as wide as their neighbours; a single centre gets a cell
    one unit wide (a decade on a log axis)."""
    c = np.log10(np.asarray(centres, dtype=float)) if log else np.asarray(centres, dtype=float)
    if c.size == 1:
        e = np.array([c[0] - 0.5, c[0] + 0.5])
    else:
        mid = 0.5 * (c[1:] + c[:-1])
        e = np.concatenate([[2 * c[0] - mid[0]], mid, [2 * c[-1] - mid[-1]]])
    return 10.0 ** e if log else e


def shade_runs(ax, t, labels, colours):
    """Shade the time axis by label: one span per run of equal labels, coloured from `colours`."""
    start = 0
    for i in range(1, len(t) + 1):
        if i == len(t) or labels[i] != labels[start]:
            ax.axvspan(t[start], t[min(i, len(t) - 1)], color=colours.get(labels[start], "white"), lw=0, zorder=0)
            start = i


def load_meta(path):
    """The JSON sidecar PATH.json written beside a CSV table."""
    with open(path + ".json") as f:
        return json.load(f)


def load_table(path):
    """(rows, meta): the CSV rows (at least one, else exit) and its JSON sidecar ({} if absent)."""
    rows = read_rows(path)
    if not rows:
        raise SystemExit(f"{path}: no rows")
    meta = load_meta(path) if os.path.exists(path + ".json") else {}
    return rows, meta


def load_columns(path, skip=()):
    """{column: float array} for every column not in `skip`; {} for a table without rows."""
    rows = read_rows(path)
    if not rows:
        return {}
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0] if k not in skip}


def load_named(path):
    """A numeric CSV as a (at least 1-D) numpy record array indexed by column name."""
    return np.atleast_1d(np.genfromtxt(path, delimiter=",", names=True))


def col(rows, name):
    """Column `name` of dict rows as a float array."""
    return np.array([float(r[name]) for r in rows])


def read_table(path):
    """{column: array} of a CSV: float arrays where every cell parses (empty cells -> nan),
    object (text) arrays otherwise (e.g. `mode`, `event`)."""
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader, [])
        columns = list(zip(*reader)) or [()] * len(header)
    out = {}
    for name, cells in zip(header, columns):
        try:
            out[name] = np.array([float(c) if c != "" else np.nan for c in cells])
        except ValueError:
            out[name] = np.array(cells, dtype=object)
    return out


class Cli:
    """Runs the blockdyn program for the figure scripts (python/fig_*.py): `cli(*args)` returns
    stdout, exits with the command and its stderr if it fails; `cli.json(*args)` parses stdout."""

    def __init__(self, program):
        self.program = program

    def __call__(self, *args):
        import subprocess
        r = subprocess.run([self.program, *map(str, args)], capture_output=True, text=True)
        if r.returncode != 0:
            raise SystemExit(f"blockdyn {' '.join(map(str, args))}: {r.stderr.strip()}")
        return r.stdout

    def json(self, *args):
        return json.loads(self(*args))

    def summary(self, script, key, rows):
        """The JSON summary a figure script prints: schema, the program's version, and `rows`."""
        return json.dumps({"schema": f"blockdyn.{script}.summary/1", "program": self("--version").strip(),
                           key: rows}, indent=1)


# ----------------------------------------------------------------------------- output

def stem(out):
    """OUT.png -> OUT."""
    return os.path.splitext(out)[0]


def plot_in_power_of_ten(ax, t, y, name, unit, **style):
    """Plots y scaled by its power of ten and puts that power into the axis label (as matplotlib's
    offset text it sat above the axes, over a legend or the panel above)."""
    top = float(np.nanmax(np.abs(y))) if len(y) else 0.0
    e10 = int(np.floor(np.log10(top))) if top > 0 and np.isfinite(top) else 0
    ax.plot(t, y / 10.0**e10, **style)
    ax.set_ylabel(f"{name} [1e{e10} {unit}]" if e10 else f"{name} [{unit}]", fontsize=8)


def thin_crowded_ticks(fig, dpi):
    """Fewer ticks on any linear x axis whose tick labels touch (long labels such as -0.0105 on a
    narrow panel ran into each other)."""
    from matplotlib.ticker import MaxNLocator

    fig.set_dpi(dpi)
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    for ax in fig.axes:
        axis = ax.xaxis
        if axis.get_scale() != "linear":
            continue
        for _ in range(3):
            boxes = [t.get_window_extent(renderer).expanded(1.1, 1.0) for t in axis.get_ticklabels()
                     if t.get_visible() and t.get_text()]
            if not any(a.overlaps(b) for a, b in zip(boxes, boxes[1:])):
                break
            axis.set_major_locator(MaxNLocator(max(2, len(boxes) // 2)))
            fig.canvas.draw()


def save(fig, out, dpi=110, svg_dpi=None):
    """Write `fig` to `out` (raster, `dpi`) and to the SVG with the same stem, then close it.

    The canvas is fitted to what is drawn (a tight bounding box): a legend placed beside the axes
    is not cut off at the figure's edge."""
    whole = {"bbox_inches": "tight", "pad_inches": 0.05}
    thin_crowded_ticks(fig, dpi)
    fig.savefig(out, dpi=dpi, **whole)
    if svg_dpi is None:
        fig.savefig(stem(out) + ".svg", **whole)
    else:
        fig.savefig(stem(out) + ".svg", dpi=svg_dpi, **whole)
    plt.close(fig)


# ----------------------------------------------------------------------------- arguments

def split_args(argv, doc, n_inputs):
    """argv = [script, IN_1 .. IN_n, OUT.png, [TITLE]] -> ([IN_1 .. IN_n], OUT.png, TITLE or "").

    Any other argument count exits with the usage text `doc`."""
    if len(argv) not in (n_inputs + 2, n_inputs + 3):
        raise SystemExit(doc)
    title = argv[n_inputs + 2] if len(argv) == n_inputs + 3 else ""
    return argv[1:n_inputs + 1], argv[n_inputs + 1], title


def figure_script_args(argv, doc):
    """argv = [script, BLOCKDYN, OUTDIR, [--tiny]] -> (Cli(BLOCKDYN), OUTDIR (created), tiny).

    The calling convention of the fig_*.py scripts; any other form exits with the usage `doc`."""
    if len(argv) not in (3, 4) or (len(argv) == 4 and argv[3] != "--tiny"):
        raise SystemExit(doc)
    os.makedirs(argv[2], exist_ok=True)
    return Cli(argv[1]), argv[2], len(argv) == 4


def run_in_out(main, doc):
    """Call main(TABLE.csv, OUT.png) from the command line; exit with `doc` on a wrong count."""
    if len(sys.argv) != 3:
        sys.exit(doc)
    main(sys.argv[1], sys.argv[2])


def run_modes(argv, doc, modes):
    """argv = [script, TABLE.csv, OUT.png, MODE]: call modes[MODE](rows, meta, OUT.png)."""
    if len(argv) != 4:
        raise SystemExit(doc)
    rows, meta = load_table(argv[1])
    if argv[3] not in modes:
        raise SystemExit(f"unknown mode {argv[3]!r}; one of {sorted(modes)}")
    modes[argv[3]](rows, meta, argv[2])


# ----------------------------------------------------------------------------- styling

def t_end(meta):
    """t_end of the run options recorded in a sidecar ('?' if absent)."""
    return meta.get("run_options", {}).get("t_end", "?")


def run_title(meta):
    """'IC: r = R, mu = MU, t_end = T' from a sidecar (for the k-scan plots)."""
    return (f"{meta.get('ic', '')}: r = {meta.get('r', '?')}, mu = {meta.get('mu', '?')}, "
            f"t_end = {t_end(meta)}")


def k_scan_figure():
    """Two stacked panels sharing a k axis: (fig, (top, bottom)) for the k-scan plots."""
    return plt.subplots(2, 1, sharex=True, figsize=(9, 5.5), constrained_layout=True)


def finish_k_scan(fig, axes, meta, out, top_label, bottom_label, what):
    """Label a `k_scan_figure` (log k, the legend outside the data, a title saying `what` is shown
    for which run), then `save` it."""
    top, bottom = axes
    top.set_xscale("log")
    top.set_ylabel(top_label)
    legend_outside(top)
    fig.suptitle(f"{what} versus k - {run_title(meta)}", fontsize=10)
    bottom.set_ylabel(bottom_label)
    bottom.set_xlabel("k")
    save(fig, out)


def legend_outside(ax, **kw):
    """A legend to the right of the axes, outside the data (the figure needs constrained layout)."""
    kw.setdefault("fontsize", 8)
    return ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0, **kw)


def legend_below(fig, handles, ncol=2, height=0.07):
    """A figure legend in a band of `height` (figure fraction) below the axes, which constrained
    layout keeps clear."""
    fig.get_layout_engine().set(rect=(0.0, height, 1.0, 1.0 - height))
    return fig.legend(handles=handles, loc="lower center", ncol=ncol, fontsize=8, frameon=False)


def log_axes(ax, xlabel, ylabel):
    """Log-log axes with labels and a light grid on major and minor ticks."""
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(True, which="both", lw=0.3)
