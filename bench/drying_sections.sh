#!/usr/bin/env bash
# Section descriptors of the drying scene averaged over 13 planes: the runs of
# bench/drying_error.sh (same points, same WORK folder: runs already there are reused), then
# tools/section_planes.lmp on each run's wall dump (LAMMPS rerun; compute cell/shape plane normal
# over the cube's 3 axes, 6 face and 4 body diagonals, through the volume centroid). Per plane the
# area, perimeter and Feret diameter relative to the same plane's section of the turgid cell (the
# dump's first snapshot), then the mean over the 13 and its standard error (std / sqrt(13)); at
# X/X0 = 0.5 and 0.2 (interpolated in X/X0, from the run's thermo output), against the first point.
#   WORK=dir bash bench/drying_sections.sh "312 a3e6" "642 a3e6" "1092 a3e6"
# (environment as bench/drying_error.sh: NP, XS, LMPVARS, CELLSPH_BUILD)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${CELLSPH_BUILD:-$here/../build}
export WORK=${WORK:-$(mktemp -d)}
points=("$@")
bash "$here/drying_error.sh" "${points[@]}" >"$WORK/drying_error.txt"
cd "$WORK"
export LAMMPS_POTENTIALS=$here/../potentials
for p in "${points[@]}"; do
  set -- $p
  tag="n$1_t$2"
  [ "${3:-1}" = 1 ] || tag+="_d$3"
  [ -z "${4:-}" ] || tag+="_s$4"
  [ -s "sections_$tag.dat" ] ||
    "$build/bin/lmp" -in "$here/../tools/section_planes.lmp" -var data "c$1.data" \
      -var dump "wall_$tag.dump" -var out "sections_$tag.dat" -log "log.sections_$tag" >/dev/null
done
XS=${XS:-0.5 0.2} python3 - "$here/../tools" "${points[@]}" <<'PY'
import os
import sys
sys.path.insert(0, sys.argv[1])
from section_planes import at_x, mean_se, relative, x_by_step  # noqa: E402
XS = [float(x) for x in os.environ["XS"].split()]
pts = [p.split() for p in sys.argv[2:]]
tags = [f"n{p[0]}_t{p[1]}" + (f"_d{p[2]}" if len(p) > 2 and p[2] != "1" else "") +
        (f"_s{p[3]}" if len(p) > 3 else "") for p in pts]
vals = {t: {x: at_x(relative(f"sections_{t}.dat"), x_by_step(f"log.{t}"), x) for x in XS} for t in tags}
print("13-plane means relative to the turgid cell, +- standard error of the mean (std / sqrt 13); "
      "[std over the planes]; (difference from the first point)")
head = [f"{k}@{x}" for x in XS for k in ("A", "P", "F")]
print("| wall | point | " + " | ".join(head) + " |")
print("|---" * (2 + len(head)) + "|")
ref = tags[0]
for p, t in zip(pts, tags):
    cells = []
    for x in XS:
        for k in range(3):
            if vals[t][x] is None:
                cells.append("–")
                continue
            m, se, sd = mean_se(vals[t][x][k])
            txt = f"{m:.3f}±{se:.3f} [{sd:.3f}]"
            if t != ref and vals[ref][x] is not None:
                txt += f" ({m / mean_se(vals[ref][x][k])[0] - 1:+.1%})"
            cells.append(txt)
    print(f"| {p[0]} | {' '.join(p[1:])} | " + " | ".join(cells) + " |")
PY
echo "runs in $WORK"
