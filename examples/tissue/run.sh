#!/usr/bin/env bash
# examples/tissue (README.md): a slab of 27 apple cells, 3 deep, settled (in.settle) and dried from
# its top face in air at 60 C (its surface cooled by the evaporation; in.tissue) at apple's own
# cell-to-cell conductance on 2 ranks, then the analysis (figures and tables in out/). One command:
#   bash examples/tissue/run.sh [extra lmp -var NAME VALUE pairs, e.g. -var maxout 20]
# Environment: CELLSPH_BUILD (build folder, default build/), NP (MPI ranks, default 2), CELLS
# (cells along x y z, default "3 3 3"), SEED (cellgen's, default 5: its seed 1 makes a cell too
# small for 24 um at 3 x 3 x 3), EXCHANGE (extra fix cell/turgor keywords, default the
# cell-to-cell water of apple.cellsph's L_cc = 5e-14 m/s/Pa times LSCALE through the junctions' contact
# areas; "" for none), LSCALE (a bridging of the exchange, default 1: apple's own L_cc), ACCEL
# (fix cell/turgor's accel, default in.tissue's "auto 0.1 change 4e-3"), COOLING (in.tissue's cooling: yes, the
# default, or no for the surface at the air's T), MAXOUT (in.tissue's maxout, default 80: 4000
# drying steps). Variables given on the command line win over these defaults.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${CELLSPH_BUILD:-$here/../../build}
np=${NP:-2}
cells=${CELLS:-3 3 3}
out=${OUT:-$here/out}
if [ "$(id -u)" = 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
mkdir -p "$out"
cd "$out"
start=$(date +%s)
# shellcheck disable=SC2086
"$build/tools/cellgen/cellgen" tissue --cells $cells --slab z --size 230e-6 --cv 0.35 --porosity 0.15 \
  --dx 24e-6 --junction-gap 10e-6 --wall-mass 1e-12 --seed "${SEED:-5}" --dihedrals --out tissue.data > cellgen.txt
lcc=$(awk "BEGIN { printf \"%.6g\", 5e-14 * ${LSCALE:-1} }")
exchange=${EXCHANGE-exchange $lcc bondtype 2 areas tissue.data.junctions}
# the fresh slab settled (in.settle: settled.restart, fresh.dump), then dried (in.tissue)
mpirun -np "$np" "$build/bin/lmp" -in "$here/in.settle" "$@" -log log.settle > screen_settle.txt
mpirun -np "$np" "$build/bin/lmp" -in "$here/in.tissue" -var exchange "$exchange" \
  "$@" ${ACCEL:+-var accel "$ACCEL"} -var cooling "${COOLING:-yes}" -var maxout "${MAXOUT:-80}" \
  -log log.lammps > screen.txt
echo "simulation: $(( $(date +%s) - start )) s on $np ranks (load average $(cut -d' ' -f1-3 /proc/loadavg))" | tee wallclock.txt
python3 "$here/analyse.py" "$out"
