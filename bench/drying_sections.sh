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
XS=${XS:-0.5 0.2} python3 - "${points[@]}" <<'PY'
import math
import os
import sys
XS = [float(x) for x in os.environ["XS"].split()]
pts = [p.split() for p in sys.argv[1:]]
tags = [f"n{p[0]}_t{p[1]}" + (f"_d{p[2]}" if len(p) > 2 and p[2] != "1" else "") +
        (f"_s{p[3]}" if len(p) > 3 else "") for p in pts]
def xof(tag):
    """X/X0 by step, from the thermo lines of the run's log (Step CPU v_t v_X ...)"""
    out, cols = {}, None
    for line in open(f"log.{tag}"):
        w = line.split()
        if w[:4] == ["Step", "CPU", "v_t", "v_X"]:
            cols = len(w)
        elif cols and len(w) == cols:
            try:
                out[int(w[0])] = float(w[3])
            except ValueError:
                cols = None
    return out
def series(tag):
    """(X/X0, [A/A0 ...13], [P/P0 ...], [F/F0 ...]) per snapshot after the turgid one"""
    rows = [list(map(float, l.split())) for l in open(f"sections_{tag}.dat") if not l.startswith("#")]
    x = xof(tag)
    ref = rows[0]
    out = []
    for r in rows[1:]:
        step = int(r[0])
        if step not in x:
            continue
        rel = [r[i] / ref[i] for i in range(1, 40)]
        out.append((x[step], rel[0::3], rel[1::3], rel[2::3]))
    return out
def at(s, x, k):
    """the 13 values of descriptor k (0 area, 1 perimeter, 2 Feret) at X/X0 = x"""
    for a, b in zip(s, s[1:]):
        if a[0] >= x >= b[0]:
            w = (a[0] - x) / (a[0] - b[0])
            return [u + w * (v - u) for u, v in zip(a[k + 1], b[k + 1])]
    # a run that stopped just above x (as bench/drying_error.sh: within 1e-3): its last snapshot
    return s[-1][k + 1] if s and x >= s[-1][0] - 1e-3 else None
def stats(v):
    m = sum(v) / len(v)
    sd = math.sqrt(sum((a - m) ** 2 for a in v) / (len(v) - 1))
    return m, sd / math.sqrt(len(v)), sd
data = {t: series(t) for t in tags}
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
            v = at(data[t], x, k)
            if v is None:
                cells.append("–")
                continue
            m, se, sd = stats(v)
            txt = f"{m:.3f}±{se:.3f} [{sd:.3f}]"
            if t != ref:
                r = at(data[ref], x, k)
                if r is not None:
                    txt += f" ({m / stats(r)[0] - 1:+.1%})"
            cells.append(txt)
    print(f"| {p[0]} | {' '.join(p[1:])} | " + " | ".join(cells) + " |")
PY
echo "runs in $WORK"
