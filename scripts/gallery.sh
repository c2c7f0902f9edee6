#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Regenerates the figures of every analysis family. Usage: scripts/gallery.sh [OUTDIR] [TARGET ...]
# (default OUTDIR out/gallery; needs a built ./build). Targets (default: core thesis):
#   core         one figure of every analysis family at modest resolution (about 2.5 minutes on 2 cores:
#                107 s wall, the map 52 s of it, plus the assembly figures 42 s)
#   thesis       the thesis's figures of chapters 3-4 that are cheap: code checks (Figs 3.2-3.11),
#                typical responses (4.1-4.4), time to first flight (4.6-4.13), overturning (4.21-4.28),
#                equilibrium landscapes and bifurcations (4.35-4.39) (127 s CPU; 215 s wall measured on
#                the shared 2-core machine under load; the code checks' 120k-row force traces 68 s of it)
#   thesis-long  opt-in, expensive: long-term responses (4.41-4.56), the chaos layouts (5.1-5.7,
#                5.13-5.14) and the response maps with sensitive dependence and k3 (6.1-6.2)
#                (133 s CPU, 254 s wall on the shared 2-core machine; the long-term responses 47 s CPU of it)
#   all          the three
# The figures in docs/figures/ of the thesis targets are exactly these (copied from OUTDIR).
set -euo pipefail
cd "$(dirname "$0")/.."
B=./build/blockdyn
O=${1:-out/gallery}
shift || true
TARGETS=${*:-core thesis}
[ "$TARGETS" = all ] && TARGETS="core thesis thesis-long"
for t in $TARGETS; do
  case $t in core|thesis|thesis-long) ;; *) echo "error: unknown target '$t' (core, thesis, thesis-long, all)" >&2; exit 2;; esac
done
mkdir -p "$O"
run() { echo "+ $*"; "$@" >/dev/null; }
# A figure script's JSON summary (the numbers the docs quote) is kept beside its figures.
runpy() { echo "+ python/$1 $B $O"; /usr/bin/python3 "python/$1" "$B" "$O" > "$O/${1%.py}.json"; }
wants() { [[ " $TARGETS " == *" $1 "* ]]; }

core() {
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
}

thesis() {
# Code checks against the rigid-ground model and the closed-form bounce (thesis 3.3)
runpy fig_convergence.py
# Typical responses, ic1 (thesis 4.1): settles and slides (4.1), steady rocking (4.2), a stiffer
# foundation (4.3), zero friction (4.4)
run $B simulate --r 0.5 --mu 0.1 --k 1e4 --ic ic1 --t-end 20 --plot "$O/typical_fig4_1.png"
run $B simulate --r 0.2 --mu 0.2 --k 1e3 --ic ic1 --t-end 10 --plot "$O/typical_fig4_2.png"
run $B simulate --r 0.2 --mu 0.2 --k 1e5 --ic ic1 --t-end 10 --plot "$O/typical_fig4_3.png"
run $B simulate --r 0.5 --mu 0 --k 1e4 --ic ic1 --t-end 20 --plot "$O/typical_fig4_4.png"
# Time to first flight (4.6-4.13) and time/ihor at overturning (4.21-4.28)
runpy fig_flight_time.py
runpy fig_overturn.py
# Equilibrium landscapes (4.35-4.36) and bifurcation diagrams (4.37-4.39)
for k in 4.5 6.2 100; do run $B equilibria --r 0.9 --k $k --plot "$O/equil_landscape_r0.9_k$k.png"; done
for k in 500 599.1 2000; do run $B equilibria --r 0.1 --k $k --plot "$O/equil_landscape_r0.1_k$k.png"; done
for r in 1 0.95 0.7 0.5 0.2 0.1; do run $B bifurcation --r $r --plot "$O/equil_bifurcation_r$r.png"; done
}

thesis_long() {
# Long-term responses, Table 4.1 (4.41-4.55) and the settle-down steady state (4.56)
runpy fig_long_term.py
# Chaos: energy-surface projections (5.1-5.2), Poincare/energy/Lyapunov layouts (5.3-5.7, 5.13-5.14)
runpy fig_chaos.py
# Response maps with sensitive dependence and k3 (6.1-6.2)
for ic in ic1 ic2; do
  run $B map --mu 0.2 --ic $ic --k 1e1:1e8:15 --inv-r 1:20:12 --t-end 30 --boundary-points 8 --sensitivity \
    -o "$O/map_$ic.csv" --overwrite --quiet --plot "$O/map_$ic.png"
done
}

wants core && core
wants thesis && thesis
wants thesis-long && thesis_long
echo "gallery written to $O"
