#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The figures and numbers of docs/forced-chaos.md and docs/periodic-orbits.md (issue 9, items 6-7):
# chaos maps of the Housner block, Lyapunov convergence, rocking periodic orbits, their branches
# and existence/stability regions, and (slow: about an hour of CPU) the Lyapunov exponent of seed
# 002's chaotic trilith (Fig. 15). Usage: scripts/forced_chaos_figures.sh [FIGDIR [DATADIR]] [--trilith]
# (figures to FIGDIR, default docs/figures; tables and JSON to DATADIR, default out/forced-chaos;
# needs a built ./build). Without --trilith about 50 s of CPU.
set -euo pipefail
cd "$(dirname "$0")/.."
B=./build/blockdyn
O=docs/figures
D=out/forced-chaos
[[ $# -ge 1 && $1 != --* ]] && O=$1
[[ $# -ge 2 && $2 != --* ]] && D=$2
mkdir -p "$O" "$D"
run() { echo "+ $*"; "$@"; }
BLOCK=(--model housner --width 0.3 --height 1.5)

# Chaos maps over (beta, omega), seed 002's excitation (Housner's e_H = 0.943, then e = 0.995).
run $B chaos-map "${BLOCK[@]}" --beta-min 0.5 --beta-max 4.5 --beta-points 33 --omega-min 1 --omega-max 12 \
  --omega-points 45 --periods 400 --transient-periods 200 --out "$D/chaos_map_housner.csv" \
  --json-out "$D/chaos_map_housner.json" --plot "$O/chaos_map_housner.png" --progress none
run $B chaos-map "${BLOCK[@]}" --restitution 0.995 --beta-min 0.5 --beta-max 6 --beta-points 34 --omega-min 1 \
  --omega-max 12 --omega-points 45 --periods 400 --transient-periods 200 --out "$D/chaos_map_housner_e0995.csv" \
  --json-out "$D/chaos_map_housner_e0995.json" --plot "$O/chaos_map_housner_e0995.png" --progress none
# Convergence of the exponent: a stable rocking orbit and a chaotic one; the two nearby orbits.
run $B lyapunov "${BLOCK[@]}" --beta 1.5 --omega 3 --t-end 300 --t-transient 30 \
  --csv "$D/lyapunov_housner_periodic.csv" --twin-csv "$D/lyapunov_housner_periodic_twin.csv" \
  --json-out "$D/lyapunov_housner_periodic.json" --plot "$O/lyapunov_housner_periodic.png"
run $B lyapunov "${BLOCK[@]}" --restitution 1 --beta 3 --omega 12 --t-end 300 --t-transient 30 \
  --csv "$D/lyapunov_housner_chaotic.csv" --twin-csv "$D/lyapunov_housner_chaotic_twin.csv" \
  --json-out "$D/lyapunov_housner_chaotic.json" --plot "$O/lyapunov_housner_chaotic.png"
run $B lyapunov --model rigid --width 0.3 --height 1.5 --mu-s 2 --beta 1.5 --omega 3 --t-end 300 --t-transient 30 \
  --json-out "$D/lyapunov_rigid_periodic.json"

# Rocking periodic orbits (seed 001 sec. 4.1): a slender block (b/h = 0.151, alpha = 0.15), e = 0.9.
PO=(--width 0.151 --height 1 --restitution 0.9)
run $B periodic-orbits "${PO[@]}" --beta 1.2 --omega 2 --json-out "$D/orbits_11.json" --plot "$O/orbits_11.png"
run $B periodic-orbits "${PO[@]}" --beta 1.2 --omega 2 --continue ks --continue-min 0.005 --continue-max 0.6 \
  --out "$D/orbits_11_branches_ks.csv" --json-out "$D/orbits_11_branches_ks.json" --plot "$O/orbits_11_branches_ks.png"
run $B periodic-orbits "${PO[@]}" --beta 2 --omega 4 --continue omega --continue-min 0.5 --continue-max 12 \
  --out "$D/orbits_11_branches_omega.csv" --json-out "$D/orbits_11_branches_omega.json" \
  --plot "$O/orbits_11_branches_omega.png"
run $B periodic-orbits "${PO[@]}" --region --ks-min 0.005 --ks-max 0.6 --ks-points 40 --omega-min 0.5 --omega-max 10 \
  --omega-points 40 --out "$D/orbits_11_region.csv" --json-out "$D/orbits_11_region.json" \
  --plot "$O/orbits_11_region.png" --progress none
run $B periodic-orbits "${PO[@]}" --cycle 1,3 --region --ks-min 0.005 --ks-max 0.6 --ks-points 40 --omega-min 0.5 \
  --omega-max 15 --omega-points 40 --out "$D/orbits_13_region.csv" --json-out "$D/orbits_13_region.json" \
  --plot "$O/orbits_13_region.png" --progress none
# Housner's own restitution for the same block (e_H = 0.966).
run $B periodic-orbits --width 0.151 --height 1 --region --ks-min 0.005 --ks-max 0.6 --ks-points 40 --omega-min 0.5 \
  --omega-max 10 --omega-points 40 --out "$D/orbits_11_region_eH.csv" --json-out "$D/orbits_11_region_eH.json" \
  --plot "$O/orbits_11_region_eH.png" --progress none

# Seed 002 Fig. 15: the trilith's chaotic case (phi = 14.7 deg, omega = 3, beta = 1.664), deformable contacts.
if [[ " $* " == *" --trilith "* ]]; then
  # At three tolerances: the exponent's convergence (1e-8: about 6 min of CPU).
  for tol in "1e-6 1e-8" "1e-7 1e-9" "1e-8 1e-10"; do
    set -- $tol
    run $B lyapunov --model assembly --preset trilith --phi-s 14.7 --phi-l 14.7 --beta 1.664 --omega 3 --t-end 60 \
      --rtol "$1" --atol "$2" --csv "$D/lyapunov_trilith_fig15_$1.csv" --twin-csv "$D/lyapunov_trilith_fig15_twin_$1.csv" \
      --json-out "$D/lyapunov_trilith_fig15_$1.json" --plot "$O/lyapunov_trilith_fig15_$1.png"
  done
fi
