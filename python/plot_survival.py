# SPDX-License-Identifier: Apache-2.0
"""Survival domain over (omega, beta) in the style of seed 002 Figs. 6-9: collapse points marked
by their t* class (stars <= 5 s, triangles short, diamonds medium, squares long, circles very
long), filled for mode 2 and hollow for mode 1; stable points as small grey dots, rest as
crosses. With --refined DW DB (a map refined near class changes; DW, DB the coarse steps in omega
and beta) every point is drawn as a tile of its level's cell size, coarse tiles first, so the
fine boundary shows. Usage: plot_survival.py POINTS.csv OUT.png [--title T] [--refined DW DB]"""

from plotkit import read_rows, save, figure_parser, plt  # noqa: E402

MARKERS = {"short": "^", "medium": "D", "long": "s", "very long": "o"}


def main():
    ap = figure_parser()
    ap.add_argument("--refined", nargs=2, type=float, metavar=("DW", "DB"))
    a = ap.parse_args()
    rows = read_rows(a.csv)
    if a.refined:
        return tiles(rows, a)
    fig, ax = plt.subplots(figsize=(7.5, 5))
    groups = {}  # label -> (xs, ys, style): one scatter call per group

    def put(x, y, label, **kw):
        groups.setdefault(label, ([], [], kw))
        groups[label][0].append(x)
        groups[label][1].append(y)

    for r in rows:
        w, b = float(r["omega"]), float(r["beta"])
        if r["motion"] == "rest":
            put(w, b, "rest", marker="x", color="0.6", s=14)
        elif r["motion"] == "stable":
            put(w, b, "stable", marker=".", color="tab:blue", s=20)
        elif r["motion"] == "invalid":
            put(w, b, "invalid", marker="$?$", color="tab:red", s=20)
        else:
            cls, mode = r["t_star_class"], r["collapse_mode"]
            marker = "*" if cls.startswith("<=") else MARKERS.get(cls, "o")
            filled = mode == "2"
            put(w, b, f"collapse mode {mode}, t* {cls}", marker=marker, s=40,
                facecolors="k" if filled else "none", edgecolors="k")
    for label, (xs, ys, kw) in groups.items():
        ax.scatter(xs, ys, label=label, **kw)
    ax.set_xlabel("omega = Omega / p")
    ax.set_ylabel("beta")
    ax.set_title(a.title, fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    save(fig, a.out, dpi=120)


TILE_COLOURS = {"rest": "0.85", "stable": "#9ecae1", "invalid": "#ff00ff"}
COLLAPSE_COLOURS = ["#67000d", "#cb181d", "#fb6a4a", "#fcae91", "#fee5d9"]  # t* classes, earliest darkest


def tiles(rows, a):
    from matplotlib.collections import PatchCollection
    from matplotlib.patches import Patch, Rectangle
    classes = ["<=", "short", "medium", "long", "very long"]
    rects, colours, seen = [], [], {}
    for r in sorted(rows, key=lambda r: int(r["level"])):
        lv = int(r["level"])
        w, b = float(r["omega"]), float(r["beta"])
        dw, db = a.refined[0] / 2 ** lv, a.refined[1] / 2 ** lv
        if r["motion"] == "collapse":
            k = next(i for i, c in enumerate(classes) if r["t_star_class"].startswith(c))
            c = COLLAPSE_COLOURS[k]
            label = f"collapse, t* {r['t_star_class']}" + (" (mode 2 hatched)" if r["collapse_mode"] == "2" else "")
        else:
            c = TILE_COLOURS.get(r["motion"], "k")
            label = r["motion"]
        rects.append(Rectangle((w - dw / 2, b - db / 2), dw, db, hatch="//" if r["collapse_mode"] == "2" else None))
        colours.append(c)
        seen.setdefault(label, c)
    fig, ax = plt.subplots(figsize=(7.5, 5))
    ax.add_collection(PatchCollection(rects, facecolors=colours, edgecolors="none"))
    ws = [float(r["omega"]) for r in rows]
    bs = [float(r["beta"]) for r in rows]
    ax.set_xlim(min(ws) - a.refined[0] / 2, max(ws) + a.refined[0] / 2)
    ax.set_ylim(min(bs) - a.refined[1] / 2, max(bs) + a.refined[1] / 2)
    ax.set_xlabel("omega = Omega / p")
    ax.set_ylabel("beta")
    ax.set_title(a.title + f"\n{len(rows)} points, refined near class changes", fontsize=8)
    ax.legend(handles=[Patch(color=c, label=l) for l, c in seen.items()], fontsize=7, loc="upper left",
              bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    save(fig, a.out, dpi=150)


if __name__ == "__main__":
    main()
