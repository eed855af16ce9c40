#!/usr/bin/env bash
# Speed against error of the drying cell, in one table:
#  1. examples/drying/in.drying as examples/drying/run.sh runs it (the seed cell, 1092 wall + 1647
#     fluid particles; 70 C, RH 0.15, cooling yes, accel auto 0.05), turgid to X/X0 <= 0.2, on each
#     rank count of NPS: wall-clock (the whole LAMMPS process: uptake, rest and drying) and the
#     drying run's particle-steps/s/core; its error against a less bridged reference run (accel
#     fixed at half the mean accel of the first auto run, below the smallest it used, on REFNP
#     ranks; REFACCEL="a1 a2 ...": fixed accels, a row each, the last the reference): the
#     turgor-loss X/X0 (first P_T <= 0, interpolated between outputs), the physical time at
#     X/X0 = 0.2 and the section area A/A0 at X/X0 = 0.2 (mean of the planes x, y, z through the
#     centroid; both interpolated between the last two outputs);
#  2. the cost per particle-step of the folded dry cell against the turgid one, from the same runs:
#     the median wall-clock of an output interval (250 steps, thermo column CPU) over the first and
#     over the last NMED (default 8) outputs of the drying;
#  3. bench/speed/cell_model_speed.sh on 1 rank: the full model (the SPH wall boundary, h adaptive:
#     its model "adaptive") beside the particle model and the boundary at fixed h, STEPS (default
#     5000) steps, best of 3.
# The 3 x 3 x 6 slab of the issue is not run here (about 15 min on its own).
#   bash bench/speed/speed_against_error.sh [parts="drying model"]
# Environment: CELLSPH_BUILD, WORK (default /tmp/cellsph-bench/speed_against_error; runs found there
# are reused: delete it to run again), NPS (default "1 2"), REFNP (default 2), REFACCEL (above),
# NMED, STEPS. The default run took 12 min at load average 2-5 (7 Dec 2026); its wall-clocks depend
# on what else runs: each row gives the load average at its start and end.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${CELLSPH_BUILD:-$here/../../build}
work=${WORK:-/tmp/cellsph-bench/speed_against_error}
parts=${1:-drying model}
nps=${NPS:-1 2}
refnp=${REFNP:-2}
mkdir -p "$work"
if [ "$(id -u)" -eq 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
export LAMMPS_POTENTIALS=$here/../../potentials
cd "$work"
load() { cut -d' ' -f1 /proc/loadavg; }
drying() {    # NP TAG ACCEL [-var ...]: one run of in.drying (run.sh's settings); TAG.time: wall-clock, loads
  local np=$1 tag=$2 accel=$3 cmd=("$build/bin/lmp")
  shift 3
  [ -s "final_$tag.txt" ] && return
  [ "$np" = 1 ] || cmd=(mpirun -np "$np" "$build/bin/lmp")
  local l0 t0 t1
  l0=$(load) t0=$(date +%s.%N)
  nice "${cmd[@]}" -in "$here/../../examples/drying/in.drying" -var T 343.15 -var RH 0.15 \
    -var accel "$accel" -var cooling yes -var tag "$tag" "$@" -log "log.$tag" >"$tag.screen" ||
    { echo "run $tag failed: $(grep -m1 ERROR "log.$tag" || tail -2 "$tag.screen")"; exit 1; }
  t1=$(date +%s.%N)
  echo "$np $(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.1f", b - a }') $l0 $(load)" >"$tag.time"
}
if [[ " $parts " == *" drying "* ]]; then
  [ -s cell.data ] || "$build/tools/cellgen/cellgen" --wall-mass 1e-12 --dihedrals --out cell.data >cellgen.log
  first=
  for np in $nps; do
    drying "$np" "auto_np$np" "auto 0.05"
    first=${first:-auto_np$np}
  done
  # half the mean accel of the first auto run: physical time / (drying steps x dt)
  refs=${REFACCEL:-$(awk '!/^#/ { if (s0 == "") { s0 = $27 }; t = $1; s = $27 } END { printf "%.3g", t / ((s - s0) * 2e-8) / 2 }' "dry_$first.dat")}
  tags=()
  for np in $nps; do tags+=("auto_np$np"); done
  for a in $refs; do    # the last is the reference
    drying "$refnp" "ref_a$a" "$a" -var maxout 2000    # more outputs than in.drying's 200 allow
    tags+=("ref_a$a")
  done
  echo "speed against error: in.drying, the seed cell, 70 C, RH 0.15, cooling yes; reference: the last row"
  python3 "$here/speed_against_error.py" --nmed "${NMED:-8}" "${tags[@]}"
fi
if [[ " $parts " == *" model "* ]]; then
  echo
  echo "cell_model_speed.sh, 1 rank, ${STEPS:-5000} steps, best of 3 (load average $(load) at the start)"
  NPS=1 OUT=$work/cell_model_speed nice bash "$here/cell_model_speed.sh" "${STEPS:-5000}" 3 "particles boundary adaptive"
  echo "(load average $(load) at the end)"
fi
