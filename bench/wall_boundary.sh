#!/usr/bin/env bash
# The SPH wall boundary against the old wall-fluid model on the seed-resolution sealed cell
# (1092 wall, 1647 fluid, 1.35 x water, 0.4 ms, 2 ranks): the final summary line of each run and
# the radial pressure shells, one particle spacing (9.6 um) wide. About 1 minute.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${CELLSPH_BUILD:-$here/../build}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [ "$(id -u)" -eq 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
export LAMMPS_POTENTIALS=$here/../potentials
run() {    # name bnd gap r0
  mkdir -p "$work/$1" && cd "$work/$1"
  "$build/tools/cellgen/cellgen" --gap "$3" --wall-mass 1e-12 --out cell.data >/dev/null
  mpirun -np 2 "$build/bin/lmp" -in "$here/wall_boundary.lmp" -var bnd "$2" -var gap "$3" \
    -var r0 "$4" -log log.lammps | grep RESULT
  python3 "$here/pressure_shells.py" "profile_$2.txt" 9.6e-6
}
echo "== without the boundary: gap = r0 = 11 um (apple.cellsph wallfluid)"
run old 0 11e-6 11e-6
echo "== with the boundary: cellgen gap dx/2, repulsion backstop r0 = 7 um"
run boundary 1 4.79885e-6 7e-6
