#!/usr/bin/env bash
# Speed of the full sealed-cell model (bench/cell_model_speed.lmp: SPH fluid, wall-fluid and
# wall-wall terms, damped Neo-Hookean wall bonds, compute cell/props) at the seed's resolution
# (cellgen default, wall-fluid gap 7.5 um: 1092 wall + 1647 fluid particles) on 1 and 2 MPI ranks.
#   bash bench/cell_model_speed.sh [nsteps=5000] [repeats=3]
# Prints particle-steps per second per core of the timed run (best of the repeats). Environment:
# CELLSPH_BUILD (build folder), MPIEXEC (default mpirun), OUT (work folder).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${CELLSPH_BUILD:-$here/../build}
out=${OUT:-/tmp/cellsph-bench/cell_model_speed}
nsteps=${1:-5000}
repeats=${2:-3}
if [ "$(id -u)" -eq 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
mkdir -p "$out"
cd "$out"
"$build/tools/cellgen/cellgen" --gap 11e-6 --wall-mass 1e-12 --out cell.data >cellgen.log

echo "| MPI ranks | particles | steps | loop time (s), best of $repeats | particle-steps/s | per core |"
echo "|---:|---:|---:|---:|---:|---:|"
for np in 1 2; do
  best=
  for r in $(seq "$repeats"); do
    log=log.np$np.$r
    if [ "$np" = 1 ]; then cmd=("$build/bin/lmp"); else cmd=("${MPIEXEC:-mpirun}" -np "$np" "$build/bin/lmp"); fi
    "${cmd[@]}" -in "$here/cell_model_speed.lmp" -var nsteps "$nsteps" -log "$log" >/dev/null
    # the timed run is the last "Loop time" line
    t=$(awk '/^Loop time of/ { t = $4; n = $9; a = $12 } END { print t }' "$log")
    if [ -z "$best" ] || awk -v a="$t" -v b="$best" 'BEGIN { exit !(a < b) }'; then best=$t; fi
  done
  atoms=$(awk '/^Loop time of/ { a = $12 } END { print a }' "log.np$np.1")
  awk -v np="$np" -v t="$best" -v n="$nsteps" -v a="$atoms" \
    'BEGIN { r = a * n / t; printf "| %d | %d | %d | %.2f | %.3g | %.3g |\n", np, a, n, t, r, r / np }'
done
