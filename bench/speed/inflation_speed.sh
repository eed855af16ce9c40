#!/usr/bin/env bash
# Speed against error of the seed's inflation experiment (examples/inflation): one apple cell
# (R0 = 75 um, 1092 wall particles, calibrated apple set, pi0 = 200 kPa, pure water,
# L_P = 2.5e-6 m/(s Pa)) at about 500, 1600 and 5000 fluid particles (h = 1.322 dx), on 2 MPI
# ranks (wall-fluid f0 raised for the coarse fluid: inflation_speed.lmp). Per resolution: a
# reference run (time step dt0/2, accel 1, 400 us of physical time) and
# runs with dt0 = 2e-8 s (h / 12.2 um) and accel 1, 4, 16 that stop once the cell is steady (accel
# only stretches physical time here: L_P = 2.5e-6 is as fast as the mechanics; it is kept to show it)
# (|pi - P_T| < 200 Pa; at most as many steps as 400 us at accel 1). Prints a table: steady fluid mass M/M0 and its error against the
# reference of the same resolution and against the finest reference, area stretch against the
# thin Neo-Hookean membrane at 200 kPa, time to 90 % of the uptake (physical time) and its error,
# wall-clock time. Not a test; takes about 10 minutes. Run from anywhere after tools/setup.sh.
# MODEL=boundary holds the fluid with the SPH wall boundary of pair cell/sph (cellgen's default gap)
# instead of the wall-fluid particles; MODEL=auto as boundary with pair cell/sph background auto
# 5e3 (doc/pair_cell_sph.md, background pressure); NFLIST="500 1624" picks resolutions.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${CELLSPH_BUILD:-$here/../../build}
work=${INFLATION_BENCH_DIR:-/tmp/cellsph-inflation-bench}
export LAMMPS_POTENTIALS=${LAMMPS_POTENTIALS:-$here/../../potentials}
if [ "$(id -u)" -eq 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
mkdir -p "$work"
cd "$work"
rm -f series_*.dat final_*.txt runs.txt

echo "# inflation_speed: $(date -u), $(nproc) cores, load average $(cut -d ' ' -f 1-3 /proc/loadavg)"
model=${MODEL:-particles}
bg=-1
case $model in
  boundary) gapopt=() bnd=1 ;;
  auto) gapopt=() bnd=1 bg=5e3 ;;
  *) gapopt=(--gap 11e-6) bnd=0 ;;
esac
echo "# wall-fluid model: $model"
for nf in ${NFLIST:-500 1624 5000}; do
  "$build/tools/cellgen/cellgen" --nfluid $nf "${gapopt[@]}" --wall-mass 1e-12 --out cell$nf.data \
    >cellgen$nf.log
  dx=$(sed -n 's/.*DX = \([0-9.e+-]*\) m.*/\1/p' cellgen$nf.log)
  count=$(sed -n 's/^particles: \([0-9]*\) fluid.*/\1/p' cellgen$nf.log)
  h=$(python3 -c "print(f'{1.322 * $dx:.6g}')")
  dt0=$(python3 -c "print(f'{2e-8 * $h / 12.2e-6:.2g}')")
  dtref=$(python3 -c "print(f'{$dt0 / 2:.2g}')")
  for run in "ref $dtref 1 0" "a1 $dt0 1 1" "a4 $dt0 4 1" "a16 $dt0 16 1"; do
    set -- $run
    tag=n$nf-$1
    t0=$(date +%s.%N)
    mpirun -np 2 "$build/bin/lmp" -in "$here/inflation_speed.lmp" -log none -var data cell$nf.data \
      -var dx $dx -var dt $2 -var accel $3 -var halt $4 -var tend $(python3 -c "print(4e-4 * $3)") \
      -var tag $tag -var bnd $bnd -var bg $bg >$tag.log 2>&1 ||
      echo "run $tag failed: $(grep -m 1 ERROR $tag.log)" >&2
    t1=$(date +%s.%N)
    echo "$nf $count $dx $h $2 $3 $1 $tag $(python3 -c "print(f'{$t1 - $t0:.1f}')")" >>runs.txt
  done
done

python3 - <<'PY'
import math
runs = [l.split() for l in open("runs.txt")]
lam_law = 1.10859   # thin Neo-Hookean membrane, 2 G t0 / R0 (1/lam - 1/lam^7) = 200 kPa, R0 = 74.89 um

def load(tag):
    try:
        open(f"final_{tag}.txt")
    except OSError:
        nan = float("nan")
        return dict(t=nan, m=nan, P=nan, lam=nan, steps=0, t90=nan)
    rows = [list(map(float, l.split())) for l in open(f"series_{tag}.dat") if not l.startswith("#")]
    fin = list(map(float, open(f"final_{tag}.txt").read().split()))
    t90 = next(r[0] for r in rows if r[1] - 1 >= 0.9 * (fin[1] - 1))
    return dict(t=fin[0], m=fin[1], P=fin[2], lam=fin[3], steps=int(fin[4]), t90=t90)

res = {}
for nf, count, dx, h, dt, accel, kind, tag, wall in runs:
    res[(nf, kind)] = dict(load(tag), count=count, dx=float(dx), h=float(h), dt=float(dt),
                           accel=accel, wall=float(wall))
finest = res[(max((k[0] for k in res), key=int), "ref")]
print("| fluid | dx (um) | h (um) | dt (s) | accel | steps | t_end (us) | M/M0 | err M vs ref | "
      "err M vs finest | lambda | err lambda vs law | t90 (us) | err t90 vs ref | wall (s) |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
for (nf, kind), r in res.items():
    ref = res[(nf, "ref")]
    print(f"| {r['count']} | {r['dx'] * 1e6:.2f} | {r['h'] * 1e6:.2f} | {r['dt']:.2g} | {r['accel']} | "
          f"{r['steps']} | {r['t'] * 1e6:.0f} | {r['m']:.4f} | {r['m'] / ref['m'] - 1:+.2%} | "
          f"{r['m'] / finest['m'] - 1:+.2%} | {r['lam']:.5f} | {r['lam'] / lam_law - 1:+.3%} | "
          f"{r['t90'] * 1e6:.1f} | {r['t90'] / ref['t90'] - 1:+.1%} | {r['wall']:.1f} |")
PY
