#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Regenerates one figure of every analysis family at modest resolution (about 2.5 minutes on
# 2 cores, the map 52 s and the assembly figures 42 s of it; see README). Usage: scripts/gallery.sh [OUTDIR]
# (default out/gallery; needs a built ./build)
set -euo pipefail
cd "$(dirname "$0")/.."
B=./build/blockdyn
O=${1:-out/gallery}
mkdir -p "$O"
run() { echo "+ $*"; "$@" >/dev/null; }

# Time histories (simulate)
run $B simulate --r 0.2 --mu 0.2 --k 1e6 --t-end 10 --trajectory "$O/simulate.csv" --plot "$O/simulate.png"
# Parameter sweep: first-flight map (sweep engine)
run $B sweep --k 1e2:1e8:16 --inv-r 1:20:12 --mu 0.2 --ic ic2 --t-end 30 --stop-at-first-flight \
  -o "$O/sweep.csv" --overwrite --quiet --plot "$O/sweep.png"
# Flight (thesis 4.2)
run $B flight-time --ic ic1 --r 0.1 --mu 0.2 --k-min 1e2 --k-max 1e9 --points 40 --csv "$O/flight_time.csv" --plot "$O/flight_time.png"
run $B kmin --mu 0.2 --points 20 --csv "$O/kmin.csv" --plot "$O/kmin.png"
run $B flight-boundary --ic ic2 --mu 0.2 --r-min 0.1 --r-max 1 --points 5 --per-decade 4 --csv "$O/flight_boundary.csv" --plot "$O/flight_boundary.png"
run $B flight-map --ic ic1 --mu 0.2 --r-min 0.1 --r-max 1 --r-points 8 --k-min 1e2 --k-max 1e8 --k-points 16 --csv "$O/flight_map.csv" --plot "$O/flight_map.png"
# Stability (thesis 4.3.1-4.3.2)
run $B overturn --ic ic2 --r 0.1 --mu 0.2 --k-min 100 --k-max 5000 --points 40 --csv "$O/overturn.csv" --plot "$O/overturn.png"
run $B stability-curve --ic ic2 --which both --mu 0.2 --r-min 0.07 --r-max 1 --points 6 --csv "$O/stability_curve.csv" --plot "$O/stability_curve.png"
run $B blowup --mu-list 0.1,0.2 --k-hi 1e6 --csv "$O/blowup.csv" --plot "$O/blowup.png"
# Static equilibria and bifurcations (thesis 4.3.3)
run $B equilibria --r 0.9 --k 6.2 --csv "$O/equilibria.csv" --plot "$O/equilibria.png"
run $B bifurcation --r 0.5 --k-min 2 --k-max 1e4 --points 200 --csv "$O/bifurcation.csv" --plot "$O/bifurcation.png"
run $B bifurcation-curves --r-min 0.05 --r-max 1 --points 40 --csv "$O/bifurcation_curves.csv" --plot "$O/bifurcation_curves.png"
# Long-term response (thesis 4.4) and chaos (thesis 5)
run $B response --r 0.2 --mu 0.2 --k 1e4 --ic ic1 --t-end 100 --csv-prefix "$O/response" --plot "$O/response.png"
run $B lyapunov --r 0.1 --mu 0 --k 1e6 --ic ic1 --t-end 60 --csv "$O/lyapunov.csv" --plot "$O/lyapunov.png"
run $B poincare --mu 0 --r 0.5 --k 1e4 --t-end 200 --csv "$O/poincare.csv" --plot "$O/poincare.png"
run $B energy-surface --mu 0.3 --r 0.2 --k 1e5 --ic ic1 --t-end 100 --phase-dt 0.1 --plot "$O/energy_surface.png"
# Response map (thesis ch. 6)
run $B map --k 1e1:1e8:12 --inv-r 1:20:10 --mu 0.2 --ic ic1 --t-end 30 --boundary-points 6 \
  -o "$O/map.csv" --overwrite --quiet --plot "$O/map.png"
# Rigid block on rigid ground (Housner, 3-DOF): time histories and the validation figures
run $B simulate examples/housner_pulse.toml --trajectory "$O/housner_pulse.csv" --plot "$O/housner_pulse.png"
run $B simulate examples/rigid_record.toml --trajectory "$O/rigid_record.csv" --plot "$O/rigid_record.png"
run /usr/bin/python3 python/fig_rigid_ground.py "$B" "$O" tests/fixtures/synthetic_60s.AT2
# Overturning spectra (Housner block, rectangular and one-sine pulses)
run $B spectrum --model housner --width 0.3 --height 1.5 --pulse rect --duration-min 0.05 --duration-max 5 \
  --duration-points 30 --plot "$O/spectrum_rect.png" --quiet
run $B spectrum --model housner --width 0.3 --height 1.5 --pulse one-sine --duration-min 0.1 --duration-max 5 \
  --duration-points 30 --scan-points 80 --amplitude-max 10 --plot "$O/spectrum_one_sine.png" --quiet
# Survival domain of the Housner block (40 x 40, 20 forcing periods)
run $B survival --model housner --width 0.3 --height 1.5 --beta-min 0.5 --beta-max 6 --beta-points 40 \
  --omega-min 1 --omega-max 20 --omega-points 40 --periods 20 --plot "$O/survival_housner.png" --quiet
# Cycles and the impact map of the Housner block under harmonic motion (a (1,3) orbit)
run $B cycles --model housner --width 0.3 --height 1.5 --beta 3.3 --omega 10 --periods 200 --plot "$O/cycles.png" --quiet
run $B impact-map --model housner --width 0.3 --height 1.5 --beta 3.3 --omega 10 --periods 200 --transient 50 \
  --plot "$O/impact_map.png" --quiet
# Block assemblies (seed 002 trilith): frame rocking, the harmonic case, a figure and an animation
run /usr/bin/python3 python/fig_assembly.py "$B" "$O"
echo "gallery written to $O"
