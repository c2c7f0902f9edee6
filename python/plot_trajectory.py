#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Time histories and phase portraits of one `blockdyn simulate` trajectory CSV.

usage: plot_trajectory.py TRAJECTORY.csv OUT.png   (an SVG is written beside the PNG)
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

MODE_CODE = {"contact": 0, "slide": 1, "flight": 2}


def load(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise SystemExit(f"{path}: no rows")
    num = lambda k: np.array([float(r[k]) for r in rows])  # noqa: E731
    data = {k: num(k) for k in ("t", "x", "y", "w", "vx", "vy", "vw", "Ry", "E_total",
                                "E_kin_x", "E_kin_y", "E_rot", "E_grav", "E_springs")}
    data["mode"] = np.array([MODE_CODE[r["mode"]] for r in rows])
    data["event"] = [r["event"] for r in rows]
    return data


def main(argv):
    if len(argv) != 3:
        raise SystemExit(__doc__)
    d = load(argv[1])
    out = argv[2]
    t = d["t"]
    fig, ax = plt.subplots(3, 2, figsize=(11, 9), constrained_layout=True)
    ax[0, 0].plot(t, d["w"], lw=0.8)
    ax[0, 0].set_ylabel("w [rad]")
    ax[0, 0].set_title("rotation")
    ax[1, 0].plot(t, d["y"] - 0.5, lw=0.8, color="C1")
    ax[1, 0].set_ylabel("y - 1/2")
    ax[1, 0].set_title("vertical position of the centre")
    ax[2, 0].plot(t, d["x"], lw=0.8, color="C2")
    ax[2, 0].set_ylabel("x")
    ax[2, 0].set_xlabel("t")
    ax[2, 0].set_title("horizontal position")
    ax[0, 1].plot(d["w"], d["vw"], lw=0.5)
    ax[0, 1].set_xlabel("w")
    ax[0, 1].set_ylabel("w'")
    ax[0, 1].set_title("phase portrait (w, w')")
    ax[1, 1].step(t, d["mode"], where="post", lw=0.8, color="C3")
    ax[1, 1].set_yticks([0, 1, 2], ["contact", "slide", "flight"])
    ax[1, 1].set_title("mode")
    for name, col in (("E_kin_x", "C0"), ("E_kin_y", "C1"), ("E_rot", "C2"), ("E_grav", "C3"),
                      ("E_springs", "C4"), ("E_total", "k")):
        ax[2, 1].plot(t, d[name], lw=0.8, color=col, label=name)
    ax[2, 1].set_xlabel("t")
    ax[2, 1].set_title("energy components")
    ax[2, 1].legend(fontsize=7, ncol=3)
    flights = [i for i, e in enumerate(d["event"]) if e == "takeoff"]
    for i in flights[:200]:
        ax[0, 0].axvline(t[i], color="0.85", lw=0.5, zorder=0)
    fig.suptitle(os.path.basename(argv[1]))
    fig.savefig(out, dpi=110)
    fig.savefig(os.path.splitext(out)[0] + ".svg")


if __name__ == "__main__":
    main(sys.argv)
