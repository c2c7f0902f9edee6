#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Energy-surface projections onto (y, y') and (w, w') with the trajectory overlaid (thesis
Figs. 5.1-5.2, 5.8-5.11).

usage: plot_energy_surface.py HEAVE.csv ROCK.csv PHASE.csv OUT.png [TITLE]   (SVG beside the PNG)
"""
import sys

from plotkit import load_columns, plt, save, split_args


def main(argv):
    (heave, rock, phase), out, title = split_args(argv, __doc__, 3)
    hv, rk, ph = load_columns(heave), load_columns(rock), load_columns(phase, skip=("regime",))
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.6), constrained_layout=True)
    dot = dict(s=0.6, c="k", linewidths=0, rasterized=True)
    inside = hv["vy_max"] > 0
    ax[0].fill_between(hv["y"], -hv["vy_max"], hv["vy_max"], where=inside, color="tab:blue", alpha=0.15,
                       label="projection of the energy surface")
    ax[0].plot(hv["y"][inside], hv["vy_max"][inside], "b", lw=0.8)
    ax[0].plot(hv["y"][inside], -hv["vy_max"][inside], "b", lw=0.8)
    if ph:
        ax[0].scatter(ph["y"], ph["vy"], label="trajectory", **dot)
        ax[0].plot(ph["y"][:1], ph["vy"][:1], "ro", ms=5, label="initial condition")
    ax[0].set_xlabel("y")
    ax[0].set_ylabel("y'")
    # Below the panels: inside they covered the trajectory and the surface.
    ax[0].legend(loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=3, fontsize=8, frameon=False)
    ax[1].fill_between(rk["w"], -rk["vw_free"], rk["vw_free"], color="tab:blue", alpha=0.15,
                       label="mu=0 / 6-D bound: I w'^2/2 + U(w) <= E")
    ax[1].plot(rk["w"], rk["vw_contact"], "g", lw=0.8, label="contact: (I+B^2) w'^2/2 + U(w) <= E")
    ax[1].plot(rk["w"], -rk["vw_contact"], "g", lw=0.8)
    if ph:
        ax[1].scatter(ph["w"], ph["vw"], **dot)
        ax[1].plot(ph["w"][:1], ph["vw"][:1], "ro", ms=5)
    ax[1].set_xlabel("w [rad]")
    ax[1].set_ylabel("w' [rad]")
    ax[1].legend(loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2, fontsize=8, frameon=False)
    fig.suptitle(title)
    save(fig, out, dpi=80, svg_dpi=80)


if __name__ == "__main__":
    main(sys.argv)
