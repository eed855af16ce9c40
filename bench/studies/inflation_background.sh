#!/usr/bin/env bash
# Mass transfer with the SPH wall boundary and a background pressure (issue 8's "mass transfer"):
# examples/inflation's cell (seed resolution, pi0 = 200 kPa fixed, pure water; cellgen's default
# gap, pair_coeff 1 2 cell/sph wall) with pair cell/sph background auto P_MIN (default 5e3 Pa), over
# L_P 2.5e-3 to 2.5e-7 m/(s Pa), accel 1 and 100 and dt 2e-8 and 1e-8 s, each with fix cell/turgor's
# turgor wall (the mean SPH pressure minus its running offset D from the wall load) and turgor sph
# (the mean SPH pressure alone, no offset). One core per run, two runs at a time. Prints, per run,
# the steady fluid mass M/M0 and its spread over the runs of each turgor measure, the wall load P_T,
# the mean SPH pressure and their difference, the bond turgor P_L, the area stretch against the thin
# membrane's 1.10859 and the wall-clock time; then the time each run's mass took to come within
# 0.5 % of its end value. Not a test; about 7 minutes on 2 cores.
#   bash bench/studies/inflation_background.sh         (environment: CELLSPH_BUILD, OUT, P_MIN)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${CELLSPH_BUILD:-$here/../../build}
out=${OUT:-/tmp/cellsph-bench/inflation_background}
pmin=${P_MIN:-5e3}
export LAMMPS_POTENTIALS=${LAMMPS_POTENTIALS:-$here/../../potentials}
mkdir -p "$out"
cd "$out"
rm -f final_*.txt mass_*.dat runs.txt
echo "# inflation_background: $(date -u), $(nproc) cores, load average $(cut -d ' ' -f 1-3 /proc/loadavg)"
"$build/tools/cellgen/cellgen" --wall-mass 1e-12 --out cell.data >cellgen.log
# examples/inflation's input (the wall boundary with background auto 5e3, the fix's default turgor)
# with P_MIN and the turgor measure of each run
sed -e "s/background auto 5e3/background auto $pmin/" \
  -e 's/^\(fix  *turgor all cell\/turgor .*\)$/\1 turgor ${turgor}/' \
  "$here/../../examples/inflation/in.inflation" >in.inflation

# LP accel dt steps: 0.4 ms of MD time (40 ms of transfer time at accel 100); 0.8 ms at 2.5e-6,
# which is not steady at 0.4 ms (P_T 199.7 kPa)
cases=("2.5e-3 1 2e-8 20000" "2.5e-4 1 2e-8 20000" "2.5e-5 1 2e-8 20000" "2.5e-5 1 1e-8 40000"
  "2.5e-6 1 2e-8 40000" "2.5e-7 100 2e-8 20000")
jobs=()
for c in "${cases[@]}"; do
  for measure in wall sph; do jobs+=("$c $measure"); done
done
one() {
  set -- $1
  local tag="LP$1-a$2-dt$3-$5" t0 t1
  t0=$(date +%s.%N)
  "$build/bin/lmp" -in in.inflation -log none \
    -var LP "$1" -var accel "$2" -var dt "$3" -var steps "$4" -var turgor "$5" -var every 100 \
    -var tag "$tag" >"$tag.log" 2>&1 || echo "run $tag failed: $(grep -m 1 ERROR "$tag.log")" >&2
  t1=$(date +%s.%N)
  echo "$tag $5 $(python3 -c "print(f'{$t1 - $t0:.1f}')")" >>runs.txt
}
for ((k = 0; k < ${#jobs[@]}; k += 2)); do
  one "${jobs[k]}" &
  if ((k + 1 < ${#jobs[@]})); then one "${jobs[k + 1]}"; fi
  wait
done

python3 - <<'PY'
lam_law = 1.10859   # thin Neo-Hookean membrane at 200 kPa (R0 = 74.89 um)
rows = []
for line in open("runs.txt"):
    tag, measure, wall = line.split()
    try:
        f = open(f"final_{tag}.txt").read().split()
    except OSError:
        print(f"| {tag} | failed |")
        continue
    t, mm, pt, pi, lam, lamv, dtk, pl, psph = map(float, f[2:])
    series = [list(map(float, l.split())) for l in open(f"mass_{tag}.dat") if not l.startswith("#")]
    # MD steps until M/M0 stays within 0.5 % of its end value (a line every 100 steps)
    k = len(series)
    while k > 0 and abs(series[k - 1][1] / mm - 1) < 5e-3:
        k -= 1
    rows.append((tag, measure, mm, pt, psph, pl, lam, float(wall), 100 * k))
print("| run | turgor | M/M0 | P_T (kPa) | P_SPH (kPa) | P_SPH/P_T - 1 | P_L (kPa) | lambda | vs law | "
      "steps to M within 0.5 % | wall-clock (s) |")
print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
for tag, measure, mm, pt, psph, pl, lam, wall, steps in rows:
    print(f"| {tag} | {measure} | {mm:.6f} | {pt / 1e3:.2f} | {psph / 1e3:.2f} | {psph / pt - 1:+.2%} | "
          f"{pl / 1e3:.2f} | {lam:.6f} | {lam / lam_law - 1:+.3%} | {steps} | {wall:.1f} |")
for measure in ("wall", "sph"):
    m = [r[2] for r in rows if r[1] == measure]
    if m:
        print(f"turgor {measure}: steady M/M0 from {min(m):.6f} to {max(m):.6f}, spread "
              f"{max(m) / min(m) - 1:.3%} over {len(m)} runs")
PY
