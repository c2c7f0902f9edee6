#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Configures and builds blockdyn into ./build (Release, warnings as errors as in CI), always with
# the same flags, so scripts/demo.sh's build is the one scripts/test.sh reuses (BLOCKDYN_WERROR=OFF
# for another compiler). Arguments name the targets (default: all: the library, the program, the
# Python module and the tests; the benchmarks on request: scripts/build.sh blockdyn_bench).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DBLOCKDYN_WERROR="${BLOCKDYN_WERROR:-ON}" >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build build -j"$(nproc)" "${targets[@]}"
