# SPDX-License-Identifier: Apache-2.0
# Sourced by the figure scripts (docs-figures.sh, cycles-figures.sh, earthquake-figures.sh): from
# the repository's root, the program B, the figure directory F ($1, default docs/figures) and the
# data directory D ($2, default FIGURES_DATA_DIR), both created, and `run` to echo and run a
# command (its output discarded; with TIME=1 also its wall and CPU times).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
B=./build/blockdyn
F=${1:-docs/figures}
D=${2:-$FIGURES_DATA_DIR}
mkdir -p "$F" "$D"
run() {
  echo "+ $*"
  if [[ ${TIME:-0} == 1 ]]; then
    /usr/bin/time -f "  %e s wall, %U s user" "$@" >/dev/null
  else
    "$@" >/dev/null
  fi
}
