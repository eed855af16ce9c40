#!/usr/bin/env bash
# Set up cellsph (tools/setup.sh) and run the main example; its outputs land in
# examples/<example>/out/ (log.lammps, inflation.dat, PNG pictures).
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$repo/tools/setup.sh"
bash "$repo/examples/wall-inflation/run.sh"
