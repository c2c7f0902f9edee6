#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Animation of a 3D run (`blockdyn simulate --model rigid3d`), GIF with Pillow or MP4 with ffmpeg.

usage: animate_rigid3d.py TRAJECTORY.csv OUT.gif|OUT.mp4 --shape box|cylinder --size B,D,H,A
                          [--frames N] [--fps F] [--title T]

The body is drawn at its pose (centroid and quaternion of each row) as a wire frame over the
ground plane, in the ground's frame; the contact mode and the time are written in the frame. N
frames uniformly spaced in time (default 120).
"""
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib import animation  # noqa: E402
from plotkit import figure_parser  # noqa: E402


def rotation(qw, qx, qy, qz):
    return np.array([[1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qw * qz), 2 * (qx * qz + qw * qy)],
                     [2 * (qx * qy + qw * qz), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qw * qx)],
                     [2 * (qx * qz - qw * qy), 2 * (qy * qz + qw * qx), 1 - 2 * (qx * qx + qy * qy)]])


def outline(shape, b, d, h, a):
    """Line segments of the body's wire frame in its own frame (centroid at the origin)."""
    c = h / 2
    if shape == "box":
        base = [(-b / 2, -d / 2), (b / 2, -d / 2), (b / 2, d / 2), (-b / 2, d / 2), (-b / 2, -d / 2)]
    else:
        f = np.linspace(0, 2 * np.pi, 41)
        base = list(zip(a * np.cos(f), a * np.sin(f)))
    low = np.array([(x, y, -c) for x, y in base])
    high = np.array([(x, y, c) for x, y in base])
    verticals = [np.array([low[i], high[i]]) for i in range(0, len(base) - 1, 1 if shape == "box" else 10)]
    return [low, high] + verticals


def main():
    ap = figure_parser()
    ap.add_argument("--shape", choices=("box", "cylinder"), required=True)
    ap.add_argument("--size", required=True, help="B,D,H,A: width, depth, height, radius (m)")
    ap.add_argument("--frames", type=int, default=120)
    ap.add_argument("--fps", type=int, default=20)
    a = ap.parse_args()
    b, d, h, r = (float(x) for x in a.size.split(","))
    with open(a.csv, newline="") as f:
        rows = [row for row in csv.DictReader(f) if row["event"] == ""]
    if not rows:
        raise SystemExit(f"{a.csv}: no rows")
    t = np.array([float(x["t"]) for x in rows])
    picks = np.unique(np.searchsorted(t, np.linspace(t[0], t[-1], max(2, a.frames)), side="left").clip(0, len(t) - 1))
    lines = outline(a.shape, b, d, h, r)
    span = max(b, d, 2 * r, h)
    xs = np.array([float(x["x"]) for x in rows])
    ys = np.array([float(x["y"]) for x in rows])

    fig = plt.figure(figsize=(6, 6))
    ax = fig.add_subplot(projection="3d")
    drawn = [ax.plot([], [], [], color="C0", lw=1.2)[0] for _ in lines]
    label = ax.text2D(0.02, 0.95, "", transform=ax.transAxes, fontsize=9)
    g = np.linspace(-span, span, 2)
    gx, gy = np.meshgrid(g + xs.mean(), g + ys.mean())
    ax.plot_surface(gx, gy, 0 * gx, color="0.85", alpha=0.5, lw=0)
    ax.set_xlim(xs.mean() - span, xs.mean() + span)
    ax.set_ylim(ys.mean() - span, ys.mean() + span)
    ax.set_zlim(0, 2 * span)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_zlabel("z [m]")
    ax.set_title(a.title or "3D body on rigid ground", fontsize=10)

    def frame(k):
        row = rows[picks[k]]
        rot = rotation(*(float(row[q]) for q in ("qw", "qx", "qy", "qz")))
        centre = np.array([float(row["x"]), float(row["y"]), float(row["z"])])
        for line, seg in zip(drawn, lines):
            p = seg @ rot.T + centre
            line.set_data(p[:, 0], p[:, 1])
            line.set_3d_properties(p[:, 2])
        label.set_text(f"t = {float(row['t']):.2f} s   {row['mode']}")
        return drawn + [label]

    anim = animation.FuncAnimation(fig, frame, frames=len(picks), blit=False)
    if a.out.endswith(".mp4"):
        writer = animation.FFMpegWriter(fps=a.fps, bitrate=1800)
    else:
        writer = animation.PillowWriter(fps=a.fps)
    anim.save(a.out, writer=writer, dpi=80)


if __name__ == "__main__":
    main()
