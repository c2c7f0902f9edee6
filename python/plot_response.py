#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Long-term response of one block (thesis Figs. 4.41-4.57): phase portraits (y, y'), (w, w'),
(x, x') sampled at constant time intervals, swing-averaged energies and swing lengths.

usage: plot_response.py [--log-energy] SWINGS.csv PHASE.csv OUT.png [TITLE]
(an SVG is written beside the PNG; --log-energy: symmetric-log energy axis)
"""
import sys

from plotkit import load_columns, plt, save, split_args


def main(argv):
    log_energy = "--log-energy" in argv
    argv = [a for a in argv if a != "--log-energy"]
    (swings, phase), out, title = split_args(argv, __doc__, 2)
    sw = load_columns(swings)
    ph = load_columns(phase, skip=("regime",))
    fig = plt.figure(figsize=(10, 8.5), constrained_layout=True)
    gs = fig.add_gridspec(3, 3, height_ratios=[1.2, 1, 0.7])
    dot = dict(s=0.5, c="k", linewidths=0, rasterized=True)
    for i, (a, b, la, lb) in enumerate([("y", "vy", "y", "y'"), ("w", "vw", "w [rad]", "w' [rad]"),
                                        ("x", "vx", "x", "x'")]):
        ax = fig.add_subplot(gs[0, i])
        if ph:
            ax.scatter(ph[a], ph[b], **dot)
        ax.set_xlabel(la)
        ax.set_ylabel(lb)
    ax = fig.add_subplot(gs[1, :])
    if sw:
        t = sw["t_end"]
        for key, label in [("ave_rotation", "ave_w'"), ("ave_kinetic_y", "ave_y'"), ("ave_kinetic_x", "ave_x'"),
                           ("ave_gravity", "ave_y"), ("ave_springs", "ave_k"), ("ave_total", "total")]:
            ax.plot(t, sw[key], lw=0.8, label=label, rasterized=len(t) > 500)
        # Outside the axes: inside, it covered the curves of the first swings.
        ax.legend(loc="upper left", bbox_to_anchor=(1.005, 1.0), fontsize=8, borderaxespad=0.0)
        if log_energy:
            # Symmetric log: gravity and total energy go negative; six decades below the largest
            # value stay logarithmic, so the early rise of a small component is visible.
            top = max((abs(v) for key in ("ave_rotation", "ave_kinetic_y", "ave_kinetic_x", "ave_gravity",
                                          "ave_springs", "ave_total") for v in sw[key]), default=0.0)
            if top > 0:
                ax.set_yscale("symlog", linthresh=1e-6 * top)
    ax.set_xlabel("time (end of swing)")
    ax.set_ylabel("swing-averaged energy" + (" (symmetric log)" if log_energy else ""))
    ax = fig.add_subplot(gs[2, :])
    if sw:
        ax.plot(sw["t_end"], sw["length"], ".", ms=2, rasterized=True)
    ax.set_xlabel("time (end of swing)")
    ax.set_ylabel("swing length")
    fig.suptitle(title)
    save(fig, out, dpi=80, svg_dpi=80)


if __name__ == "__main__":
    main(sys.argv)
