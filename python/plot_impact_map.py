# SPDX-License-Identifier: Apache-2.0
"""Impact map and forced Poincare map (seed 002 Fig. 15): (a) the trajectory in the (theta,
theta') plane, (b) the forcing phase of each impact against the angular velocity before it,
(c) the state at the forcing phase phi0 once per period.
Usage: plot_impact_map.py IMPACTS.csv OUT.png --poincare SECTION.csv --trace TRACE.csv --block B
[--section-phase PHI0] [--title T]"""
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from plotkit import figure_parser, save  # noqa: E402


def load(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in (rows[0].keys() if rows else [])}


def main():
    ap = figure_parser()
    ap.add_argument("--poincare", required=True)
    ap.add_argument("--trace", required=True)
    ap.add_argument("--block", type=int, default=0)
    ap.add_argument("--section-phase", default="0")
    ap.add_argument("--period", type=float, default=0.0, help="forcing period: (a) shows the last 30 periods")
    a = ap.parse_args()
    b = a.block
    imp, sec, tr = load(a.csv), load(a.poincare), load(a.trace)
    fig, ax = plt.subplots(1, 3, figsize=(14, 4.6))
    span = "whole run"
    if tr:
        sel = np.ones(len(tr["t"]), dtype=bool)
        if a.period > 0 and tr["t"][-1] - tr["t"][0] > 30 * a.period:
            sel = tr["t"] >= tr["t"][-1] - 30 * a.period
            span = "last 30 periods"
        ax[0].plot(tr[f"theta_{b}"][sel], tr[f"omega_{b}"][sel], lw=0.5, color="C0")
    ax[0].set_xlabel(f"theta_{b} [rad]")
    ax[0].set_ylabel(f"theta'_{b} [rad/s]")
    ax[0].set_title(f"(a) trajectory, {span}", fontsize=9)
    if imp:
        ax[1].plot(imp["phase"], imp["omega_before"], ".", ms=2.5, color="C3")
    ax[1].set_xlim(0, 2 * np.pi)
    ax[1].set_xticks([0, np.pi / 2, np.pi, 3 * np.pi / 2, 2 * np.pi])
    ax[1].set_xticklabels(["0", "pi/2", "pi", "3pi/2", "2pi"])
    ax[1].set_xlabel("Phi = (Omega t + phase) mod 2 pi")
    ax[1].set_ylabel(f"theta'_{b} before impact [rad/s]")
    ax[1].set_title(f"(b) impact map, {len(imp.get('phase', []))} impacts", fontsize=9)
    if sec:
        ax[2].plot(sec[f"theta_{b}"], sec[f"omega_{b}"], ".", ms=2.5, color="C2")
    ax[2].set_xlabel(f"theta_{b} [rad]")
    ax[2].set_ylabel(f"theta'_{b} [rad/s]")
    ax[2].set_title(f"(c) Poincare section at forcing phase {a.section_phase}, {len(sec.get('t', []))} points",
                    fontsize=9)
    for x in ax:
        x.grid(alpha=0.3)
    if a.title:
        fig.suptitle(a.title, fontsize=10)
    fig.tight_layout()
    save(fig, a.out, dpi=120)


if __name__ == "__main__":
    main()
