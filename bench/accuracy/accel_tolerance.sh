#!/usr/bin/env bash
# accel auto against less accelerated runs (doc/fix_cell_turgor.md, doc/model.md §5.12). Coarse
# cells (cellgen --nwall 312 --nfluid 450 scaled as bench/common/scaled_cell.sh does, SPH wall boundary,
# apple wall, van 't Hoff pi) at L_P = 1e-13 m/(s Pa), R0 = 50, 75 and 100 um: each is filled to
# turgor, then psi_ext steps to -50 kPa and the cell relaxes for TEND s of physical time with
# 'accel auto TOL'; then with fixed accel a/2 and a/4, a the largest accel the auto run used, and
# 4 a (too large). Printed: t50, t20 (physical time until |psi_ext - psi_cell| falls to 50 and 20 %
# of its start), the relaxation time tau (fit of its log between 60 and 10 %), M/M0 and V at TEND,
# each against the a/4 run. Then a drying run in air (60 C, RH 0.3, h_m 0.39 m/s: Sh = 2 of a lone
# cell, wall-limited) of the 75 um cell for 1.7 s with 'accel auto TOL max 2e4' (cycles of 100 open
# and 25 sealed transfers) and with a fixed a/4: X/X0 against time. One rank per run, at most two
# at a time; `bench/accuracy/accel_tolerance.sh psi` or `... air` runs one part; WORK=<folder> keeps the runs
# there and skips those already finished. On a loaded 2-core machine the psi part took about 15
# minutes, the air part 2.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${CELLSPH_BUILD:-$here/../../build}
work=${WORK:-$(mktemp -d)}
export LAMMPS_POTENTIALS=$here/../../potentials
parts=${1:-psi air}
tol=${TOL:-0.05}
tend=${TEND:-1000}
source "$here/../common/scaled_cell.sh"
lmp() { nice "$build/bin/lmp" -in "$here/accel_tolerance.lmp" -var h "$h" -var dt "$dt" "$@"; }
# run TAG ARGS...: one run to ts_TAG.dat, unless a finished one is there (WORK=<folder> again)
run() {
  local tag=$1
  shift
  grep -qs "Total wall time" "$tag.log" || lmp -var stage run -var tag "$tag" -log "$tag.log" "$@" >/dev/null
}
fill() {    # radius: cell.data and filled.restart in $work/R<radius>
  mkdir -p "$work/R$1" && cd "$work/R$1"
  scaled_cell 312 450 --radius "$1e-6"
  dt=$(python3 -c "print(min(2e-8, 2*$dt))")
  [ -f filled.restart ] || lmp -var stage fill -log fill.log >/dev/null
}
amax() { awk '!/^#/ { if ($6 + 0 > m + 0) m = $6 } END { printf "%.6g", m }' "$1"; }
if [[ $parts == *psi* ]]; then
  for r in 50 75 100; do
    fill $r
    run auto -var accel "auto $tol" -var tend "$tend"
    a=$(amax ts_auto.dat)
    for k in 2 4; do
      run a$k -var accel "$(python3 -c "print($a/$k)")" -var tend "$tend" &
    done
    wait
    run big -var accel "$(python3 -c "print(4*$a)")" -var tend "$tend"
    echo "R0 = $r um: auto $tol, a = $a" >summary.txt
    python3 "$here/accel_tolerance.py" relax ts_a4.dat ts_auto.dat ts_a2.dat ts_big.dat >>summary.txt
    cat summary.txt
  done
fi
if [[ $parts == *air* ]]; then
  fill 75
  dry=(-var drive air -var hm 0.39 -var tend "${TDRY:-1.7}" -var every 100)
  run dry_auto "${dry[@]}" -var accel "auto $tol max ${DRYMAX:-2e4} every 100 hold 25"
  a=$(amax ts_dry_auto.dat)
  run dry_a4 "${dry[@]}" -var accel "$(python3 -c "print($a/4)")"
  echo "drying in air, R0 = 75 um: auto $tol (largest accel $a) against fixed a/4"
  python3 "$here/accel_tolerance.py" dry ts_dry_a4.dat ts_dry_auto.dat
fi
echo "(runs in $work)"
