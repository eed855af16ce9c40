#!/usr/bin/env bash
# Drying of a lone apple-sized cell in air (bench/accuracy/drying_lone_cell.lmp; doc/fix_cell_turgor.md):
# physical time, X/X0, X, psi_cell, the surface water potential psi_s and dM/dt every 0.1 s, then the
# moisture content at t = 1.2 s (the falling-rate period) for h = 0.01 s and 0.0025 s against the
# GAB equilibrium X_GAB(0.15) of potentials/apple.cellsph. A few seconds.
#   bash bench/accuracy/drying_lone_cell.sh
# Environment: CELLSPH_BUILD (build folder), OUT (work folder, default /tmp/cellsph-bench/drying).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${CELLSPH_BUILD:-$here/../../build}
out=${OUT:-/tmp/cellsph-bench/drying}
mkdir -p "$out"
cd "$out"
vars=(-var cellgen "$build/tools/cellgen/cellgen" -var potentials "$here/../../potentials")
"$build/bin/lmp" -in "$here/drying_lone_cell.lmp" "${vars[@]}" -var acc 1e6 -var th 10 -var nrun 200 \
  -log drying.log | sed -n '/^ *Step/,/^Loop/p' | grep -v '^Loop'
for acc in 1e6 2.5e5; do
  n=$(python3 -c "print(round(1.2 / ($acc * 1e-8)))")
  "$build/bin/lmp" -in "$here/drying_lone_cell.lmp" "${vars[@]}" -var acc $acc -var th $n -var nrun $n \
    -log none | sed -n '/^ *Step/,/^Loop/p' | tail -2 | head -1 |
    awk -v h="$(python3 -c "print($acc * 1e-8)")" '{print "h = " h " s: t = " $2 " s, X/X0 = " $3 ", X = " $4}'
done
python3 - "$here/../../potentials/apple.cellsph" <<'PY'
import sys
p = {l.split()[0]: float(l.split()[1]) for l in open(sys.argv[1])
     if l.split() and l.split()[0].startswith("turgor_gab_")}
xm, c, k = p["turgor_gab_Xm"], p["turgor_gab_C"], p["turgor_gab_K"]
y = k * 0.15
print("X_GAB(0.15) =", round(xm * c * y / ((1 - y) * (1 - y + c * y)), 6), "(GAB equilibrium, apple.cellsph)")
PY
