#!/usr/bin/env bash
# The uniform fluid (doc/pair_cell_sph.md, "Uniformity with h adaptive"): sealed cells at
# rest with the SPH wall boundary and h adaptive (bench/accuracy/wall_boundary.lmp), each VARIANT at each
# CASE; prints one table row per run: the stretch, P_SPH / P_wall - 1, P_wall / law - 1, std/mean
# of P over all fluid atoms, its split into between-shell and within-shell parts, the worst shell
# (one spacing wide, bench/common/pressure_shells.py) and where it is (0 = next to the wall), the wall
# shell, and the wall-clock of the run.
#   VARIANTS: name:settings, settings a comma list of wall_boundary.lmp variables, key=value with
#     '+' for spaces ('-' for none): e.g. "base:- q10:eta=1.0,supp=3,popt=kernel+quintic";
#     lattice=shells: the fluid start of cellgen --fluid-lattice shells (default cubic)
#   CASES: coarse seed fine seed-1.06 seed-2.2 (312, 1092, 2562 wall atoms; 1.35 x water unless
#     stated, stretch about 1.11; 1.06 and 2.2 x water: about 1.02 and 1.30)
#   NP ranks (default 1)
#   KEEP=folder: keep each run's last profile there
# e.g. VARIANTS="base:- jig02:jig=0.2" CASES="seed" bench/studies/uniform_fluid.sh
# (seed case, 1 rank: 14-15 min each with the 2 cores loaded about 3 times over)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../common/setup.sh"
bench_work
source "$here/../common/scaled_cell.sh"
echo "| variant | case | wall, fluid | stretch | P_SPH/P_wall-1 | P_wall/law-1 | std/mean | between | within | worst shell (at) | wall shell | s |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
for v in ${VARIANTS:-base:-}; do
  name=${v%%:*} settings=${v#*:}
  for case in ${CASES:-seed}; do
    f=1.35
    case $case in
      coarse) nw=300 nf=450 ;;
      seed) nw=1091 nf=1624 ;;
      fine) nw=2562 nf=3900 ;;
      seed-1.06) nw=1091 nf=1624 f=1.06 ;;
      seed-2.2) nw=1091 nf=1624 f=2.2 ;;
      *) echo "unknown case $case" >&2 && exit 1 ;;
    esac
    d=$work/$name-$case
    mkdir -p "$d" && cd "$d"
    kv=()
    if [ "$settings" != - ]; then IFS=, read -ra kv <<<"$settings"; fi
    # lattice=shells: cellgen --fluid-lattice shells, the ramp starting from its fill radius
    lattice=cubic
    for s in "${kv[@]}"; do if [ "${s%%=*}" = lattice ]; then lattice=${s#*=}; fi; done
    scaled_cell "$nw" "$nf" --fluid-lattice "$lattice"
    hcap=1.3
    if [ "${f%.*}" -ge 2 ]; then hcap=1.5; fi
    vars=(-var bnd 1 -var f "$f" -var h "$h" -var dt "$dt" -var gap "$gap" -var ws "$ws"
      -var hmode adaptive -var eta 1.27 -var hcap "$hcap")
    if [ "$lattice" = shells ]; then
      vars+=(-var rfill "$(sed -nE 's/.*fill radius ([0-9.e+-]+) m.*/\1/p' cellgen.log)")
    fi
    # the variant's settings go first: LAMMPS keeps the first -var of a name (index variables are
    # not redefined), so a setting placed after the defaults above would be ignored
    over=()
    if [ ${#kv[@]} -gt 0 ]; then
      for s in "${kv[@]}"; do
        key=${s%%=*} val=${s#*=}
        if [ "$key" = lattice ]; then continue; fi
        # eta: h/dx of the start as well (h = eta dx, dx from cellgen)
        if [ "$key" = eta ]; then over+=(-var h "$(python3 -c "print($h*$val/1.27)")"); fi
        over+=(-var "$key" "${val//+/ }")
      done
    fi
    vars=("${over[@]}" "${vars[@]}")
    t0=$SECONDS
    mpirun -np "${NP:-1}" "$build/bin/lmp" -in "$here/../accuracy/wall_boundary.lmp" "${vars[@]}" -log log.lammps >out.txt
    res=$(grep RESULT out.txt)
    sh=$(python3 "$here/../common/pressure_shells.py" profile.txt | tail -1)
    python3 - "$name" "$case" "$nwall, $nfluid" "$res" "$sh" "$((SECONDS - t0))" <<'EOF'
import re, sys
name, case, n, res, sh, secs = sys.argv[1:]
g = lambda pat, s: re.search(pat, s).group(1)
lam = g(r"lam ([0-9.]+)", res)
ps = float(g(r"PS/PW-1 (\S+)", res)) * 100
pw = float(g(r"PW/Plaw-1 (\S+)", res)) * 100
out = g(r"outside (\S+)", res)
print(f"| {name} | {case} | {n} | {lam} | {ps:+.1f} % | {pw:+.2f} % | {g(r'std/mean ([0-9.]+)', sh)} % "
      f"| {g(r'between ([0-9.]+)', sh)} % | {g(r'within ([0-9.]+)', sh)} % "
      f"| {g(r'worst shell ([0-9.]+)', sh)} % ({g(r'worst at shell (-?[0-9]+)', sh)}) "
      f"| {g(r'wall shell ([-+0-9.]+)', sh)} % | {secs} |" + ("" if out in ("0", "0.0") else f" outside {out}"))
EOF
    # nprof=N among the settings: the worst shell and std/mean every N steps of the relaxation
    for p in $(ls profile.*.txt 2>/dev/null | sort -t. -k2 -n); do
      echo "    timestep ${p//[^0-9]/} (relaxation from 10000): $(python3 "$here/../common/pressure_shells.py" "$p" | tail -1 | cut -d: -f2-)"
    done
    if [ -n "${KEEP:-}" ]; then mkdir -p "$KEEP" && cp profile.txt "$KEEP/$name-$case.profile.txt"; fi
  done
done
