#!/usr/bin/env bash
# Set up cellsph (tools/setup.sh) and run the main example; its outputs land in
# examples/inflation/out/ (the seed's single-cell inflation: logs, tables, Fig. 4 and Fig. 5 PNGs).
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$repo/tools/setup.sh"
bash "$repo/examples/inflation/run.sh"
