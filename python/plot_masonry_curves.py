#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""docs/masonry.md's curves: the arch's collapse multiplier lambda against t/R (one curve per
voussoir count) and against the number of voussoirs, with the minimum thickness marked.

usage: plot_masonry_curves.py LAMBDA_T.csv LAMBDA_N.csv OUT.png
LAMBDA_T.csv: voussoirs,ratio,lambda   LAMBDA_N.csv: voussoirs,lambda,min_thickness_ratio"""
import sys

from plotkit import plt, read_rows, save  # noqa: E402


def main():
    by_t, by_n, out = sys.argv[1], sys.argv[2], sys.argv[3]
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.2), constrained_layout=True)
    curves = {}
    for r in read_rows(by_t):
        curves.setdefault(int(r["voussoirs"]), []).append((float(r["ratio"]), float(r["lambda"])))
    for n, pts in sorted(curves.items()):
        pts.sort()
        a1.plot([p[0] for p in pts], [p[1] for p in pts], "o-", ms=3, label=f"{n} voussoirs")
    a1.axvline(0.1075, color="k", ls=":", lw=1, label="Milankovitch t/R = 0.1075 (continuous arch)")
    a1.axhline(0, color="k", lw=0.6)
    a1.set_xlabel("ring thickness / centreline radius t/R")
    a1.set_ylabel("lambda = a_H / g at collapse")
    a1.set_title("semicircular arch: static collapse multiplier", fontsize=10)
    a1.legend(fontsize=8)
    rows = read_rows(by_n)
    ns = [int(r["voussoirs"]) for r in rows]
    a2.plot(ns, [float(r["lambda"]) for r in rows], "o-", color="C0", ms=4, label="lambda at t/R = 0.15")
    a2.set_xscale("log")
    a2.set_xlabel("voussoirs")
    a2.set_ylabel("lambda", color="C0")
    b = a2.twinx()
    b.plot(ns, [float(r["min_thickness_ratio"]) for r in rows], "s--", color="C3", ms=4, label="minimum t/R")
    b.axhline(0.1075, color="C3", ls=":", lw=1)
    b.set_ylabel("minimum thickness t/R", color="C3")
    a2.set_title("against the number of voussoirs", fontsize=10)
    save(fig, out)


if __name__ == "__main__":
    main()
