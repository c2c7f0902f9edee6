#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds the library and the unit tests with AddressSanitizer + UndefinedBehaviorSanitizer (clang,
# preset asan-ubsan, float-cast-overflow included) and runs the unit tests under them; Open MPI's
# own leaks are suppressed (tests/lsan.supp). Part of CI (.ci/run); about 5 minutes on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset asan-ubsan >/dev/null
cmake --build --preset asan-ubsan --target blockdyn_unit_tests -j"$(nproc)"
ctest --preset asan-ubsan -j"$(nproc)" --timeout 900
