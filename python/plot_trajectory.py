#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Time histories and phase portrait of one Winkler-block trajectory (`blockdyn simulate`).

usage: plot_trajectory.py TRAJECTORY.csv OUT.png [--alpha A] [--title T]

Panels: rotation with +-alpha and the mode (contact / slide / flight) as coloured bands, take-offs
marked; heave of the centre; horizontal position; the (w, w') phase portrait; the foundation's
reactions Rx, Ry; the energy components with the closed balance. An SVG is written beside the PNG.
"""
import csv

from plotkit import figure_parser, np, plot_in_power_of_ten, plt, save, shade_runs

MODE_COLOURS = {"contact": "0.93", "slide": "#cfe8ff", "flight": "#e4d4ff"}


def load(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise SystemExit(f"{path}: no rows")
    num = lambda k: np.array([float(r[k]) for r in rows])  # noqa: E731
    data = {k: num(k) for k in ("t", "x", "y", "w", "vx", "vy", "vw", "Rx", "Ry", "E_total", "E_kin_x",
                                "E_kin_y", "E_rot", "E_grav", "E_springs", "energy_balance")}
    data["mode"] = [r["mode"] for r in rows]
    data["event"] = [r["event"] for r in rows]
    return data



def main():
    ap = figure_parser()
    ap.add_argument("--alpha", type=float)
    a = ap.parse_args()
    d = load(a.csv)
    t = d["t"]
    fig, ax = plt.subplots(3, 2, figsize=(12, 9.5), constrained_layout=True)
    shade_runs(ax[0, 0], t, d["mode"], MODE_COLOURS)
    ax[0, 0].plot(t, d["w"], lw=0.8, color="C0")
    if a.alpha:
        for s in (1, -1):
            ax[0, 0].axhline(s * a.alpha, color="C3", lw=0.7, ls="--")
    takeoffs = [i for i, e in enumerate(d["event"]) if e == "takeoff"]
    ax[0, 0].plot(t[takeoffs], d["w"][takeoffs], "k^", ms=3, label="take-off")
    handles = [plt.Rectangle((0, 0), 1, 1, color=c) for c in MODE_COLOURS.values()]
    # +-alpha named in the legend: a text label would sit on the mode bands.
    extra = [plt.Line2D([], [], color="C3", lw=0.7, ls="--")] if a.alpha else []
    ax[0, 0].legend(handles + ax[0, 0].lines[-1:] + extra,
                    list(MODE_COLOURS) + ["take-off"] + (["+-alpha"] if a.alpha else []), fontsize=7, ncol=5,
                    loc="lower left", bbox_to_anchor=(0, 1.0), frameon=False)
    ax[0, 0].set_ylabel("rotation w [rad]")
    ax[1, 0].plot(t, d["y"] - 0.5, lw=0.8, color="C1")
    ax[1, 0].set_ylabel("heave y - 1/2")
    ax[2, 0].plot(t, d["x"], lw=0.8, color="C2")
    ax[2, 0].set_ylabel("x")
    ax[2, 0].set_xlabel("t")
    ax[0, 1].plot(d["w"], d["vw"], lw=0.5)
    ax[0, 1].set_xlabel("w")
    ax[0, 1].set_ylabel("w'")
    ax[0, 1].set_title("phase portrait (w, w')", fontsize=9)
    ax[1, 1].plot(t, d["Ry"], lw=0.8, label="Ry")
    ax[1, 1].plot(t, d["Rx"], lw=0.8, label="Rx")
    ax[1, 1].set_ylabel("foundation reaction [m g]")
    ax[1, 1].legend(fontsize=7, ncol=2, loc="lower left", bbox_to_anchor=(0, 1.0), frameon=False)
    for name, col in (("E_kin_x", "C0"), ("E_kin_y", "C1"), ("E_rot", "C2"), ("E_grav", "C3"),
                      ("E_springs", "C4"), ("E_total", "k")):
        ax[2, 1].plot(t, d[name], lw=0.8, color=col, label=name)
    ax[2, 1].set_xlabel("t")
    ax[2, 1].set_ylabel("energy [m g a]")
    ax[2, 1].legend(fontsize=7, ncol=6, loc="lower left", bbox_to_anchor=(0, 1.0), frameon=False)
    bal = ax[2, 1].twinx()
    err = d["energy_balance"] - d["energy_balance"][0]
    plot_in_power_of_ten(bal, t, err, "balance error", "m g a", lw=0.6, color="0.4", ls=":")
    fig.suptitle(a.title or a.csv, fontsize=10)
    save(fig, a.out)


if __name__ == "__main__":
    main()
