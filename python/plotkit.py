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

__all__ = ["plt", "np", "read_rows", "load_meta", "load_table", "load_columns", "load_named", "col",
           "save", "stem", "split_args", "run_in_out", "run_modes", "t_end", "run_title", "k_scan_figure",
           "finish_k_scan", "log_axes"]


# ----------------------------------------------------------------------------- loading

def read_rows(path):
    """All rows of a CSV file as dicts (column name -> text)."""
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


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


# ----------------------------------------------------------------------------- output

def stem(out):
    """OUT.png -> OUT."""
    return os.path.splitext(out)[0]


def save(fig, out, dpi=110, svg_dpi=None):
    """Write `fig` to `out` (raster, `dpi`) and to the SVG with the same stem, then close it."""
    fig.savefig(out, dpi=dpi)
    if svg_dpi is None:
        fig.savefig(stem(out) + ".svg")
    else:
        fig.savefig(stem(out) + ".svg", dpi=svg_dpi)
    plt.close(fig)


# ----------------------------------------------------------------------------- arguments

def split_args(argv, doc, n_inputs):
    """argv = [script, IN_1 .. IN_n, OUT.png, [TITLE]] -> ([IN_1 .. IN_n], OUT.png, TITLE or "").

    Any other argument count exits with the usage text `doc`."""
    if len(argv) not in (n_inputs + 2, n_inputs + 3):
        raise SystemExit(doc)
    title = argv[n_inputs + 2] if len(argv) == n_inputs + 3 else ""
    return argv[1:n_inputs + 1], argv[n_inputs + 1], title


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
    return plt.subplots(2, 1, sharex=True, figsize=(7, 5.5), constrained_layout=True)


def finish_k_scan(fig, axes, meta, out, top_label, bottom_label):
    """Label a `k_scan_figure` (log k, legend and run title on top), then `save` it."""
    top, bottom = axes
    top.set_xscale("log")
    top.set_ylabel(top_label)
    top.legend(fontsize=8, loc="best")
    top.set_title(run_title(meta))
    bottom.set_ylabel(bottom_label)
    bottom.set_xlabel("k")
    save(fig, out)


def log_axes(ax, xlabel, ylabel):
    """Log-log axes with labels and a light grid on major and minor ticks."""
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(True, which="both", lw=0.3)
