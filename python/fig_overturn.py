#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Time and ihor at overturning versus k, ic2 (thesis Figs 4.21-4.28), with `blockdyn overturn`.

usage: fig_overturn.py BLOCKDYN OUTDIR [--tiny]

One figure per thesis figure, two aspect ratios side by side (time at overturning on top, ihor
below, t_end = 30 as in the thesis; a block that does not overturn is plotted at t_end with its
ihor then). The pairs the OCR keeps are the thesis's (4.21: mu = 0, r = 0.15; 4.22: mu = 0.1,
r = 0.3 and 0.125; 4.23: mu = 0.1, r = 0.092; 4.25: mu = 0.2, r = 0.2 and 0.1; 4.26: mu = 0.2,
r = 0.055); the others are ours, chosen to show what the text describes (4.24: r so small that the
block overturns for every k; 4.27-4.28: mu = 0.3). Written into OUTDIR: overturn_fig4_21.png ...
overturn_fig4_28.png (+ SVG). Each panel marks k2_stability and k3_stability (`--window-points`
resolves the second-swing window between them) and k_uns (no stable equilibrium below it).
Prints a JSON summary per panel (k2, k3, overturning counts, the lowest grid k without
overturning, whether any k above it overturns again: the thesis's "exceptions").
--tiny: one figure with 10 points per panel (for the test that the script runs).
"""
import json
import os
import sys
import tempfile

from plotkit import figure_script_args, np, plt, read_table, save

FIGS = [  # (figure, mu, [(r, k_min, k_max), ...])
    ("4.21", 0.0, [(0.3, 10, 1e5), (0.15, 10, 1e6)]),
    ("4.22", 0.1, [(0.3, 10, 1e5), (0.125, 10, 1e6)]),
    ("4.23", 0.1, [(0.1, 1e2, 1e6), (0.092, 1e2, 1e7)]),
    ("4.24", 0.1, [(0.08, 1e2, 1e7), (0.07, 1e2, 1e7)]),
    ("4.25", 0.2, [(0.2, 20, 2e3), (0.1, 1e2, 5e3)]),
    ("4.26", 0.2, [(0.055, 1e2, 1e7), (0.05, 1e2, 1e7)]),
    ("4.27", 0.3, [(0.2, 20, 1e5), (0.1, 1e2, 1e6)]),
    ("4.28", 0.3, [(0.04, 1e2, 1e7), (0.035, 1e2, 1e7)]),
]
T_END = 30


def panel(ax_t, ax_i, tab, meta):
    k, t, ihor = tab["k"], tab["time"], tab["ihor"]
    over = tab["overturned"] > 0.5
    for a, y in ((ax_t, t), (ax_i, ihor)):
        a.plot(k[over], y[over], "k.", ms=3.5, label="overturned")
        a.plot(k[~over], y[~over], "x", color="0.55", ms=3.5, label=f"no overturning by t = {T_END}")
        if meta.get("k_uns"):
            a.axvline(meta["k_uns"], color="C0", ls=":", lw=1.0, label="k_uns (no stable equilibrium below)")
        win = meta.get("second_swing_window") or {}
        for key, style in (("k2_stability", "-"), ("k3_stability", "--")):
            if win.get(key):
                a.axvline(win[key], color="C1", ls=style, lw=0.8, label=key)
        a.set_xscale("log")
        a.grid(True, lw=0.3)
    ax_i.set_xlabel("k")
    # The thesis's exceptions: overturning again above the lowest k that did not overturn.
    i0 = int(np.argmax(~over)) if (~over).any() else None
    again = bool(i0 is not None and over[i0:].any())
    win = meta.get("second_swing_window") or {}
    return dict(runs=int(len(k)), overturned=int(over.sum()), overturned_ihor1=int((over & (ihor <= 1)).sum()),
                overturned_ihor2=int((over & (ihor == 2)).sum()), overturned_ihor3plus=int((over & (ihor >= 3)).sum()),
                lowest_k_without_overturning=float(k[i0]) if i0 is not None else None,
                overturns_again_above_it=again, k2_stability=win.get("k2_stability"),
                k3_stability=win.get("k3_stability"), k_uns=meta.get("k_uns"))


def main(argv):
    cli, out, tiny = figure_script_args(argv, __doc__)
    figs = [FIGS[4]] if tiny else FIGS
    points, window = (10, 4) if tiny else (120, 40)
    summary = []
    with tempfile.TemporaryDirectory(prefix="blockdyn-ov-") as tmp:
        for label, mu, cols in figs:
            fig, ax = plt.subplots(2, len(cols), figsize=(4.2 * len(cols) + 2.6, 6), sharex="col",
                                   squeeze=False, constrained_layout=True)
            for j, (r, k_lo, k_hi) in enumerate(cols):
                path = os.path.join(tmp, f"ov_{label}_{j}.csv")
                js = os.path.join(tmp, f"ov_{label}_{j}.json")
                cli("overturn", "--ic", "ic2", "--r", r, "--mu", mu, "--k-min", k_lo, "--k-max", k_hi,
                    "--points", points, "--window-points", window, "--t-end", T_END, "--csv", path, "--json", js)
                with open(js) as f:
                    meta = json.load(f)
                res = panel(ax[0, j], ax[1, j], read_table(path), meta)
                summary.append(dict(figure=label, r=r, mu=mu, **res))
                k2, k3 = res["k2_stability"], res["k3_stability"]
                crit = f"k2 = {k2:.4g}, k3 = {k3:.4g}" if k2 and k3 else "no k2/k3 in range"
                ax[0, j].set_title(f"r = {r}, mu = {mu}: {crit}\n{res['overturned']} of {res['runs']} overturn "
                                   f"({res['overturned_ihor1']} with ihor 1, {res['overturned_ihor2']} with ihor 2)",
                                   fontsize=8)
            ax[0, 0].set_ylabel("time at overturning\n(t_end if none)")
            ax[1, 0].set_ylabel("ihor at overturning\n(at t_end if none)")
            labels = {}
            for a in ax[0]:
                for h, lab in zip(*a.get_legend_handles_labels()):
                    labels.setdefault(lab, h)
            ax[0, -1].legend(labels.values(), labels.keys(), loc="upper left", bbox_to_anchor=(1.01, 1.0),
                             borderaxespad=0.0, fontsize=8)
            fig.suptitle(f"Time and ihor at overturning versus k, ic2 (thesis Fig {label}), t_end = {T_END}",
                         fontsize=10)
            save(fig, os.path.join(out, f"overturn_fig{label.replace('.', '_')}.png"))
    print(cli.summary("fig-overturn", "panels", summary))


if __name__ == "__main__":
    main(sys.argv)
