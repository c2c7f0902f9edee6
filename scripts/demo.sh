#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# From a fresh Debian 12 machine: install what the demo needs, build the program, and ask whether
# a museum statue survives an earthquake: a reproducible synthetic record (out/demo_record/), the
# statue's response figure (out/demo.png/.svg), its animation (out/demo.gif), the trajectory
# (out/demo_trajectory.csv) and the JSON verdict (out/demo.json). Then the thesis's Winkler block
# as a second example (out/winkler_demo.png, .csv).
set -euo pipefail
cd "$(dirname "$0")/.."
# The compilers and libraries first; the plotting packages install while the program compiles.
bash scripts/install-deps.sh build
mkdir -p out
bash scripts/install-deps.sh plot > out/install-plot.log 2>&1 &
plot_deps=$!
bash scripts/build.sh blockdyn_cli   # the program only (the tests are scripts/test.sh's)
if ! wait "$plot_deps"; then cat out/install-plot.log >&2; exit 1; fi
rm -f out/install-plot.log
./build/blockdyn motion generate --model rezaeian --arias 3.888 --d5-95 12 --t-mid 10 --f-mid 2.5 \
  --f-slope -0.05 --t-end 40 --seed 2026 --out out/demo_record --overwrite --quiet
./build/blockdyn simulate examples/statue_earthquake.toml --json-out out/demo.json --animate out/demo.gif
./build/blockdyn simulate examples/winkler_demo.toml > /dev/null
echo "verdict: $(/usr/bin/python3 -c 'import json; d = json.load(open("out/demo.json")); print("the statue", "overturns at t = %.2f s" % d["overturn_time"] if d["status"] == "overturned" else "survives (max rotation %.3g alpha)" % d["max_abs_rotation_over_alpha"])')"
echo "wrote out/demo.png, out/demo.svg, out/demo.gif, out/demo.json, out/demo_trajectory.csv, out/demo_record/;"
echo "      out/winkler_demo.png, out/winkler_demo_trajectory.csv (the Winkler block)"
