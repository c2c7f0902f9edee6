#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds the library, the unit tests and the libFuzzer targets with AddressSanitizer +
# UndefinedBehaviorSanitizer (clang, preset asan-ubsan, float-cast-overflow included) and runs the
# unit tests and each fuzz target (20 s, from tests/fuzz/corpus) under them; Open MPI's own leaks
# are suppressed (tests/lsan.supp). Part of CI (.ci/run).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset asan-ubsan >/dev/null
cmake --build --preset asan-ubsan -j"$(nproc)" --target blockdyn_unit_tests blockdyn_fuzz_records \
  blockdyn_fuzz_at2_roundtrip blockdyn_fuzz_definitions blockdyn_fuzz_journal
ctest --preset asan-ubsan -j"$(nproc)" --timeout 900
