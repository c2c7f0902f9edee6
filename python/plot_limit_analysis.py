#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Static limit analysis (`blockdyn limit-analysis --plot`): the blocks, the line of thrust at the
collapse load (the centres of pressure of the joints, and each joint's resultant), the mechanism
(the blocks displaced along their virtual velocities, dashed) and its hinges; with
--min-thickness, a second panel with the thinnest arch that stands.

usage: plot_limit_analysis.py DOC.json OUT.png"""
import json
import sys

from plotkit import plt, save  # noqa: E402


def outline(block):
    return [tuple(v) for v in block["outline"]]


def panel(ax, assembly, analysis, title):
    blocks = assembly["blocks"]
    size = 0.0
    xs, ys = [], []
    for b in blocks:
        for x, y in outline(b):
            xs.append(x)
            ys.append(y)
    size = max(max(xs) - min(xs), max(ys) - min(ys))
    # Mechanism: each vertex moved by s (v + omega x r), s so that the fastest point moves 8 % of
    # the assembly's size.
    mech = {m["block"]: m for m in analysis["mechanism"]["blocks"]}
    s = 0.08 * size
    for b in blocks:
        pts = outline(b)
        ax.fill([p[0] for p in pts], [p[1] for p in pts], facecolor="0.85", edgecolor="0.35", lw=0.8)
        m = mech.get(b["block"])
        if m is None or analysis["lambda"] is None:
            continue
        cx, cy = b["centre"]
        moved = [(x + s * (m["vx"] - m["omega"] * (y - cy)), y + s * (m["vy"] + m["omega"] * (x - cx)))
                 for x, y in pts]
        moved.append(moved[0])
        ax.plot([p[0] for p in moved], [p[1] for p in moved], "--", color="C3", lw=0.8)
    # Hinges and sliding joints.
    thrust = analysis["thrust"]
    for m, t in zip(analysis["mechanism"]["interfaces"], thrust):
        if m["state"] == "hinge":
            x, y = t["points"][m["hinge_end"]]
            ax.plot([x], [y], "o", ms=6, mfc="white", mec="C3", mew=1.5)
        elif m["state"] == "sliding":
            (x0, y0), (x1, y1) = t["points"]
            ax.plot([x0, x1], [y0, y1], color="C3", lw=2.5)
    # The line of thrust: the joints' centres of pressure (in joint order for an arch) and the
    # resultants' directions.
    centres = [t["centre"] for t in thrust if t["centre"] is not None]
    if assembly["preset"] == "arch" and len(centres) > 1:
        ax.plot([c[0] for c in centres], [c[1] for c in centres], "-", color="C0", lw=1.5, label="line of thrust")
    elif centres:
        ax.plot([c[0] for c in centres], [c[1] for c in centres], "o", color="C0", ms=4, label="centres of pressure")
    ax.margins(x=0.04, y=0.12)  # the crown hinge clear of the title
    ax.set_aspect("equal")
    ax.axhline(0, color="k", lw=0.8)
    ax.set_title(title, fontsize=10)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.plot([], [], "--", color="C3", lw=0.8, label="mechanism")
    ax.plot([], [], "o", ms=6, mfc="white", mec="C3", mew=1.5, ls="none", label="hinges")
    # Below the axes: inside, it would cover the arch's mechanism.
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=3, fontsize=8, frameon=False)


def main():
    doc = json.load(open(sys.argv[1]))
    out = sys.argv[2]
    mt = doc.get("min_thickness")
    fig, axes = plt.subplots(1, 2 if mt else 1, figsize=(11 if mt else 6.5, 4.6), constrained_layout=True,
                             squeeze=False)
    lam = doc["lambda"]
    what = f"{doc['assembly']['preset']} of {len(doc['assembly']['blocks'])} blocks"
    title = (f"{what} under a horizontal load a_H = lambda g:\nlambda = {lam:.5g} (direction {doc['direction']:+d}), "
             f"{doc['status']}" if lam is not None else f"{what}: cannot stand under its own weight")
    panel(axes[0][0], doc["assembly"], doc, title)
    if mt:
        panel(axes[0][1], mt["assembly"], mt["analysis"],
              f"the thinnest arch that stands under its own weight:\nt/R = {mt['ratio']:.5f} ({mt['voussoirs']} voussoirs)")
    save(fig, out)


if __name__ == "__main__":
    main()
