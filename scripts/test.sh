#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# From a fresh Debian 12 machine (or after scripts/demo.sh, whose build it reuses): install the
# dependencies, build everything (warnings as errors), run the whole test suite (ctest labels:
# unit, cli, validation, install, python, docs).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh build plot test
bash scripts/build.sh
cd build
ctest --output-on-failure -j"$(nproc)" --timeout 900
