#!/usr/bin/env bash
# Wall triangles held per rank and the time of one evaluation of compute cell/props (leak count)
# and compute cell/shape (hull, section) at 10^3 and 10^4 tiny cells on 1 and 2 ranks
# (bench/speed/perrank_triangles.lmp), for this build ("after": each cell's triangles on its home rank
# only) and, if BEFORE is set, for the plugin at $BEFORE ("before": every cell's triangles on every
# rank, CellReduce::gather_triangles of main before the perrank branch). Per evaluation: the loop
# time per step with the compute at every step minus without it (wall, ms), the same in CPU time
# (loop time x LAMMPS's "% CPU use" x ranks, summed over ranks), the compute's vector (after: the
# most triangles held on one rank, the sum over ranks) and the largest rank's maximum resident set
# size (/usr/bin/time). Prints the load average with each row. About 5 minutes on 2 loaded cores.
#   BEFORE=/path/to/old/cellsphplugin.so bash bench/speed/perrank_triangles.sh
# Environment: CELLSPH_BUILD (build folder), OUT (work folder, default /tmp/cellsph-bench/perrank),
# NRUN (evaluations per run, default 10), SIZES (cells per side, default "10 22").
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${CELLSPH_BUILD:-$here/../../build}
out=${OUT:-/tmp/cellsph-bench/perrank}
nrun=${NRUN:-10}
sizes=${SIZES:-10 22}
mkdir -p "$out"
cd "$out"
if [ "$(id -u)" = 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
vars=(-var cellgen "$build/tools/cellgen/cellgen" -var nrun "$nrun")
load() { cut -d' ' -f1 /proc/loadavg; }

# run one case: n ranks style plugin held -> "loop_seconds steps cpu_percent maxrss_kB thermo..."
run_case() {
  local n=$1 np=$2 style=$3 plugin=$4 held=$5 log=$3_n$1_np$2_held$5.log
  local cmd=("$build/bin/lmp" -in "$here/perrank_triangles.lmp" "${vars[@]}" -var n "$n" -var style "$style"
    -var plugin "$plugin" -var held "$held" -log "$log" -screen none)
  [ "$np" -gt 1 ] && cmd=(mpirun -np "$np" "${cmd[@]}")
  /usr/bin/time -f "%M" -o "$log.rss" "${cmd[@]}" > /dev/null
  python3 - "$log" "$(tail -1 "$log.rss")" <<'PY'
import re, sys
log = open(sys.argv[1]).read()
loop = re.findall(r"Loop time of ([0-9.e+-]+) on \d+ procs for (\d+) steps", log)[-1]
cpu = re.findall(r"([0-9.]+)% CPU use with", log)[-1]
rows = re.findall(r"^\s+(\d+(?:\s+[-0-9.e+]+)*)\s*$", log, re.M)
print(loop[0], loop[1], cpu, sys.argv[2], rows[-1] if rows else "")
PY
}

echo "## One evaluation of compute cell/props and cell/shape, tiny cells (20 triangles each)"
echo
echo "| cells | ranks | compute | code | wall ms per evaluation | CPU ms per evaluation (all ranks) | triangles held, most on a rank (before: own + all, by construction) | triangles held, all ranks | max RSS of a rank (MB) | load average at start |"
echo "|---:|---:|---|---|---:|---:|---:|---:|---:|---:|"
for n in $sizes; do
  for np in 1 2; do
    l0=$(load)
    base=$(run_case "$n" "$np" none cellsphplugin.so 0)
    read -r bt bs bc _ <<< "$base"
    for style in props shape; do
      codes=("after|cellsphplugin.so|1")
      [ -n "${BEFORE:-}" ] && codes=("before|$BEFORE|0" "${codes[@]}")
      for c in "${codes[@]}"; do
        IFS='|' read -r code plugin held <<< "$c"
        l1=$(load)
        res=$(run_case "$n" "$np" "$style" "$plugin" "$held")
        read -r t s cpu rss thermo <<< "$res"
        python3 - "$n" "$np" "$style" "$code" "$t" "$s" "$cpu" "$rss" "$bt" "$bs" "$bc" "$thermo" "$l0/$l1" <<'PY'
import sys
n, np_, style, code = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3], sys.argv[4]
t, s, cpu, rss, bt, bs, bc = map(float, sys.argv[5:12])
thermo, l0 = sys.argv[12].split(), sys.argv[13]
wall = (t - bt) / s * 1e3
cputime = (t * cpu - bt * bc) / 100 * np_ / s * 1e3 if np_ > 1 else (t * cpu - bt * bc) / 100 / s * 1e3
ntri = 20 * n ** 3
if code == "after":
    most, total = int(float(thermo[2])), int(float(thermo[3]))
else:
    # by construction of gather_triangles: its own (about 1/ranks of them) plus every cell's
    most, total = ntri // np_ + ntri, ntri + np_ * ntri
print(f"| {n**3} | {np_} | {style} | {code} | {wall:.2f} | {cputime:.2f} | {most} | {total} | {rss/1024:.0f} | {l0} |")
PY
      done
    done
  done
done
