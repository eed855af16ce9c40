#!/usr/bin/env bash
# Containment by the SPH wall boundary at five resolutions (312 to 10242 wall particles, R0 = 75
# um, h = 1.27 DX, time step 1e-8 s x DX / 9.6 um): a sealed cell inflated to 1.35 x its volume's
# worth of water, and one shrunk to 0.35 x with wall-fluid adhesion over the boundary (drying goes
# there; without adhesion the fluid leaves the wall instead of pulling it in). apple.cellsph
# unchanged but for the wall-wall contact, whose size follows the wall spacing (at 10242 wall
# particles the seed's sigma = 7.7 um spans two rings of neighbours and blows the wall up);
# cellgen's default gap. Prints the number of fluid atoms outside the wall (winding
# number, compute cell/props column 16), the volume, the fluid-free volume and the pressures.
# About 15 minutes on 2 free cores. `bench/accuracy/wall_boundary_containment.sh 312 1092` runs some.
# MODES (default "inflate shrink"): also shrinkbg, shrunk to 0.35 x without adhesion, the fluid
# held by pair cell/sph background 3e5 (doc/pair_cell_sph.md, background pressure).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../common/setup.sh"
bench_work
source "$here/../common/scaled_cell.sh"
declare -A NFLUID=([312]=450 [642]=733 [1092]=1624 [2562]=3900 [5762]=8800 [10242]=15600)
for want in ${*:-312 1092 2562 5762 10242}; do
  for mode in ${MODES:-inflate shrink}; do
    dir="$work/$want-$mode"
    mkdir -p "$dir" && cd "$dir"
    scaled_cell "$want" "${NFLUID[$want]}"    # the wall-wall contact follows the wall spacing
    popt="kernel wendland"
    case $mode in
      inflate) f=1.35 adh=0 ;;
      shrink) f=0.35 adh=1 ;;
      shrinkbg) f=0.35 adh=0 popt="kernel wendland background 3e5" ;;
      *) echo "unknown mode $mode" >&2 && exit 1 ;;
    esac
    t0=$SECONDS
    result=$(mpirun -np 2 "$build/bin/lmp" -in "$here/wall_boundary.lmp" -var bnd 1 -var adh "$adh" -var ws "$ws" -var popt "$popt" \
      -var f "$f" -var h "$h" -var dt "$dt" -var gap "$gap" -var nrelax 20000 -log log.lammps |
      grep RESULT || echo "RESULT failed: $(grep -m1 ERROR log.lammps)")
    echo "$nwall wall, $nfluid fluid, $mode: ${result#RESULT } ($((SECONDS - t0)) s)"
  done
done
