#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# docs/earthquake.md's worked case: a museum statue (0.4 m x 1.7 m) on a generated suite for a
# site; the commands exactly as the page gives them, timed. Usage:
# scripts/earthquake-figures.sh [FIGDIR [DATADIR]] (defaults docs/figures and out/earthquake; needs a built ./build).
FIGURES_DATA_DIR=out/earthquake
TIME=1
# shellcheck source=scripts/figures-env.sh
source "$(dirname "$0")/figures-env.sh"

# The site's suite: 40 records of 30 s.
run $B motion generate --model rezaeian --arias 0.8 --d5-95 12 --t-mid 7 --f-mid 3 --f-slope -0.05 --zeta-f 0.25 \
  --dt 0.01 --t-end 30 --count 40 --seed 2026 --out "$D/suite" --overwrite --plot "$F/earthquake_suite.png"
run $B motion info "$D/suite/rezaeian_0001.AT2" --spectrum --period-min 0.05 --period-max 4 --json-out "$D/info.json"
# The statue's rocking spectrum under the first record at 1x and 2x, its own p = 2.90 rad/s inside.
run $B rocking-spectrum --model housner --record "$D/suite/rezaeian_0001.AT2" --alpha 0.2311 --p-min 0.8 \
  --p-max 12 --p-points 60 --scales 1,2,3 --json-out "$D/rocking.json" --plot "$F/earthquake_rocking_spectrum.png"
# Its fragility: every record at 12 PGA levels, Housner's model and the 3-DOF block with friction.
run $B fragility --model housner --width 0.4 --height 1.7 --records "$D/suite/*.AT2" --im pga --levels 0.1:1.2:12 \
  --bootstrap 500 --out "$D/fragility_housner.csv" --overwrite --json-out "$D/fragility_housner_summary.json" \
  --plot "$F/earthquake_fragility_housner.png"
run $B fragility --model rigid --width 0.4 --height 1.7 --mu-s 0.3 --records "$D/suite/*.AT2" --im pga \
  --levels 0.1:1.2:12 --bootstrap 500 --out "$D/fragility_rigid.csv" --overwrite \
  --json-out "$D/fragility_rigid_summary.json" --plot "$F/earthquake_fragility_rigid.png"
run $B fragility --model housner --width 0.4 --height 1.7 --records "$D/suite/*.AT2" --im pga-over-uplift \
  --levels 0.5:5:12 --bootstrap 500 --out "$D/fragility_dimless.csv" --overwrite \
  --json-out "$D/fragility_dimless_summary.json" --plot "$F/earthquake_fragility_dimensionless.png"
