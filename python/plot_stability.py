#!/usr/bin/env python3
"""Plots of the stability studies written by `blockdyn overturn | stability-curve | blowup`.

usage: plot_stability.py TABLE.csv OUT.png MODE     MODE: overturn | curve | blowup
The CSV's JSON sidecar (TABLE.csv.json) supplies the parameters for the title.
An SVG with the same stem is written beside the PNG.
"""
import csv
import json
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


def plot_overturn(rows, meta, out):
    k, t, ihor = col(rows, "k"), col(rows, "time"), col(rows, "ihor")
    over = col(rows, "overturned") > 0.5
    fig, (a, b) = plt.subplots(2, 1, sharex=True, figsize=(7, 5.5), constrained_layout=True)
    a.plot(k[over], t[over], "k.", ms=4, label="overturned")
    a.plot(k[~over], t[~over], "x", color="0.6", ms=4, label="no overturning by t_end")
    a.set_xscale("log")
    a.set_ylabel("time at overturning")
    a.legend(fontsize=8, loc="best")
    a.set_title(f"{meta.get('ic', '')}: r = {meta.get('r', '?')}, mu = {meta.get('mu', '?')}, "
                f"t_end = {meta.get('run_options', {}).get('t_end', '?')}")
    b.plot(k[over], ihor[over], "k.", ms=4)
    b.plot(k[~over], ihor[~over], "x", color="0.6", ms=4)
    b.set_ylabel("ihor at overturning\n(at t_end if none)")
    b.set_xlabel("k")
    save(fig, out)


def plot_curve(rows, meta, out):
    r = col(rows, "r")
    fig, ax = plt.subplots(figsize=(6.5, 4.5), constrained_layout=True)
    styles = {"k1_stability": "-", "k2_stability": "-", "k3_stability": "--"}
    for name in [c for c in rows[0].keys() if c.endswith("_stability")]:
        v = col(rows, name)
        ok = np.isfinite(v)
        ax.plot(1.0 / r[ok], v[ok], styles.get(name, "-"), marker="o", ms=3, label=name)
    ax.set_yscale("log")
    ax.set_xlabel("1/r")
    ax.set_ylabel("critical k")
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=8)
    ax.set_title(f"critical stability curves, {meta.get('ic', '')}, mu = {meta.get('mu', '?')}, "
                 f"t_end = {meta.get('run_options', {}).get('t_end', '?')}")
    save(fig, out)


def plot_blowup(rows, meta, out):
    mu = col(rows, "mu")
    fig, ax = plt.subplots(figsize=(6, 4.2), constrained_layout=True)
    for name, style in (("r2_s", "o-"), ("r3_s", "s--")):
        if name in rows[0]:
            v = col(rows, name)
            ok = np.isfinite(v)
            ax.plot(mu[ok], v[ok], style, ms=4, label=name)
    ax.set_xlabel("mu")
    ax.set_ylabel("r")
    ax.set_ylim(bottom=0)
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=8)
    cap = meta.get("k_search", {}).get("k_range", [None, None])[1]
    ax.set_title(f"r2_s(mu), r3_s(mu), ic2 (k cap {cap:g})" if cap else "r2_s(mu), r3_s(mu), ic2")
    save(fig, out)


def main(argv):
    if len(argv) != 4:
        raise SystemExit(__doc__)
    rows, meta = load(argv[1])
    modes = {"overturn": plot_overturn, "curve": plot_curve, "blowup": plot_blowup}
    if argv[3] not in modes:
        raise SystemExit(f"unknown mode {argv[3]!r}; one of {sorted(modes)}")
    modes[argv[3]](rows, meta, argv[2])


if __name__ == "__main__":
    main(sys.argv)
