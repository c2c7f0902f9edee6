# SPDX-License-Identifier: Apache-2.0
"""Arm and energy landscape of the static equilibria (thesis Figs 4.35-4.36).

Usage: plot_equilibria.py LANDSCAPE.csv OUT.png  (reads LANDSCAPE.csv.json for the equilibria)
Writes OUT.png and OUT.svg.
"""
from plotkit import load_meta, load_named, np, plt, run_in_out, save, stem


def main(csv_path, out_png):
    data = load_named(csv_path)
    meta = load_meta(csv_path)
    r, k = meta["params"]["r"], meta["params"]["k"]
    alpha = meta["params"]["alpha"]
    eqs = meta["equilibria"]

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    # The thesis plots the restoring arm (positive = pushes back upright), i.e. -(x_R - x).
    ax1.plot(data["w"], -data["arm"], "k-", lw=1.2)
    ax1.axhline(0.0, color="0.6", lw=0.8)
    ax1.set_xlabel("w")
    ax1.set_ylabel("restoring arm  -(x_R - x)")
    ax1.set_title(f"arm, r = {r:g}, k = {k:g}")
    ax2.plot(data["w"], data["energy"], "k-", lw=1.2, label="-int arm dw (thesis energy)")
    ax2.plot(data["w"], data["potential"], "C1--", lw=1.0, label="springs + gravity V + y")
    ax2.set_xlabel("w")
    ax2.set_ylabel("energy (m g a)")
    ax2.set_title(f"energy, r = {r:g}, k = {k:g}")
    energy_at = np.interp([e["w"] for e in eqs], data["w"], data["energy"])
    for e, en in zip(eqs, energy_at):
        style = dict(marker="o", ms=6, color="C0", ls="none")
        style["mfc"] = "C0" if e["stable"] else "white"
        ax1.plot([e["w"]], [0.0], **style)
        ax2.plot([e["w"]], [en], **style)
    for ax in (ax1, ax2):
        ax.axvline(alpha, color="0.5", ls=":", lw=0.8)
        ax.set_xlim(0.0, alpha * 1.02)
    ax2.plot([], [], "o", color="C0", label="stable")
    ax2.plot([], [], "o", color="C0", mfc="white", label="unstable")
    fig.tight_layout(rect=(0, 0.08, 1, 1))
    # In a band below the panels: inside, the energy curves ran under it.
    fig.legend(*ax2.get_legend_handles_labels(), loc="lower center", ncol=4, fontsize=8, frameon=False)
    save(fig, stem(out_png) + ".png")


if __name__ == "__main__":
    run_in_out(main, __doc__)
