#!/usr/bin/env python3
"""Plots of the flight studies written by `blockdyn flight-time | flight-boundary | kmin | flight-map`.

usage: plot_flight.py TABLE.csv OUT.png MODE     MODE: time | boundary | kmin | map
The CSV's JSON sidecar (TABLE.csv.json) supplies the parameters for the title.
An SVG with the same stem is written beside the PNG.
"""
import csv
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def load(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise SystemExit(f"{path}: no rows")
    meta = {}
    if os.path.exists(path + ".json"):
        with open(path + ".json") as f:
            meta = json.load(f)
    return rows, meta


def col(rows, name):
    return np.array([float(r[name]) for r in rows])


def save(fig, out):
    fig.savefig(out, dpi=110)
    fig.savefig(os.path.splitext(out)[0] + ".svg")
    plt.close(fig)


def plot_time(rows, meta, out):
    k, t, ihor = col(rows, "k"), col(rows, "time"), col(rows, "ihor")
    flew = col(rows, "flew") > 0.5
    status = np.array([r["status"] for r in rows])
    groups = [(flew, ".", "first flight"),
              (~flew & (status == "overturned"), "v", "overturned, no flight (plotted at t_end)"),
              (~flew & (status != "overturned"), "x", "no flight by t_end")]
    fig, (a, b) = plt.subplots(2, 1, sharex=True, figsize=(7, 5.5), constrained_layout=True)
    for sel, style, label in groups:
        if sel.any():
            a.plot(k[sel], t[sel], style, ms=4, color="k" if style == "." else "0.55", label=label)
            b.plot(k[sel], ihor[sel], style, ms=4, color="k" if style == "." else "0.55")
    a.set_xscale("log")
    a.set_ylabel("time to first flight")
    a.legend(fontsize=8, loc="best")
    a.set_title(f"{meta.get('ic', '')}: r = {meta.get('r', '?')}, mu = {meta.get('mu', '?')}, "
                f"t_end = {meta.get('run_options', {}).get('t_end', '?')}")
    b.set_ylabel("ihor at first flight\n(at the end if none)")
    b.set_xlabel("k")
    save(fig, out)


def plot_boundary(rows, meta, out):
    r = col(rows, "r")
    fig, ax = plt.subplots(figsize=(7, 5), constrained_layout=True)
    styles = ["-", "--", "-.", ":"]
    names = [c for c in rows[0].keys() if c.startswith("k_") and not c.endswith("_status")]
    for i, name in enumerate(names):
        v = col(rows, name)
        ok = np.isfinite(v)
        if not ok.any():
            continue
        ax.plot(r[ok], v[ok], styles[i % len(styles)], marker="o", ms=3, label=name)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("r")
    ax.set_ylabel("k")
    ax.legend(fontsize=8)
    ax.grid(True, which="both", lw=0.3)
    ax.set_title(f"flight boundaries, {meta.get('ic', '')}, mu = {meta.get('mu', '?')}")
    save(fig, out)


def plot_kmin(rows, meta, out):
    r = col(rows, "r")
    fig, ax = plt.subplots(figsize=(6.5, 4.5), constrained_layout=True)
    for name in [c for c in rows[0].keys() if c.startswith("k_min_")]:
        v = col(rows, name)
        ok = np.isfinite(v)
        ax.plot(r[ok], v[ok], label=name[len("k_min_"):])
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("r")
    ax.set_ylabel("k_min (E0 = 0)")
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=8)
    ax.set_title(f"energy lower bound of the flight region, mu = {meta.get('mu', '?')}")
    save(fig, out)


def plot_map(rows, meta, out):
    r, k, t = col(rows, "r"), col(rows, "k"), col(rows, "time")
    rs, ks = np.unique(r), np.unique(k)
    grid = np.full((len(rs), len(ks)), np.nan)
    ir = {v: i for i, v in enumerate(rs)}
    ik = {v: i for i, v in enumerate(ks)}
    for a, b, c in zip(r, k, t):
        grid[ir[a], ik[b]] = c

    def edges(v):
        lv = np.log(v)
        mid = 0.5 * (lv[1:] + lv[:-1])
        return np.exp(np.concatenate([[lv[0] - (mid[0] - lv[0])], mid, [lv[-1] + (lv[-1] - mid[-1])]]))

    fig, ax = plt.subplots(figsize=(7, 5), constrained_layout=True)
    m = ax.pcolormesh(edges(ks), edges(rs), grid, cmap="gray_r", shading="flat", rasterized=True)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("k")
    ax.set_ylabel("r")
    fig.colorbar(m, ax=ax, label="time to first flight (t_end: no flight)")
    ax.set_title(f"time to first flight, {meta.get('ic', '')}, mu = {meta.get('mu', '?')} (darker: later)")
    save(fig, out)


def main(argv):
    if len(argv) != 4:
        raise SystemExit(__doc__)
    rows, meta = load(argv[1])
    modes = {"time": plot_time, "boundary": plot_boundary, "kmin": plot_kmin, "map": plot_map}
    if argv[3] not in modes:
        raise SystemExit(f"unknown mode {argv[3]!r}; one of {sorted(modes)}")
    modes[argv[3]](rows, meta, argv[2])


if __name__ == "__main__":
    main(sys.argv)
