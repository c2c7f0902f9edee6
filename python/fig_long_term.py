#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Long-term response figures (thesis Table 4.1, Figs 4.41-4.55, and Fig 4.56), with `blockdyn response`.

usage: fig_long_term.py BLOCKDYN OUTDIR [--tiny]

Writes into OUTDIR (PNG + SVG): response_fig4_41.png ... response_fig4_55.png - per Table 4.1 row
the phase portraits (y, y'), (w, w'), (x, x'), the swing-averaged energies and the swing lengths
of `blockdyn response` to t = 1000; 4.52 (the block of 4.51) instead shows the region the
trajectory fills with an initial and a typical stretch of it drawn as lines - and response_fig4_56.png, the steady state of the settle-down
block (r = 0.2, k = 1e4, mu = 0.1, ic2): (y, y') and (w, w') over the last tenth of the run, with
the start of that window. The k values the OCR garbles are those of docs/response.md (the ones
that reproduce the tabulated type). Prints a JSON summary: per row the thesis's type, ours, and
the metrics behind it.
--tiny: three rows (one of them 4.52) and the 4.56 figure to t = 20 (for the test that the script runs).
"""
import json
import os
import sys
import tempfile

from plotkit import figure_script_args, legend_outside, np, plt, read_table, save

# Table 4.1: (figure, mu, r, k, ic, the thesis's type)
TABLE = [
    ("4.41", 0.0, 0.5, 1e2, "ic1", "steady rocking"),
    ("4.42", 0.0, 0.5, 1e4, "ic1", "zero friction rock-flight"),
    ("4.43", 0.0, 0.1, 1e6, "ic1", "rock to vertical"),
    ("4.44", 0.0, 0.5, 1e2, "ic2", "steady rocking"),
    ("4.45", 0.0, 0.5, 1e4, "ic2", "zero friction rock-flight"),
    ("4.46", 0.0, 0.2, 1e6, "ic2", "rock to vertical"),
    ("4.47", 0.2, 0.2, 1e3, "ic1", "steady rocking"),
    ("4.48", 0.1, 0.5, 1e6, "ic1", "settle down"),
    ("4.49", 0.1, 0.5, 1e5, "ic1", "settle down"),
    ("4.50", 0.3, 0.2, 1e5, "ic1", "rock to vertical"),
    ("4.51", 0.2, 0.1, 1e6, "ic1", "rock to vertical"),
    ("4.52", 0.2, 0.1, 1e6, "ic1", "rock to vertical"),
    ("4.53", 0.2, 0.3, 1e4, "ic2", "steady rocking"),
    ("4.54", 0.1, 0.2, 1e4, "ic2", "settle down"),
    ("4.55", 0.2, 0.15, 1e5, "ic2", "rock to vertical"),
]
T_END = 1000


def fig_4_56(cli, tmp, out, t_end):
    """The settle-down steady state: phase portraits over the last tenth of the run."""
    prefix = os.path.join(tmp, "settle")
    js = os.path.join(tmp, "settle.json")
    cli("response", "--mu", 0.1, "--r", 0.2, "--k", 1e4, "--ic", "ic2", "--t-end", t_end, "--phase-dt", 0.005,
        "--csv-prefix", prefix, "--json-out", js)
    with open(js) as f:
        summary = json.load(f)
    ph = read_table(prefix + "_phase.csv")
    late = ph["t"] >= 0.9 * t_end
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.6), constrained_layout=True)
    for a, (u, v, lu, lv) in zip(ax, (("y", "vy", "y", "y'"), ("w", "vw", "w", "w'"))):
        a.plot(ph[u][late], ph[v][late], "-", color="C0", lw=0.6, label=f"t in [{0.9 * t_end:g}, {t_end:g}]",
               rasterized=True)
        a.plot(ph[u][late][:1], ph[v][late][:1], "o", color="C3", ms=5, label="window start")
        a.set_xlabel(lu)
        a.set_ylabel(lv)
        a.grid(True, lw=0.3)
        a.ticklabel_format(style="sci", scilimits=(-3, 3))
    legend_outside(ax[1])
    m = summary["metrics"]
    fig.suptitle(f"Settle-down steady state (thesis Fig 4.56): r = 0.2, k = 1e4, mu = 0.1, ic2 - type "
                 f"{summary['type']}, late flight fraction {m.get('late_flight_fraction', float('nan')):.2f}",
                 fontsize=10)
    save(fig, os.path.join(out, "response_fig4_56.png"))
    return dict(figure="4.56", type=summary["type"], late_flight_fraction=m.get("late_flight_fraction"),
                y_range_late=[float(ph["y"][late].min()), float(ph["y"][late].max())],
                max_abs_w_late=float(np.max(np.abs(ph["w"][late]))))


def fig_4_52(cli, tmp, out, t_end, seg):
    """Rock to vertical (mu = 0.2, r = 0.1, k = 1e6, ic1): the region the trajectory fills (samples
    every 0.1) with an initial and a typical stretch of the trajectory drawn as lines, as the
    thesis's Fig 4.52. The typical stretch restarts from the state sampled at t_end/2."""
    args = ["--mu", 0.2, "--r", 0.1, "--k", 1e6]
    prefix = os.path.join(tmp, "rtv")
    cli("response", *args, "--ic", "ic1", "--t-end", t_end, "--phase-dt", 0.1, "--csv-prefix", prefix)
    ph = read_table(prefix + "_phase.csv")
    i = int(np.argmin(np.abs(ph["t"] - 0.5 * t_end)))
    state = [(f"--{n}0", repr(float(ph[n][i]))) for n in ("x", "y", "w", "vx", "vy", "vw")]
    lines = []
    for name, extra in (("initial", ["--ic", "ic1"]), ("typical", ["--ic", "custom"] + [a for p in state for a in p])):
        path = os.path.join(tmp, f"rtv_{name}.csv")
        cli("simulate", *args, *extra, "--t-end", seg, "--output-interval", 2e-4, "--trajectory", path, "--quiet")
        lines.append(read_table(path))
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.8), constrained_layout=True)
    t0 = float(ph["t"][i])
    for a, (u, v, lu, lv) in zip(ax, (("y", "vy", "y - 1/2", "y'"), ("w", "vw", "w", "w'"))):
        off = 0.5 if u == "y" else 0.0
        a.plot(ph[u] - off, ph[v], ".", ms=1, color="0.6", rasterized=True, label=f"samples every 0.1, t <= {t_end:g}")
        for tr, colour, lab in zip(lines, ("C0", "C3"), (f"initial, t in [0, {seg:g}]",
                                                        f"typical, t in [{t0:g}, {t0 + seg:g}]")):
            a.plot(tr[u] - off, tr[v], "-", color=colour, lw=0.7, label=lab, rasterized=True)
        a.set_xlabel(lu)
        a.set_ylabel(lv)
        a.grid(True, lw=0.3)
        a.ticklabel_format(style="sci", scilimits=(-3, 3))
    legend_outside(ax[1])
    fig.suptitle("Rock to vertical (thesis Fig 4.52): mu = 0.2, r = 0.1, k = 1e6, ic1\nthe initial trajectory "
                 "runs along the rim in (w, w') and near y' = 0 in (y, y'); later ones fill the region", fontsize=10)
    save(fig, os.path.join(out, "response_fig4_52.png"))
    return dict(figure="4.52", typical_from=t0,
                initial_max_abs_vy=float(np.max(np.abs(lines[0]["vy"]))),
                typical_max_abs_vy=float(np.max(np.abs(lines[1]["vy"]))),
                initial_max_abs_w=float(np.max(np.abs(lines[0]["w"]))),
                typical_max_abs_w=float(np.max(np.abs(lines[1]["w"]))))


def main(argv):
    cli, out, tiny = figure_script_args(argv, __doc__)
    rows = [TABLE[0], TABLE[6], TABLE[11]] if tiny else TABLE
    t_end = 20 if tiny else T_END
    summary = []
    with tempfile.TemporaryDirectory(prefix="blockdyn-lt-") as tmp:
        for fig, mu, r, k, ic, thesis in rows:
            if fig == "4.52":  # the same block as 4.51, drawn with its trajectories
                summary.append(fig_4_52(cli, tmp, out, t_end, 1 if tiny else 5))
                continue
            js = os.path.join(tmp, "r.json")
            cli("response", "--mu", mu, "--r", r, "--k", k, "--ic", ic, "--t-end", t_end, "--phase-dt", 0.1,
                "--plot", os.path.join(out, f"response_fig{fig.replace('.', '_')}.png"), "--json-out", js)
            with open(js) as f:
                s = json.load(f)
            m = s["metrics"]
            summary.append(dict(figure=fig, mu=mu, r=r, k=k, ic=ic, thesis=thesis, ours=s["type"],
                                agrees=s["type"] == thesis.replace(" ", "_").replace("-", "_"),
                                **{key: m.get(key) for key in ("late_flight_fraction", "dissipated_fraction")}))
        summary.append(fig_4_56(cli, tmp, out, t_end))
    print(cli.summary("fig-long-term", "figures", summary))


if __name__ == "__main__":
    main(sys.argv)
