#!/usr/bin/env bash
# The SPH wall boundary (pair_coeff 1 2 cell/sph wall) against the wall-fluid particle model
# (pair cell/wall wallfluid): sealed cells given more water relax at rest, then the radial pressure
# shells (bench/common/pressure_shells.py) and the mean SPH pressure against the wall load and the
# Neo-Hookean membrane law. h and the time step scale with the fluid spacing DX (h = 1.27 DX, the
# seed's 12.2 um at 9.6 um; the old model keeps apple.cellsph's 12.2 um), the wall-wall contact
# size with the wall spacing (bench/common/scaled_cell.sh). On 2 ranks (NP=1: on one, faster on a loaded machine):
#   A. seed resolution (1092 wall, 1647 fluid), 1.35 x water: old model (gap 11 um) and boundary
#   B. seed resolution, boundary, 1.06 and 2.2 x water (stretch about 1.02 and 1.30)
#   C. boundary at 1.35 x water, coarse (312 wall, 461 fluid) and fine (2562 wall, 3911 fluid)
#   H. the smoothing length (boundary): fixed h and h adaptive (eta = 1.27, h/dx of the
#      fluid lattice) at three resolutions, 1.35 x water, and at the seed resolution, 1.06 and 2.2 x
#      (HMODES and HCASES pick a subset: HMODES=adaptive HCASES="coarse seed")
#   U. uniformity of the fluid against the fluid's parameters: each of UVARIANTS, given as
#      name:K:h/dx:hmode:pair_style options (options with '+' for spaces, '-' for none), at each
#      of UCASES (coarse seed fine seed-1.06 seed-2.2); default: the seed's K = 20 MPa against
#      K = 5 MPa and h/dx = 1.27 against 1.5, fixed h, at the seed resolution
# About 25 minutes on 2 free cores (H alone about 40, estimated; under load 2 hours);
# `bench/accuracy/wall_boundary.sh A` runs one part.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../common/setup.sh"
bench_work
parts=${1:-ABC}
source "$here/../common/scaled_cell.sh"
hmode=fixed K=20e6 hdx=1.27 popt="kernel wendland"
run() {    # name bnd f nwall nfluid [cellgen options]; $hmode: the smoothing length mode
  local name=$1 bnd=$2 f=$3 nwall=$4 nfluid=$5
  shift 5
  mkdir -p "$work/$name" && cd "$work/$name"
  local dx gap h dt ws
  scaled_cell "$nwall" "$nfluid" "$@"
  h=$(python3 -c "print($h*$hdx/1.27)")    # h/dx other than the seed's (part U)
  if [ "$bnd" = 0 ]; then h=12.2e-6 dt=1e-8; fi    # the old model as calibrated (apple.cellsph)
  # per-atom h grows with the water from the lattice's h: the neighbour cutoff for h up to hcap h
  local hcap=1.3
  if [ "${f%.*}" -ge 2 ]; then hcap=1.5; fi
  local t0=$SECONDS
  mpirun -np "${NP:-2}" "$build/bin/lmp" -in "$here/wall_boundary.lmp" -var bnd "$bnd" -var f "$f" \
    -var h "$h" -var dt "$dt" -var gap "$gap" -var ws "$ws" -var hmode "$hmode" -var hcap "$hcap" -var K "$K" -var popt "$popt" -var eta "$hdx" -log log.lammps | grep RESULT
  python3 "$here/../common/pressure_shells.py" profile.txt "$name" | tail -1
  echo "  ($((SECONDS - t0)) s, DX $dx, gap $gap)"
}
if [[ $parts == *A* ]]; then
  echo "== A. seed resolution, 1.35 x water"
  run old 0 1.35 1091 1624 --gap 11e-6
  run boundary 1 1.35 1091 1624
fi
if [[ $parts == *B* ]]; then
  echo "== B. seed resolution, boundary, stretch about 1.02 and 1.30"
  run boundary-1.06 1 1.06 1091 1624
  run boundary-2.2 1 2.2 1091 1624
fi
if [[ $parts == *C* ]]; then
  echo "== C. boundary, 1.35 x water, coarse and fine"
  run coarse 1 1.35 300 450
  run fine 1 1.35 2562 3900
fi
# variant case: one sealed cell of parts H and U (coarse, seed, fine; the seed at 1.06 and 2.2 x water)
run_case() {
  case $2 in
    coarse) run "$1-coarse" 1 1.35 300 450 ;;
    seed) run "$1-seed" 1 1.35 1091 1624 ;;
    fine) run "$1-fine" 1 1.35 2562 3900 ;;
    seed-1.06) run "$1-seed-1.06" 1 1.06 1091 1624 ;;
    seed-2.2) run "$1-seed-2.2" 1 2.2 1091 1624 ;;
  esac
}
if [[ $parts == *H* ]]; then
  echo "== H. boundary: fixed h, h adaptive"
  for hmode in ${HMODES:-fixed adaptive}; do
    for case in ${HCASES:-coarse seed fine seed-1.06 seed-2.2}; do run_case "$hmode" "$case"; done
  done
  hmode=fixed
fi
if [[ $parts == *U* ]]; then
  echo "== U. uniformity against K, h/dx, the h mode and pair_style options"
  for v in ${UVARIANTS:-k20:20e6:1.27:fixed:- k5:5e6:1.27:fixed:- hdx1.5:20e6:1.5:fixed:-}; do
    IFS=: read -r vname K hdx hmode popt <<<"$v"
    if [ "$popt" = - ]; then popt="kernel wendland"; else popt=${popt//+/ }; fi
    for case in ${UCASES:-seed}; do run_case "$vname" "$case"; done
  done
  hmode=fixed K=20e6 hdx=1.27 popt="kernel wendland"
fi
