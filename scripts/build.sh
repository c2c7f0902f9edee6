#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Configures and builds blockdyn into ./build (Release). BLOCKDYN_WERROR=ON (set by test.sh, as in
# CI) turns compiler warnings into errors. Arguments name the targets to build (default: all,
# which is the library, the program, the Python module and the tests; the benchmarks are built
# on request: scripts/build.sh blockdyn_bench).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DBLOCKDYN_WERROR="${BLOCKDYN_WERROR:-OFF}" >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build build -j"$(nproc)" "${targets[@]}"
