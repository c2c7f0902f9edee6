#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Checks that every C++ file is formatted as .clang-format says (Debian 12's clang-format 14);
# exits 77 (ctest: skipped) without clang-format. scripts/check-format.sh --fix formats in place.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null || { echo "clang-format not installed: skipped"; exit 77; }
mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.ipp' '*.h' '*.cc' 2>/dev/null || find src apps tests bench python -name '*.[ch]pp')
if [ "${1:-}" = "--fix" ]; then
  clang-format -i "${files[@]}"
  exit 0
fi
# One process for all files (a few seconds); each file off its format is named by a diagnostic.
if ! out=$(clang-format --dry-run --Werror "${files[@]}" 2>&1); then
  echo "not formatted (scripts/check-format.sh --fix):" >&2
  grep -o '^[^:]*:[0-9]*:[0-9]*: error' <<<"$out" | cut -d: -f1 | sort -u >&2
  exit 1
fi
echo "${#files[@]} files formatted"
