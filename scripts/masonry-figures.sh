#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# docs/masonry.md's figures and numbers: the arch's lambda against t/R and against the voussoir
# count, its minimum thickness, the limit-analysis figures, and the dynamic overturning
# thresholds of the arch and the trilith under pulses beside their static lambda. Usage:
# scripts/masonry-figures.sh [FIGDIR [DATADIR]] (defaults docs/figures and out/masonry; needs a built ./build).
FIGURES_DATA_DIR=out/masonry
TIME=1
# shellcheck source=scripts/figures-env.sh
source "$(dirname "$0")/figures-env.sh"
PY=/usr/bin/python3
field() { $PY -c "import json,sys; print(json.load(sys.stdin)[sys.argv[1]])" "$1"; }

echo "voussoirs,ratio,lambda" >"$D/lambda_t.csv"
for n in 9 20 60; do
  for t in 0.11 0.12 0.13 0.15 0.175 0.2 0.25 0.3 0.4 0.5; do
    echo "$n,$t,$($B limit-analysis --preset arch --voussoirs $n --thickness-ratio $t --json | field lambda)" >>"$D/lambda_t.csv"
  done
done
echo "voussoirs,lambda,min_thickness_ratio" >"$D/lambda_n.csv"
for n in 5 7 9 13 20 30 50 100 200; do
  j=$($B limit-analysis --preset arch --voussoirs $n --thickness-ratio 0.15 --min-thickness --json)
  echo "$n,$(echo "$j" | field lambda),$(echo "$j" | field min_thickness_ratio)" >>"$D/lambda_n.csv"
done
run $PY python/plot_masonry_curves.py "$D/lambda_t.csv" "$D/lambda_n.csv" "$F/masonry_arch_lambda.png"
run $B limit-analysis --preset arch --voussoirs 20 --thickness-ratio 0.15 --min-thickness --plot "$F/masonry_arch_limit.png" \
  --json-out "$D/arch20.json"
run $B limit-analysis --preset trilith --lintel-length 0.6 --overhang 0.03 --plot "$F/masonry_trilith_limit.png" \
  --json-out "$D/trilith.json"
# Dynamics beside statics: half-sine pulses on the 9-voussoir arch (t/R = 0.15, deformable joints)
# and seed 002's trilith (both laws); the static lambda is each row's long-pulse limit.
run $B limit-analysis --preset arch --voussoirs 9 --thickness-ratio 0.15 --json-out "$D/arch9.json"
run $B spectrum --model assembly --preset arch --voussoirs 9 --thickness-ratio 0.15 --pulse half-sine \
  --durations 0.1,0.2,0.5,1,2 --t-after 2 --scan-points 16 --amplitude-min 0.05 --amplitude-max 3 \
  --json-out "$D/spectrum_arch.json" --quiet --plot "$F/masonry_arch_spectrum.png"
run $B spectrum --model assembly --preset arch --voussoirs 9 --thickness-ratio 0.15 --contact rigid --pulse half-sine \
  --durations 0.1,0.2,0.5,1,2 --t-after 2 --scan-points 16 --amplitude-min 0.05 --amplitude-max 3 \
  --json-out "$D/spectrum_arch_rigid.json" --quiet
for c in deformable rigid; do
  run $B spectrum --model assembly --preset trilith --contact $c --pulse half-sine --durations 0.1,0.2,0.5,1,2 \
    --t-after 2 --scan-points 16 --amplitude-min 0.05 --amplitude-max 3 --json-out "$D/spectrum_trilith_$c.json" --quiet
done
