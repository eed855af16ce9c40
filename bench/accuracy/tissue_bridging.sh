#!/usr/bin/env bash
# The bridging error of examples/tissue at apple's own L_cc
# (doc/notes/2026-12-07-tissue-physical-lcc.md): one slab (cellgen tissue as run.sh, CELLS cells,
# default "3 3 3", SEED default 5), settled once (in.settle, 2 ranks), then dried by in.tissue with
# its defaults (L_cc x 1, accel auto 0.1, the surface cooled as run.sh) at each accel auto 'change'
# of CHANGES (default "4e-3 1e-3": the ceiling on a cell's water per transfer), each for at most
# MAXOUT outputs of 50 steps (default "80 80", one per change), NP ranks each (default 1), one
# after the other: the runs of the note (there two at a time, 2051 and 1606 s at load average
# 17-27). Then tissue_bridging.py compares each run with the last (the least bridged) over their
# common physical time: top-layer X/X0(t) and the layer moisture profile. WORK=<folder> keeps the
# runs (default a temporary folder) and skips those already finished. Extra arguments go to
# in.tissue (e.g. -var Xend 0.5).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
scene=$here/../../examples/tissue
build=${CELLSPH_BUILD:-$here/../../build}
work=${WORK:-$(mktemp -d)}
np=${NP:-1}
read -r -a changes <<< "${CHANGES:-4e-3 1e-3}"
read -r -a maxouts <<< "${MAXOUT:-80 80}"
if [ "$(id -u)" = 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
mkdir -p "$work" && cd "$work"
# shellcheck disable=SC2086
[ -f tissue.data ] || "$build/tools/cellgen/cellgen" tissue --cells ${CELLS:-3 3 3} --slab z --size 230e-6 \
  --cv 0.35 --porosity 0.15 --dx 24e-6 --junction-gap 10e-6 --wall-mass 1e-12 --seed "${SEED:-5}" --dihedrals \
  --out tissue.data > cellgen.txt
[ -f settled.restart ] || nice mpirun -np 2 "$build/bin/lmp" -in "$scene/in.settle" -log log.settle > /dev/null
runs=()
for k in "${!changes[@]}"; do
  c=${changes[$k]}
  mkdir -p "change_$c" && cd "change_$c"
  ln -sf ../tissue.data ../tissue.data.junctions ../fresh.dump .
  start=$(date +%s)
  grep -qs "Total wall time" log.lammps || nice mpirun -np "$np" "$build/bin/lmp" -in "$scene/in.tissue" \
    -var restart ../settled.restart -var cooling yes -var accel "auto 0.1 change $c" \
    -var maxout "${maxouts[$k]:-${maxouts[-1]}}" "$@" -log log.lammps > screen.txt
  [ -f wallclock.txt ] || echo "$(( $(date +%s) - start )) s on $np ranks (load average $(cut -d' ' -f1-3 /proc/loadavg))" > wallclock.txt
  cd ..
  runs+=("change_$c")
done
[ ${#runs[@]} -lt 2 ] || python3 "$here/tissue_bridging.py" "${runs[@]}"
