#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The figures of the analysis pages made by single commands, exactly as the pages give them
# (docs/flight.md, stability.md, equilibria.md, chaos.md, response-curve.md, survival.md, sweep.md,
# rigid-ground.md). With scripts/gallery.sh (thesis figures), scripts/cycles-figures.sh,
# scripts/forced_chaos_figures.sh and scripts/reproduce_forced.sh it regenerates every figure in
# docs/figures. About 6 minutes of CPU. Usage: scripts/docs-figures.sh [FIGDIR [DATADIR]]
# (defaults docs/figures and out/docs-figures; needs a built ./build).
FIGURES_DATA_DIR=out/docs-figures
# shellcheck source=scripts/figures-env.sh
source "$(dirname "$0")/figures-env.sh"

# docs/flight.md
run $B flight-time --ic ic1 --r 0.1 --mu 0.2 --k-min 1e2 --k-max 1e9 --points 120 --csv "$D/ft_ic1.csv" \
  --plot "$F/flight_time_ic1_r0.1.png"
run $B flight-time --ic ic2 --r 0.3 --mu 0.2 --k-min 1e2 --k-max 1e8 --points 120 --plot "$F/flight_time_ic2_r0.3.png"
run $B kmin --mu 0.2 --plot "$F/flight_kmin.png"
run $B flight-boundary --ic ic1 --mu 0.2 --r-min 0.05 --r-max 1 --points 14 --per-decade 8 --rel-tol 0.005 --n 2,10 \
  --json "$D/fb_ic1.json" --plot "$F/flight_boundary_ic1.png"
run $B flight-boundary --ic ic2 --mu 0.2 --r-min 0.05 --r-max 1 --points 14 --per-decade 8 --rel-tol 0.005 --n 2,10 \
  --plot "$F/flight_boundary_ic2.png"
run $B flight-map --ic ic1 --mu 0.2 --r-min 0.05 --r-max 1 --r-points 30 --k-min 1e2 --k-max 1e10 --k-points 60 \
  --csv "$D/fmap.csv" --plot "$F/flight_map_ic1.png"

# docs/stability.md
run $B overturn --ic ic2 --r 0.2 --mu 0.2 --k-min 20 --k-max 2000 --points 120 --window-points 40 \
  --plot "$F/stability_overturn_ic2_r0.2.png"
run $B overturn --ic ic2 --r 0.1 --mu 0.2 --k-min 100 --k-max 5000 --points 120 --window-points 40 \
  --csv "$D/ov_r01.csv" --plot "$F/stability_overturn_ic2_r0.1.png"
run $B overturn --ic ic1 --r 0.2 --mu 0.2 --k-min 20 --k-max 5000 --points 100 --plot "$F/stability_overturn_ic1_r0.2.png"
run $B stability-curve --ic ic2 --which both --mu 0.2 --r-min 0.05 --r-max 1 --points 20 --rel-tol 1e-3 \
  --json "$D/sc_ic2.json" --plot "$F/stability_curve_ic2_mu0.2.png"
run $B stability-curve --ic ic1 --mu 0.2 --r-min 0.05 --r-max 1 --points 20 --rel-tol 1e-3 \
  --plot "$F/stability_curve_ic1_mu0.2.png"
run $B blowup --mu-list 0,0.05,0.1,0.15,0.2,0.25,0.3 --csv "$D/blowup.csv" --plot "$F/stability_blowup.png"

# docs/equilibria.md
run $B equilibria --r 0.9 --k 6.2 --plot "$F/equil_landscape_r0.9_k6.2.png"
run $B bifurcation --r 1 --plot "$F/equil_bifurcation_r1.png"
run $B bifurcation-curves --plot "$F/equil_curves.png"

# docs/chaos.md
run $B energy-surface --mu 0.3 --r 0.2 --k 1e5 --ic surface --w0-alpha 0.125 --y0 0.502 --t-end 1000 --phase-dt 0.1 \
  --plot "$F/energy_fig5_8.png"
run $B response --mu 0.3 --r 0.2 --k 1e5 --ic surface --w0-alpha 0.015625 --y0 0.5002 --t-end 1000 --phase-dt 0.1 \
  --plot "$F/response_fig5_10.png"
run $B energy-surface --mu 0.3 --r 0.2 --k 1e5 --ic ic1 --t-end 1000 --phase-dt 0.1 --plot "$F/energy_ic1_rock_to_vertical.png"
run $B energy-surface --mu 0.2 --r 0.2 --k 1e3 --ic ic1 --t-end 1000 --phase-dt 0.1 --plot "$F/energy_steady_rocking.png"
run $B poincare --mu 0.2 --r 0.1 --k 1e6 --t-end 1000 --plot "$F/poincare_rock_to_vertical.png"
run $B poincare --mu 0 --r 0.5 --k 1e4 --t-end 1000 --plot "$F/poincare_zero_friction.png"
run $B poincare --mu 0.1 --r 0.5 --k 1e5 --t-end 200 --t-min 20 --plot "$F/poincare_settle_down.png"
run $B poincare --mu 0 --r 0.5 --k 1e2 --t-end 1000 --plot "$F/poincare_steady_rocking.png"
run $B lyapunov --mu 0.2 --r 0.1 --k 1e6 --t-end 500 --plot "$F/lyapunov_rock_to_vertical.png"
run $B lyapunov --mu 0 --r 0.5 --k 1e2 --t-end 1000 --plot "$F/lyapunov_steady_rocking.png"
run $B lyapunov --mu 0.1 --r 0.5 --k 1e5 --t-end 500 --plot "$F/lyapunov_settle_down.png"

# docs/response-curve.md, docs/survival.md
run $B response-curve --model housner --width 0.3 --height 1.5 --betas 1.5,2,3 --omega-min 2 --omega-max 20 \
  --omega-points 30 --t-end 10 --out "$D/rc_housner.csv" --overwrite --quiet --plot "$F/response_curve_housner.png"
run $B response-curve --model assembly --preset trilith --contact rigid --phi-l 15 --betas 1.5,3 --omega-min 3 \
  --omega-max 20 --omega-points 10 --t-end 5 --out "$D/rc_trilith.csv" --overwrite --quiet \
  --plot "$F/response_curve_trilith.png"
run $B survival --model assembly --preset trilith --beta-min 1 --beta-max 6 --beta-points 12 --omega-min 2 \
  --omega-max 24 --omega-points 12 --t-end 20 --out "$D/survival_trilith.csv" --overwrite --quiet \
  --plot "$F/survival_trilith.png"

# docs/sweep.md
run $B sweep examples/sweep_flight_map.toml -o "$D/sweep_flight_map.csv" --overwrite --quiet \
  --plot "$F/sweep_flight_map.png"
run $B sweep examples/sweep_flight_map.toml -o "$D/sweep_flight_map.csv" --resume --quiet --plot-column status \
  --plot "$F/sweep_status_map.png"
run $B sweep --k 1e3:1e8:200 --r 0.2 --ic ic1 --w0-over-alpha 0.25 --stop-at-first-flight -o "$D/ttf.csv" --overwrite \
  --quiet --plot "$F/sweep_time_to_flight.png"

# docs/rigid-ground.md
run $B simulate --model rigid --width 0.6 --height 1.8 --mass 150 --mu-s 0.35 --mu-k 0.3 \
  --ground-h-record tests/fixtures/synthetic_60s.AT2 --ground-h-scale 2 --t-end 40 --plot "$F/rigid_record_history.png"
# docs/3d.md
run $B simulate --model rigid3d --width 0.4 --depth 0.3 --height 1.2 --mass 250 --yaw 20 --tilt 0.15 \
  --tilt-azimuth 50 --angular-velocity 0,0,0.5 --mu-s 5 --t-end 3 --output-interval 0.005 \
  --plot "$F/rigid3d_wobble.png" --animate "$F/rigid3d_wobble.gif" --animate-frames 80
run $B simulate --model rigid3d --shape cylinder --radius 0.15 --height 0.1 --mass 5 --tilt 0.3 \
  --angular-velocity=-4,0.5,6 --mu-s 5 --t-end 3 --output-interval 0.005 --plot "$F/rigid3d_roll.png"
run $B simulate --model rigid3d --shape cylinder --radius 0.5 --height 0.6 --mass 300 --mu-s 0.5 --mu-k 0.45 \
  --ground-azimuth 25 --ground-h-amplitude 0.6 --ground-h-frequency 1.3 --ground-h2-amplitude 0.45 \
  --ground-h2-frequency 2.1 --t-end 4 --output-interval 0.005 --plot "$F/rigid3d_drum_slide.png"
run $B motion generate --model rezaeian --arias 3.888 --d5-95 12 --t-mid 10 --f-mid 2.5 --f-slope -0.05 --t-end 40 \
  --seed 2026 --count 2 --out "$D/bidirectional" --overwrite --quiet
run $B simulate --model rigid3d --width 0.35 --depth 0.35 --height 1.2 --mass 250 --mu-s 100 --t-end 40 \
  --ground-h-record "$D/bidirectional/rezaeian_0001.AT2" --ground-h-scale 0.8 \
  --ground-h2-record "$D/bidirectional/rezaeian_0002.AT2" --ground-h2-scale 0.8 --plot "$F/rigid3d_bidirectional.png"
# README.md, docs/index.md, docs/getting-started.md: the demo's statue (scripts/demo.sh)
run $B motion generate --model rezaeian --arias 3.888 --d5-95 12 --t-mid 10 --f-mid 2.5 --f-slope -0.05 --t-end 40 \
  --seed 2026 --out out/demo_record --overwrite --quiet
run $B simulate examples/statue_earthquake.toml --trajectory "$D/statue.csv" --plot "$F/statue_earthquake.png" \
  --animate "$F/statue_earthquake.gif" --animate-frames 80
run $B simulate examples/statue_earthquake.toml --ground-h-scale 0.8 --trajectory "$D/statue_0.8.csv" \
  --plot "$F/statue_earthquake_0.8.png"
echo "figures in $F, tables in $D"
