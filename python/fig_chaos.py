#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The chaos chapter's figure layouts (thesis Figs 5.1-5.7, 5.13-5.14), with `blockdyn
energy-surface`, `poincare`, `response` and `lyapunov`.

usage: fig_chaos.py BLOCKDYN OUTDIR [--tiny]

Writes into OUTDIR (PNG + SVG):
  chaos_fig5_1.png   steady rocking and settle down: trajectory samples in (w, w') and (y, y') inside
                     the projections of their energy surface (thesis Fig 5.1)
  chaos_fig5_2.png   rock to vertical and zero-friction rock-flight, the same (Fig 5.2)
  chaos_fig5_3.png ... chaos_fig5_7.png
                     the thesis's layout: Poincare section w = 0 projected on (y, y') and (y, w') on
                     top, the swing-averaged energies below, the largest Lyapunov exponent in the
                     title - rock to vertical (5.3, 5.4), zero-friction rock-flight (5.5), settle down
                     (5.6), steady rocking (5.7), ic1
  chaos_fig5_13.png, chaos_fig5_14.png
                     r = 0.1, k = 1e6, mu = 0, ic2 with the impulse scaled to x'(0) = 0.010144 (so
                     w'(0) = 6 x'(0) / (1 + r^2)) and y'(0) = 0: to t = 180 and to t = 600, same scale
The orbits of 5.3-5.7 are Table 4.1 points of the named types (the OCR does not say which the
thesis used). Prints a JSON summary (exponents, crossings, how far trajectories leave their
energy surface: negative = inside).
--tiny: short runs of one figure of each layout (for the test that the script runs).
"""
import os
import sys
import tempfile

from plotkit import figure_script_args, legend_below, legend_outside, plt, read_table, save

SURFACE = [  # (figure, [(type, mu, r, k), ...])
    ("5_1", [("steady rocking", 0.2, 0.2, 1e3), ("settle down", 0.1, 0.5, 1e5)]),
    ("5_2", [("rock to vertical", 0.3, 0.2, 1e5), ("zero friction rock-flight", 0.0, 0.5, 1e4)]),
]
POINCARE = [  # (figure, type, mu, r, k, t_min of the section)
    ("5_3", "rock to vertical", 0.2, 0.1, 1e6, 0),
    ("5_4", "rock to vertical", 0.3, 0.2, 1e5, 0),
    ("5_5", "zero friction rock-flight", 0.0, 0.5, 1e4, 0),
    ("5_6", "settle down", 0.1, 0.5, 1e5, 20),
    ("5_7", "steady rocking", 0.0, 0.5, 1e2, 0),
]
ENERGY_NAMES = [("ave_rotation", "ave_w'"), ("ave_kinetic_y", "ave_y'"), ("ave_kinetic_x", "ave_x'"),
                ("ave_gravity", "ave_y"), ("ave_springs", "ave_k"), ("ave_total", "total")]


def block_args(mu, r, k, extra=()):
    return ["--mu", mu, "--r", r, "--k", k, *extra]


def surface_figure(cli, tmp, out, label, cases, t_end):
    fig, ax = plt.subplots(len(cases), 2, figsize=(10, 4.2 * len(cases) + 0.8), squeeze=False,
                           constrained_layout=True)
    res = []
    for i, (kind, mu, r, k) in enumerate(cases):
        prefix = os.path.join(tmp, f"es{label}_{i}")
        s = cli.json("energy-surface", *block_args(mu, r, k), "--ic", "ic1", "--t-end", t_end, "--phase-dt", 0.1,
                     "--csv-prefix", prefix, "--json")
        rock, heave, ph = (read_table(prefix + f"_{n}.csv") for n in ("rock", "heave", "phase"))
        a = ax[i, 0]
        a.plot(ph["w"], ph["vw"], ",", color="k", rasterized=True)
        for name, style, lab in (("vw_free", "-", "(w, w') bound: mu = 0, flight, 6-D surface (thesis 5.1, 5.2)"),
                                 ("vw_contact", "--", "(w, w') bound in contact mode (thesis 5.3)")):
            inside = rock[name] > 0  # where the potential U(w) stays below E
            a.plot(rock["w"][inside], rock[name][inside], style, color="C3", lw=1, label=lab)
            a.plot(rock["w"][inside], -rock[name][inside], style, color="C3", lw=1)
        a.set_xlabel("w")
        a.set_ylabel("w'")
        a.set_title(f"{kind}: mu = {mu}, r = {r}, k = {k:g}, ic1", fontsize=9)
        b = ax[i, 1]
        b.plot(ph["y"], ph["vy"], ",", color="k", rasterized=True)
        b.plot(heave["y"], heave["vy_max"], "-", color="C1", lw=1, label="(y, y') projection of E <= E0")
        b.plot(heave["y"], -heave["vy_max"], "-", color="C1", lw=1)
        b.set_xlabel("y")
        b.set_ylabel("y'")
        b.set_title(f"(y, y'): furthest outside {s['max_heave_excess']:.1e}", fontsize=9)
        for c in (a, b):
            c.grid(True, lw=0.3)
        res.append(dict(figure=label, type=kind, max_heave_excess=s["max_heave_excess"],
                        max_rock_excess=s["max_rock_excess"], samples=s["samples"]))
    handles = ax[0, 0].get_legend_handles_labels()[0] + ax[0, 1].get_legend_handles_labels()[0]
    handles.append(plt.Line2D([], [], ls="", marker=".", color="k", label="trajectory samples"))
    legend_below(fig, handles, ncol=2, height=0.06)
    fig.suptitle(f"Trajectory samples (every 0.1 time units to t = {t_end:g}) inside the projected energy surface "
                 f"(thesis Fig {label.replace('_', '.')})", fontsize=10)
    save(fig, os.path.join(out, f"chaos_fig{label}.png"))
    return res


def poincare_figure(cli, tmp, out, label, title, args, t_end, t_le, t_min=0, limits=None):
    """Section on (y, y') and (y, w'), swing-averaged energies below, the exponent in the title."""
    sec = os.path.join(tmp, f"p{label}.csv")
    cli("poincare", *args, "--t-end", t_end, "--t-min", t_min, "--csv", sec)
    prefix = os.path.join(tmp, f"r{label}")
    cli("response", *args, "--t-end", t_end, "--phase-dt", 0, "--csv-prefix", prefix)
    le = cli.json("lyapunov", *args, "--t-end", t_le, "--json")
    p, sw = read_table(sec), read_table(prefix + "_swings.csv")
    fig = plt.figure(figsize=(10.5, 7.5), constrained_layout=True)
    gs = fig.add_gridspec(2, 2, height_ratios=[1.2, 1])
    a, b, c = fig.add_subplot(gs[0, 0]), fig.add_subplot(gs[0, 1]), fig.add_subplot(gs[1, :])
    a.plot(p["h"], p["vy"], ".", ms=1.5, color="k", rasterized=True)
    b.plot(p["h"], p["vw"], ".", ms=1.5, color="k", rasterized=True)
    a.set(xlabel="y - 1/2", ylabel="y'")
    b.set(xlabel="y - 1/2", ylabel="w'")
    if limits:
        a.set_xlim(limits[0]), a.set_ylim(limits[1]), b.set_xlim(limits[0]), b.set_ylim(limits[2])
    for name, lab in ENERGY_NAMES:
        c.plot(sw["t_end"], sw[name], lw=0.8, label=lab, rasterized=True)
    c.set(xlabel="time (end of swing)", ylabel="swing-averaged energy")
    legend_outside(c)
    for x in (a, b, c):
        x.grid(True, lw=0.3)
        x.ticklabel_format(style="sci", scilimits=(-3, 4), useOffset=False)
    fig.suptitle(f"{title}\nPoincare section w = 0 ({len(p['t'])} crossings, t in [{t_min:g}, {t_end:g}]); "
                 f"LE = {le['exponent']:.3f} (t = {t_le:g}; second half {le['exponent_second_half']:.3f})", fontsize=10)
    save(fig, os.path.join(out, f"chaos_fig{label}.png"))
    lim = ((float(p["h"].min()), float(p["h"].max())), (float(p["vy"].min()), float(p["vy"].max())),
           (float(p["vw"].min()), float(p["vw"].max())))
    return dict(figure=label, crossings=int(len(p["t"])), exponent=le["exponent"],
                exponent_second_half=le["exponent_second_half"]), lim


def main(argv):
    cli, out, tiny = figure_script_args(argv, __doc__)
    t_end, t_le = (20, 10) if tiny else (1000, 300)
    summary = []
    with tempfile.TemporaryDirectory(prefix="blockdyn-chaos-") as tmp:
        for label, cases in (SURFACE[:1] if tiny else SURFACE):
            summary += surface_figure(cli, tmp, out, label, cases, t_end)
        for label, kind, mu, r, k, t_min in (POINCARE[:1] if tiny else POINCARE):
            res, _ = poincare_figure(cli, tmp, out, label,
                                     f"{kind} (thesis Fig {label.replace('_', '.')}): mu = {mu}, r = {r}, k = {k:g}, ic1",
                                     block_args(mu, r, k, ["--ic", "ic1"]), t_end, t_le, t_min=min(t_min, t_end / 2))
            summary.append(dict(type=kind, **res))
        # Figs 5.13-5.14: the thesis's "ic2 y'(0) = 0, x'(0) = 0.010144": the same base impulse, scaled
        # (ic2 sets w'(0) = 6 x'(0) / (1 + r^2)), without the vertical one.
        r, vx = 0.1, 0.010144
        args = block_args(0.0, r, 1e6, ["--ic", "ic2", "--vy0", 0, "--vx0", vx, "--vw0", 6 * vx / (1 + r * r)])
        short, long_ = (8, 20) if tiny else (180, 600)
        res, lim = poincare_figure(cli, tmp, out, "5_14", f"r = {r}, k = 1e6, mu = 0, ic2 with x'(0) = {vx} "
                                   f"(thesis Fig 5.14, long run)", args, long_, min(t_le, long_))
        summary.append(dict(type="ic2 scaled, long", **res))
        pad = lambda lo_hi: (lo_hi[0] - 0.05 * (lo_hi[1] - lo_hi[0]), lo_hi[1] + 0.05 * (lo_hi[1] - lo_hi[0]))  # noqa: E731
        res, _ = poincare_figure(cli, tmp, out, "5_13", f"r = {r}, k = 1e6, mu = 0, ic2 with x'(0) = {vx} "
                                 f"(thesis Fig 5.13, short run; same scale as 5.14)", args, short, min(t_le, short),
                                 limits=[pad(v) for v in lim])
        summary.append(dict(type="ic2 scaled, short", **res))
    print(cli.summary("fig-chaos", "figures", summary))


if __name__ == "__main__":
    main(sys.argv)
