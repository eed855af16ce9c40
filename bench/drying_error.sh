#!/usr/bin/env bash
# Speed against error of the drying scene (examples/drying/in.drying, 70 C, RH 0.15): the section
# descriptors (compute cell/shape plane z: area, perimeter, Feret, relative to the turgid cell), the
# volume and the wrinkling at X/X0 = 0.5 and 0.2 of cheaper runs (coarser wall, larger accel)
# against a reference run (finer and less accelerated), and the wall-clock of each run. Prints a
# table. Points: "NWALL ACCEL" pairs; the first is the reference. Default:
#   bench/drying_error.sh "1092 1.5e6" "1092 3e6" "312 1e6" "312 2e6" "312 4e6"
# Each run is one LAMMPS run on NP ranks (default 2), a few minutes for the seed resolution on a
# loaded machine; the wall-clock depends on what else runs on the cores (note it with the table).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${CELLSPH_BUILD:-$here/../build}
np=${NP:-2}
work=${WORK:-$(mktemp -d)}
mkdir -p "$work"
if [ "$(id -u)" -eq 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
export LAMMPS_POTENTIALS=$here/../potentials
if [ "$np" = 1 ]; then lmp=("$build/bin/lmp"); else lmp=(mpirun -np "$np" "$build/bin/lmp"); fi
points=("$@")
[ ${#points[@]} -gt 0 ] || points=("1092 1.5e6" "1092 3e6" "312 1e6" "312 2e6" "312 4e6")
cd "$work"
for p in "${points[@]}"; do
  set -- $p
  nw=$1 acc=$2 tag="n$1_a$2"
  if [ "$nw" = 312 ]; then
    "$build/tools/cellgen/cellgen" --nwall 312 --nfluid 450 --wall-mass 1e-12 --dihedrals --out "c$nw.data" >/dev/null
    scale=(-var h 18.18e-6 -var dt 1.5e-8 -var ws 1.871 -var nup 6000)
  elif [ "$nw" = 1092 ]; then
    "$build/tools/cellgen/cellgen" --wall-mass 1e-12 --dihedrals --out "c$nw.data" >/dev/null
    scale=()
  else
    echo "drying_error: NWALL 312 or 1092" >&2; exit 2
  fi
  if [ ! -s "final_$tag.txt" ]; then
    t0=$SECONDS
    "${lmp[@]}" -in "$here/../examples/drying/in.drying" -var data "c$nw.data" -var tag "$tag" -var accel "$acc" \
      "${scale[@]}" -log "log.$tag" >"$tag.screen" || echo "run $tag failed: $(grep -m1 ERROR "log.$tag")"
    echo "$((SECONDS - t0))" >"wall_$tag.txt"
  fi
done
python3 - "${points[@]}" <<'PY'
import sys
COLS = "t X X_db PT pi PW V A P F round elong compact wrink out free aw dMdt moved dMfluid".split()
def rows(tag):
    with open(f"dry_{tag}.dat") as f:
        return [dict(zip(COLS, map(float, l.split()))) for l in f if not l.startswith("#")]
def at(rs, x, key):
    """linear interpolation in X/X0 (falling)"""
    for a, b in zip(rs, rs[1:]):
        if a["X"] >= x >= b["X"]:
            w = (a["X"] - x) / (a["X"] - b["X"])
            return a[key] + w * (b[key] - a[key])
    return rs[-1][key] if x >= rs[-1]["X"] - 1e-3 else float("nan")
pts = [p.split() for p in sys.argv[1:]]
tags = [f"n{n}_a{a}" for n, a in pts]
data = {t: rows(t) for t in tags}
ref = tags[0]
keys = ("A", "P", "F", "V", "wrink")
print(f"reference: {pts[0][0]} wall particles, accel {pts[0][1]}; values at X/X0 = 0.5 and 0.2 (section plane z, relative to the turgid cell)")
print("| wall | accel | " + " | ".join(f"{k}@0.5" for k in keys) + " | " + " | ".join(f"{k}@0.2" for k in keys) + " | max err | wall-clock (s) |")
print("|---" * (2 + 2 * len(keys) + 2) + "|")
for (n, a), t in zip(pts, tags):
    vals, errs = [], []
    for x in (0.5, 0.2):
        for k in keys:
            v, r = at(data[t], x, k), at(data[ref], x, k)
            vals.append(f"{v:.3f}" + ("" if t == ref else f" ({v / r - 1:+.1%})"))
            if t != ref:
                errs.append(abs(v / r - 1))
    with open(f"wall_{t}.txt") as f:
        wc = f.read().strip()
    print(f"| {n} | {a} | " + " | ".join(vals) + f" | {max(errs):.1%} | {wc} |" if errs else f"| {n} | {a} | " + " | ".join(vals) + f" | (ref) | {wc} |")
PY
echo "runs in $work"
