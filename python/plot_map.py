#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Response map over (1/r, k) with boundary curves (thesis Figs 6.1-6.2).

usage: plot_map.py MAP.csv BOUNDARIES.csv OUT.png TITLE   (an SVG is written beside the PNG)
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from plotkit import save  # noqa: E402

STYLE = {  # response type -> (marker, face colour, label)
    "steady_rocking": ("s", "none", "steady rocking"),
    "settle_down": ("o", "none", "settle down"),
    "settled": ("o", "C0", "settled (at rest)"),
    "rock_to_vertical": ("v", "C3", "rock to vertical"),
    "zero_friction_rock_flight": ("*", "C2", "zero-friction rock-flight"),  # "+" is sensitive dependence
    "overturned": (".", "0.6", "overturned"),
    "unclassified": ("d", "C4", "unclassified"),
    "failed": ("x", "C1", "failed"),
    "outside_model": ("_", "C7", "initial state outside the model"),
}


def num(s):
    try:
        v = float(s)
        return v if math.isfinite(v) else None
    except (TypeError, ValueError):
        return None


def main(argv):
    if len(argv) != 5:
        raise SystemExit(__doc__)
    map_csv, bnd_csv, out, title = argv[1:]
    with open(map_csv, newline="") as f:
        rows = list(csv.DictReader(f))
    groups = {}
    for r in rows:
        status = r["status"]
        t = r.get("response_type") or (status if status == "outside_model" else
                                       "failed" if status in ("error", "numerical_failure") else "unclassified")
        groups.setdefault(t, []).append((float(r["inv_r"]), math.log10(float(r["k"]))))
    fig, ax = plt.subplots(figsize=(10.5, 6.5), constrained_layout=True)
    for t, pts in sorted(groups.items()):
        m, fc, label = STYLE.get(t, ("*", "k", t))
        xs, ys = zip(*pts)
        kw = dict(marker=m, s=28, label=f"{label} ({len(pts)})")
        if fc == "none":
            kw.update(facecolors="none", edgecolors="k", linewidths=0.7)
        else:
            kw.update(c=fc, linewidths=0.9)
        ax.scatter(xs, ys, **kw)
    # Sensitive dependence (map --sensitivity): a "+" over the point, as in the thesis's Figs 6.1-6.2;
    # it is not exclusive of the response type (a rock-to-vertical point is also chaotic).
    sens = [(float(r["inv_r"]), math.log10(float(r["k"]))) for r in rows if r.get("sensitive_dependence") == "1"]
    if sens:
        xs, ys = zip(*sens)
        ax.scatter(xs, ys, marker="+", s=70, c="C1", linewidths=1.2, label=f"sensitive dependence ({len(sens)})")
    with open(bnd_csv, newline="") as f:
        brows = list(csv.DictReader(f))
    for col, style, label in (("k_stability", "-", "stability boundary"),
                              ("k_high", "--", "k_high (early flight boundary)"),
                              ("k_critical", "-.", "k_critical (no flight boundary)"),
                              ("k3_stability", ":", "k3 (ic2: overturning on the 2nd swing below)")):
        pts = [(float(b["inv_r"]), num(b.get(col))) for b in brows]
        pts = [(x, math.log10(v)) for x, v in pts if v]
        if pts:
            xs, ys = zip(*pts)
            ax.plot(xs, ys, style, color="k", lw=1.3, label=label)
    ax.set_xlabel("1/r = height/width")
    ax.set_ylabel("log10 k")
    ax.set_title(f"response types in the (k, 1/r) plane, {title}")
    # Outside the axes: inside, it hid the lower-right corner of the grid.
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
    save(fig, out, dpi=110)


if __name__ == "__main__":
    main(sys.argv)
