# SPDX-License-Identifier: Apache-2.0
"""Figure of an assembly run: each block's rotation and horizontal displacement, the contact
forces per interface, the ground acceleration and the energy balance.
Usage: plot_assembly.py TRAJECTORY.csv OUT.png [--title T]"""
from assembly_csv import load  # noqa: E402
from plotkit import save, figure_parser, plt  # noqa: E402


def main():
    ap = figure_parser()
    a = ap.parse_args()
    c, nb, npts = load(a.csv)
    t = c["t"]
    fig, ax = plt.subplots(4, 1, figsize=(9, 10), sharex=True)
    for b in range(nb):
        ax[0].plot(t, c[f"theta_{b}"], lw=0.8, label=f"block {b}")
        ax[1].plot(t, c[f"x_{b}"] - c[f"x_{b}"][0], lw=0.8, label=f"block {b}")
    ax[0].set_ylabel("rotation [rad]")
    ax[1].set_ylabel("x - x(0) [m]")
    for i in range(npts // 2):
        ax[2].plot(t, c[f"fn_{i}_0"] + c[f"fn_{i}_1"], lw=0.7, label=f"interface {i}")
    ax[2].set_ylabel("normal force [N]")
    ax[3].plot(t, c["a_h"], lw=0.8, color="k", label="a_h [g]")
    ax3b = ax[3].twinx()
    ax3b.plot(t, c["energy_balance"], lw=0.8, color="tab:red", label="energy balance error [J]")
    ax3b.set_ylabel("balance error [J]", color="tab:red")
    ax[3].set_ylabel("ground acc. [g]")
    ax[3].set_xlabel("t [s]")
    for x in ax[:3]:
        x.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8)
        x.grid(alpha=0.3)
    fig.suptitle(a.title, fontsize=10)
    fig.tight_layout()
    save(fig, a.out, dpi=120)


if __name__ == "__main__":
    main()
