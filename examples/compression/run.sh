#!/usr/bin/env bash
# Single-cell compression between two flat plates: a turgid apple cell (in.turgid, written to
# turgid.data) squeezed to 50 % of its height at three plate speeds (in.compression), held there
# while water leaves through the wall (physiological L_P, physical time), contact patch measured
# (contact_area.py), tables (analyse.py), plots (gnuplot) and pictures (tools/cut_picture.py).
# Outputs in out/.
# Needs the set-up of tools/setup.sh (build/bin/lmp, build/tools/cellgen/cellgen). NP=1 runs on one
# rank. README.md gives the time.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${CELLSPH_BUILD:-$here/../../build}
np=${NP:-2}
out=$here/out
mkdir -p "$out"
cd "$out"
rm -f compress_*.dat hold_*.dat walls_*.txt wallshold_*.txt area_*.txt fd_*.dat final_*.txt pic_*.png \
  fig_*.png summary.txt turgid.data turgid.txt wall_*.dump fluid_*.dump
export LAMMPS_POTENTIALS=${LAMMPS_POTENTIALS:-$here/../../potentials}
if [ "$(id -u)" -eq 0 ]; then    # Open MPI refuses to run as root unless told it may
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
if [ "$np" = 1 ]; then lmp=("$build/bin/lmp"); else lmp=(mpirun -np "$np" "$build/bin/lmp"); fi
start=$(date +%s)
stamp() { echo "[compression] $1 ($(($(date +%s) - start)) s)"; }

# 1. the turgid cell: seed resolution (R0 = 75 um, 1092 wall and 1647 fluid particles), cellgen's
# default gap (the SPH wall boundary), wall particles as heavy as fluid particles (dt = 2e-8 s), box
# 1.2 R0 beyond the cell (room for the flattened cell); uptake to P_T = pi = 200 kPa -> turgid.data
"$build/tools/cellgen/cellgen" --wall-mass 1e-12 --margin 1.2 --out cell.data >cellgen.log
"${lmp[@]}" -in "$here/in.turgid" -log log.turgid >turgid.screen
stamp "turgid cell: $(cat turgid.txt)"

# 2. compression to 50 % at three plate speeds (each plate); the middle one is then held with water
# leaving (L_P = 1e-13 m/(s Pa), accel 2.5e6: 0.05 s of physical time per step) and pictured
for v in 0.1 0.05 0.025; do
  extra=()
  if [ "$v" = 0.05 ]; then extra=(-var holdsteps 40000 -var images 1); fi
  "${lmp[@]}" -in "$here/in.compression" -var v "$v" -var tag "v$v" "${extra[@]}" -log "log.v$v" >"v$v.screen"
  python3 "$here/contact_area.py" turgid.data "walls_v$v.txt" "area_v$v.txt"
  stamp "v = $v m/s: $(head -n 1 "final_v$v.txt")"
done
python3 "$here/contact_area.py" turgid.data wallshold_v0.05.txt areahold_v0.05.txt
# the pictures (tools/cut_picture.py): the section through the cell's centre by the plane y (x across,
# z between the plates), the wall's outline, the fluid within 5 um coloured by its SPH pressure, a
# scale bar, and the state of final_v0.05.txt in the title
for what in before compressed relaxed; do
  case $what in
  before) state="turgid, before the compression" ;;
  compressed) state=$(sed -n '1s/^maximum compression: \(strain [^,]*, F = [^,]*\), .*/compressed: \1/p' final_v0.05.txt) ;;
  relaxed) state=$(sed -n '3s/^after the hold: \(t = [^,]*\), \(F = [^,]*\), .*\(M\/M0 = [^,]*\), .*/held: \1 of water loss, \2, \3/p' final_v0.05.txt) ;;
  esac
  python3 "$here/../../tools/cut_picture.py" turgid.data "wall_${what}_v0.05.dump" --fluid "fluid_${what}_v0.05.dump" \
    --color c_pp --cscale 1e-3 --crange 0:600 --clabel "SPH pressure (kPa)" --plane y --slab 5e-6 \
    --frame 260e-6 --bar 50e-6 --title "Compression at 0.05 m/s per plate\\n$state" --out "pic_$what.png"
done

# 3. tables: force against turgor x contact area, rate independence, the hold
python3 "$here/analyse.py" 0.1 0.05 0.025 >summary.txt

# 4. plots
gnuplot <<'GP'
set terminal pngcairo size 1400,600 noenhanced font ",11"
set output 'fig_force_displacement.png'
set multiplot layout 1,2 title "Compression of a turgid apple cell (R0 = 75 um, turgor 200 kPa) between flat plates, sealed"
set grid
set key top left
set xlabel 'plate displacement delta = H0 - H (um)'
set ylabel 'plate force F (mN)'
set title 'force against displacement, three plate speeds'
plot 'fd_v0.1.dat' using ($1*1e6):($3*1e3) with lines lw 2 title 'v = 0.1 m/s', \
     'fd_v0.05.dat' using ($1*1e6):($3*1e3) with lines lw 2 title 'v = 0.05 m/s', \
     'fd_v0.025.dat' using ($1*1e6):($3*1e3) with lines lw 2 title 'v = 0.025 m/s', \
     'fd_v0.025.dat' using ($1*1e6):($4*$7*1e3) every 4 with points pt 7 ps 0.8 lc rgb 'black' title 'P_W x A_trib (v = 0.025)', \
     'fd_v0.025.dat' using ($1*1e6):($4*$6*1e3) with lines dt 2 lc rgb 'gray40' title 'P_W x A_in, P_W x A_out', \
     'fd_v0.025.dat' using ($1*1e6):($4*$8*1e3) with lines dt 2 lc rgb 'gray40' notitle
set title 'turgor and contact area (v = 0.025 m/s)'
set ylabel 'pressure (kPa)'
set y2label 'contact area (1e-9 m^2), each plate'
set y2tics
set ytics nomirror
set key top left
plot 'fd_v0.025.dat' using ($1*1e6):($4/1e3) with lines lw 2 title 'turgor P_W (fluid load on the wall)', \
     '' using ($1*1e6):($7*1e9) axes x1y2 with lines lw 2 title 'A_trib', \
     '' using ($1*1e6):($6*1e9) axes x1y2 with lines dt 2 title 'A_in', \
     '' using ($1*1e6):($8*1e9) axes x1y2 with lines dt 2 title 'A_out', \
     '' using ($1*1e6):($3/$4*1e9) axes x1y2 with points pt 6 ps 0.6 title 'F / P_W'
unset multiplot

set output 'fig_hold.png'
set terminal pngcairo size 1200,900 noenhanced font ",11"
set multiplot layout 2,2 title "Hold at 50 % compression: water leaves through the wall (L_P = 1e-13 m/(s Pa), van 't Hoff pi, accel 2.5e6)"
unset y2label
unset y2tics
set ytics mirror
set xlabel 'physical time (min)'
set key top right
set ylabel 'plate force F (mN)'
set title 'force'
plot 'holdfd_v0.05.dat' using ($1/60):($2*1e3) with lines lw 2 title 'F', \
     '' using ($1/60):($3*$6*1e3) with points pt 7 ps 0.5 title 'P_W x A_trib'
set ylabel 'pressure (kPa)'
set title 'turgor and osmotic pressure'
plot 'holdfd_v0.05.dat' using ($1/60):($4/1e3) with lines lw 2 title 'turgor P_T', \
     '' using ($1/60):($3/1e3) with lines lw 1 title 'wall load P_W', \
     '' using ($1/60):($9/1e3) with lines lw 2 title 'osmotic pressure pi = pi0 M0/M'
set ylabel 'relative to the turgid cell'
set title 'volume and water'
plot 'holdfd_v0.05.dat' using ($1/60):7 with lines lw 2 title 'V / V0 (wall-enclosed)', \
     '' using ($1/60):8 with lines lw 2 title 'M / M0 (fluid mass)'
set ylabel 'contact area (1e-9 m^2), each plate'
set title 'contact area'
plot 'holdfd_v0.05.dat' using ($1/60):($6*1e9) with lines lw 2 title 'A_trib', \
     '' using ($1/60):($5*1e9) with lines dt 2 title 'A_in', \
     '' using ($1/60):($10*1e9) with lines dt 2 title 'A_out'
unset multiplot
GP

stamp "done; outputs in $out"
cat summary.txt
