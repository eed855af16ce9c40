#!/usr/bin/env bash
# bash examples/drying/run.sh [extra lmp -var NAME VALUE pairs, e.g. -var hm 0.03]
# Drying of one turgid apple cell in hot air, in physical time, to X/X0 <= 0.2 (in.drying), once
# per air of AIRS, then the analysis (analyse.py, gnuplot): drying curves, section descriptors and
# volume against X/X0 with the end values of Karunasena et al. 2014 marked, pictures of the cell
# fresh, at the turgor loss point, half dry and dry (tools/cut_picture.py), and a check that the
# wall never passed through itself (tools/wall_self_intersection.py). Environment:
#   AIRS     the air of each run, "T:RH" with T in C, runs separated by spaces (default
#            "70:0.15 40:0.15"); the outputs of a run are named T<T>C_RH<RH> (dry_T70C_RH0.15.dat)
#   RES      seed (the seed's 1092-particle wall, default) or coarse (312 particles)
#   NP       MPI ranks (default 2; NP=1 can be faster on a machine whose cores other jobs load)
#   OUT      output folder (default examples/drying/out)
#   ACCEL    fix cell/turgor's accel (default "auto 0.05": the fix chooses it, README.md)
#   COOLING  yes (default: the cell at the surface temperature of evaporative cooling, as in
#            examples/tissue) or no (the cell at the air's temperature)
#   ELONG    e.g. 1.45: start from a prolate cell of the sphere's volume (cellgen --elongation)
# Needs the set-up of tools/setup.sh. Times: README.md, What we get.
set -euo pipefail
extra=("$@")
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${CELLSPH_BUILD:-$here/../../build}
tools=$here/../../tools
np=${NP:-2}
res=${RES:-seed}
airs=${AIRS:-70:0.15 40:0.15}
accel=${ACCEL:-auto 0.05}
cooling=${COOLING:-yes}
elong=${ELONG:-}
out=${OUT:-$here/out}
for air in $airs; do    # each T:RH, checked before anything runs
  if [[ "$air" != *:* ]] || ! awk -v t="${air%%:*}" -v r="${air#*:}" \
    'BEGIN { exit !(t + 0 == t && r + 0 == r && t > -273.15 && r >= 0 && r < 1) }'; then
    echo "[drying] AIRS: '$air' is not T:RH (T in C above -273.15, 0 <= RH < 1)" >&2; exit 1
  fi
done
mkdir -p "$out"
cd "$out"
rm -f dry_*.dat final_*.txt wall_*.dump fluid_*.dump pic_*.png cut_*.step fig_*.png summary.txt \
  intersections_*.txt sections_*.dat planes_*.txt stability_*.txt
export LAMMPS_POTENTIALS=${LAMMPS_POTENTIALS:-$here/../../potentials}
if [ "$(id -u)" -eq 0 ]; then    # Open MPI refuses to run as root unless told it may
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
if [ "$np" = 1 ]; then lmp=("$build/bin/lmp"); else lmp=(mpirun -np "$np" "$build/bin/lmp"); fi
start=$(date +%s)
stamp() { echo "[drying] $1 ($(($(date +%s) - start)) s, load average $(cut -d' ' -f1 /proc/loadavg))"; }

# the cell: sphere of R0 = 75 um (or with ELONG a prolate spheroid along x of its volume),
# icosahedral wall with one dihedral per edge; h and dt follow the fluid spacing (h = 1.27 DX)
shape=()
[ -z "$elong" ] || shape=(--elongation "$elong")
case $res in
coarse)
  "$build/tools/cellgen/cellgen" --nwall 312 --nfluid 450 --wall-mass 1e-12 --dihedrals "${shape[@]}" --out cell.data >cellgen.log
  scale=(-var h 18.18e-6 -var dt 3e-8 -var ws 1.871 -var nup 3000) ;;
seed)
  "$build/tools/cellgen/cellgen" --wall-mass 1e-12 --dihedrals "${shape[@]}" --out cell.data >cellgen.log
  scale=() ;;
*) echo "[drying] RES=$res: expected seed or coarse" >&2; exit 1 ;;
esac

tags=()
for air in $airs; do
  tc=${air%%:*} rh=${air#*:}
  tag=T${tc}C_RH$rh
  tags+=("$tag")
  t0=$(date +%s)
  "${lmp[@]}" -in "$here/in.drying" -var tag "$tag" -var T "$(awk -v t="$tc" 'BEGIN { printf "%.2f", t + 273.15 }')" \
    -var RH "$rh" -var accel "$accel" -var cooling "$cooling" "${scale[@]}" "${extra[@]}" -log "log.$tag" >"$tag.screen"
  stamp "$tag: $(grep '^dried' "$tag.screen" | cut -d, -f1-2) [$(($(date +%s) - t0)) s]"
  python3 "$tools/wall_self_intersection.py" cell.data "wall_$tag.dump" --quiet --out "intersections_$tag.txt" ||
    echo "[drying] $tag: the wall passed through itself (intersections_$tag.txt)"
  # the section descriptors over 13 planes of every wall snapshot (LAMMPS rerun, a few seconds)
  "$build/bin/lmp" -in "$tools/section_planes.lmp" -var data cell.data -var dump "wall_$tag.dump" \
    -var out "sections_$tag.dat" -log "log.sections_$tag" >/dev/null
done

# the summary, the figures (analyse.py writes figures.gp: every title names the air of its run)
# and the pictures of the snapshots analyse.py chose (cut_TAG_NAME.step: step and title)
python3 "$here/analyse.py" "${tags[@]}" >summary.txt
gnuplot figures.gp
for pick in cut_*.step; do
  name=${pick#cut_}; name=${name%.step}; tag=${name%_*}
  { read -r step; read -r title; } <"$pick"
  python3 "$tools/cut_picture.py" cell.data "wall_$tag.dump" --fluid "fluid_$tag.dump" \
    --color d_pressure --cscale 1e-3 --clabel "SPH pressure (kPa)" --step "$step" --title "$title" \
    --frame 230e-6 --bar 50e-6 --out "pic_$name.png"    # one frame: the shrinkage shows
done
stamp "done; outputs in $out"
cat summary.txt
