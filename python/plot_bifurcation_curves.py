"""Critical stiffnesses k_os(r), k_uns(r) and their difference (thesis Fig 4.40).

Usage: plot_bifurcation_curves.py CURVES.csv OUT.png   Writes OUT.png and OUT.svg.
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main(csv_path, out_png):
    d = np.genfromtxt(csv_path, delimiter=",", names=True)
    d = np.atleast_1d(d)
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
    stem = os.path.splitext(out_png)[0]
    fig.savefig(stem + ".png", dpi=110)
    fig.savefig(stem + ".svg")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
