#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""A generated suite (`blockdyn motion generate --plot`): three of its records, and each record's
measured Arias intensity, D5-95 and t_mid against the targets.

usage: plot_motions.py DIR/motions.json OUT.png"""
import json
import os
import sys

from plotkit import np, plt, save  # noqa: E402


def read_at2(path):
    with open(path) as f:
        lines = f.read().splitlines()
    dt = float(lines[3].split("DT=")[1].split()[0])
    a = np.array([float(x) for line in lines[4:] for x in line.split()])
    return np.arange(len(a)) * dt, a


def main():
    src, out = sys.argv[1], sys.argv[2]
    with open(src) as f:
        j = json.load(f)
    recs = j["records"]
    fig = plt.figure(figsize=(9, 6.5), constrained_layout=True)
    grid = fig.add_gridspec(4, 3)
    for k, r in enumerate(recs[:3]):
        ax = fig.add_subplot(grid[k, :])
        t, a = read_at2(os.path.join(os.path.dirname(src), r["file"]))
        ax.plot(t, a, lw=0.6)
        ax.set_ylabel("a [g]")
        ax.set_title(f"{r['file']}: pga {r['pga']:.3g} g, Arias {r['arias']:.3g} m/s, D5-95 {r['d5_95']:.3g} s",
                     fontsize=9)
    ax.set_xlabel("t [s]")
    targets = j.get("targets", {})
    for col, key, unit in ((0, "arias", "m/s"), (1, "d5_95", "s"), (2, "t_mid", "s")):
        ax = fig.add_subplot(grid[3, col])
        v = [r[key] for r in recs]
        ax.hist(v, bins=max(5, min(20, len(v) // 3)), color="0.7")
        ax.axvline(np.median(v), color="C0", label="median")
        if key in targets:
            ax.axvline(targets[key], color="C3", ls="--", label="target")
        ax.set_xlabel(f"{key} [{unit}]")
        if col == 0:
            ax.legend(fontsize=7)
    fig.suptitle(f"{j['model']} suite: {j['count']} records, seed {j['seed']}")
    save(fig, out)


if __name__ == "__main__":
    main()
