#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs blockdyn's build and plot dependencies from Debian 12 packages (idempotent).
set -euo pipefail
PKGS=(build-essential cmake ninja-build pkg-config
      libboost-dev libeigen3-dev libglpk-dev libcli11-dev libtomlplusplus-dev nlohmann-json3-dev libfmt-dev
      libgtest-dev libgmock-dev libbenchmark-dev
      libopenmpi-dev openmpi-bin
      python3-numpy python3-scipy python3-matplotlib python3-pil python3-pytest python3-dev pybind11-dev ffmpeg
      dpkg-dev clang libclang-rt-14-dev)
missing=()
for p in "${PKGS[@]}"; do dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p"); done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
