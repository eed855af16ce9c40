#!/usr/bin/env bash
# Does a drying cell's result depend on how the script splits its runs? (continuity of the state across runs)
# bench/accuracy/run_split.lmp makes the coarse drying cell (312 wall + 450 fluid asked for, the model of
# examples/drying/in.drying) turgid, dries it NWARM steps (default 1009: a transfer waits at the
# end) and writes start.restart (on 1 rank). From there each variant runs NSTEPS (default 4000)
# steps of drying: as 1, 2, 10 and 100 equal `run` commands, and as NSTEPS/2 steps, write_restart,
# and NSTEPS/2 steps in a second LAMMPS process (read_restart); each on 1 and 2 ranks. With the
# default lengths every run boundary falls one step before a transfer (fix cell/turgor 10); with
# NWARM=1004 each falls between transfers. Numbers: doc/notes/2026-12-07-run-split.md.
# Prints two tables:
#  1. against the single run on the same ranks: the largest relative difference of the cell's
#     fluid mass M, wall volume V and fluid volume sum m/rho, and of the turgor P_T (relative to
#     the largest |P_T| of the single run), at the last step and over every step; "bitwise": every
#     number of those columns the same to all 17 digits at every step. The restart variant is also
#     compared with the 2-run variant (the same step sequence: one setup at NSTEPS/2).
#  2. the mean SPH pressure Pbar (compute cell/props column 14) at each run boundary: the largest
#     |jump| between the last step of a run and the next run's setup (same positions and masses),
#     and of the relative jump of sum m/rho, against the step-to-step |change| of Pbar in the
#     single run (median and largest) and in the split run away from boundaries (steps >= 2 after
#     a setup).
# WORK=dir keeps the runs there (reused: delete it to run again). NPS="1 2" the rank counts.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${CELLSPH_BUILD:-$here/../../build}
work=${WORK:-$(mktemp -d)}
nsteps=${NSTEPS:-4000}
nwarm=${NWARM:-1009}
nps=${NPS:-1 2}
mkdir -p "$work"
if [ "$(id -u)" -eq 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
export LAMMPS_POTENTIALS=$here/../../potentials
cd "$work"
lmprun() {    # NP LOG ARGS...: one LAMMPS run, its CPU time in LOG.cpu
  local np=$1 log=$2
  shift 2
  local cmd=("$build/bin/lmp")
  [ "$np" = 1 ] || cmd=(mpirun -np "$np" "$build/bin/lmp")
  /usr/bin/time -f "%U %S" -o "$log.cpu" nice "${cmd[@]}" -in "$here/run_split.lmp" \
    -var cellgen "$build/tools/cellgen/cellgen" -log "$log" "$@" >"$log.screen" ||
    { echo "run $log failed: $(grep -m1 ERROR "$log" || tail -2 "$log.screen")"; exit 1; }
}
[ -s start.restart ] || lmprun 1 log.prep -var mode prep -var nwarm "$nwarm"
for np in $nps; do
  for n in 1 2 10 100; do
    [ -s "log.np$np.n$n" ] || lmprun "$np" "log.np$np.n$n" -var nsteps "$nsteps" -var nruns "$n"
  done
  if [ ! -s "log.np$np.rb" ]; then
    lmprun "$np" "log.np$np.ra" -var nsteps $((nsteps / 2)) -var to "mid$np"
    lmprun "$np" "log.np$np.rb" -var nsteps $((nsteps / 2)) -var from "mid$np.restart"
  fi
done
python3 - "$nps" <<'EOF'
import statistics
import sys


def blocks(*logs):
    """rows of the thermo blocks of these logs: one list per run, its first row the setup's"""
    runs = []
    for log in logs:
        rows = None
        for line in open(log):
            w = line.split()
            if w[:2] == ["Step", "c_props[1][2]"]:
                rows = []
                runs.append(rows)
            elif rows is not None and len(w) == 8 and w[0].isdigit():
                rows.append([int(w[0])] + w[1:])
            else:
                rows = None
    return runs


def dynamics(runs):
    """step -> the row the dynamics computed (each run's setup row only at the first run's step)"""
    out = {}
    for k, rows in enumerate(runs):
        for r in rows[0 if k == 0 else 1:]:
            out[r[0]] = r
    return out


def compare(a, b):
    """largest relative differences (M, V, sum m/rho, P_T / max|P_T|) at the end and over all
    steps, and whether the columns are the same strings at every step"""
    steps = sorted(b)
    scale = max(abs(float(b[s][4])) for s in steps)
    def rel(s, c):
        x, y = float(a[s][c]), float(b[s][c])
        return abs(x - y) / (scale if c == 4 else abs(y))
    end = [rel(steps[-1], c) for c in (1, 2, 3, 4)]
    most = [max(rel(s, c) for s in steps) for c in (1, 2, 3, 4)]
    same = all(a[s][1:6] == b[s][1:6] for s in steps)
    return end, most, same


nps = sys.argv[1].split()
print("Table 1: against the single run on the same ranks (relative; P_T relative to max |P_T|)")
print(f"{'ranks':>5} {'variant':>10} | {'end: M':>8} {'V':>8} {'sum m/rho':>9} {'P_T':>8} |"
      f" {'all steps: M':>12} {'V':>8} {'sum m/rho':>9} {'P_T':>8} | bitwise")
runs = {}
for np in nps:
    for v in ("n1", "n2", "n10", "n100"):
        runs[np, v] = blocks(f"log.np{np}.{v}")
    runs[np, "restart"] = blocks(f"log.np{np}.ra", f"log.np{np}.rb")
    ref = dynamics(runs[np, "n1"])
    pairs = [(v, "n1") for v in ("n2", "n10", "n100", "restart")] + [("restart", "n2")]
    for v, r in pairs:
        end, most, same = compare(dynamics(runs[np, v]), dynamics(runs[np, r]))
        name = v if r == "n1" else f"{v}/{r}"
        print(f"{np:>5} {name:>10} | " + " ".join(f"{x:8.1e}" for x in end[:2]) +
              f" {end[2]:9.1e} {end[3]:8.1e} | {most[0]:12.1e} {most[1]:8.1e} {most[2]:9.1e}"
              f" {most[3]:8.1e} | {'yes' if same else 'no'}")
    one = dynamics(runs[np, "n1"])
    print(f"{np:>5} {'1 vs ' + nps[0] + ' rk':>10} | " if np != nps[0] else "", end="")
    if np != nps[0]:
        end, most, same = compare(one, dynamics(runs[nps[0], "n1"]))
        print(" ".join(f"{x:8.1e}" for x in end[:2]) + f" {end[2]:9.1e} {end[3]:8.1e} |"
              f" {most[0]:12.1e} {most[1]:8.1e} {most[2]:9.1e} {most[3]:8.1e} | "
              f"{'yes' if same else 'no'}")

print()
print("Table 2: mean SPH pressure Pbar at the run boundaries (Pa) against its step-to-step change")
print(f"{'ranks':>5} {'variant':>8} | {'bounds':>6} {'max|jump|':>9} {'med|jump|':>9}"
      f" {'dsum m/rho':>10} | {'step change in the single run: median':>37} {'max':>7} |"
      f" {'split run, away from bounds: median':>35} {'max':>7}")
for np in nps:
    one = dynamics(runs[np, "n1"])
    steps = sorted(one)
    d1 = [abs(float(one[s][5]) - float(one[p][5])) for p, s in zip(steps, steps[1:])]
    for v in ("n2", "n10", "n100", "restart"):
        rs = runs[np, v]
        jumps, dvs, away = [], [], []
        for prev, rows in zip(rs, rs[1:]):
            end, setup = prev[-1], rows[0]
            assert end[0] == setup[0]
            jumps.append(abs(float(setup[5]) - float(end[5])))
            dvs.append(abs(float(setup[3]) / float(end[3]) - 1))
        for rows in rs:
            for p, s in zip(rows[2:], rows[3:]):
                away.append(abs(float(s[5]) - float(p[5])))
        print(f"{np:>5} {v:>8} | {len(jumps):>6} {max(jumps):9.3g} {statistics.median(jumps):9.3g}"
              f" {max(dvs):10.1e} | {statistics.median(d1):37.3g} {max(d1):7.3g} |"
              f" {statistics.median(away):35.3g} {max(away):7.3g}")
EOF
echo "runs in $work; CPU seconds (user system) of each: $(for f in log.*.cpu; do printf '%s %s; ' "${f%.cpu}" "$(cat "$f")"; done)"
