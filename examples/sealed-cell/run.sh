#!/usr/bin/env bash
# Sealed cell: geometry, LAMMPS run on 2 MPI ranks, plot and pictures; outputs in
# examples/sealed-cell/out/. Needs the set-up of tools/setup.sh (build/bin/lmp, cellgen).
# NP=1 bash run.sh runs on one rank.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${CELLSPH_BUILD:-$here/../../build}
np=${NP:-2}
out=$here/out
mkdir -p "$out"
cd "$out"
rm -f cut_*.png sealed_cell.dat profile.txt wall.dump fluid.dump
if [ "$(id -u)" -eq 0 ]; then    # Open MPI refuses to run as root unless told it may
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
# seed resolution: R0 = 75 um, 1092 wall and 1647 fluid particles, cellgen's default gap DX/2
"$build/tools/cellgen/cellgen" --wall-mass 1e-12 --out cell.data >cellgen.log
if [ "$np" = 1 ]; then run=("$build/bin/lmp"); else run=(mpirun -np "$np" "$build/bin/lmp"); fi
"${run[@]}" -in "$here/in.sealed_cell" -log log.lammps \
  >screen.log
# the pictures (tools/cut_picture.py): the section through the centre by the plane z, the wall's
# outline, the fluid within 5 um coloured by its SPH pressure P_i, a scale bar; the time, P_W and
# the area stretch of sealed_cell.dat at that step (dt = 1e-8 s) in the title
last=$(awk '/^ITEM: TIMESTEP/ { getline; s = $1 } END { print s }' wall.dump)
for pick in "watered 10000" "final $last"; do
  set -- $pick
  state=$(awk -v t="$2" '!/^#/ && ($1 - t * 1e-8)^2 < 1e-24 { printf "t = %.2f ms, P_W = %.1f kPa, area stretch %.4f", $1 * 1e3, $2 / 1e3, $3; exit }' sealed_cell.dat)
  python3 "$here/../../tools/cut_picture.py" cell.data wall.dump --fluid fluid.dump --step "$2" \
    --color c_pp --cscale 1e-3 --crange 0:400 --clabel "SPH pressure P_i (kPa)" --slab 5e-6 \
    --frame 200e-6 --bar 50e-6 --title "Sealed cell, $1: $state" --out "cut_$1.png"
done
sed '1,9d' profile.txt > profile.dat   # drop the dump header
gnuplot <<'GP'
set terminal pngcairo size 900,1000 noenhanced
set output 'sealed_cell.png'
set multiplot layout 3,1
set lmargin 12
set xlabel 'time (ms)'
set ylabel 'pressure (kPa)'
set yrange [-50:450]
set key top right
plot 'sealed_cell.dat' using ($1*1e3):($2/1e3) with lines lw 2 title 'wall load P_W (load of the fluid on the wall)', \
     '' using ($1*1e3):($5/1e3) with lines lw 2 title 'membrane law P(lam), lam = sqrt(A / A0)', \
     '' using ($1*1e3):($6/1e3) with lines dt 2 lw 2 title 'Laplace 2T/R of the wall tension', \
     '' using ($1*1e3):($9/1e3) with lines lw 1 title 'turgor P_T (mean SPH pressure)', \
     '' using ($1*1e3):($7/1e3) with lines lw 1 title 'interior SPH pressure (deeper than 2h)'
set ylabel 'relative to P_law(lam) (%)'
set yrange [-50:40]
set key bottom right
plot 'sealed_cell.dat' using ($1 > 1e-4 ? $1*1e3 : 1/0):(100*($2/$5-1)) with lines lw 2 title 'P_W / P_law - 1', \
     '' using ($1 > 1e-4 ? $1*1e3 : 1/0):(100*($6/$5-1)) with lines dt 2 lw 2 title '2T/R / P_law - 1 (the wall)', \
     '' using ($1 > 1e-4 ? $1*1e3 : 1/0):(100*($9/$5-1)) with lines lw 1 title 'P_T / P_law - 1 (mean SPH pressure)', \
     '' using ($1 > 1e-4 ? $1*1e3 : 1/0):(100*($7/$5-1)) with lines lw 1 title 'P_interior / P_law - 1', \
     0 with lines lc rgb 'black' notitle
set yrange [*:*]
set ylabel 'stretch lam'
plot 'sealed_cell.dat' using ($1*1e3):3 with lines lw 2 title 'sqrt(A / A0), wall area', \
     '' using ($1*1e3):4 with lines dt 2 lw 2 title '(V / V0)^(1/3), triangulated volume', \
     '' using ($1*1e3):10 with lines dt 3 lw 2 title 'mean wall radius / R0'
unset multiplot
set output 'profile.png'
set xlabel 'distance from the cell centre (um)'
set ylabel 'SPH pressure P_i (kPa)'
set key top left
set xrange [0:*]
plot 'profile.dat' using ($2 == 1 ? $3*1e6 : 1/0):($4/1e3) with points pt 7 ps 0.6 title 'fluid particles', \
     '' using ($2 == 2 ? $3*1e6 : 1/0):(0) with points pt 1 ps 0.6 lc rgb 'gray40' title 'wall particles (at P = 0)'
GP
echo "sealed-cell: outputs in $out (sealed_cell.dat, sealed_cell.png, profile.png, cut_watered.png, cut_final.png, log.lammps)"
grep "^sealed cell at equilibrium" log.lammps
