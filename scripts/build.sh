#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Configures and builds blockdyn into ./build (Release). BLOCKDYN_WERROR=ON (set by test.sh, as in
# CI) turns compiler warnings into errors.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DBLOCKDYN_WERROR="${BLOCKDYN_WERROR:-OFF}" >/dev/null
cmake --build build -j"$(nproc)"
