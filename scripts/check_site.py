#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Checks that pages of the built site render in a real browser with their figures.

usage: check_site.py SITE_DIR PAGE.html [PAGE.html ...]

For each page: its HTML names at least one figure and every figure it names exists in the site;
headless Chromium renders it to SITE_DIR/screenshots/<page>.png, and once more with images turned
off; the two renderings must differ over a figure-sized region (at least 300 x 200 px: the
figure, drawn) and the rendering must not be blank. Exit 1 naming the page and what failed.
"""

import html.parser
import os
import subprocess
import sys
import tempfile

from PIL import Image, ImageChops


class Images(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.sources = []

    def handle_starttag(self, tag, attrs):
        if tag == "img":
            src = dict(attrs).get("src", "")
            if src and not src.startswith(("http:", "https:", "data:")):
                self.sources.append(src)


def render(url, out, images=True):
    args = ["chromium", "--headless=new", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
            "--window-size=1280,6000", "--virtual-time-budget=5000", f"--screenshot={out}"]
    if not images:
        args.append("--blink-settings=imagesEnabled=false")
    with tempfile.TemporaryDirectory() as profile:
        subprocess.run(args + [f"--user-data-dir={profile}", url], check=True, capture_output=True,
                       timeout=120)
    return Image.open(out).convert("RGB")


def check(site, page):
    path = os.path.join(site, page)
    if not os.path.exists(path):
        return [f"{page}: not in the site"]
    parser = Images()
    with open(path, encoding="utf-8") as f:
        parser.feed(f.read())
    figures = [s for s in parser.sources if s.lower().endswith((".png", ".svg", ".gif"))
               and "assets/" not in s]
    problems = []
    if not figures:
        problems.append(f"{page}: names no figure")
    for src in figures:
        if not os.path.exists(os.path.normpath(os.path.join(os.path.dirname(path), src))):
            problems.append(f"{page}: figure {src} is missing from the site")
    shots = os.path.join(site, "screenshots")
    os.makedirs(shots, exist_ok=True)
    url = "file://" + os.path.abspath(path)
    name = os.path.splitext(page)[0].replace("/", "_")
    with_images = render(url, os.path.join(shots, name + ".png"))
    without = render(url, os.path.join(shots, name + "_no_images.png"), images=False)
    # Rendered: more than a handful of colours and not all one shade.
    if len(with_images.getcolors(1 << 20) or range(1 << 20)) < 50:
        problems.append(f"{page}: the rendering is blank")
    # The figure is where the two renderings differ: that region must be figure-sized.
    diff = ImageChops.difference(with_images, without).convert("L").point(lambda v: 255 if v > 24 else 0)
    box = diff.getbbox()
    w, h = (box[2] - box[0], box[3] - box[1]) if box else (0, 0)
    if w < 300 or h < 200:
        problems.append(f"{page}: its figures do not show (images change a {w} x {h} px region)")
    print(f"{page}: {len(figures)} figure(s), drawn over a {w} x {h} px region")
    return problems


def main():
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    site = sys.argv[1]
    problems = [p for page in sys.argv[2:] for p in check(site, page)]
    for p in problems:
        print(p, file=sys.stderr)
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
