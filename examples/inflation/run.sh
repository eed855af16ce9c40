#!/usr/bin/env bash
# The seed's inflation experiment (Figs. 4 and 5) with the calibrated apple set and the SPH wall
# boundary (in.inflation), the seed's own Table-1 wall with its particle wall-fluid model
# (in.inflation_seed: limit-point stop), and a physiological L_P in physical time. Outputs in out/.
# Needs the set-up of tools/setup.sh (build/bin/lmp, build/tools/cellgen/cellgen). Independent runs
# go two at a time, one core each (README.md gives the time).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${CELLSPH_BUILD:-$here/../../build}
lmp=$build/bin/lmp
out=$here/out
mkdir -p "$out"
cd "$out"
rm -f mass_*.dat final_*.txt fig4_*.png wall_*.dump fluid_*.dump fig5.png seed_wall.txt summary.txt physiological.txt
export LAMMPS_POTENTIALS=${LAMMPS_POTENTIALS:-$here/../../potentials}
start=$(date +%s)

# the seed's resolution (R0 = 75 um, 1092 wall and 1647 fluid particles), wall particles as heavy as
# fluid particles; cellgen's default gap DX/2 for the wall boundary, and for the seed's particle
# model the gap at its repulsion range r0 = 11 um (potentials/apple-seed.cellsph)
"$build/tools/cellgen/cellgen" --wall-mass 1e-12 --out cell.data >cellgen.log
"$build/tools/cellgen/cellgen" --gap 11e-6 --wall-mass 1e-12 --out cell_seed.data >cellgen_seed.log

run() {    # run INPUT TAG [-var NAME VALUE ...]: one LAMMPS run on one core, screen output in TAG.log
  local input=$1 tag=$2
  shift 2
  "$lmp" -in "$here/$input" -log "log.$tag" -var tag "$tag" "$@" >"$tag.log" 2>&1
}

# lane 1: L_P = 2.5e-7 (the seed's "too slow"), unaccelerated, 2.5 ms; then the physiological
# L_P = 1e-13 m/(s Pa) with van 't Hoff pi in physical time (67 min) with time-scale bridging: each
# step advances mass transfer by accel dt, accel = 4e7 and 1e7 (and 2.5e6 in lane 2)
{
  run in.inflation LP2.5e-7 -var LP 2.5e-7 -var steps 125000 -var every 500
  run in.inflation phys4e7 -var LP 1e-13 -var osmotic vanthoff -var accel 4e7 -var steps 5000 -var every 25
  run in.inflation phys1e7 -var LP 1e-13 -var osmotic vanthoff -var accel 1e7 -var steps 20000 -var every 100
} &
lane1=$!

# lane 2: L_P = 2.5e-6 (with the Fig. 4 pictures), 2.5e-5, 2.5e-4, 400 us each; the seed's wall;
# the physiological run with accel = 2.5e6
{
  run in.inflation LP2.5e-6 -var LP 2.5e-6 -var images 1
  run in.inflation LP2.5e-5 -var LP 2.5e-5
  run in.inflation LP2.5e-4 -var LP 2.5e-4
  # the seed's model (Table-1 wall, t0 = 126 nm; particle wall-fluid model) cannot hold
  # pi = 200 kPa: the fix stops at once ...
  if run in.inflation_seed seed; then echo "expected a limit-point stop" >&2; exit 1; fi
  grep -m 1 '^ERROR' seed.log >seed_wall.txt
  # ... and, told to go on (limit warn), the cell balloons (stopped at an area stretch of 1.15)
  run in.inflation_seed seedwarn -var limit warn
  grep -m 1 '^WARNING: Fix cell/turgor' seedwarn.log >>seed_wall.txt
  grep -m 1 'Fix halt condition' seedwarn.log >>seed_wall.txt
  run in.inflation phys2.5e6 -var LP 1e-13 -var osmotic vanthoff -var accel 2.5e6 -var steps 80000 -var every 400
} &
lane2=$!
wait $lane1
wait $lane2

python3 "$here/analyse.py" summary physiological
# Fig. 4 (tools/cut_picture.py): the section through the cell's centre, the wall's outline, the fluid
# within 8 um of the plane coloured by its SPH pressure, the same frame and scale bar fresh and turgid
read -r _ _ t mm _ _ lam _ <final_LP2.5e-6.txt
for state in fresh turgid; do
  if [ $state = fresh ]; then title="fresh: t = 0, M/M0 = 1, area stretch 1"; else
    title=$(awk -v t="$t" -v m="$mm" -v l="$lam" 'BEGIN { printf "turgid: t = %.0f us, M/M0 = %.3f, area stretch %.3f", t * 1e6, m, l }')
  fi
  python3 "$here/../../tools/cut_picture.py" cell.data "wall_${state}_LP2.5e-6.dump" --fluid "fluid_${state}_LP2.5e-6.dump" \
    --color d_pressure --cscale 1e-3 --crange -50:250 --clabel "SPH pressure (kPa)" --frame 200e-6 --bar 50e-6 \
    --title "One apple cell in pure water (L_P = 2.5e-6, pi0 = 200 kPa)\n$title" --out "fig4_$state.png"
done

gnuplot <<'GP'
set terminal pngcairo size 1400,600 noenhanced font ",11"
set output 'fig5.png'
set multiplot layout 1,2 title "Fig. 5: cell fluid mass against time, one apple cell in pure water, pi0 = 200 kPa (cellsph, calibrated apple set, SPH wall boundary)"
set ylabel 'fluid mass M / M0'
set yrange [0.95:1.9]
set key bottom right
set grid
set xlabel 'time (us)'
set xrange [0:400]
set title 'the seed window'
plot 'mass_LP2.5e-4.dat' using ($1*1e6):2 with lines lw 2 title 'L_P = 2.5e-4', \
     'mass_LP2.5e-5.dat' using ($1*1e6):2 with lines lw 2 title 'L_P = 2.5e-5', \
     'mass_LP2.5e-6.dat' using ($1*1e6):2 with lines lw 2 title 'L_P = 2.5e-6', \
     'mass_LP2.5e-7.dat' using ($1*1e6):2 with lines lw 2 title 'L_P = 2.5e-7', \
     'mass_seedwarn.dat' using ($1*1e6):2 with lines lw 2 dt 2 lc rgb 'black' title 'seed model (Table-1 wall, particle wall-fluid)'
set logscale x
set xrange [1:2500]
set xlabel 'time (us), logarithmic'
set title 'to the steady state'
unset key
plot 'mass_LP2.5e-4.dat' using ($1*1e6):2 with lines lw 2, \
     'mass_LP2.5e-5.dat' using ($1*1e6):2 with lines lw 2, \
     'mass_LP2.5e-6.dat' using ($1*1e6):2 with lines lw 2, \
     'mass_LP2.5e-7.dat' using ($1*1e6):2 with lines lw 2, \
     'mass_seedwarn.dat' using ($1*1e6):2 with lines lw 2 dt 2 lc rgb 'black'
unset multiplot
GP

echo "inflation: $(($(date +%s) - start)) s; outputs in $out"
cat summary.txt seed_wall.txt physiological.txt
