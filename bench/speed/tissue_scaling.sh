#!/usr/bin/env bash
# Scaling of a drying tissue on this machine (doc/notes/2026-12-07-tissue-scaling.md): particle-steps per second per
# core of the tissue of tests/tissue/tissue.lmp (160 um cells, 16 um spacing, all the physics of
# examples/tissue) for a periodic block and a slab of 27 and 64 cells on 1 and 2 ranks (2 ranks:
# without and with fix balance shift), the 2-rank efficiency, the memory per particle from LAMMPS's
# "Per MPI rank memory" line, and the cost per step of fix cell/turgor's per-cell work (one
# CellReduce::reduce(), its sums sent to the cells' home ranks, then the transfer) against the number
# of cells (bench/speed/cell_reduce_cost.lmp: tiny lumped cells, no pair forces). Prints the load average
# with each row and LAMMPS's "% CPU use" (the share of the wall-clock the ranks got): on a shared
# machine the rate per CPU second (rate / CPU share) estimates the idle-machine rate, but Open MPI's
# busy waiting counts as CPU use, so the 2-rank efficiency from it is an upper bound. About 15 minutes on an idle 2-core machine.
#   bash bench/speed/tissue_scaling.sh [quick|reduce|exchange]   (quick: the 27-cell rows and 10^3 cells
#     only; reduce: the per-cell work only, exchange: the same with the water network
#     (bench/speed/cell_exchange_cost.lmp: the tiny cells joined to their lattice neighbours), at n^3
#     cells for each n of SIZES, default "10 22 46": 10^3, 10^4 and 10^5 cells; 200 timed steps,
#     with exchange 2e5/n^3, at least 10)
# Environment: CELLSPH_BUILD (build folder), OUT (work folder, default /tmp/cellsph-bench/tissue).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${CELLSPH_BUILD:-$here/../../build}
out=${OUT:-/tmp/cellsph-bench/tissue}
mode=${1:-full}
mkdir -p "$out"
cd "$out"
if [ "$(id -u)" = 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
lmp=("$build/bin/lmp")
vars=(-var cellgen "$build/tools/cellgen/cellgen" -var testdir "$here/../../tests")
load() { cut -d' ' -f1 /proc/loadavg; }

# loop time, steps, atoms and max memory per rank of the last run of a log
loop_line() {
  python3 - "$1" <<'PY'
import re, sys
log = open(sys.argv[1]).read()
loop = re.findall(r"Loop time of ([0-9.e+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms", log)[-1]
mem = re.findall(r"Per MPI rank memory allocation \(min/avg/max\) = [0-9.]+ \| [0-9.]+ \| ([0-9.]+) Mbytes", log)[-1]
cpu = re.findall(r"([0-9.]+)% CPU use with", log)[-1]
print(*loop, mem, cpu)
PY
}

run_tissue() {   # name ranks tissue-options boundary balance -> one table row
  local name=$1 np=$2 opts=$3 bc=$4 bal=$5 log=$1_np$2_bal$5.log
  local cmd=("${lmp[@]}" -in "$here/tissue_scaling.lmp" "${vars[@]}" -var tissue "$opts" -var bc "$bc"
    -var bal "$bal" -var proc "* * *" -log "$log" -screen none)
  [ "$np" -gt 1 ] && cmd=(mpirun -np "$np" "${cmd[@]}")
  local l0; l0=$(load)
  "${cmd[@]}" > /dev/null
  read -r t p n a mem cpu < <(loop_line "$log")
  python3 -c "
t, p, n, a, mem, cpu = $t, $p, $n, $a, $mem, $cpu
print(f'| $name | {p} | {\"yes\" if $bal else \"no\"} | {a} | {n} | {t:.1f} | {a*n/t/p:.3g} | {cpu:.0f} | {a*n/t/p/(cpu/100):.3g} | {mem*p*1e6/a/1024:.2f} | $l0 |')"
}

if [ "$mode" != reduce ] && [ "$mode" != exchange ]; then
echo "## Tissue: particle-steps per second per core (300 timed steps after 100)"
echo
echo "| tissue | ranks | fix balance | particles | steps | loop time (s) | particle-steps/s/core | CPU use (%) | particle-steps per CPU second per rank | memory per particle (kB) | load average at start |"
echo "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|"
cases=("block27|--count 27|p p p" "slab27|--cells 3 3 3 --slab z|p p f")
[ "$mode" = quick ] || cases+=("block64|--count 64|p p p" "slab64|--cells 4 4 4 --slab z|p p f")
for c in "${cases[@]}"; do
  IFS='|' read -r name opts bc <<< "$c"
  run_tissue "$name" 1 "$opts" "$bc" 0
  run_tissue "$name" 2 "$opts" "$bc" 0
  run_tissue "$name" 2 "$opts" "$bc" 1
done

fi
cost_table() {   # title input [scaled]: one row per size and rank count
  echo
  echo "## $1"
  echo
  echo "| cells | ranks | atoms | step without (ms) | step with fix cell/turgor every step (ms) | per-cell work (ms per step) | per cell (us) | load average at start |"
  echo "|---:|---:|---:|---:|---:|---:|---:|---:|"
  for n in "${sizes[@]}"; do
    # scaled: fewer steps for the larger sizes (minutes, not tens of minutes, per row)
    local nrun=200
    [ -n "${3:-}" ] && nrun=$((200 * 1000 / (n * n * n) > 10 ? 200 * 1000 / (n * n * n) : 10))
    for np in 1 2; do
      local log=$2_n${n}_np$np.log
      local cmd=("${lmp[@]}" -in "$here/$2.lmp" "${vars[@]}" -var n "$n" -var nrun "$nrun" -log "$log" -screen none)
      [ "$np" -gt 1 ] && cmd=(mpirun -np "$np" "${cmd[@]}")
      local l0; l0=$(load)
      "${cmd[@]}" > /dev/null
      python3 - "$log" "$n" "$np" "$l0" <<'PY'
import re, sys
log, n, np_, l0 = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
loops = re.findall(r"Loop time of ([0-9.e+-]+) on \d+ procs for (\d+) steps with (\d+) atoms", open(log).read())
base, with_fix = loops[1], loops[3]
b, w = float(base[0]) / int(base[1]) * 1e3, float(with_fix[0]) / int(with_fix[1]) * 1e3
cells = n ** 3
print(f"| {cells} | {np_} | {base[2]} | {b:.3f} | {w:.3f} | {w - b:.3f} | {(w - b) / cells * 1e3:.2f} | {l0} |")
PY
    done
  done
}
sizes=(10 22)
[ "$mode" = quick ] && sizes=(10)
case "$mode" in reduce | exchange) read -ra sizes <<< "${SIZES:-10 22 46}" ;; esac
[ "$mode" = exchange ] || cost_table "fix cell/turgor's per-cell work per step against the number of cells" cell_reduce_cost
[ "$mode" = reduce ] || cost_table "fix cell/turgor with exchange (per-cell work and the water network) per step against the number of cells" cell_exchange_cost scaled
