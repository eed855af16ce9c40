#!/usr/bin/env bash
# Time of one water-network step of fix cell/turgor's 'exchange' (src/cell_network.cpp: assemble,
# conjugate gradients, fluxes) against the number of cells, 1e2 to 5e4, on a periodic BCC lattice
# of Kelvin cells (14 junctions per cell) at step stiffnesses dt_w g s of 1-100 and 1e4-1e6 (a
# huge L_cc), and on a simple cubic one (6 junctions): one core, one table each
# (bench/network_step.cpp). Usage: bench/network_step.sh [repeats=10]
# The driver is compiled here with the same compiler flags as the plugin's Release build
# (-O3 -DNDEBUG); Eigen from the system (Debian libeigen3-dev).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
work=${WORK:-$(mktemp -d)}
eigen=$(pkg-config --cflags eigen3 2>/dev/null || echo -I/usr/include/eigen3)
${CXX:-g++} -std=c++17 -O3 -DNDEBUG $eigen -I"$here/../src" "$here/network_step.cpp" "$here/../src/cell_network.cpp" \
  -o "$work/network_step"
"$work/network_step" bcc "${1:-10}" 1
"$work/network_step" bcc "${1:-10}" 1e4
"$work/network_step" sc "${1:-10}" 1
