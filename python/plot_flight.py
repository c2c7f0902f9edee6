#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Plots of the flight studies written by `blockdyn flight-time | flight-boundary | kmin | flight-map`.

usage: plot_flight.py TABLE.csv OUT.png MODE     MODE: time | boundary | kmin | map
The CSV's JSON sidecar (TABLE.csv.json) supplies the parameters for the title.
An SVG with the same stem is written beside the PNG.
"""
import sys

from plotkit import cell_edges, col, finish_k_scan, k_scan_figure, legend_outside, log_axes, np, plt, run_modes, save, t_end


def plot_time(rows, meta, out):
    k, t, ihor = col(rows, "k"), col(rows, "time"), col(rows, "ihor")
    flew = col(rows, "flew") > 0.5
    status = np.array([r["status"] for r in rows])
    groups = [(flew, ".", "first flight"),
              (~flew & (status == "overturned"), "v", "overturned, no flight (plotted at t_end)"),
              (~flew & (status != "overturned"), "x", "no flight by t_end")]
    fig, (a, b) = k_scan_figure()
    for sel, style, label in groups:
        if sel.any():
            a.plot(k[sel], t[sel], style, ms=4, color="k" if style == "." else "0.55", label=label)
            b.plot(k[sel], ihor[sel], style, ms=4, color="k" if style == "." else "0.55")
    finish_k_scan(fig, (a, b), meta, out, "time to first flight",
                  "ihor at first flight\n(at the end if none)", "Time and ihor at the first flight")


def plot_boundary(rows, meta, out):
    r = col(rows, "r")
    fig, ax = plt.subplots(figsize=(9, 5), constrained_layout=True)
    styles = ["-", "--", "-.", ":"]
    names = [c for c in rows[0].keys() if c.startswith("k_") and not c.endswith("_status")]
    for i, name in enumerate(names):
        v = col(rows, name)
        ok = np.isfinite(v)
        if not ok.any():
            continue
        ax.plot(r[ok], v[ok], styles[i % len(styles)], marker="o", ms=3, label=name)
    log_axes(ax, "r", "k")
    legend_outside(ax)
    ax.set_title(f"Flight boundaries versus r (no flight below k_critical_n, early flight above k_high;\n"
                 f"k_min: energy bound), {meta.get('ic', '')}, mu = {meta.get('mu', '?')}, t_end = {t_end(meta)}",
                 fontsize=10)
    save(fig, out)


def plot_kmin(rows, meta, out):
    r = col(rows, "r")
    fig, ax = plt.subplots(figsize=(8, 4.5), constrained_layout=True)
    for name in [c for c in rows[0].keys() if c.startswith("k_min_")]:
        v = col(rows, name)
        ok = np.isfinite(v)
        ax.plot(r[ok], v[ok], label=name[len("k_min_"):])
    log_axes(ax, "r", "k_min (E0 = 0)")
    legend_outside(ax, title="initial conditions")
    ax.set_title(f"k_min(r): the energy lower bound of the flight region\n(no flight possible below), "
                 f"mu = {meta.get('mu', '?')}", fontsize=10)
    save(fig, out)


def plot_map(rows, meta, out):
    r, k, t = col(rows, "r"), col(rows, "k"), col(rows, "time")
    rs, ks = np.unique(r), np.unique(k)
    grid = np.full((len(rs), len(ks)), np.nan)
    ir = {v: i for i, v in enumerate(rs)}
    ik = {v: i for i, v in enumerate(ks)}
    for a, b, c in zip(r, k, t):
        grid[ir[a], ik[b]] = c

    fig, ax = plt.subplots(figsize=(7, 5), constrained_layout=True)
    m = ax.pcolormesh(cell_edges(ks, log=True), cell_edges(rs, log=True), grid, cmap="gray_r", shading="flat", rasterized=True)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("k")
    ax.set_ylabel("r")
    fig.colorbar(m, ax=ax, label="time to first flight (t_end: no flight)")
    ax.set_title(f"Time to first flight over (k, r), {meta.get('ic', '')}, mu = {meta.get('mu', '?')}, "
                 f"t_end = {t_end(meta)} (darker: later)", fontsize=10)
    save(fig, out)


def main(argv):
    modes = {"time": plot_time, "boundary": plot_boundary, "kmin": plot_kmin, "map": plot_map}
    run_modes(argv, __doc__, modes)


if __name__ == "__main__":
    main(sys.argv)
