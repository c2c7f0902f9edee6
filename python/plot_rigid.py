#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Time histories of a rigid-ground run (`blockdyn simulate --model housner|rigid`).

usage: plot_rigid.py TRAJECTORY.csv OUT.png [--alpha A] [--model M] [--status S] [--title T]

Panels: rotation with +-alpha and the mechanism as coloured bands, impacts marked; rotation rate
with the jumps at impacts; the ground acceleration; contact forces; the energy terms and the closed
balance. An SVG is written beside the PNG.
"""

from plotkit import figure_parser, legend_outside, np, plot_in_power_of_ten, plt, read_rows, save, shade_runs

MECH_COLOURS = {"rest": "0.92", "slide": "#cfe8ff", "rock": "#fff2c2", "slide_rock": "#ffd8b0",
                "flight": "#e4d4ff"}



def main():
    ap = figure_parser()
    ap.add_argument("--alpha", type=float)
    ap.add_argument("--model", default="")
    ap.add_argument("--status", default="")
    a = ap.parse_args()
    rows = read_rows(a.csv)
    if not rows:
        raise SystemExit(f"{a.csv}: no rows")
    num = lambda k: np.array([float(r[k]) for r in rows])  # noqa: E731
    t, w, vw = num("t"), num("w"), num("vw")
    mech = [r["mode"] for r in rows]
    event = [r["event"] for r in rows]
    imp = [i for i, e in enumerate(event) if e == "impact"]

    fig, ax = plt.subplots(5, 1, figsize=(10, 12), sharex=True, constrained_layout=True)
    shade_runs(ax[0], t, mech, MECH_COLOURS)
    ax[0].plot(t, w, lw=0.8, color="C0")
    if a.alpha:
        for s in (1, -1):
            ax[0].axhline(s * a.alpha, color="C3", lw=0.7, ls="--")
    ax[0].plot(t[imp], w[imp], "k|", ms=6, label="impacts")
    ax[0].set_ylabel("rotation w [rad]")
    handles = [plt.Rectangle((0, 0), 1, 1, color=c) for c in MECH_COLOURS.values()]
    # +-alpha named in the legend: a text label would sit on the mechanism bands.
    extra = [plt.Line2D([], [], color="C3", lw=0.7, ls="--")] if a.alpha else []
    legend_outside(ax[0], handles=handles + [ax[0].lines[-1]] + extra,
                   labels=list(MECH_COLOURS) + ["impact"] + (["+-alpha"] if a.alpha else []), title="mechanism",
                   fontsize=7)

    ax[1].plot(t, vw, lw=0.8, color="C1")
    ax[1].plot(t[imp], vw[imp], "k.", ms=3)
    ax[1].set_ylabel("w' [rad/s]")

    ax[2].plot(t, num("a_h"), lw=0.8, label="horizontal a_H")
    ax[2].plot(t, num("a_v"), lw=0.8, label="vertical a_V")
    ax[2].set_ylabel("ground [g]")
    legend_outside(ax[2], fontsize=7)

    for k, c in (("N_A", "C0"), ("N_B", "C1")):
        ax[3].plot(t, num(k), lw=0.8, color=c, label=k)
    for k, c in (("T_A", "C0"), ("T_B", "C1")):
        ax[3].plot(t, num(k), lw=0.8, color=c, ls=":", label=k)
    ax[3].set_ylabel("contact forces [N]")
    legend_outside(ax[3], fontsize=7)

    for k, c in (("E_kin", "C0"), ("E_pot", "C1"), ("W_friction", "C2"), ("W_ground", "C4"),
                 ("W_impact", "C3")):
        ax[4].plot(t, num(k), lw=0.8, color=c, label=k)
    ax[4].set_ylabel("energy [J]")
    ax[4].set_xlabel("t [s]")
    bal = num("energy_balance")
    ax4b = ax[4].twinx()
    plot_in_power_of_ten(ax4b, t, bal, "balance error", "J", lw=0.6, color="k", alpha=0.6)
    # The balance error's own axis sits on the right: this legend goes below the panel.
    ax[4].legend(fontsize=7, ncol=5, loc="upper left", bbox_to_anchor=(0.0, -0.28), frameon=False)

    status = f"status {a.status}" if a.status else ""
    maxw = np.max(np.abs(w))
    rel = f" = {maxw / a.alpha:.3g} alpha" if a.alpha else ""
    fig.suptitle(f"{a.title}\n"
                 f"{status}, max |w| {maxw:.4g} rad{rel}, {len(imp)} impacts", fontsize=10)
    save(fig, a.out)


if __name__ == "__main__":
    main()
