#!/usr/bin/env bash
# Evaporative cooling of the air drive (fix cell/turgor air ... cooling yes, doc/model.md §5.14):
# surface temperature and surface flux with and without it. Prints three tables:
#  1. the air alone (python, the model's formulas): the wet-bulb temperature of the heat balance
#     (Chilton-Colburn film), the adiabatic-saturation wet bulb of ASHRAE's psychrometric equation,
#     the free-water flux h_m (rho_v,sat(T_wb) - RH rho_v,sat(T_air)) at h_m = 0.02 m/s against the
#     flux at the air's temperature, and the gain lambda h_m drho_v,sat/dT / h_c of a scheme that
#     would lag T_s by one transfer (above 1: it would oscillate and diverge);
#  2. the coarse drying cell of examples/drying (312 wall, 450 fluid atoms asked, h, dt and accel
#     of bench/accuracy/drying_error.sh's "312 0.03"; turgid stage, then 'maxout' x 100 steps of drying in
#     air at RH 0.15, h_m 0.02 m/s on 1 % of the wall) at 60 and 70 C, cooling no and yes: T_s
#     (output 15), the mean flux over the exposed wall (output 16) at the end, X/X0 at the end and
#     the CPU time of the run;
#  3. the tiny tissue of tests/tissue/scene_runs_at_a_tiny_size (2 x 2 x 2 slab, 20 settling steps,
#     the scene's air 60 C, RH 0.1, h_m 0.02, exchange at 1000 x L_cc, accel 1e7) dried for
#     'tsteps' steps: T_s, the mean flux over the exposed wall (output 16) and the slab's flux per
#     area of its top face, (M0 - M) / (t A_box), against apple's 0.08-0.4 g m^-2 s^-1.
#   bash bench/studies/drying_cooling.sh
# Environment: CELLSPH_BUILD (build folder), WORK (work folder, kept and reused; default a new
# temporary one), MAXOUT (cell: drying intervals of 100 steps, default 20), TSTEPS (tissue drying
# steps, default 100: the slab without cooling went unstable in pair cell/sph after 130 of them),
# NP (ranks of the LAMMPS runs, default 1).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../common/setup.sh"
work=${WORK:-$(mktemp -d)}
np=${NP:-1}
maxout=${MAXOUT:-20}
tsteps=${TSTEPS:-100}
mkdir -p "$work"
cd "$work"
if [ "$np" = 1 ]; then lmp=("$build/bin/lmp"); else lmp=(mpirun -np "$np" "$build/bin/lmp"); fi

python3 - <<'PY'
import math
R, MW = 8.314462618, 18.015e-3
def psat(t):    # Wagner & Pruss 1993
    v = 1 - t / 647.096
    s = (-7.85951783 * v + 1.84408259 * v**1.5 - 11.7866497 * v**3 + 22.6807411 * v**3.5
         - 15.9618719 * v**4 + 1.80122502 * v**7.5)
    return 22.064e6 * math.exp(647.096 / t * s)
rsat = lambda t: psat(t) * MW / (R * t)
lam = lambda t: 2.501e6 - 2361 * (t - 273.15)
def film(t):    # rho_a c_p Le^(2/3) = h_c / h_m at the air's temperature
    rho = 101325 * 28.965e-3 / (R * t)
    d = -2.775e-6 + 4.479e-8 * t + 1.656e-10 * t * t
    k = 0.0241 * (t / 273) ** 1.5 * (273 + 194) / (t + 194)
    return rho * 1007 * (k / (rho * 1007 * d)) ** (2 / 3)
def bisect(f, lo, hi):
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if f(mid) > 0 else (lo, mid)
    return 0.5 * (lo + hi)
def wet_bulb(ta, rh):
    ra = rh * rsat(ta)
    return bisect(lambda t: film(ta) * (ta - t) - lam(t) * (rsat(t) - ra), 273.16, ta)
def ashrae(ta, rh, p=101325.0):    # ASHRAE Fundamentals (2017) ch. 1, eq. 33 (t in C, kJ/kg)
    t = ta - 273.15
    pw = rh * psat(ta)
    w = 0.621945 * pw / (p - pw)
    def g(ts):
        ws = 0.621945 * psat(ts + 273.15) / (p - psat(ts + 273.15))
        return ((2501 - 2.326 * ts) * ws - 1.006 * (t - ts)) / (2501 + 1.86 * t - 4.186 * ts) - w
    return bisect(lambda ts: -g(ts), 0.01, t) + 273.15
print("| air | RH | T_wb, heat balance (C) | T_wb, ASHRAE adiabatic saturation (C) | free-water flux at T_wb (g/m2/s, h_m 0.02) | at T_air | lag gain |")
print("|---|---|---|---|---|---|---|")
for ta, rh in [(333.15, 0.1), (333.15, 0.15), (343.15, 0.15), (313.15, 0.15)]:
    tw = wet_bulb(ta, rh)
    ra = rh * rsat(ta)
    gain = lam(tw) * (rsat(tw + 1e-3) - rsat(tw - 1e-3)) / 2e-3 / film(ta)
    print(f"| {ta - 273.15:.0f} C | {rh} | {tw - 273.15:.2f} | {ashrae(ta, rh) - 273.15:.2f} | "
          f"{0.02 * (rsat(tw) - ra) * 1e3:.3f} | {0.02 * (rsat(ta) - ra) * 1e3:.3f} | {gain:.2f} |")
PY
echo

# 2. the coarse drying cell
"$build/tools/cellgen/cellgen" --nwall 312 --nfluid 450 --wall-mass 1e-12 --dihedrals --out c312.data >cellgen312.log
read -r h dt ws nup acc < <(python3 "$here/../common/cell_scale.py" cellgen312.log 0.03)
for t in 333.15 343.15; do
  for c in no yes; do
    tag=cell_T${t%.*}_$c
    [ -s "cpu_$tag.txt" ] && continue
    /usr/bin/time -f "%U %S" -o "cpu_$tag.txt" "${lmp[@]}" -in "$here/../../examples/drying/in.drying" \
      -var data c312.data -var tag "$tag" -var accel "$acc" -var h "$h" -var dt "$dt" -var ws "$ws" \
      -var nup "$nup" -var nrest "$((nup / 6))" -var nout 100 -var maxout "$maxout" -var T "$t" -var cooling "$c" \
      -log "log.$tag" >"$tag.screen" || echo "run $tag failed: $(grep -m1 ERROR "log.$tag")"
  done
done
python3 - "$maxout" <<'PY'
import sys
print("| cell | air | cooling | T_s (C) | flux over the exposed wall (g/m2/s) | X/X0 at the end | physical time (s) | CPU (s) |")
print("|---|---|---|---|---|---|---|---|")
for t in ("333", "343"):
    for c in ("no", "yes"):
        tag = f"cell_T{t}_{c}"
        try:
            lines = open(f"log.{tag}").read().splitlines()
        except OSError:
            continue
        head = [i for i, l in enumerate(lines) if l.split()[:3] == ["Step", "CPU", "v_t"]]
        rows = [l.split() for l in lines[head[-1] + 1:] if l.split() and l.split()[0].isdigit()]
        last = rows[-1]
        cpu = sum(map(float, open(f"cpu_{tag}.txt").read().split()))
        print(f"| 312 wall | {int(t) - 273} C, RH 0.15 | {c} | {float(last[13]) - 273.15:.2f} | "
              f"{float(last[14]) * 1e3:.4f} | {float(last[3]):.4f} | {float(last[2]):.2f} | {cpu:.0f} |")
PY
echo

# 3. the tiny tissue
"$build/tools/cellgen/cellgen" tissue --cells 2 2 2 --slab z --size 230e-6 --cv 0.35 --porosity 0.15 --dx 24e-6 \
  --junction-gap 10e-6 --wall-mass 1e-12 --seed 1 --dihedrals --out tissue.data >cellgen_tissue.log
for c in no yes; do
  mkdir -p "tissue_$c"
  (
    cd "tissue_$c"
    [ -s final.txt ] && exit 0
    cp ../tissue.data ../tissue.data.junctions .
    "${lmp[@]}" -in "$here/../../examples/tissue/in.settle" -var nsettle 20 -log log.settle >/dev/null
    /usr/bin/time -f "%U %S" -o cpu.txt "${lmp[@]}" -in "$here/../../examples/tissue/in.tissue" \
      -var nout 50 -var maxout $((tsteps / 50)) -var Xhalf 0 -var accel 1e7 \
      -var exchange "exchange 5e-11 bondtype 2 areas tissue.data.junctions" -var cooling "$c" \
      -log log.lammps >screen.txt || echo "tissue run cooling $c failed: $(grep -m1 ERROR log.lammps)"
  )
done
python3 - <<'PY'
import re
print("| tissue | cooling | T_s (C) | flux over the exposed wall (g/m2/s) | flux per top face (g/m2/s) | X/X0 at the end | physical time (s) | CPU (s) |")
print("|---|---|---|---|---|---|---|---|")
for c in ("no", "yes"):
    try:
        text = open(f"tissue_{c}/log.lammps").read()
    except OSError:
        continue
    # the box of the settled slab (in.settle's print), which in.tissue continues from
    box = re.search(r"box ([0-9.e+-]+) x ([0-9.e+-]+) m,", open(f"tissue_{c}/log.settle").read())
    area = float(box.group(1)) * float(box.group(2))
    lines = text.splitlines()
    head = [i for i, l in enumerate(lines) if l.split()[:3] == ["Step", "CPU", "v_t"]]
    rows = [l.split() for l in lines[head[-1] + 1:] if l.split() and l.split()[0].isdigit()]
    last = rows[-1]
    t, x, moved, dm = (float(v) for i, v in enumerate(open(f"tissue_{c}/final.txt").read().split())
                       if i in (0, 1, 4, 5))
    cpu = sum(map(float, open(f"tissue_{c}/cpu.txt").read().split()))
    print(f"| 2 x 2 x 2, 60 C, RH 0.1 | {c} | {float(last[8]) - 273.15:.2f} | {float(last[9]) * 1e3:.4f} | "
          f"{-dm / (t * area) * 1e3:.4f} | {x:.4f} | {t:.2f} | {cpu:.0f} |")
print("apple slabs, constant-rate period at 40-70 C and 0.5-2 m/s: 0.08-0.4 g/m2/s (doc/model.md §10.2)")
PY
