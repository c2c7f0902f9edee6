#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Time histories of a 3D run (`blockdyn simulate --model rigid3d`).

usage: plot_rigid3d.py TRAJECTORY.csv OUT.png [--weight W] [--height H] [--title T]

Panels: the tilt (the angle of the body's axis from the vertical) with the contact mode as
coloured bands and impacts marked; the direction the body leans to (tilt azimuth); the
centroid's, the top's and the contact's tracks seen from above; the normal force over the weight; the closed energy balance's
error. An SVG is written beside the PNG.
"""

from plotkit import figure_parser, legend_outside, np, plot_in_power_of_ten, plt, read_rows, save, shade_runs

MODE_COLOURS = {"rest": "0.92", "slide": "#d4ecd4", "edge": "#fff2c2", "rim": "#fff2c2", "roll": "#fde0ef", "corner": "#ffd8b0",
                "flight": "#e4d4ff"}


def main():
    ap = figure_parser()
    ap.add_argument("--weight", type=float, default=0.0, help="m g [N]: the normal force is drawn over it")
    ap.add_argument("--height", type=float, default=0.0, help="the body's height [m]: its top's path is drawn")
    a = ap.parse_args()
    rows = read_rows(a.csv)
    if not rows:
        raise SystemExit(f"{a.csv}: no rows")
    num = lambda k: np.array([float(r[k]) if r[k] != "" else np.nan for r in rows])  # noqa: E731
    t, tilt = num("t"), num("tilt")
    mode = [r["mode"] for r in rows]
    imp = [i for i, r in enumerate(rows) if r["event"] == "impact"]

    fig = plt.figure(figsize=(10, 11), constrained_layout=True)
    grid = fig.add_gridspec(4, 2, width_ratios=(3, 1.2))
    ax = [fig.add_subplot(grid[0, :])]
    ax.append(fig.add_subplot(grid[1, 0], sharex=ax[0]))
    top = fig.add_subplot(grid[1, 1])
    ax.append(fig.add_subplot(grid[2, :], sharex=ax[0]))
    ax.append(fig.add_subplot(grid[3, :], sharex=ax[0]))

    shade_runs(ax[0], t, mode, MODE_COLOURS)
    ax[0].plot(t, tilt, lw=0.8, color="C0")
    ax[0].plot(t[imp], tilt[imp], "k|", ms=6)
    ax[0].set_ylabel("tilt [rad]")
    seen = [m for m in MODE_COLOURS if m in mode]
    handles = [plt.Rectangle((0, 0), 1, 1, color=MODE_COLOURS[m]) for m in seen]
    legend_outside(ax[0], handles=handles + [plt.Line2D([], [], color="k", marker="|", ls="")],
                   labels=seen + ["impact"], title="contact", fontsize=7)

    leaning = tilt > 1e-9
    ax[1].plot(t[leaning], num("tilt_azimuth")[leaning], ".", ms=1.5, color="C2")
    ax[1].set_ylabel("leans towards [deg]")
    ax[1].set_ylim(-185, 185)

    # Millimetres: a track of a few tenths of a millimetre would put an offset label over the title.
    q = [num(k) for k in ("qw", "qx", "qy", "qz")]
    half = a.height / 2
    # The top's centre, G + R (0, 0, h/2): R's third column.
    top_x = num("x") + half * 2 * (q[1] * q[3] + q[0] * q[2])
    top_y = num("y") + half * 2 * (q[2] * q[3] - q[0] * q[1])
    top.plot(1e3 * num("x"), 1e3 * num("y"), lw=0.8, color="C4", label="centroid")
    if a.height > 0:
        top.plot(1e3 * top_x, 1e3 * top_y, lw=0.6, color="C5", label="top")
    top.plot(1e3 * num("contact_x"), 1e3 * num("contact_y"), ".", ms=2, color="k", label="contact")
    top.legend(fontsize=6, loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0)
    top.set_aspect("equal", adjustable="datalim")
    top.ticklabel_format(useOffset=False)
    top.set_xlabel("x [mm]")
    top.set_ylabel("y [mm]")
    top.set_title("seen from above", fontsize=9)

    n = num("normal_force")
    ax[2].plot(t, n / a.weight if a.weight > 0 else n, lw=0.8, color="C1")
    ax[2].set_ylabel("normal force / m g" if a.weight > 0 else "normal force [N]")

    plot_in_power_of_ten(ax[3], t, num("energy_error"), "energy balance error", "J", lw=0.8, color="C3")
    ax[3].set_xlabel("t [s]")
    fig.suptitle(a.title or "3D body on rigid ground", fontsize=10)
    save(fig, a.out)


if __name__ == "__main__":
    main()
