#!/usr/bin/env bash
# The fluid in tension in the drying scene (examples/drying/in.drying, 70 C): the clumping (share
# of fluid atoms with another within dx/2, dx = (M/(rho0 N))^(1/3): examples/drying/analyse.py)
# at X/X0 = 0.6, 0.4, 0.2 and the section descriptors at X/X0 = 0.5 and 0.2 against the
# resolution, for the walls given (default 312 642 1092; 0.03 s of physical time per step), each
# run by bench/drying_error.sh (one LAMMPS run per point, NP ranks, default 1, with its CPU time).
# MODES chooses the ways of holding the fluid in tension (default "background wells"):
#   background  the scene: pair cell/sph background 3e5 from the drying on, no adhesion
#   wells       the scene before: pair cell/wall's adhesion wells and the artificial stress
#               tensile 0.2 (-var background 0 -var adhmode cellwall -var tensile 0.2)
#   bare        the wells without the artificial stress (... -var tensile 0)
# WORK=dir keeps and reuses the runs (WORK/<mode>). Prints the clumping table, then
# drying_error.sh's table per mode (the first wall given is its reference).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
work=${WORK:-$(mktemp -d)}
walls=("$@")
[ ${#walls[@]} -gt 0 ] || walls=(1092 642 312)
points=()
for w in "${walls[@]}"; do points+=("$w 0.03"); done
export NP=${NP:-1}
modes=${MODES:-background wells}
for mode in $modes; do
  mkdir -p "$work/$mode"
  case $mode in
    background) vars="" ;;
    wells) vars="-var background 0 -var adhmode cellwall -var tensile 0.2" ;;
    bare) vars="-var background 0 -var adhmode cellwall -var tensile 0" ;;
    *) echo "unknown mode $mode" >&2 && exit 1 ;;
  esac
  WORK=$work/$mode LMPVARS=$vars bash "$here/drying_error.sh" "${points[@]}" >"$work/$mode/table.txt"
done
cd "$work"
WORKDIR=$work HERE=$here/.. MODES=$modes python3 - "${walls[@]}" <<'PY'
import os
import sys
sys.path.insert(0, os.path.join(os.environ["HERE"], "examples", "drying"))
import analyse
print("| wall | mode | within dx/2 at X/X0 0.6 | 0.4 | 0.2 (end) | wall atoms held at the end | CPU (s) |")
print("|---|---|---|---|---|---|---|")
for w in sys.argv[1:]:
    for mode in os.environ["MODES"].split():
        os.chdir(os.path.join(os.environ["WORKDIR"], mode))
        tag = f"n{w}_t0.03"
        try:
            rs = analyse.rows(tag)
            st = analyse.stability(tag, analyse.reach_of(tag), rs)
        except OSError:
            print(f"| {w} | {mode} | (no run) |||||")
            continue
        def share(x):
            return min(st, key=lambda s: abs(s[1] - x))
        vals = [share(x) for x in (0.6, 0.4)] + [st[-1]]
        with open(f"wall_{tag}.txt") as f:
            cpu = f.read().split("/")[-1].strip()
        print(f"| {w} | {mode} | "
              + " | ".join(f"{s[4]:.3f} ({s[1]:.2f})" for s in vals) + f" | {st[-1][5]:.3f} | {cpu} |")
PY
for mode in $modes; do
  echo "$mode:"
  cat "$work/$mode/table.txt"
done
echo "runs in $work"
