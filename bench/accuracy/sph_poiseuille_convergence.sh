#!/usr/bin/env bash
# Accuracy of pair_style cell/sph against the plane Poiseuille start-up series solution (Morris,
# Fox & Zhu 1997): L2 error of v_x(y) at t = 0.0225, 0.1125 and 0.225 L^2/nu for each kernel and
# h/dx at N = 20, 40, 80 particle spacings across the channel, with the wall-clock time of each
# run (bench/accuracy/sph_poiseuille.lmp, one rank). The CI test (tests/pair_cell_sph/
# poiseuille_startup_matches_series.in) checks two of these rows.
#
#   bash bench/accuracy/sph_poiseuille_convergence.sh [N values (default "20 40 80")]
#   LMP=<lmp wrapper> to use another build (default build/bin/lmp)
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
lmp=${LMP:-$repo/build/bin/lmp}
resolutions=${1:-"20 40 80"}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

printf '%-9s %5s %4s %10s %10s %10s %8s\n' kernel h/dx N "t=0.0225" "t=0.1125" "t=0.225" "time(s)"
for case in "wendland 1.2" "wendland 1.5" "cubic 1.2" "quintic 1.0" "lucy 2.4"; do
  set -- $case
  for n in $resolutions; do
    log=$work/$1.$2.$n.log
    start=$(date +%s.%N)
    (cd "$work" && "$lmp" -in "$repo/bench/accuracy/sph_poiseuille.lmp" -var kernel "$1" -var hratio "$2" \
      -var nrows "$n" -log "$log" -screen none >/dev/null 2>&1) ||
      { echo "run failed: $case N=$n, see $log" >&2; exit 1; }
    end=$(date +%s.%N)
    grep "^L2 " "$log" | awk -v k="$1" -v h="$2" -v n="$n" -v s="$start" -v e="$end" '
      { err[NR] = $6 } END { printf "%-9s %5s %4s %10s %10s %10s %8.1f\n", k, h, n, err[1], err[2], err[3], e - s }'
  done
done
