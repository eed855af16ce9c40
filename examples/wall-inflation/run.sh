#!/usr/bin/env bash
# Wall inflation: geometry, LAMMPS run and plot; outputs in examples/wall-inflation/out/.
# Needs the set-up of tools/setup.sh (build/bin/lmp, build/tools/cellgen/cellgen).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${CELLSPH_BUILD:-$here/../../build}
out=$here/out
mkdir -p "$out"
cd "$out"
if [ "$(id -u)" -eq 0 ]; then    # Open MPI refuses to run as root unless told it may
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
"$build/tools/cellgen/cellgen" --nfluid 0 --wall-mass 1e-12 --out wall.data >cellgen.log
"$build/bin/lmp" -in "$here/in.wall_inflation" -log log.lammps >screen.log
mv "$(ls -t wall.*.png | head -n 1)" wall.png && rm -f wall.*.png
gnuplot <<'GP'
set terminal pngcairo size 800,600 noenhanced
set output 'inflation.png'
set xlabel 'stretch lambda = R / R0'
set ylabel 'turgor pressure P (kPa)'
set key bottom right
G = 18e6; t0 = 1e-6; R0 = 75e-6
P(l) = 2*G*t0/R0*(1/l - l**-7)/1e3
set xrange [1:1.45]
plot P(x) title 'thin Neo-Hookean membrane, 2 G t0/R0 (1/lam - 1/lam^7)' lw 2, \
     'inflation.dat' using 2:($1/1e3) with points pt 7 ps 1.5 title 'cellsph wall (cellgen default mesh), static equilibria'
GP
echo "wall-inflation: outputs in $out (inflation.dat, inflation.png, wall.png, log.lammps)"
cat inflation.dat
