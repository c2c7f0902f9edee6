#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs blockdyn's dependencies from Debian 12 packages (idempotent). Arguments name groups:
#   build  the compilers and the libraries the program is built from
#   plot   Python and matplotlib for the figures and animations (Pillow: GIF)
#   test   what the test suite adds: GoogleTest, Google Benchmark, Open MPI, SciPy, pytest,
#          pybind11 (the Python module), ffmpeg (MP4), dpkg-dev and file (the .deb package),
#          clang and libFuzzer (the sanitizer job), clang-format (the style check)
#   docs   MkDocs with the Material theme, and Chromium to check the site renders
# No argument: build, plot and test.
set -euo pipefail
declare -A GROUP=(
  [build]="build-essential cmake ninja-build pkg-config libboost-dev libeigen3-dev libglpk-dev libcli11-dev
           libtomlplusplus-dev nlohmann-json3-dev libfmt-dev"
  [plot]="python3-numpy python3-matplotlib python3-pil"
  [test]="libgtest-dev libgmock-dev libbenchmark-dev libopenmpi-dev openmpi-bin python3-scipy python3-pytest
          python3-dev pybind11-dev ffmpeg dpkg-dev file clang libclang-rt-14-dev clang-format libbullet-dev"
  [docs]="mkdocs mkdocs-material chromium"
)
groups=("$@")
[ ${#groups[@]} -eq 0 ] && groups=(build plot test)
missing=()
for g in "${groups[@]}"; do
  [ -n "${GROUP[$g]:-}" ] || { echo "install-deps.sh: unknown group '$g' (build, plot, test, docs)" >&2; exit 2; }
  for p in ${GROUP[$g]}; do dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p"); done
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  APT=(apt-get -o DPkg::Lock::Timeout=600)   # wait for another install instead of failing
  $SUDO "${APT[@]}" update -qq
  $SUDO "${APT[@]}" install -y -qq --no-install-recommends "${missing[@]}"
fi
