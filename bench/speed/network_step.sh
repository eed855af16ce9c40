#!/usr/bin/env bash
# Time of one water-network step of fix cell/turgor's 'exchange' (src/fix_cell_turgor_network.cpp: halo,
# assemble, conjugate gradients, fluxes) against the number of cells on a periodic BCC lattice of
# Kelvin cells (14 junctions per cell) at step stiffnesses dt_w g s of 1-100 and 1e4-1e6 (a huge
# L_cc), and on a simple cubic one (6 junctions), on 1 and 2 MPI ranks (each rank a slab of the
# lattice): one table each (bench/speed/network_step.cpp; its last column is the same bit for bit on any
# number of ranks). Usage: bench/speed/network_step.sh [repeats=10 [m ...]], m the lattice sizes (bcc:
# 2 m^3 cells, default 4 6 8 10 14 17 22 30; "8 17 37": about 1e3, 1e4 and 1e5 cells; sc: 1.26 m,
# as many cells; default 5 8 10 14 22 28 38).
# The driver is compiled here with the same compiler flags as the plugin's Release build
# (-O3 -DNDEBUG) by the MPI compiler wrapper (MPICXX, default mpicxx); Eigen from the system
# (Debian libeigen3-dev). Run it under nice on a shared machine: wall-clock times are upper bounds.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
work=${WORK:-$(mktemp -d)}
if [ "$(id -u)" = 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
eigen=$(pkg-config --cflags eigen3 2>/dev/null || echo -I/usr/include/eigen3)
${MPICXX:-mpicxx} -std=c++17 -O3 -DNDEBUG $eigen -I"$here/../../src" "$here/network_step.cpp" \
  "$here/../../src/fix_cell_turgor_network.cpp" -o "$work/network_step"
repeats=${1:-10}
sizes=("${@:2}")
# sc: about as many cells as bcc's 2 m^3
sc=()
for m in "${sizes[@]}"; do sc+=("$(awk -v m="$m" 'BEGIN { printf "%d", m * 1.26 + 0.5 }')"); done
for args in "bcc 1" "bcc 1e4" "sc 1"; do
  read -r lattice amp <<< "$args"
  list=("${sizes[@]}")
  [ "$lattice" = sc ] && list=("${sc[@]}")
  for np in 1 2; do
    echo "# load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
    mpirun -np "$np" "$work/network_step" "$lattice" "$repeats" "$amp" "${list[@]}"
  done
done
