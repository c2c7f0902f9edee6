#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The figures of docs/cycles.md and docs/impact-map.md: stroboscopic samples, (m, n) cycles and
# impact maps of Housner's block and of seed 002's trilith (Figs. 12-15), about 2 minutes of CPU
# on one core (the 400 s trilith runs take 15 s each). Usage: scripts/cycles-figures.sh [FIGDIR [DATADIR]]
# (defaults docs/figures and out/cycles; needs a built ./build)
FIGURES_DATA_DIR=out/cycles
# shellcheck source=scripts/figures-env.sh
source "$(dirname "$0")/figures-env.sh"
T="--model assembly --preset trilith"

# Housner's block (0.3 x 1.5 m): a (2,6) transient settling on the (1,3) orbit.
run $B cycles --model housner --width 0.3 --height 1.5 --beta 3.3 --omega 10 --periods 200 --trace-per-period 64 \
  --plot "$F/cycles_housner.png" --json-out "$D/cycles_housner.json" --out "$D/cycles_housner.csv" --quiet
# Seed 002 Figs. 12-14: phi_s = phi_l = 90 deg, beta = 4, omega = 10, deformable and rigid contacts.
run $B cycles $T --beta 4 --omega 10 --t-end 400 --trace-per-period 64 \
  --plot "$F/cycles_trilith.png" --json-out "$D/cycles_trilith.json" --out "$D/cycles_trilith.csv" --quiet
run $B cycles $T --contact rigid --beta 4 --omega 10 --t-end 400 --trace-per-period 64 \
  --plot "$F/cycles_trilith_rigid.png" --json-out "$D/cycles_trilith_rigid.json" --out "$D/cycles_trilith_rigid.csv" --quiet
# Seed 002 Fig. 15: phi_s = phi_l = 14.7 deg, beta = 1.664, omega = 3 (the first 20 periods left out of the maps).
run $B impact-map $T --phi-s 14.7 --phi-l 14.7 --beta 1.664 --omega 3 --t-end 300 --transient 20 \
  --trace-per-period 64 --plot "$F/impact_map_trilith.png" --json-out "$D/impact_map_trilith.json" \
  --out "$D/impact_map_trilith.csv" --poincare "$D/impact_map_trilith_section.csv" --quiet
run $B cycles $T --phi-s 14.7 --phi-l 14.7 --beta 1.664 --omega 3 --t-end 300 \
  --json-out "$D/cycles_trilith_phi14.7.json" --quiet
# The docs show the PNGs; the SVGs of these long trajectories run to megabytes.
rm -f "$F"/cycles_housner.svg "$F"/cycles_trilith.svg "$F"/cycles_trilith_rigid.svg "$F"/impact_map_trilith.svg
echo "figures written to $F, data to $D"
