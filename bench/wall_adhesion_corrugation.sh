#!/usr/bin/env bash
# Lateral corrugation of the wall-fluid adhesion: a scan atom at fixed depth d under the wall of a
# sealed cell (R0 = 75 um; 312 and 1092 wall particles, h = 1.27 x the fluid spacing, 18.18 and
# 12.2 um), along N = 2000 directions (bench/wall_adhesion_corrugation.py), for pair cell/sph's
# wall adhesion (W = 0.17 J/m^2) and pair cell/wall's Morse wells (tests/drying_cell/cell.lmp's);
# per depth d/h = 0.4 (the contact range) and 0.7: the mean adhesion energy per scan atom and the
# spread (max - min) / |mean| and std / |mean| over the directions.
#   bash bench/wall_adhesion_corrugation.sh
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${CELLSPH_BUILD:-$here/../build}
work=${WORK:-$(mktemp -d)}
cd "$work"
echo "| wall atoms | h (um) | d/h | adhesion | mean energy (J) | (max-min)/|mean| | std/|mean| |"
echo "|---|---|---|---|---|---|---|"
for res in "312 450 18.18e-6" "1092 1600 12.2e-6"; do
  set -- $res
  "$build/tools/cellgen/cellgen" --radius 75e-6 --nwall "$1" --nfluid "$2" --wall-mass 1e-12 --out cell$1.data >/dev/null
  for dh in 0.4 0.7; do
    python3 "$here/wall_adhesion_corrugation.py" cell$1.data 2000 "$(python3 -c "print($dh*$3)")" scan.lmp
    for mode in sph cellwall; do
      "$build/bin/lmp" -in "$here/wall_adhesion_corrugation.lmp" -var data cell$1.data -var h "$3" \
        -var adhmode $mode -var adhw 0.17 -var out e_$1_${dh}_$mode.txt -log none -screen none
      python3 - "$1" "$3" "$dh" "$mode" e_$1_${dh}_$mode.txt <<'PY'
import statistics, sys
e = [float(l.split()[1]) for l in open(sys.argv[5]).readlines()[9:]]
m = statistics.mean(e)
print(f"| {sys.argv[1]} | {float(sys.argv[2])*1e6:.2f} | {sys.argv[3]} | {sys.argv[4]} | {m:.3e} | "
      f"{(max(e) - min(e)) / abs(m):.3f} | {statistics.pstdev(e) / abs(m):.3f} |")
PY
    done
  done
done
