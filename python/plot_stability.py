#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Plots of the stability studies written by `blockdyn overturn | stability-curve | blowup`.

usage: plot_stability.py TABLE.csv OUT.png MODE     MODE: overturn | curve | blowup
The CSV's JSON sidecar (TABLE.csv.json) supplies the parameters for the title.
An SVG with the same stem is written beside the PNG.
"""
import sys

from plotkit import col, finish_k_scan, k_scan_figure, legend_outside, np, plt, run_modes, save, t_end


def plot_overturn(rows, meta, out):
    k, t, ihor = col(rows, "k"), col(rows, "time"), col(rows, "ihor")
    over = col(rows, "overturned") > 0.5
    fig, (a, b) = k_scan_figure()
    a.plot(k[over], t[over], "k.", ms=4, label="overturned")
    a.plot(k[~over], t[~over], "x", color="0.6", ms=4, label="no overturning by t_end")
    b.plot(k[over], ihor[over], "k.", ms=4)
    b.plot(k[~over], ihor[~over], "x", color="0.6", ms=4)
    # Below k_uns no stable equilibrium exists: overturning from any start.
    if meta.get("k_uns"):
        for ax in (a, b):
            ax.axvline(meta["k_uns"], color="C0", ls=":", lw=1.2,
                       label="k_uns (no stable equilibrium below)" if ax is a else None)
    win = meta.get("second_swing_window") or {}
    if win.get("k_range"):  # the fine window between k2 and k3 (overturn --window-points)
        for ax in (a, b):
            ax.axvspan(*win["k_range"], color="C1", alpha=0.12, lw=0,
                       label=f"k2-k3 window ({meta.get('window_points')} extra points)" if ax is a else None)
    finish_k_scan(fig, (a, b), meta, out, "time at overturning", "ihor at overturning\n(at t_end if none)",
                  "Time and ihor at overturning")


def plot_curve(rows, meta, out):
    r = col(rows, "r")
    fig, ax = plt.subplots(figsize=(8.5, 4.5), constrained_layout=True)
    styles = {"k1_stability": "-", "k2_stability": "-", "k3_stability": "--"}
    for name in [c for c in rows[0].keys() if c.endswith("_stability")]:
        v = col(rows, name)
        ok = np.isfinite(v)
        ax.plot(1.0 / r[ok], v[ok], styles.get(name, "-"), marker="o", ms=3, label=name)
    if "k_uns" in rows[0]:  # static limit: below k_uns no stable equilibrium (docs/equilibria.md)
        v = col(rows, "k_uns")
        ok = np.isfinite(v)
        ax.plot(1.0 / r[ok], v[ok], ":", color="0.3", lw=1.5, label="k_uns (no stable equilibrium below)")
    ax.set_yscale("log")
    ax.set_xlabel("1/r")
    ax.set_ylabel("critical k")
    ax.grid(True, which="both", lw=0.3)
    legend_outside(ax)
    ax.set_title(f"Critical stability curves versus 1/r (overturning below), {meta.get('ic', '')},\n"
                 f"mu = {meta.get('mu', '?')}, t_end = {t_end(meta)}", fontsize=10)
    save(fig, out)


def plot_blowup(rows, meta, out):
    mu = col(rows, "mu")
    fig, ax = plt.subplots(figsize=(7, 4.2), constrained_layout=True)
    for name, style in (("r2_s", "o-"), ("r3_s", "s--")):
        if name in rows[0]:
            v = col(rows, name)
            ok = np.isfinite(v)
            ax.plot(mu[ok], v[ok], style, ms=4, label=name)
    ax.set_xlabel("mu")
    ax.set_ylabel("r")
    ax.set_ylim(bottom=0)
    ax.grid(True, lw=0.3)
    legend_outside(ax)
    cap = meta.get("k_search", {}).get("k_range", [None, None])[1]
    ax.set_title("Aspect ratios below which ic2 overturns for every k: r2_s (while ihor = 1),\n"
                 "r3_s (while ihor <= 2) versus mu" + (f" (k up to {cap:g})" if cap else ""), fontsize=10)
    save(fig, out)


def main(argv):
    run_modes(argv, __doc__, {"overturn": plot_overturn, "curve": plot_curve, "blowup": plot_blowup})


if __name__ == "__main__":
    main(sys.argv)
