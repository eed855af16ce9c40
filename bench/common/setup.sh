# Sourced by the bench scripts, after 'set -euo pipefail', as their first step:
#   source "$(dirname "${BASH_SOURCE[0]}")/../common/setup.sh"
# Sets here (the sourcing script's folder), root (the repository), build ($CELLSPH_BUILD, default
# root/build: its bin/lmp and tools/cellgen/cellgen), lets Open MPI run as root and points
# LAMMPS_POTENTIALS at the repository's potentials/. bench_work makes work, a temporary folder
# removed when the script exits.
here=$(cd "$(dirname "${BASH_SOURCE[1]}")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${CELLSPH_BUILD:-$root/build}
if [ "$(id -u)" -eq 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
export LAMMPS_POTENTIALS=$root/potentials
bench_work() {
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
}
