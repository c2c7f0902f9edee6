# SPDX-License-Identifier: Apache-2.0
"""theta_MAX / alpha versus omega (or versus the friction angle phi_l with --x phi_l), one curve
per beta (and per phi_s when it varies), collapsed points marked, and the largest slip between
blocks over b when any. Usage: plot_response_curve.py POINTS.csv OUT.png [--title T] [--x omega|phi_l]"""
import csv

from plotkit import save, figure_parser, plt  # noqa: E402


def main():
    ap = figure_parser()
    ap.add_argument("--x", default="omega", choices=["omega", "phi_l"])
    a = ap.parse_args()
    with open(a.csv, newline="") as f:
        rows = list(csv.DictReader(f))
    # Curves: one per value of the parameters that are not the abscissa and vary.
    keys = [k for k in ("beta", "phi_s", "phi_l", "omega") if k != a.x and k in rows[0]
            and len({r[k] for r in rows}) > 1]

    def label(r):
        names = {"beta": "beta", "phi_s": "phi_s", "phi_l": "phi_l", "omega": "omega"}
        return ", ".join(f"{names[k]} = {float(r[k]):g}" for k in keys) or "response"

    curves = {}
    for r in rows:
        curves.setdefault(tuple(r[k] for k in keys), []).append(r)
    sliding = any(float(r["max_sliding_over_b"]) > 0 for r in rows)
    fig, axes = plt.subplots(2 if sliding else 1, 1, figsize=(8, 7 if sliding else 4.5), sharex=True, squeeze=False)
    ax = axes[0][0]
    for _, rs in sorted(curves.items(), key=lambda kv: tuple(float(x) for x in kv[0])):
        rs = sorted(rs, key=lambda r: float(r[a.x]))
        x = [float(r[a.x]) for r in rs]
        th = [float(r["theta_max_over_alpha"]) for r in rs]
        line, = ax.plot(x, th, "o-", ms=3, label=label(rs[0]))
        col = [(u, y) for u, y, r in zip(x, th, rs) if r["motion"] == "collapse"]
        if col:
            ax.plot(*zip(*col), "x", color=line.get_color(), ms=8)
        if sliding:
            axes[1][0].plot(x, [float(r["max_sliding_over_b"]) for r in rs], "o-", ms=3, color=line.get_color())
    ax.axhline(1.0, color="0.5", lw=0.8, ls="--")
    ax.set_ylabel("theta_MAX / alpha (x: collapsed)")
    ax.set_title(a.title, fontsize=9)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    ax.grid(alpha=0.3)
    if sliding:
        axes[1][0].set_ylabel("max slip between blocks / b")
        axes[1][0].grid(alpha=0.3)
    axes[-1][0].set_xlabel("omega = Omega / p" if a.x == "omega" else "friction angle between blocks phi_l [deg]")
    fig.tight_layout()
    save(fig, a.out, dpi=120)


if __name__ == "__main__":
    main()
