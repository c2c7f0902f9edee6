#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds the documentation site into site/ (MkDocs, Material theme): generates the reference pages
# from the program (docs/reference/commands.md, outputs.md: scripts/docs_reference.py), builds in
# strict mode (a broken link, a missing page or figure fails), then renders the home page and an
# analysis page in headless Chromium (site/screenshots/*.png) and checks each shows its figure.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh build plot docs
[ -x build/blockdyn ] || bash scripts/build.sh blockdyn_cli
/usr/bin/python3 scripts/docs_reference.py build/blockdyn docs/reference
mkdocs build --strict --quiet --site-dir site
/usr/bin/python3 scripts/check_site.py site index.html earthquake.html
echo "site/index.html (screenshots: site/screenshots/)"
