#!/usr/bin/env bash
# bash examples/drying/run.sh [extra lmp -var NAME VALUE pairs]
# Drying of one turgid apple cell in hot air at 40 and 70 C (RH 0.15), in physical time, to
# X/X0 <= 0.2 (in.drying): drying curves X/X0 against time, section descriptors and volume against
# X/X0 with the end values of Karunasena et al. 2014 marked (analyse.py, gnuplot), pictures of the
# cell fresh, at the turgor loss point, half dry and dry, and a check that the wall never passed
# through itself (tools/wall_self_intersection.py on every wall snapshot). Outputs in out/.
# Needs the set-up of tools/setup.sh. The two temperatures run one after the other on NP ranks
# (default 2; NP=1 was faster on a machine whose cores other jobs loaded). RES=coarse runs the
# 312-particle wall instead of the seed's 1092; ELONG=1.45 starts from a prolate cell (cellgen
# --elongation) instead of the sphere. Measured (README.md): RES=coarse NP=1 344 s on 2 cores
# shared with about twenty other processes; the seed resolution takes about 160 s of CPU time per
# temperature on one rank.
set -euo pipefail
extra=("$@")    # extra lmp -var NAME VALUE pairs for in.drying, e.g. -var RH 0.3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${CELLSPH_BUILD:-$here/../../build}
np=${NP:-2}
res=${RES:-seed}
elong=${ELONG:-}    # ELONG=1.45: start from a prolate cell of that elongation (apple), the sphere's volume
out=$here/out
mkdir -p "$out"
cd "$out"
rm -f dry_*.dat final_*.txt wall_*.dump fluid_*.dump pic_*.png cut_*.dat cut_*.step fig_*.png summary.txt \
  intersections_*.txt sections_*.dat planes_*.txt
export LAMMPS_POTENTIALS=${LAMMPS_POTENTIALS:-$here/../../potentials}
if [ "$(id -u)" -eq 0 ]; then    # Open MPI refuses to run as root unless told it may
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
if [ "$np" = 1 ]; then lmp=("$build/bin/lmp"); else lmp=(mpirun -np "$np" "$build/bin/lmp"); fi
start=$(date +%s)
stamp() { echo "[drying] $1 ($(($(date +%s) - start)) s)"; }

# the cell: sphere of R0 = 75 um (or with ELONG a prolate spheroid along x of its volume),
# icosahedral wall with one dihedral per edge (bending), wall particles as heavy as fluid
# particles; h and dt follow the fluid spacing (h = 1.27 DX)
shape=()
[ -z "$elong" ] || shape=(--elongation "$elong")
if [ "$res" = coarse ]; then
  "$build/tools/cellgen/cellgen" --nwall 312 --nfluid 450 --wall-mass 1e-12 --dihedrals "${shape[@]}" --out cell.data >cellgen.log
  scale=(-var h 18.18e-6 -var dt 3e-8 -var ws 1.871 -var nup 3000)
  runs=("T70 343.15 2e6" "T40 313.15 8e6")
else
  "$build/tools/cellgen/cellgen" --wall-mass 1e-12 --dihedrals "${shape[@]}" --out cell.data >cellgen.log
  scale=()
  runs=("T70 343.15 3e6" "T40 313.15 1.2e7")
fi

# 70 C and 40 C, RH 0.15, h_m = 2 cm/s on 1 % of the wall; accel chosen so that both dry to 0.2 in
# about the same number of steps (0.06 s of physical time per step at 70 C, dt = 2e-8 s; the air at
# 40 C carries 3.9 x less vapour)
for run in "${runs[@]}"; do
  set -- $run
  t0=$(date +%s)
  "${lmp[@]}" -in "$here/in.drying" -var tag "$1" -var T "$2" -var accel "$3" "${scale[@]}" \
    "${extra[@]}" -log "log.$1" >"$1.screen"
  stamp "$1: $(grep '^dried' "$1.screen") [$(($(date +%s) - t0)) s]"
  python3 "$here/../../tools/wall_self_intersection.py" cell.data "wall_$1.dump" --quiet --out "intersections_$1.txt" ||
    echo "[drying] $1: the wall passed through itself (intersections_$1.txt)"
  # the section descriptors over 13 planes of every wall snapshot (LAMMPS rerun, a few seconds)
  "$build/bin/lmp" -in "$here/../../tools/section_planes.lmp" -var data cell.data -var dump "wall_$1.dump" \
    -var out "sections_$1.dat" -log "log.sections_$1" >/dev/null
done

python3 "$here/analyse.py" T70 T40 >summary.txt
# the air that ran, from the runs' own headers ("# drying at T = 343.15 K, RH 0.15, h_m 0.02 m/s on
# 0.01 of the wall, ...")
air=$(sed -n '1s/^# drying at T = [^,]*, \(RH [^,]*\), h_m \([^ ]*\) m\/s on \([^ ]*\) of the wall.*/\1, h_m \2 m\/s on \3 of the wall/p' dry_T70.dat)

# the plots (the title's AIRTEXT: the air above)
sed "s|AIRTEXT|${air:-air not recorded}|" <<'GP' | gnuplot
set terminal pngcairo size 1400,600 noenhanced font ",11"
set output 'fig_drying_curve.png'
set multiplot layout 1,2 title "Drying of one apple cell in air (AIRTEXT)"
set grid
set xlabel 'physical time (min)'
set ylabel 'X / X0'
set key top right
plot 'dry_T70.dat' using ($1/60):2 with lines lw 2 title '70 C', 'dry_T40.dat' using ($1/60):2 with lines lw 2 title '40 C'
set ylabel 'pressure (kPa)'
set xlabel 'X / X0'
set xrange [1:0]
plot 'dry_T70.dat' using 2:($4/1e3) with lines lw 2 title 'turgor P_T, 70 C', 'dry_T40.dat' using 2:($4/1e3) with lines lw 2 title 'turgor P_T, 40 C', \
     'dry_T70.dat' using 2:($5/1e3) with lines dt 2 title 'osmotic pressure, 70 C'
unset multiplot
set output 'fig_shrinkage.png'
set terminal pngcairo size 1400,1000 noenhanced font ",11"
set multiplot layout 2,2 title "Section through the cell centre (plane z) and volume against X/X0; crosses: Karunasena et al. 2014 (dried Gala apple)"
set xrange [1:0]
set yrange [0:1.6]
set ylabel 'relative to the turgid cell'
set key bottom left
set title 'section area (z; thin: x, y; dashed: mean of 13 planes)'
plot 'dry_T70.dat' using 2:8 with lines lw 2 title '70 C', 'dry_T40.dat' using 2:8 with lines lw 2 title '40 C', \
     'dry_T70.dat' using 2:21 with lines lw 1 lc 1 notitle, 'dry_T70.dat' using 2:24 with lines lw 1 lc 1 notitle, \
     'planes_T70.txt' using 1:2 with lines dt 2 lw 3 lc 1 title '70 C, 13 planes', 'planes_T40.txt' using 1:2 with lines dt 2 lw 3 lc 2 title '40 C, 13 planes', \
     '-' using 1:2 with points pt 2 ps 3 lw 3 lc rgb 'black' title 'apple, dried: -60 %'
0.2 0.4
e
set title 'perimeter (z; dashed: mean of 13 planes)'
plot 'dry_T70.dat' using 2:9 with lines lw 2 title '70 C', 'dry_T40.dat' using 2:9 with lines lw 2 title '40 C', \
     'planes_T70.txt' using 1:3 with lines dt 2 lw 3 lc 1 notitle, 'planes_T40.txt' using 1:3 with lines dt 2 lw 3 lc 2 notitle, '-' using 1:2 with points pt 2 ps 3 lw 3 lc rgb 'black' title 'apple, dried: -30 %'
0.2 0.7
e
set title 'Feret diameter (z; dashed: mean of 13 planes)'
plot 'dry_T70.dat' using 2:10 with lines lw 2 title '70 C', 'dry_T40.dat' using 2:10 with lines lw 2 title '40 C', \
     'planes_T70.txt' using 1:4 with lines dt 2 lw 3 lc 1 notitle, 'planes_T40.txt' using 1:4 with lines dt 2 lw 3 lc 2 notitle, '-' using 1:2 with points pt 2 ps 3 lw 3 lc rgb 'black' title 'apple, dried: -40 %'
0.2 0.6
e
set title 'volume (wall-enclosed) and wrinkling'
plot 'dry_T70.dat' using 2:7 with lines lw 2 title 'V/V0, 70 C', 'dry_T40.dat' using 2:7 with lines lw 2 title 'V/V0, 40 C', \
     'dry_T70.dat' using 2:14 with lines dt 2 lw 2 title 'wrinkling, 70 C', x with lines dt 3 lc rgb 'gray' title 'V/V0 = X/X0'
unset multiplot
set output 'fig_tension.png'
set terminal pngcairo size 1400,600 noenhanced font ",11"
set multiplot layout 1,2 title "The fluid in tension (analyse.py, stability_T*.txt): dx = spacing of the fluid mass at the water density"
set xrange [1:0]
set yrange [0:1.05]
set xlabel 'X / X0'
set ylabel ''
set key bottom left
set title 'fluid nearest-neighbour distance / dx'
plot 'stability_T70.txt' using 2:3 with lines lw 2 title 'smallest, 70 C', 'stability_T70.txt' using 2:4 with lines lw 2 title 'mean, 70 C', \
     'stability_T40.txt' using 2:3 with lines dt 2 title 'smallest, 40 C', 'stability_T40.txt' using 2:4 with lines dt 2 title 'mean, 40 C'
set title 'clumping and the protoplast on the wall'
plot 'stability_T70.txt' using 2:5 with lines lw 2 title 'share of fluid atoms within dx/2 of another, 70 C', \
     'stability_T70.txt' using 2:6 with lines lw 2 title 'share of wall atoms with fluid within the adhesion reach, 70 C', \
     'stability_T40.txt' using 2:5 with lines dt 2 title 'within dx/2, 40 C', 'stability_T40.txt' using 2:6 with lines dt 2 title 'held, 40 C'
unset multiplot
GP
# the pictures (tools/cut_picture.py): the section through the wall's centre by the plane z as a
# micrograph, the wall's outline and the sap within 8 um coloured by its SPH pressure, a scale bar,
# the time and X/X0 (the snapshots that analyse.py chose: cut_TAG_NAME.step)
for pick in cut_*.step; do
  name=${pick#cut_}; name=${name%.step}; tag=${name%_*}
  read -r step minutes x <"$pick"
  t_c=$(sed -n '1s/^# drying at T = \([0-9.]*\) K.*/\1/p' "dry_$tag.dat")
  python3 "$here/../../tools/cut_picture.py" cell.data "wall_$tag.dump" --fluid "fluid_$tag.dump" \
    --color d_pressure --cscale 1e-3 --clabel "SPH pressure (kPa)" --step "$step" \
    --title "$(awk -v t="$t_c" 'BEGIN { printf "%.0f C", t - 273.15 }'), ${air:-}: t = $minutes min, X/X0 = $x" \
    --out "pic_$name.png"
done
stamp "done; outputs in $out"
cat summary.txt
