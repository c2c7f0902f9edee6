#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# From a fresh Debian 12 machine: install dependencies, build (warnings as errors), and run the
# whole test suite (ctest labels: unit, cli, validation, install).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
BLOCKDYN_WERROR=ON bash scripts/build.sh
cd build
ctest --output-on-failure -j"$(nproc)" --timeout 900
