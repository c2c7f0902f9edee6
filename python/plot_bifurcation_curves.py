# SPDX-License-Identifier: Apache-2.0
"""Critical stiffnesses k_os(r), k_uns(r) and their difference (thesis Fig 4.40).

Usage: plot_bifurcation_curves.py CURVES.csv OUT.png   Writes OUT.png and OUT.svg.
"""
from plotkit import load_named, plt, run_in_out, save, stem


def main(csv_path, out_png):
    d = load_named(csv_path)
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(7, 7), sharex=True)
    ax1.semilogy(d["r"], d["k_os"], "k-", label="k_os(r)")
    ax1.semilogy(d["r"], d["k_uns"], "C3--", label="k_uns(r)")
    ax1.set_ylabel("k")
    ax1.legend()
    ax1.set_title("equilibrium bifurcation in the (k, r) plane")
    ax2.plot(d["r"], d["k_os_minus_k_uns"], "k-", label="k_os - k_uns")
    ax2.plot(d["r"], d["small_angle_minus_k_os"], "C0-.", label="6/r^2 - 0.5 - k_os")
    ax2.axhline(5.0 / 6.0, color="0.5", ls=":", lw=0.8, label="5/6 (small-r limit)")
    ax2.set_xlabel("r")
    ax2.set_ylabel("k difference")
    ax2.legend(fontsize=8)
    fig.tight_layout()
    save(fig, stem(out_png) + ".png")


if __name__ == "__main__":
    run_in_out(main, __doc__)
