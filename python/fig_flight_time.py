#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Time to first flight versus k (thesis Figs 4.6-4.13), computed with `blockdyn flight-time`.

usage: fig_flight_time.py BLOCKDYN OUTDIR [--tiny]

The thesis plots, per figure, the time of the first flight against k for one (r, mu), ic2 on top
and ic1 below; its captions are lost in the OCR, so the (r, mu) pairs here are ours, except that
the text's example (its Fig 4.7, ic1: first flight at t = 13, first-impact flights at t = 0.55)
fits r = 0.05, mu = 0 (see docs/flight.md). Written into OUTDIR (PNG + SVG):
  flight_time_fig4_6-4_9.png     mu = 0.2, r = 1, 0.5, 0.3, 0.2 (one column per (r, mu))
  flight_time_fig4_10-4_13.png   r = 0.1 and 0.05 at mu = 0.2 and at mu = 0, r = 0.1 at mu = 0.3
Each column: ic2 (top), ic1 (bottom); one point per k (log grid 1e2..1e9, t_end = 30), coloured by
ihor at the first flight (capped at 10); grey crosses: no flight by t_end; grey triangles: overturned first.
Prints a JSON summary per scan: k_min, the lowest k that flies, the k above which every k flies
during the first impact (ic2: ihor = 1; ic1: see first_impact_boundary) and whether that set is upward closed on the grid (the thesis's statement for ic1).
--tiny: two columns of 12 points (for the test that the script runs).
"""
import os
import sys
import tempfile

from plotkit import figure_script_args, legend_below, plt, read_table, save

FIGS = [
    ("flight_time_fig4_6-4_9.png", "4.6-4.9", [(1.0, 0.2), (0.5, 0.2), (0.3, 0.2), (0.2, 0.2)]),
    ("flight_time_fig4_10-4_13.png", "4.10-4.13",
     [(0.1, 0.2), (0.05, 0.2), (0.1, 0.0), (0.05, 0.0), (0.1, 0.3)]),
]
T_END = 30
IHOR_TOP = 10


def first_impact_boundary(k, flew, ihor, time, ic):
    """(lowest k of the final run of grid points that fly during the first impact, whether no
    point below it does so: the set is upward closed on the grid). ic2: flight while ihor = 1
    (the thesis's reading for ic2). ic1: flight while ihor <= 1 and within half as long again as
    the first-impact flight at the largest k (ihor alone would count the flights that start just
    before the second passage through w = 0, i.e. at the second impact)."""
    if ic == "ic2":
        hit = flew & (ihor <= 1)
    else:
        hit = flew & (ihor <= 1) & (time <= 1.5 * time[-1])
    if not hit[-1]:
        return None, False
    i = len(hit) - 1
    while i > 0 and hit[i - 1]:
        i -= 1
    return float(k[i]), not hit[:i].any()


def draw(ax, tab, k_min, cmap, norm):
    k, t, ihor = tab["k"], tab["time"], tab["ihor"]
    flew = tab["flew"] > 0.5
    over = ~flew & (tab["status"] == "overturned")
    ax.scatter(k[flew], t[flew], c=ihor[flew], cmap=cmap, norm=norm, s=9, lw=0, rasterized=True)
    ax.plot(k[~flew & ~over], t[~flew & ~over], "x", color="0.6", ms=3.5, rasterized=True)
    ax.plot(k[over], t[over], "v", color="0.6", ms=3.5, rasterized=True)
    if k_min and k_min > k[0]:
        ax.axvline(k_min, color="C3", lw=0.8, ls=":")
    ax.set_xscale("log")
    ax.set_ylim(-0.5, 1.05 * T_END)
    ax.grid(True, which="major", lw=0.3)


def main(argv):
    cli, out, tiny = figure_script_args(argv, __doc__)
    points = 12 if tiny else 200
    figs = [(FIGS[0][0], FIGS[0][1], FIGS[0][2][:2])] if tiny else FIGS
    cmap = plt.get_cmap("viridis")
    summary = []
    with tempfile.TemporaryDirectory(prefix="blockdyn-ft-") as tmp:
        for name, label, cols in figs:
            fig, ax = plt.subplots(2, len(cols), figsize=(3.3 * len(cols) + 1.5, 6.2), sharex=True, sharey="row",
                                   squeeze=False, constrained_layout=True)
            tabs = {}
            for j, (r, mu) in enumerate(cols):
                for ic in ("ic2", "ic1"):
                    path = os.path.join(tmp, f"{ic}_{r}_{mu}.csv")
                    js = os.path.join(tmp, f"{ic}_{r}_{mu}.json")
                    cli("flight-time", "--ic", ic, "--r", r, "--mu", mu, "--k-min", 1e2, "--k-max", 1e9,
                        "--points", points, "--t-end", T_END, "--csv", path, "--json", js)
                    tabs[(j, ic)] = read_table(path)
            norm = plt.Normalize(0, IHOR_TOP)  # most first flights come within a few passages
            for j, (r, mu) in enumerate(cols):
                kmins = cli.json("kmin", "--mu", mu, "--ic", "ic1,ic2", "--r-min", r, "--r-max", r * 1.001,
                                 "--points", 2, "--json", "-")["curves"]
                for i, ic in enumerate(("ic2", "ic1")):
                    tab = tabs[(j, ic)]
                    k_min = kmins[ic][0]["value"] if kmins[ic][0]["status"] == "found" else None
                    draw(ax[i, j], tab, k_min, cmap, norm)
                    flew = tab["flew"] > 0.5
                    k_fly = float(tab["k"][flew].min()) if flew.any() else None
                    k_first, closed = first_impact_boundary(tab["k"], flew, tab["ihor"], tab["time"], ic)
                    summary.append(dict(figure=label, ic=ic, r=r, mu=mu, k_min=k_min, lowest_k_flying=k_fly,
                                        time_at_lowest_k_flying=float(tab["time"][flew][0]) if k_fly else None,
                                        first_impact_flight_from_k=k_first, upward_closed=closed,
                                        time_at_k_max=float(tab["time"][-1])))
                    txt = (f"{ic}: lowest k flying {k_fly:.2g}" if k_fly else f"{ic}: no flight") + \
                        (f"\nfirst-impact flight for k >= {k_first:.2g}" if k_first else "")
                    ax[i, j].text(0.97, 0.95, txt, transform=ax[i, j].transAxes, fontsize=7, va="top", ha="right",
                                  bbox=dict(fc="white", ec="none", alpha=0.8))
                ax[0, j].set_title(f"r = {r}, mu = {mu}", fontsize=9)
                ax[1, j].set_xlabel("k")
            ax[0, 0].set_ylabel("ic2: time to first flight")
            ax[1, 0].set_ylabel("ic1: time to first flight")
            sm = plt.cm.ScalarMappable(norm=norm, cmap=cmap)
            fig.colorbar(sm, ax=ax, label="ihor at the first flight", shrink=0.6, extend="max")
            handles = [plt.Line2D([], [], ls="", marker="x", color="0.6", label=f"no flight by t = {T_END}"),
                       plt.Line2D([], [], ls="", marker="v", color="0.6", label="overturned first"),
                       plt.Line2D([], [], ls=":", color="C3", label="k_min (E0 = 0)")]
            legend_below(fig, handles, ncol=3, height=0.06)
            fig.suptitle(f"Time to first flight versus k (thesis Figs {label} family), t_end = {T_END}", fontsize=10)
            save(fig, os.path.join(out, name))
    print(cli.summary("fig-flight-time", "panels", summary))


if __name__ == "__main__":
    main(sys.argv)
