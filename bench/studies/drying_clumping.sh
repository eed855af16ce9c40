#!/usr/bin/env bash
# Why does the sap of the drying example clump (fluid atoms within dx/2 of another from X/X0 0.42,
# doc/notes/2026-12-07-turgor-steps-and-clumping.md)? Runs examples/drying/in.drying as run.sh does
# (seed cell, AIR, accel auto 0.05, cooling yes, one rank) once per background minimum P_MIN of
# PMINS, with the fluid dump extended by d_h d_rho d_omega mass and the background pressure P_b
# (compute pair cell/sph [3]) written every output (pb_TAG.dat), then drying_clumping.py: for the
# clumped against the other fluid atoms, the local absolute pressure P_b + P, h/dx and the
# distance to the wall and to a fold's other side, per snapshot and just before atoms pair up.
# Prints per P_MIN the share clumped at the end, the X/X0 of the turgor loss (P_T <= 0 first) and
# the wall-clock time of the run. About 3-4 min per P_MIN on one loaded core.
#   bash bench/studies/drying_clumping.sh   (environment: CELLSPH_BUILD, OUT, AIR "70:0.15",
#                                            PMINS "3e4" (in.drying's), EVERY 1: analyse every
#                                            EVERY-th snapshot)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${CELLSPH_BUILD:-$here/../../build}
out=${OUT:-/tmp/cellsph-bench/drying_clumping}
air=${AIR:-70:0.15}
pmins=${PMINS:-3e4}
every=${EVERY:-1}
export LAMMPS_POTENTIALS=${LAMMPS_POTENTIALS:-$here/../../potentials}
mkdir -p "$out"
cd "$out"
echo "# drying_clumping: $(date -u), air $air, P_MIN $pmins, load average $(cut -d ' ' -f 1-3 /proc/loadavg)"
"$build/tools/cellgen/cellgen" --wall-mass 1e-12 --dihedrals --out cell.data >cellgen.log
tc=${air%%:*} rh=${air#*:}
for pmin in $pmins; do
  tag=P$pmin
  # in.drying with background auto P_MIN, the extended fluid dump and P_b per output
  sed -e "s/background auto 3e4/background auto $pmin/" \
    -e 's/^\(dump  *fluids fluid custom .* d_pressure\)$/\1 d_h d_rho d_omega mass/' \
    -e 's/^\(dump  *walls wall custom .*\)$/compute pbs all pair cell\/sph\nfix pbout all print ${nout} "$(step) $(c_pbs[3]:%.6e)" file pb_${tag}.dat screen no\n\1/' \
    "$here/../../examples/drying/in.drying" >in.$tag
  grep -q "background auto $pmin" in.$tag && grep -q "d_omega mass" in.$tag && grep -q pbout in.$tag ||
    { echo "drying_clumping: in.drying changed, the edits did not apply" >&2; exit 1; }
  t0=$(date +%s)
  "$build/bin/lmp" -in in.$tag -var tag "$tag" -var T "$(awk -v t="$tc" 'BEGIN { printf "%.2f", t + 273.15 }')" \
    -var RH "$rh" -var accel "auto 0.05" -var cooling yes -log "log.$tag" >"$tag.screen"
  secs=$(($(date +%s) - t0))
  python3 "$here/drying_clumping.py" . "$tag" --every "$every" >"clump_$tag.txt"
  tlp=$(awk '!/^#/ && $4 <= 0 { print $2; exit }' "dry_$tag.dat")
  end=$(grep -v '^#' "clump_$tag.txt" | grep -v '^onsets\|^not' | tail -1)
  echo "P_MIN $pmin: LAMMPS $secs s; turgor lost at X/X0 $tlp; last snapshot (step X/X0 hold P_b[kPa] share ...): $end"
done
