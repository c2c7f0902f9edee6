# SPDX-License-Identifier: Apache-2.0
"""Animation of an assembly run: the blocks over the moving ground, the contact points with their
normal forces as arrows (drawn upwards: the faces of rectangles at rest), the time and the ground acceleration.
Usage: animate_assembly.py TRAJECTORY.csv OUT.gif|OUT.mp4 [--frames N] [--title T]"""

import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib import animation  # noqa: E402
from matplotlib.patches import Polygon  # noqa: E402

from assembly_csv import load  # noqa: E402
from plotkit import figure_parser  # noqa: E402


def placed(x, y, th, pts):
    c, s = np.cos(th), np.sin(th)
    return [(x + c * px - s * py, y + s * px + c * py) for px, py in pts]


def outlines(a, nb):
    """Each block's vertices about its centre: --polygons "x,y x,y ...;..." or the --sizes rectangles."""
    if a.polygons:
        return [[tuple(float(v) for v in p.split(",")) for p in blk.split()] for blk in a.polygons.split(";")]
    dims = [float(v) for v in a.sizes.split(",")]
    out = []
    for b in range(nb):
        w, h = dims[2 * b], dims[2 * b + 1]
        out.append([(-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2), (-w / 2, h / 2)])
    return out


def main():
    ap = figure_parser()
    ap.add_argument("--frames", type=int, default=120)
    ap.add_argument("--sizes", help="b0,h0,b1,h1,... block widths and heights (m)")
    ap.add_argument("--polygons", help="polygonal blocks: 'x,y x,y ...;...' vertices about each centre (m)")
    a = ap.parse_args()
    c, nb, npts = load(a.csv)
    shapes = outlines(a, nb)
    t = c["t"]
    keep = np.array([e == "" or e == "start" for e in c["event"]])
    t_k = t[keep]
    frames = np.linspace(t_k[0], t_k[-1], a.frames)
    idx = np.searchsorted(t_k, frames).clip(0, len(t_k) - 1)
    rows = np.nonzero(keep)[0][idx]
    xs = [c[f"x_{b}"] for b in range(nb)]
    ys = [c[f"y_{b}"] for b in range(nb)]
    span = max(max(p[1] for p in shapes[b]) + ys[b][0] for b in range(nb))
    width = max(abs(xs[b][0]) + max(abs(p[0]) for p in shapes[b]) for b in range(nb))
    fig, (ax, ax2) = plt.subplots(2, 1, figsize=(6, 7), gridspec_kw={"height_ratios": [4, 1]})
    ax.set_aspect("equal")
    ax.set_xlim(-1.6 * width - 0.2 * span, 1.6 * width + 0.2 * span)
    ax.set_ylim(-0.1 * span, 1.2 * span)
    ax.axhspan(-0.1 * span, 0, color="0.85")
    polys = [Polygon(np.zeros((len(shapes[b]), 2)), closed=True, fc="#c8b89a", ec="k") for b in range(nb)]
    for p in polys:
        ax.add_patch(p)
    fmax = max(np.nanmax(c[f"fn_{p // 2}_{p % 2}"]) for p in range(npts)) or 1.0
    arrows = ax.quiver(np.zeros(npts), np.zeros(npts), np.zeros(npts), np.zeros(npts), angles="xy",
                       scale_units="xy", scale=1.0, color="tab:red", width=0.006)
    label = ax.text(0.02, 0.95, "", transform=ax.transAxes, family="monospace", va="top")
    ax.set_title(textwrap.fill(a.title, 80), fontsize=8)  # two lines rather than clipped
    ax2.plot(t, c["a_h"], lw=0.8, color="k")
    ax2.set_ylabel("a_h [g]")
    ax2.set_xlabel("t [s]")
    cursor = ax2.axvline(t[0], color="tab:red")

    def draw(k):
        r = rows[k]
        for b in range(nb):
            polys[b].set_xy(placed(xs[b][r], ys[b][r], c[f"theta_{b}"][r], shapes[b]))
        px = [c[f"px_{p // 2}_{p % 2}"][r] for p in range(npts)]
        py = [c[f"py_{p // 2}_{p % 2}"][r] for p in range(npts)]
        fn = [c[f"fn_{p // 2}_{p % 2}"][r] / fmax * 0.15 * span for p in range(npts)]
        arrows.set_offsets(np.c_[px, py])
        arrows.set_UVC(np.zeros(npts), fn)
        label.set_text(f"t = {t[r]:9.4f} s")
        cursor.set_xdata([t[r], t[r]])
        return polys + [arrows, label, cursor]

    anim = animation.FuncAnimation(fig, draw, frames=len(rows), blit=False)
    if a.out.endswith(".mp4"):
        anim.save(a.out, writer=animation.FFMpegWriter(fps=24))
    else:
        anim.save(a.out, writer=animation.PillowWriter(fps=24))


if __name__ == "__main__":
    main()
