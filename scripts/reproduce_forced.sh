#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Regenerates the forced-response reproductions of docs/forced-reproductions.md: Housner-block
# overturning spectra (rect, half-sine, one-sine) against the linearised model; seed 002 Figs. 2-5
# (half-cosine pulse) and 6-11 (harmonic survival and maximum rotation) on our trilith (deformable
# law); seed 001 Figs. 4-7 trends on the rigid 5-DOF trilith; a refined (fine-mesh) survival
# boundary. Every run keeps its table, journal and sidecar in OUTDIR, so an interrupted
# reproduction continues where it stopped: RESUME=1 scripts/reproduce_forced.sh OUTDIR.
# About 20 minutes of CPU (most of it Figs. 6-9, 60 s trilith runs), 10-12 minutes on 2 idle
# cores; MPI: MPIRUN="mpirun -np 4" scripts/reproduce_forced.sh. PARTS selects parts (default all:
# "spectra pulse harmonic transient seed001"); parts write disjoint tables, so two invocations with
# different PARTS may run at the same time.
# Usage: scripts/reproduce_forced.sh [OUTDIR] (default out/forced; needs a built ./build)
set -euo pipefail
cd "$(dirname "$0")/.."
B=./build/blockdyn
O=${1:-out/forced}
mkdir -p "$O"
POLICY=--overwrite
[ "${RESUME:-0}" = 1 ] && POLICY=--resume
MPIRUN=${MPIRUN:-}
PARTS=" ${PARTS:-spectra pulse harmonic transient seed001} "
part() { [[ "$PARTS" == *" $1 "* ]]; }
run() { echo "+ $*"; $MPIRUN "$@" $POLICY --progress plain --progress-interval 30; }
T="--model assembly --preset trilith"  # seed 002's blocks: b = 0.12 m, lambda = 4 (deformable law)

HB="--model housner --width 0.3 --height 1.5"
if part spectra; then
# Housner block (0.3 x 1.5 m, alpha = 0.197): overturning spectra and the one-sine picture.
for pulse in rect half-sine one-sine; do
  run $B spectrum $HB --pulse $pulse --duration-min 0.03 --duration-max 10 --duration-points 36 \
    --amplitude-min 0.01 --amplitude-max 20 --scan-points 100 --csv "$O/spectrum_$pulse.csv" \
    --json-out "$O/spectrum_$pulse.summary.json"
done
run $B spectrum $HB --pulse one-sine --duration-min 0.1 --duration-max 3 --duration-points 80 \
  --amplitude-min 0.1 --amplitude-max 10 --scan-points 200 --csv "$O/spectrum_one_sine_map.csv" \
  --plot-map "$O/spectrum_one_sine_map.png"
/usr/bin/python3 python/fig_housner_spectra.py "$O/spectrum_rect.summary.json" "$O/spectrum_half-sine.summary.json" \
  "$O/spectrum_one-sine.summary.json" "$O/spectrum_housner_linearised.png"

# Fine mesh: Housner survival map (harmonic, 20 periods), 24 x 24 refined 4 times near class changes.
run $B survival $HB --beta-min 0.5 --beta-max 6 --beta-points 24 --omega-min 1 --omega-max 20 --omega-points 24 \
  --periods 20 --refine 4 --out "$O/survival_housner_refined.csv" --plot "$O/survival_housner_refined.png"
fi

if part pulse; then
# Seed 002 Fig. 2: survival domain, half-cosine pulse (eq. 1 for 0 <= Omega t <= pi), phi_l = 90 and 15.
for pl in 90 15; do
  run $B survival $T --phi-s 90 --phi-l $pl --excitation half-cosine --beta-min 0.25 --beta-max 10 --beta-points 14 \
    --omega-min 0.5 --omega-max 8 --omega-points 14 --t-end 8 --out "$O/seed002_fig2_phil$pl.csv" \
    --plot "$O/seed002_fig2_phil$pl.png"
done
# The same for phi_l = 90, refined twice near class changes (the fine boundary the seed could not afford).
run $B survival $T --excitation half-cosine --beta-min 0.25 --beta-max 10 --beta-points 10 --omega-min 0.5 \
  --omega-max 8 --omega-points 10 --t-end 8 --refine 2 --out "$O/seed002_fig2_refined.csv" \
  --plot "$O/seed002_fig2_refined.png"
# The one-signed half-sine A g sin(pi t / t_p) instead (not the seed's pulse), for comparison.
run $B survival $T --excitation half-sine --beta-min 0.25 --beta-max 10 --beta-points 14 --omega-min 0.5 \
  --omega-max 8 --omega-points 14 --t-end 8 --out "$O/seed002_fig2_half_sine.csv" --plot "$O/seed002_fig2_half_sine.png"
# Fig. 3: theta_MAX versus omega, phi = 90 and phi = atan(1/lambda) = 14.04 deg.
for phi in 90 14.036243467926479; do
  run $B response-curve $T --phi-s $phi --phi-l $phi --excitation half-cosine --betas 2,4,6 --omega-min 1 \
    --omega-max 12 --omega-points 12 --t-end 8 --out "$O/seed002_fig3_phi${phi%%.*}.csv" \
    --plot "$O/seed002_fig3_phi${phi%%.*}.png"
done
# Fig. 4: theta_MAX versus phi_l, phi_s = 90, omega = 10, several beta; Fig. 5: beta = 4, several phi_s.
run $B response-curve $T --excitation half-cosine --omega 10 --betas 2,4,6,8 --phi-l-values 2,4,6,8,10,12,15,20,25,30,45,60,90 \
  --t-end 8 --out "$O/seed002_fig4.csv" --plot "$O/seed002_fig4.png"
run $B response-curve $T --excitation half-cosine --omega 10 --betas 4 --phi-s-values 10,15,20,30,90 \
  --phi-l-values 2,4,6,8,10,12,15,20,25,30,45,60,90 --t-end 8 --out "$O/seed002_fig5.csv" --plot "$O/seed002_fig5.png"
fi

if part harmonic; then
# Figs. 6-9: harmonic survival domains, 60 s per run, (phi_s, phi_l) = (90, 90), (15, 15), (90, 15), (90, 5).
for pair in 90,90 15,15 90,15 90,5; do
  ps=${pair%,*}; pl=${pair#*,}
  run $B survival $T --phi-s "$ps" --phi-l "$pl" --beta-min 1 --beta-max 6 --beta-points 10 --omega-min 2 \
    --omega-max 20 --omega-points 10 --t-end 60 --out "$O/seed002_harmonic_${ps}_${pl}.csv" \
    --plot "$O/seed002_harmonic_${ps}_${pl}.png"
done
fi

if part transient; then
# Fig. 10: maximum transient rotation (20 s) versus omega, beta = 4, the friction pairs (15 | 90) x (15 | 90).
run $B response-curve $T --betas 4 --phi-s-values 15,90 --phi-l-values 15 --omega-min 2 --omega-max 20 --omega-points 12 \
  --t-end 20 --out "$O/seed002_fig10_phil15.csv" --plot "$O/seed002_fig10_phil15.png"
run $B response-curve $T --betas 4 --phi-s-values 15,90 --phi-l-values 90 --omega-min 2 --omega-max 20 --omega-points 12 \
  --t-end 20 --out "$O/seed002_fig10_phil90.csv" --plot "$O/seed002_fig10_phil90.png"
# Fig. 11: the same for phi_s = phi_l = 90 and several beta.
run $B response-curve $T --betas 2,3,4,5 --omega-min 2 --omega-max 20 --omega-points 12 --t-end 20 \
  --out "$O/seed002_fig11.csv" --plot "$O/seed002_fig11.png"
fi

if part seed001; then
# Seed 001 Figs. 4-7: rigid 5-DOF trilith (columns only rock), K_s g sin(Omega t + pi/2) = beta alpha g cos(Omega t)
# with beta = K_s / alpha (alpha = 0.24498): K_s = 0.3, 0.4, 0.5, 0.7; over 5 s (Figs. 4-5) and 100 s (Figs. 6-7).
R="$T --contact rigid --columns-rock-only --phi-l 20"
BETAS=1.2246,1.6328,2.0410,2.8574
run $B response-curve $R --betas $BETAS --omega-min 2 --omega-max 20 --omega-points 16 --t-end 5 \
  --out "$O/seed001_fig4_5.csv" --plot "$O/seed001_fig4_5.png"
run $B response-curve $R --betas $BETAS --omega-min 2 --omega-max 20 --omega-points 10 --t-end 100 \
  --out "$O/seed001_fig6_7.csv" --plot "$O/seed001_fig6_7.png"
fi
echo "figures in $O"
