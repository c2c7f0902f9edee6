#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The documentation site (ctest DocsSite, label docs): generates the reference pages from the
# program into a copy of docs/, builds the site in strict mode (a broken link or a missing figure
# fails) and checks in headless Chromium that the home page and an analysis page render with their
# figures. Skipped (77) without MkDocs or Chromium (scripts/install-deps.sh docs).
# usage: site_check.sh SOURCE_DIR BLOCKDYN WORK_DIR
set -euo pipefail
src=$1 cli=$2 work=$3
command -v mkdocs >/dev/null && command -v chromium >/dev/null || { echo "mkdocs or chromium missing: skipped"; exit 77; }
rm -rf "$work" && mkdir -p "$work"
cp -r "$src/docs" "$work/docs" && cp "$src/mkdocs.yml" "$work/"
/usr/bin/python3 "$src/scripts/docs_reference.py" "$cli" "$work/docs/reference"
(cd "$work" && mkdocs build --strict --quiet --site-dir site)
/usr/bin/python3 "$src/scripts/check_site.py" "$work/site" index.html earthquake.html
