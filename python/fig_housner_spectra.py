#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Housner-block overturning spectra (blockdyn spectrum --json-out) for the rectangular, half-sine
and one-sine pulses against the linearised model (small alpha).

usage: fig_housner_spectra.py RECT.json HALF_SINE.json ONE_SINE.json OUT.png

Linearised rocking, phi = theta / alpha pushed by the pulse a(t) = F g alpha s(t):
    phi'' = p^2 (phi - 1 + F s(t))   while phi > 0,
uplift when F s(t) first exceeds 1. For a rectangular pulse the threshold is the spec's closed
form F* = 1 / (1 - exp(-p t_p)). For s = sin(w t) the motion from uplift at t0 is in closed form,
    phi = 1 + C sin(w t) - (1 + C sin(w t0)) cosh(p (t - t0)) - (C w cos(w t0) / p) sinh(p (t - t0)),
    C = -F p^2 / (p^2 + w^2),
and after the pulse the free block escapes iff (phi - 1) + phi'/p > 0 at t_p (the component on
the unstable eigenvector). F* is the smallest F for which the block escapes without returning to
phi = 0 during the pulse ("overturning without impact"); a one-sine pulse can also overturn after
an impact, below this curve (Zhang & Makris 2001), which the nonlinear spectrum shows.
"""
import json
import math
import sys

from plotkit import np, plt, save


def sine_escapes(F, tp, p, w, lobe_end):
    """Whether the linearised block uplifted by F sin(w t) escapes without impact by t_p."""
    if F <= 1.0:
        return False
    t0 = math.asin(1.0 / F) / w
    if t0 >= lobe_end:
        return False
    C = -F * p * p / (p * p + w * w)
    d1 = -(1.0 + C * math.sin(w * t0))
    d2 = -C * w * math.cos(w * t0) / p
    t = np.linspace(t0, tp, 4001)[1:]
    u = p * (t - t0)
    phi = 1.0 + C * np.sin(w * t) + d1 * np.cosh(u) + d2 * np.sinh(u)
    if np.any(phi <= 0.0):
        return False  # back on the base during the pulse: an impact, not this mode
    dphi = C * w * math.cos(w * tp) + p * (d1 * math.sinh(u[-1]) + d2 * math.cosh(u[-1]))
    return (phi[-1] - 1.0) + dphi / p > 0.0


def threshold(kind, tp, p, fmax=2000.0):
    """Smallest F (amplitude over g alpha) that overturns the linearised block without impact."""
    if kind == "rect":
        return 1.0 / (1.0 - math.exp(-p * tp))
    w = (math.pi if kind == "half-sine" else 2.0 * math.pi) / tp
    lobe_end = math.pi / w
    test = lambda F: sine_escapes(F, tp, p, w, lobe_end)  # noqa: E731
    grid = np.geomspace(1.0 + 1e-9, fmax, 400)
    hit = next((k for k, F in enumerate(grid) if test(F)), None)
    if hit is None:
        return float("nan")
    if hit == 0:
        return grid[0]
    lo, hi = grid[hit - 1], grid[hit]
    while hi - lo > 1e-7 * hi:
        mid = math.sqrt(lo * hi)
        lo, hi = (lo, mid) if test(mid) else (mid, hi)
    return hi


def main():
    files, out = sys.argv[1:4], sys.argv[4]
    fig, axes = plt.subplots(1, 3, figsize=(14, 4.6), sharey=True)
    for ax, path in zip(axes, files):
        with open(path) as f:
            j = json.load(f)
        kind, alpha, p = j["pulse"], j["alpha"], j["p"]
        d = np.array([r["duration"] for r in j["rows"]])
        a = np.array([np.nan if r["min_overturning_amplitude"] is None else r["min_overturning_amplitude"]
                      for r in j["rows"]]) / alpha
        lin = np.array([threshold(kind, t, p) for t in d])
        ax.plot(p * d, a, "o-", ms=3, label="blockdyn (nonlinear Housner model)")
        ax.plot(p * d, lin, "k--", lw=1.2, label="linearised, overturning without impact" if kind != "rect"
                else "linearised closed form 1/(1 - exp(-p t_p))")
        isl = [k for k, r in enumerate(j["rows"]) if r["safe_islands"]]
        if isl:
            ax.plot(p * d[isl], a[isl], "^", color="tab:green", ms=6, label="safe islands above the minimum")
        ok = np.isfinite(a) & np.isfinite(lin)
        if ok.any():
            dev = np.max(np.abs(a[ok] / lin[ok] - 1.0))
            ax.text(0.03, 0.04, f"max |blockdyn / linearised - 1| = {100 * dev:.1f} %", transform=ax.transAxes,
                    fontsize=8)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("p t_p")
        ax.set_title(f"{kind} pulse (alpha = {alpha:.3f}, p = {p:.3f} rad/s)", fontsize=9)
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=7, loc="upper right")
    axes[0].set_ylabel("smallest overturning amplitude a_p / (g alpha)")
    fig.tight_layout()
    save(fig, out)


if __name__ == "__main__":
    main()
