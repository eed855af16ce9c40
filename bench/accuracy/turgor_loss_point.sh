#!/usr/bin/env bash
# The turgor-loss point of a drying cell against the membrane law, for several resolutions, airs,
# background pressures and accel (bench/accuracy/turgor_loss_point.lmp; the table's columns:
# bench/accuracy/turgor_loss_point.py). Each point is "TAG -var NAME VALUE ...", e.g.
#   bench/accuracy/turgor_loss_point.sh "c -var PbD 3e5" "w3 -var auto 3e4" \
#     "s70 -var auto 3e4 -var nwall 1092 -var nfluid 1647 -var h 12.2e-6 -var dt 2e-8 -var ws 1 -var accel 3e6"
# Default: the coarse cell (312 wall, 450 fluid) at 70 C with the fixed 300 kPa background and with
# background auto 30 kPa. One rank per run, one run at a time; WORK=dir keeps the runs.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${CELLSPH_BUILD:-$here/../../build}
work=${WORK:-$(mktemp -d)}
source "$build/env.sh"
[ $# -gt 0 ] || set -- "c -var PbD 3e5" "w3 -var auto 3e4"
cd "$work"
tags=()
for point in "$@"; do
  read -r tag vars <<<"$point"
  start=$SECONDS
  # shellcheck disable=SC2086
  lmp -in "$here/turgor_loss_point.lmp" -var tag "$tag" $vars -log "log_$tag.lammps" >/dev/null
  echo "$tag: $((SECONDS - start)) s"
  tags+=("$tag")
done
python3 "$here/turgor_loss_point.py" "${tags[@]}"
echo "(runs in $work)"
