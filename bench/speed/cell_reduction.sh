#!/bin/bash
# The cost of one per-cell reduction (fix cell/turgor's every-N-steps evaluation) against the
# number of cells, on 1 and 2 ranks, for one or more builds of the plugin:
#
#   bash bench/speed/cell_reduction.sh [LABEL=PLUGIN.so ...]      default: after=build/cellsphplugin.so
#
# e.g. before=/tmp/main-build/cellsphplugin.so after=build/cellsphplugin.so. Systems: 10^3, 10^4,
# 10^5 tiny cells (bench/speed/cell_reduction.py: 4 wall atoms, 4 triangles and 1 fluid atom each, on a
# periodic lattice whose x = 0 and mid-x planes of cells straddle the periodic and the rank
# boundary). Each run evaluates the fix every step for STEPS steps (default 200; 50 at 10^5) with
# no forces and no motion, and reports the run's Modify time / steps (the fix alone: its sums,
# their reduction, the per-cell water logic, the mass update), wall-clock and CPU (wall x the
# %CPU of timer full: on a loaded host a rank waits for a core, and the CPU time is the work it
# did), averaged over ranks, the least of REPEAT runs (default 3: the one least disturbed). CELLS="1000 10000" limits the sizes.
# COMPUTES=1 adds compute cell/props, COMPUTES=2 compute cell/shape too, each read every step
# (their time is in Modify then: with the shared sums of src/cell_set.h the three styles take one
# reduction per step, before it three).
# The last two columns are message sizes per rank and reduction computed from the exchange
# pattern, not measured: one MPI_Allreduce of 25 doubles per cell (the design before the cell
# registry), and the registry's 26 doubles (cell index + 25 sums) to the home rank and 1 double
# (dM/M) back per split cell, each rank being home to about half of them (0 on 1 rank).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../common/setup.sh"
out=${OUT:-$root/bench/out/cell_reduction}
mkdir -p "$out"
[ $# -gt 0 ] || set -- "after=$root/build/cellsphplugin.so"
lmp=$build/bin/lmp
mpi=(mpirun -np 2)
export OMPI_MCA_rmaps_base_oversubscribe=1

printf "%8s %6s %6s" cells split ranks
for spec in "$@"; do printf " %12s %12s" "${spec%%=*}[wall]" "${spec%%=*}[cpu]"; done
printf " %14s %14s\n" "allreduce[B]" "registry[B]"
for n in ${CELLS:-1000 10000 100000}; do
  data=$out/cells_$n.data
  python3 "$here/cell_reduction.py" "$n" "$data" > "$data.counts"
  read -r ncell split < "$data.counts"
  steps=${STEPS:-$([ "$n" -ge 100000 ] && echo 50 || echo 200)}
  for ranks in 1 2; do
    printf "%8s %6s %6s" "$ncell" "$split" "$ranks"
    for spec in "$@"; do
      label=${spec%%=*} plugin=${spec#*=}
      run=("$lmp")
      [ "$ranks" = 1 ] || run=("${mpi[@]}" "$lmp")
      best= bestcpu=
      for r in $(seq "${REPEAT:-3}"); do
        log=$out/log.$label.$n.np$ranks.$r
        (cd "$out" && "${run[@]}" -in "$here/cell_reduction.lmp" -log "$log" -screen none \
          -var data "$data" -var plugin "$plugin" -var steps "$steps" -var computes "${COMPUTES:-0}")
        # Modify | min | avg | max | %varavg | %CPU | %total: the average over ranks
        modify=$(awk '/^Modify/ {print $5}' "$log")
        cpu=$(awk '/^Modify/ {print $5 * $11 / 100}' "$log")
        best=$(echo "$modify $best" | awk '{print ($2 == "" || $1 < $2) ? $1 : $2}')
        bestcpu=$(echo "$cpu $bestcpu" | awk '{print ($2 == "" || $1 < $2) ? $1 : $2}')
      done
      printf " %12.3e %12.3e" "$(echo "$best / $steps" | bc -l)" "$(echo "$bestcpu / $steps" | bc -l)"
    done
    printf " %14d %14d\n" $((200 * ncell)) $(((ranks - 1) * split * (26 + 1) * 8 / 2))
  done
done
