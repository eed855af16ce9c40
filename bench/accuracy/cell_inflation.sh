#!/usr/bin/env bash
# Neo-Hookean inflation of a sealed cell (bench/accuracy/cell_inflation.lmp) at several resolutions: the
# turgor P_T (the fluid's load on the wall) against the thin-membrane law
# P(lam) = (2 G t0/R0)(1/lam - 1/lam^7) at the area stretch lam = sqrt(A/A0), with the Laplace
# pressure 2T/R of the wall tension and the mean SPH pressure beside it.
#
#   bash bench/accuracy/cell_inflation.sh [s ...]       resolutions (default: 1.5 1 0.75; s = 1 is the
#                                              seed's, 0.5 takes about an hour on one core)
#   bash bench/accuracy/cell_inflation.sh paths [s]     one resolution (default 1), f = 1.25 1.35 1.42, loaded
#                                              along different paths (drag, ramp speed): the spread
#                                              of the static equilibria
#   bash bench/accuracy/cell_inflation.sh table <run>   the table of a finished run in $OUT/<run> (e.g. s1)
# Environment: FLIST (fluid mass factors, default "1.15 1.25 1.35 1.42 1.5"), CELLSPH_BUILD (build
# folder), OUT (work folder, default /tmp/cellsph-bench/cell_inflation). Prints a table; the raw
# lines are in $OUT/<run>/stages.dat (columns named in their header).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${CELLSPH_BUILD:-$here/../../build}
out=${OUT:-/tmp/cellsph-bench/cell_inflation}
lmp=$build/bin/lmp
cellgen=$build/tools/cellgen/cellgen
if [ "$(id -u)" -eq 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi

# run <name> <lmp -var arguments...>: one inflation series in $out/<name>
run() {
  local name=$1; shift
  mkdir -p "$out/$name"
  # a copy of the input: LAMMPS re-reads it at every loop (jump), so edits must not reach a run
  cp "$here/cell_inflation.lmp" "$out/$name/in.cell_inflation"
  (cd "$out/$name" && rm -f stages.dat &&
   "$lmp" -in in.cell_inflation -log log.lammps -var cellgen "$cellgen" "$@" >screen.log 2>&1) ||
    { echo "$name: LAMMPS failed, see $out/$name/screen.log" >&2; tail -n 5 "$out/$name/screen.log" >&2; }
}

# table <name> <label>: one row per stage from stages.dat, compute time per stage from log.lammps
table() {
  local dir=$out/$1
  awk -v label="$2" '
    FNR == 1 { file++ }
    file == 1 && /^Loop time of/ { t += $4 }
    file == 1 && /^preparation done/ { prep = t; t = 0 }
    file == 1 && /^stage f = / { n++; ts[n] = t; t = 0 }
    file == 2 && /^# s=/ { for (i = 2; i <= NF; i++) { split($i, kv, "="); hdr[kv[1]] = kv[2] } }
    file == 2 && !/^#/ {
      m++
      leak = ($14 > 0 || $15 > 0) ? sprintf("yes (%d out, %d lost)", $14, $15) : "no"
      printf "| %s | %s | %s | %.2f | %.4f | %.4f | %.1f | %.1f | %+.2f %% | %+.2f %% | %+.1f %% | %.2f | %s | %.0f |\n",
        label, hdr["Nwall"], hdr["Nfluid"], $1, $2, $3, $5/1e3, $6/1e3, 100*$7, 100*$9, 100*($11/$6-1),
        $12/$6, leak, ts[m]
    }
    END { if (prep) printf "|   (%s: preparation to f = 1 took %.0f s) |\n", label, prep }
  ' "$dir/log.lammps" "$dir/stages.dat"
}

header() {
  echo "| $1 | wall | fluid | f | lam (area) | lam (volume) | P_T (kPa) | P_law(lam) (kPa) | P_T/P_law - 1 | P_T/(2T/R) - 1 | P_SPH/P_law - 1 | P_SPH,interior / P_law | leak | compute s |"
  echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|"
}

if [ "${1:-}" = table ]; then
  header run
  table "$2" "$2"
  exit 0
fi

if [ "${1:-}" = paths ]; then
  s=${2:-1}
  flist=${FLIST:-1.25 1.35 1.42}
  declare -A args=(
    [std]="-var visc 1e-6 -var nramp 10000 -var nchunk 50"
    [drag1e-5]="-var visc 1e-5 -var nramp 10000 -var nchunk 50"
    [drag1e-7]="-var visc 1e-7 -var nramp 10000 -var nchunk 50"
    [fast]="-var visc 1e-6 -var nramp 2000 -var nchunk 10"
    [slow]="-var visc 1e-6 -var nramp 40000 -var nchunk 200")
  header path
  for p in std drag1e-5 drag1e-7 fast slow; do
    # shellcheck disable=SC2086
    run "paths-s$s-$p" -var s "$s" -var flist "$flist" ${args[$p]}
    table "paths-s$s-$p" "$p"
  done
  exit 0
fi

header s
for s in "${@:-1.5 1 0.75}"; do
  for one in $s; do
    t0=$(date +%s)
    run "s$one" -var s "$one" -var flist "${FLIST:-1.15 1.25 1.35 1.42 1.5}"
    table "s$one" "$one"
    echo "|   (s = $one: $(( $(date +%s) - t0 )) s wall-clock in all) |"
  done
done
