#!/usr/bin/env bash
# Speed of pair_style cell/sph against LAMMPS's own SPH package on the same problem:
# particle-steps per second per core on a 3-D periodic block of n^3 fluid particles (simple-cubic,
# dx = 10 um, support radius 2.4 dx, same neighbour skin and steps; bench/speed/sph_block.lmp), on 1 and
# 2 MPI ranks. cell/sph: Wendland C2 kernel, summation density, linear EOS, Morris viscosity,
# fix nve. LAMMPS: atom_style sph, pair_style hybrid/overlay sph/rhosum 1 sph/taitwater/morris
# (density summation every step, Tait EOS, Morris viscosity), fix sph. The ratio is the tracked
# figure (goal >= 2). Each point is the best of <repeats> runs (Loop time of the timed run).
#
#   bash bench/speed/sph_vs_lammps_sph.sh [n (default 24)] [steps (default 200)] [repeats (default 3)]
#   LMP=<lmp wrapper> to use another build (default build/bin/lmp)
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
lmp=${LMP:-$repo/build/bin/lmp}
n=${1:-24}
steps=${2:-200}
repeats=${3:-3}
if [ "$(id -u)" -eq 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# best Loop time (s) of the timed run over the repeats: impl ranks
loop_time() {
  local impl=$1 ranks=$2 best="" t log
  for r in $(seq "$repeats"); do
    log=$work/$impl.$ranks.$r.log
    (cd "$work" && mpirun -np "$ranks" "$lmp" -in "$repo/bench/speed/sph_block.lmp" -var impl "$impl" \
      -var n "$n" -var steps "$steps" -log "$log" -screen none >/dev/null 2>&1) ||
      { echo "run failed: $impl on $ranks rank(s), see $log" >&2; tail -5 "$log" >&2; exit 1; }
    t=$(grep "^Loop time" "$log" | tail -1 | awk '{print $4}')
    best=$(awk -v a="$best" -v b="$t" 'BEGIN { print (a == "" || b < a) ? b : a }')
  done
  echo "$best"
}

natoms=$((n * n * n))
echo "cell/sph vs LAMMPS SPH: $natoms particles, $steps steps, best of $repeats ($lmp)"
printf '%-6s %22s %22s %8s\n' ranks "cell/sph (p-steps/s/core)" "LAMMPS SPH (p-steps/s/core)" ratio
for ranks in 1 2; do
  tc=$(loop_time cellsph "$ranks")
  tl=$(loop_time lammps "$ranks")
  awk -v r="$ranks" -v tc="$tc" -v tl="$tl" -v np="$natoms" -v s="$steps" 'BEGIN {
    c = np * s / (tc * r); l = np * s / (tl * r)
    printf "%-6d %22.3e %22.3e %8.2f\n", r, c, l, c / l }'
done
echo "neighbour-list entries per particle (support + skin): $(grep -h "^Ave neighs/atom" "$work"/cellsph.1.1.log |
  tail -1 | awk '{print $NF}') (cell/sph half list), $(grep -h "^Ave neighs/atom" "$work"/lammps.1.1.log |
  tail -1 | awk '{print $NF}') (LAMMPS, first of its lists)"
