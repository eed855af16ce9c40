#!/usr/bin/env bash
# Buckling of a closed wall under external pressure (bench/accuracy/wall_buckling.lmp: bond cell/neohookean
# + dihedral cell/bending, fix cell/pressure P < 0, no fluid, minimised from the reference sphere
# with random noise) against Zoelly's p_c = 4 G t0^2 / R^2 (12.8 kPa for potentials/apple.cellsph:
# G = 18 MPa, t0 = 1 um, R = 75 um). For each resolution the collapse pressure is bracketed by
# bisection in P / p_c (collapsed: V/V0 < 0.9 after the minimisation), with the bending wall and
# with a membrane-only wall (bending 1e-9 of it) for comparison.
#
#   bash bench/accuracy/wall_buckling.sh [nwall ...]    resolutions (default: 642 1442; 2562 takes ~3 min)
# Environment: STEPS (bisection steps, default 4: brackets of 3 % with bending, 19 % without),
# NOISE (start displacement / wall spacing, default 1e-3), BENDING ("yes no", default both),
# LO, HI (the bracket with bending, default 0.8 1.25; STEPS=0 runs just these two: e.g.
# STEPS=0 LO=0.92 HI=0.94 BENDING=yes bash bench/accuracy/wall_buckling.sh 4002 10242, about 6 min), CELLSPH_BUILD (build folder), OUT (work folder, default
# /tmp/cellsph-bench/wall_buckling). Prints a table.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${CELLSPH_BUILD:-$here/../../build}
out=${OUT:-/tmp/cellsph-bench/wall_buckling}
lmp=$build/bin/lmp
cellgen=$build/tools/cellgen/cellgen
steps=${STEPS:-4}
noise=${NOISE:-1e-3}
mkdir -p "$out"
rm -f "$out/runs.txt"
cp "$here/wall_buckling.lmp" "$out/in.wall_buckling"

# holds <n> <bending> <frac>: exit 0 if the wall holds (V/V0 >= 0.9); the BUCKLING line in $out/last
holds() {
  (cd "$out" && nice "$lmp" -in in.wall_buckling -log log.lammps -screen none -var cellgen "$cellgen" \
    -var n "$1" -var bending "$2" -var frac "$3" -var noise "$noise" >/dev/null 2>&1 || true)
  grep '^BUCKLING' "$out/log.lammps" >"$out/last" ||
    { echo "wall_buckling: LAMMPS failed (n=$1 frac=$3), see $out/log.lammps" >&2; exit 1; }
  cat "$out/last" >>"$out/runs.txt"
  awk '{ for (i = 1; i <= NF; i++) if ($i ~ /^V\/V0=/) v = substr($i, 6) } END { exit !(v >= 0.9) }' "$out/last"
}

# bracket <n> <bending> <lo> <hi>: bisect (geometric) between lo and hi; an end that the
# bisection never moved is run too, to check it holds (lo) or collapses (hi)
bracket() {
  local n=$1 bending=$2 lo=$3 hi=$4 lo0=$3 hi0=$4 k mid
  for ((k = 0; k < steps; k++)); do
    mid=$(python3 -c "print(f'{($lo*$hi)**0.5:.5g}')")
    if holds "$n" "$bending" "$mid"; then lo=$mid; else hi=$mid; fi
  done
  if [ "$lo" = "$lo0" ] && ! holds "$n" "$bending" "$lo"; then lo=0; fi
  if [ "$hi" = "$hi0" ] && holds "$n" "$bending" "$hi"; then hi=inf; fi
  echo "$lo $hi"
}

echo "| wall particles | spacing a (um) | critical wavelength / a | bending | holds at P/p_c | collapses at P/p_c | p_c,measured (kPa) | / Zoelly | / network prediction | time (s) |"
echo "|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|"
for n in ${*:-642 1442}; do
  for bending in ${BENDING:-yes no}; do
    start=$(date +%s)
    if [ "$bending" = yes ]; then read -r lo hi < <(bracket "$n" yes "${LO:-0.8}" "${HI:-1.25}")
    else read -r lo hi < <(bracket "$n" no 0.05 0.8); fi
    a=$(sed -E 's/.* a=([^ ]+) .*/\1/' "$out/last")
    nat=$(sed -E 's/.* n=([0-9]+) .*/\1/' "$out/last")
    python3 - "$nat" "$a" "$bending" "$lo" "$hi" "$(( $(date +%s) - start ))" <<'PY'
import math, sys
n, a, bending, lo, hi, secs = sys.argv[1:]
a, lo, hi = float(a), float(lo), float(hi)    # 0 / inf: outside the initial bracket
pc = 4 * 18e6 * 1e-6**2 / 75e-6**2
mid = math.sqrt(lo * hi)
lam = 2 * math.pi * math.sqrt(1e-6 * 75e-6 / 3)    # 2 pi (D R^2 / Y)^(1/4), Y = 3 G t0
net = 2 / math.sqrt(3)                              # network Y = 4 G t0: p_c x sqrt(4/3)
print(f"| {n} | {a*1e6:.2f} | {lam/a:.1f} | {bending} | {lo:.3f} | {hi:.3f} | {mid*pc/1e3:.2f} | "
      f"{mid:.3f} | {mid/net:.3f} | {secs} |")
PY
  done
done
