#!/usr/bin/env bash
# Set up cellsph (tools/setup.sh) and run the whole test suite, serial and on 2 MPI ranks.
# Extra arguments go to ctest (e.g. -R bond_ to run a subset).
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$repo/tools/setup.sh"
build=${CELLSPH_BUILD:-$repo/build}
cd "$build"
ctest --output-on-failure -j "$(nproc)" "$@"
