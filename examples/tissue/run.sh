#!/usr/bin/env bash
# examples/tissue (README.md): a slab of 50 apple cells dried from its top face at 60 C on 2 ranks,
# then the analysis (figures and tables in out/). One command:
#   bash examples/tissue/run.sh [extra lmp -var NAME VALUE pairs, e.g. -var maxout 20]
# Environment: CELLSPH_BUILD (build folder, default build/), NP (MPI ranks, default 2), CELLS
# (cells along x y z, default "5 5 2"), EXCHANGE (extra fix cell/turgor keywords, default the
# cell-to-cell water of apple.cellsph's L_cc = 5e-14 m/s/Pa times LSCALE through the junctions' contact
# areas; "" for none), LSCALE (the time-scale bridging of the exchange, README.md: default 1000),
# ACCEL (fix cell/turgor's accel: a number with exchange, default 1e7).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${CELLSPH_BUILD:-$here/../../build}
np=${NP:-2}
cells=${CELLS:-5 5 2}
out=${OUT:-$here/out}
if [ "$(id -u)" = 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
mkdir -p "$out"
cd "$out"
start=$(date +%s)
# shellcheck disable=SC2086
"$build/tools/cellgen/cellgen" tissue --cells $cells --slab z --size 230e-6 --cv 0.35 --porosity 0.15 \
  --dx 24e-6 --junction-gap 10e-6 --wall-mass 1e-12 --seed 1 --dihedrals --out tissue.data > cellgen.txt
lcc=$(awk "BEGIN { printf \"%.6g\", 5e-14 * ${LSCALE:-1000} }")
exchange=${EXCHANGE-exchange $lcc bondtype 2 areas tissue.data.junctions}
mpirun -np "$np" "$build/bin/lmp" -in "$here/in.tissue" -var exchange "$exchange" \
  -var accel "${ACCEL:-1e7}" -log log.lammps "$@" > screen.txt
echo "simulation: $(( $(date +%s) - start )) s on $np ranks (load average $(cut -d' ' -f1-3 /proc/loadavg))" | tee wallclock.txt
python3 "$here/analyse.py" "$out"
