#!/usr/bin/env bash
# Where and how much the fluid of the CI drying cell clumps in tension (bench/drying_clump.lmp: the
# cell of tests/drying_cell/cell.lmp, 70 C, accel 4e6, to X/X0 <= 0.2), one LAMMPS run per variant
# on one rank, measured by bench/fluid_spacing.py against each atom's own spacing (m/rho)^(1/3):
# per variant and X/X0 (the dumps nearest 0.6, 0.4 and the last, X/X0 about 0.2) the share of fluid
# atoms with another closer than half their own spacing, that share among the atoms within the
# adhesion's reach of a wall atom and in the interior, the old measure (dx = (M/(rho0 N))^(1/3)) and
# the CPU time of the run. Then, for the last dump, how the clumped atoms sit on the wall
# (bench/fluid_spacing.py --wall: the atoms of the first layer per wall atom).
#   bash bench/drying_clump.sh ["NAME:-var k v ..." ...]
# Default variants: h fixed without tensile, with tensile 0.2 and dp from the mass (dpmass 1) or
# dp = h/1.27 (cell.lmp's default), h adaptive with and without tensile 0.2. WORK=dir keeps (and
# reuses) the runs.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${CELLSPH_BUILD:-$here/../build}
work=${WORK:-$(mktemp -d)}
variants=("$@")
[ ${#variants[@]} -gt 0 ] || variants=("fixed,tensile0:-var hmode fixed -var tensile 0"
  "fixed,tensile0.2,dpmass:-var hmode fixed -var tensile 0.2 -var dpmass 1"
  "fixed,tensile0.2,dp:-var hmode fixed -var tensile 0.2" "adaptive,tensile0:-var hmode adaptive -var tensile 0"
  "adaptive,tensile0.2:-var hmode adaptive -var tensile 0.2")
h=18.18e-6
reach=$(python3 -c "print($h / 2.5 + 0.45 * $h)")    # the adhesion's rc of cell.lmp
echo "| variant | X/X0 | clumped (r/s < 0.5) | near the wall | interior | old measure (r/dx < 0.5) | CPU (s) |"
echo "|---|---|---|---|---|---|---|"
for v in "${variants[@]}"; do
  name=${v%%:*} vars=${v#*:}
  mkdir -p "$work/$name"
  cd "$work/$name"
  if [ ! -s all.dump ] || [ ! -s cpu.txt ]; then
    /usr/bin/time -f "%U %S" -o cpu.txt "$build/bin/lmp" -in "$here/drying_clump.lmp" -var testdir "$here/../tests" \
      -var cellgen "$build/tools/cellgen/cellgen" $vars -log log.lammps >screen.txt
  fi
  python3 "$here/fluid_spacing.py" all.dump "$reach" >spacing.txt
  python3 "$here/fluid_spacing.py" all.dump "$reach" --wall "$h" --last >wall.txt
  python3 - "$name" <<'PY'
import re, sys
X = {}
for line in open("log.lammps"):
    f = line.split()
    if len(f) == 7 and f[0].isdigit() and int(f[0]) % 1000 == 0:
        X[int(f[0])] = float(f[2])
rows = [l.split() for l in open("spacing.txt") if not l.startswith("#")]
rows = [r for r in rows if int(r[0]) in X]
cpu = sum(map(float, open("cpu.txt").read().split()))
pick = [min(rows, key=lambda r: abs(X[int(r[0])] - x)) for x in (0.6, 0.4)] + [rows[-1]]
for r in pick:
    print(f"| {sys.argv[1]} | {X[int(r[0])]:.2f} | {float(r[5]):.3f} | {float(r[9]):.3f} ({r[8]}) | "
          f"{float(r[11]):.3f} ({r[10]}) | {float(r[6]):.3f} | {cpu:.0f} |")
PY
  cd - >/dev/null
done
echo
for v in "${variants[@]}"; do
  name=${v%%:*}
  echo "$name, last dump: $(cat "$work/$name/wall.txt")"
done
echo "runs in $work"
