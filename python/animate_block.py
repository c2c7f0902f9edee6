#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Animation of one `blockdyn simulate` run (GIF with Pillow, MP4 with ffmpeg).

usage: animate_block.py TRAJECTORY.csv OUT.gif|OUT.mp4 --model winkler|housner|rigid
                        --width B --height H [--frames N] [--fps F] [--title T]

The block is drawn at its pose over the ground (rigid models: contact forces as arrows at the
base corners, scaled to the weight) or over the Winkler foundation (the springs' compression under
the block as a bar profile, exaggerated to be visible, the scale written in the corner); the
mechanism or mode and the time are written in the frame; a lower panel shows the ground
acceleration (rigid models; Winkler: the rotation) with a moving cursor. N frames uniformly spaced
in time (default 120).
"""
import csv
import math
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib import animation  # noqa: E402
from matplotlib.patches import Polygon  # noqa: E402
from plotkit import figure_parser  # noqa: E402


def load(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise SystemExit(f"{path}: no rows")
    num = {}
    for k in rows[0]:
        try:
            num[k] = np.array([float(r[k]) if r[k] != "" else np.nan for r in rows])
        except ValueError:
            num[k] = np.array([r[k] for r in rows], dtype=object)
    return num


def corners(x, y, w, b, h):
    c, s = math.cos(w), math.sin(w)
    pts = [(-b / 2, -h / 2), (b / 2, -h / 2), (b / 2, h / 2), (-b / 2, h / 2)]
    return np.array([(x + c * px - s * py, y + s * px + c * py) for px, py in pts])


def main():
    ap = figure_parser()
    ap.add_argument("--model", default="winkler")
    ap.add_argument("--width", type=float, required=True)
    ap.add_argument("--height", type=float, required=True)
    ap.add_argument("--frames", type=int, default=120)
    ap.add_argument("--fps", type=int, default=24)
    a = ap.parse_args()
    d = load(a.csv)
    t = d["t"]
    rigid = a.model in ("housner", "rigid")
    b, h = a.width, a.height
    # Uniform frame times; each frame shows the last trajectory row at or before its time.
    n = max(2, min(a.frames, len(t)))
    times = np.linspace(t[0], t[-1], n)
    idx = np.clip(np.searchsorted(t, times, side="right") - 1, 0, len(t) - 1)

    fig = plt.figure(figsize=(6.4, 6.0))
    ax = fig.add_axes([0.12, 0.32, 0.84, 0.6])
    lower = fig.add_axes([0.12, 0.08, 0.84, 0.17])
    span = max(b, h) * 1.1
    xc = np.nanmedian(d["x"])
    ax.set_xlim(xc - span, xc + span)
    ax.set_ylim(-0.25 * h, 1.25 * max(b, h))
    ax.set_aspect("equal")
    ax.axhline(0.0, color="0.3", lw=1.5)
    ax.fill_between([xc - 2 * span, xc + 2 * span], -h, 0, color="0.85", zorder=0)
    ax.set_xticks([])
    ax.set_yticks([])
    block = Polygon(corners(d["x"][0], d["y"][0], d["w"][0], b, h), closed=True, fc="#c9b79c", ec="k", lw=1.2)
    ax.add_patch(block)
    label = ax.text(0.02, 0.96, "", transform=ax.transAxes, va="top", fontsize=10, family="monospace")
    fig.suptitle(textwrap.fill(a.title, 90), fontsize=8)  # two lines rather than clipped
    arrows = []
    springs = None
    if rigid:
        weight = max(1e-300, np.nanmax(np.abs(np.concatenate([d["N_A"], d["N_B"]]))))
        scale = 0.35 * h / weight
        for _ in range(2):
            arrows.append(ax.quiver([0], [0], [0], [0], angles="xy", scale_units="xy", scale=1, color="C3", width=0.008))
        series, name = d["a_h"], "ground a_H [g]"
    else:
        # Compression of the foundation under the block, exaggerated: largest over the run -> 0.15 h.
        xs = np.linspace(xc - span, xc + span, 200)
        depth = []
        for i in idx:
            cs = corners(d["x"][i], d["y"][i], d["w"][i], b, h)
            bottom = np.interp(xs, *zip(*sorted([tuple(cs[0]), tuple(cs[1])])), left=np.nan, right=np.nan)
            depth.append(np.where(np.isnan(bottom), 0.0, np.maximum(0.0, -bottom)))
        depth = np.array(depth)
        top = np.nanmax(depth) if np.nanmax(depth) > 0 else 1.0
        exag = 0.15 * h / top
        springs = ax.fill_between(xs, 0, 0, color="C0", alpha=0.6)
        ax.text(0.98, 0.02, f"springs' compression x {exag:.3g}", transform=ax.transAxes, ha="right",
                fontsize=8, color="C0")
        series, name = d["w"], "rotation w [rad]"
    lower.plot(t, series, lw=0.7, color="0.3")
    lower.set_ylabel(name, fontsize=8)
    lower.set_xlabel("t [s]" if rigid else "t")
    cursor = lower.axvline(t[0], color="C3", lw=1.0)

    def frame(k):
        nonlocal springs
        i = idx[k]
        cs = corners(d["x"][i], d["y"][i], d["w"][i], b, h)
        block.set_xy(cs)
        label.set_text(f"t = {times[k]:9.4f}\n{d['mode'][i]}")
        cursor.set_xdata([times[k], times[k]])
        if rigid:
            for j, (N, T) in enumerate((("N_A", "T_A"), ("N_B", "T_B"))):
                arrows[j].set_offsets([cs[j]])
                arrows[j].set_UVC([d[T][i] * scale], [d[N][i] * scale])
        else:
            springs.remove()
            springs = ax.fill_between(xs, -depth[k] * exag, 0, color="C0", alpha=0.6)
        return [block, label, cursor]

    anim = animation.FuncAnimation(fig, frame, frames=n, blit=False)
    if a.out.lower().endswith(".gif"):
        writer = animation.PillowWriter(fps=a.fps)
    elif a.out.lower().endswith(".mp4"):
        writer = animation.FFMpegWriter(fps=a.fps, bitrate=1800)
    else:
        raise SystemExit(f"{a.out}: the animation must end in .gif or .mp4")
    anim.save(a.out, writer=writer, dpi=80)


if __name__ == "__main__":
    main()
