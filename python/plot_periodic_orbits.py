# SPDX-License-Identifier: Apache-2.0
"""Rocking periodic orbits of the Housner block (blockdyn periodic-orbits).

  --kind orbits    TRAJ.csv (orbit, stable, t, theta, rate): theta(t) over one period and the
                   phase portrait, stable orbits solid, unstable dashed;
  --kind branches  BRANCHES.csv: the impact velocity u = theta'/(alpha p) and the largest
                   |multiplier| along each branch against the parameter, stable solid, unstable
                   dashed, folds and symmetry-breaking / flip points marked; with --linear
                   "alpha,e,n,symmetric,ks,omega" the linearised closed form (grey) beside it;
  --kind region    REGION.csv: where orbits exist and where one is stable over (omega, K_s), with
                   the linearised model's fold and stability boundaries (lines).
Usage: plot_periodic_orbits.py CSV OUT.png --kind K [--parameter ks|omega] [--title T] [--linear L]
"""
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from plotkit import figure_parser, cell_edges, save  # noqa: E402


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def linear_orbits(beta, omega, e, n):
    """Closed form of the linearised symmetric (1, n) orbits (as linear_rocking_orbits.cpp)."""
    sigma = n * np.pi / omega
    ch, sh = np.cosh(sigma), np.sinh(sigma)
    B = beta / (1 + omega ** 2)
    a, b, c = (1 + ch) * (1 + e), omega * sh * (1 - e), (ch - 1) * (1 - e) / B
    R = np.hypot(a, b)
    if abs(c) > R:
        return []
    psi, asn = np.arctan2(b, a), np.arcsin(c / R)
    out = []
    for phi in (asn - psi, np.pi - asn - psi):
        S, C = np.sin(phi), np.cos(phi)
        u = ((ch - 1) - B * S * (1 + ch) - B * omega * C * sh) / sh
        s = np.linspace(0, sigma, 2001)[1:-1]
        x = 1 + (B * S - 1) * np.cosh(s) + (u + B * omega * C) * np.sinh(s) - B * np.sin(omega * s + phi)
        if u <= 0 or x.min() <= 0:
            continue
        am, ap = -1 - beta * S, 1 - beta * S
        s21 = (ap - e * am) / (-u / e) if e > 0 else 0.0
        H = -np.array([[e, 0.0], [s21, e]]) @ np.array([[ch, sh], [sh, ch]])
        mu = np.abs(np.linalg.eigvals(H)) ** 2
        out.append((u, mu.max()))
    return out


def style(stable):
    return dict(ls="-" if stable else "--", lw=1.6 if stable else 1.0)


def plot_orbits(rows, ax_pair, title):
    ax1, ax2 = ax_pair
    orbits = sorted({int(r["orbit"]) for r in rows})
    for k in orbits:
        rr = [r for r in rows if int(r["orbit"]) == k]
        st = rr[0]["stable"] == "1"
        t = np.array([float(r["t"]) for r in rr])
        th = np.array([float(r["theta"]) for r in rr])
        w = np.array([float(r["rate"]) for r in rr])
        lab = f"orbit {k} ({'stable' if st else 'unstable'})"
        ax1.plot(t, th, label=lab, **style(st))
        ax2.plot(th, w, label=lab, **style(st))
    ax1.set_xlabel("t from the reference impact [s]")
    ax1.set_ylabel("theta [rad]")
    ax2.set_xlabel("theta [rad]")
    ax2.set_ylabel("theta' [rad/s]")
    for a in ax_pair:
        a.grid(alpha=0.3)
        a.axhline(0, color="k", lw=0.5)
    ax1.legend(fontsize=7)
    ax1.set_title(title, fontsize=9)


def plot_branches(rows, par, lin, title):
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(8, 7.5), sharex=True)
    key = "ks" if par == "ks" else "omega"
    labelled = []
    xs_all = [float(r[key]) for r in rows] or [0.0]
    us_all = [float(r["velocity"]) for r in rows] or [0.0]
    xspan, uspan = (max(xs_all) - min(xs_all)) or 1.0, (max(us_all) - min(us_all)) or 1.0
    for b in sorted({int(r["branch"]) for r in rows}):
        rr = [r for r in rows if int(r["branch"]) == b]
        x = np.array([float(r[key]) for r in rr])
        u = np.array([float(r["velocity"]) for r in rr])
        mu = np.array([max(float(r["mu1_abs"]), float(r["mu2_abs"])) for r in rr])
        st = np.array([r["stable"] == "1" for r in rr])
        # Stable and unstable stretches drawn separately.
        start = 0
        for i in range(1, len(rr) + 1):
            if i == len(rr) or st[i] != st[start]:
                sl = slice(start, min(i + 1, len(rr)))
                ax1.plot(x[sl], u[sl], color="C0" if st[start] else "C3", **style(st[start]))
                ax2.semilogy(x[sl], mu[sl], color="C0" if st[start] else "C3", **style(st[start]))
                start = i
        for r, xi, ui in zip(rr, x, u):
            ev = r["event"]
            if ev:
                mk = "o" if "fold" in ev else "s" if "symmetry" in ev else "^" if "flip" in ev else "D"
                ax1.plot(xi, ui, mk, color="k", ms=6, mfc="none")
                # One label per event and place: the same event found twice nearby printed twice.
                near = [(xa, ua) for e2, xa, ua in labelled
                        if e2 == ev and abs(xa - xi) <= 0.03 * xspan and abs(ua - ui) <= 0.03 * uspan]
                if not near:
                    ax1.annotate(ev, (xi, ui), fontsize=7, xytext=(4, 4), textcoords="offset points")
                    labelled.append((ev, xi, ui))
    if lin:
        alpha, e, n, sym, ks0, om0 = lin
        if sym:
            xs = np.linspace(*ax1.get_xlim(), 400)
            pts_u, pts_x, pts_mu = [], [], []
            for xv in xs:
                beta = xv / alpha if par == "ks" else ks0 / alpha
                om = om0 if par == "ks" else xv
                if beta <= 0 or om <= 0:
                    continue
                for u, mu in linear_orbits(beta, om, e, int(n)):
                    pts_x.append(xv)
                    pts_u.append(u)
                    pts_mu.append(mu)
            ax1.plot(pts_x, pts_u, ".", color="0.6", ms=2, label="linearised closed form", zorder=0)
            ax2.plot(pts_x, pts_mu, ".", color="0.6", ms=2, zorder=0)
            ax1.legend(fontsize=7)
    ax1.plot([], [], color="C0", label="stable")
    ax1.plot([], [], color="C3", ls="--", label="unstable")
    ax1.legend(fontsize=7)
    ax1.set_ylabel("u = theta'+ / (alpha p) at the impact")
    ax2.axhline(1.0, color="k", lw=0.6)
    lo, hi = ax2.get_ylim()
    ax2.set_ylim(lo, min(hi, 1e4))  # next to grazing the multipliers are unbounded
    ax2.set_ylabel("largest |Floquet multiplier|")
    ax2.set_xlabel("K_s [g]" if par == "ks" else "omega = Omega / p")
    for a in (ax1, ax2):
        a.grid(alpha=0.3)
    ax1.set_title(title, fontsize=9)
    return fig


def plot_region(rows, lin, title):
    fig, ax = plt.subplots(figsize=(8, 5.5))
    om = sorted({float(r["omega"]) for r in rows})
    ks = sorted({float(r["ks"]) for r in rows})
    cls = np.zeros((len(ks), len(om)))
    lin_ex = np.full((len(ks), len(om)), np.nan)
    lin_st = np.full((len(ks), len(om)), np.nan)
    for r in rows:
        i, j = ks.index(float(r["ks"])), om.index(float(r["omega"]))
        cls[i, j] = 2 if int(r["stable"]) > 0 else 1 if int(r["orbits"]) > 0 else 0
        if int(r["linear_orbits"]) >= 0:
            lin_ex[i, j] = float(int(r["linear_orbits"]) > 0)
            lin_st[i, j] = float(int(r["linear_stable"]) > 0)

    from matplotlib.colors import ListedColormap
    cmap = ListedColormap(["white", "#f4b6b6", "#7fb3e0"])
    ax.pcolormesh(cell_edges(om), cell_edges(ks), cls, cmap=cmap, vmin=-0.5, vmax=2.5, shading="flat")
    ax.plot([], [], "s", color="#f4b6b6", label="orbits exist, all unstable")
    ax.plot([], [], "s", color="#7fb3e0", label="a stable orbit exists")
    if lin and lin[3] and len(om) > 1 and len(ks) > 1:
        alpha, e, n = lin[0], lin[1], int(lin[2])
        ax.contour(om, ks, np.nan_to_num(lin_st), levels=[0.5], colors="navy", linewidths=1.0, linestyles="--")
        ax.plot([], [], color="navy", ls="--", label="linearised: stability boundary")
        w = np.linspace(om[0], om[-1], 300)
        sig = n * np.pi / w
        ch, sh = np.cosh(sig), np.sinh(sig)
        fold = (ch - 1) * (1 - e) * (1 + w ** 2) / np.hypot((1 + ch) * (1 + e), w * sh * (1 - e))
        ax.plot(w, alpha * fold, color="k", lw=1.2, label="linearised fold (existence)")
        ax.set_ylim(ks[0] - 0.5 * (ks[1] - ks[0]), ks[-1] + 0.5 * (ks[1] - ks[0]))
    ax.set_xlabel("omega = Omega / p")
    ax.set_ylabel("K_s [g]")
    ax.set_title(title, fontsize=9)
    # Beside the axes: inside, it covered the regions it explains.
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
    return fig


def main():
    ap = figure_parser()
    ap.add_argument("--kind", choices=["orbits", "branches", "region"], required=True)
    ap.add_argument("--parameter", default="ks")
    ap.add_argument("--linear", default="")
    a = ap.parse_args()
    rows = read(a.csv)
    lin = [float(x) for x in a.linear.split(",")] if a.linear else None
    if a.kind == "orbits":
        fig, axs = plt.subplots(1, 2, figsize=(11, 4.5))
        plot_orbits(rows, axs, a.title)
    elif a.kind == "branches":
        fig = plot_branches(rows, a.parameter, lin, a.title)
    else:
        fig = plot_region(rows, lin, a.title)
    fig.tight_layout()
    save(fig, a.out, dpi=120)


if __name__ == "__main__":
    main()
