#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# From a fresh Debian 12 machine: install dependencies, build, and run the demo simulation
# (writes out/demo_trajectory.csv, out/demo.png/.svg, out/demo.json and the animation out/demo.gif).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh blockdyn_cli   # the program only (the tests are scripts/test.sh's)
mkdir -p out
./build/blockdyn simulate examples/demo.toml --json-out out/demo.json --animate out/demo.gif
echo "wrote out/demo_trajectory.csv, out/demo.png, out/demo.svg, out/demo.json, out/demo.gif"
