#!/usr/bin/env bash
# Speed of the full sealed-cell model (bench/speed/cell_model_speed.lmp: SPH fluid, wall-fluid and
# wall-wall terms, damped Neo-Hookean wall bonds, compute cell/props) at the seed's resolution
# (1092 wall + 1647 fluid particles) on 1 and 2 MPI ranks, for the two wall-fluid models:
# particles (pair cell/wall wallfluid, cellgen --gap 11e-6) and the SPH wall boundary
# (pair_coeff 1 2 cell/sph wall, cellgen's default gap); with the boundary, the smoothing length
# per atom, adaptive (h = 1.27 (m/rho)^(1/3)), and fixed at
# the adaptive run's mean h (boundary-h14: 14.3 um, the cost of h adaptive at equal h).
#   bash bench/speed/cell_model_speed.sh [nsteps=5000] [repeats=3] [models="particles boundary"]
#   (models also: adaptive boundary-h14 auto; auto: the boundary with pair cell/sph
#   background auto 5e4 in the timed run; 5e3 and 2e4 lost wall atoms in these undamped
#   dynamics while P_b followed its target on every step, and 5e3 runs with the default lag of
#   200 steps: doc/pair_cell_sph.md, background pressure)
# Prints particle-steps per second per core of the timed run (best of the repeats). Environment:
# CELLSPH_BUILD (build folder), MPIEXEC (default mpirun), OUT (work folder), NPS (rank counts,
# default "1 2").
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${CELLSPH_BUILD:-$here/../../build}
out=${OUT:-/tmp/cellsph-bench/cell_model_speed}
nsteps=${1:-5000}
repeats=${2:-3}
models=${3:-particles boundary}
if [ "$(id -u)" -eq 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
mkdir -p "$out"
cd "$out"
for model in $models; do
hmode=fixed hfix=12.2e-6 bg=-1
case $model in
  auto) bnd=1 gap=4.79885e-6 bg=5e4 ;;
  particles) bnd=0 gap=11e-6 ;;
  boundary) bnd=1 gap=4.79885e-6 ;;
  boundary-h14) bnd=1 gap=4.79885e-6 hfix=14.3e-6 ;;
  adaptive) bnd=1 gap=4.79885e-6 hmode=$model ;;
esac
"$build/tools/cellgen/cellgen" --gap "$gap" --wall-mass 1e-12 --out cell.data >cellgen.log
echo
echo "wall-fluid model: $model"
echo "| MPI ranks | particles | steps | loop time (s), best of $repeats | particle-steps/s | per core |"
echo "|---:|---:|---:|---:|---:|---:|"
for np in ${NPS:-1 2}; do
  best=
  for r in $(seq "$repeats"); do
    log=log.$model.np$np.$r
    if [ "$np" = 1 ]; then cmd=("$build/bin/lmp"); else cmd=("${MPIEXEC:-mpirun}" -np "$np" "$build/bin/lmp"); fi
    "${cmd[@]}" -in "$here/cell_model_speed.lmp" -var nsteps "$nsteps" -var bnd "$bnd" -var gap "$gap" -var hmode "$hmode" -var hfix "$hfix" -var bg "$bg" \
      -log "$log" >/dev/null
    # the timed run is the last "Loop time" line
    t=$(awk '/^Loop time of/ { t = $4; n = $9; a = $12 } END { print t }' "$log")
    if [ -z "$best" ] || awk -v a="$t" -v b="$best" 'BEGIN { exit !(a < b) }'; then best=$t; fi
  done
  atoms=$(awk '/^Loop time of/ { a = $12 } END { print a }' "log.$model.np$np.1")
  awk -v np="$np" -v t="$best" -v n="$nsteps" -v a="$atoms" \
    'BEGIN { r = a * n / t; printf "| %d | %d | %d | %.2f | %.3g | %.3g |\n", np, a, n, t, r, r / np }'
done
done
