#!/usr/bin/env bash
# Two builds side by side on the full sealed-cell model of bench/speed/cell_model_speed.sh (same
# machine, same load): the turgid state of each model is made once (cell_model_speed.lmp's ramp,
# new build, 1 rank) and written as a restart; then, for each repeat, model and rank count, the old
# build and the new one each time nsteps from it (bench/speed/cell_model_timed.lmp), with the load
# average (uptime) before each run. One line per run: loop time (s), "% CPU use", particle-steps/s
# per core by the wall clock (the bench's figure) and by CPU time (loop time x CPU use: less
# sensitive to the load of a shared machine). The restarts are kept in the work folder and reused.
# Models: adaptive (h adaptive 1.27, the full model),
# boundary (h fixed 12.2 um), boundary-h14 (h fixed 14.3 um, the adaptive run's mean h).
#   bash bench/speed/compare_builds.sh OLD_BUILD NEW_BUILD [nsteps=1000] [repeats=3] \
#     [models="adaptive boundary-h14"]
# Environment: NPS (rank counts, default "1 2"), MPIEXEC (default mpirun), OUT (work folder).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
old=$1
new=$2
nsteps=${3:-1000}
repeats=${4:-3}
models=${5:-adaptive boundary-h14}
out=${OUT:-/tmp/cellsph-bench/compare_builds}
if [ "$(id -u)" -eq 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
mkdir -p "$out"
cd "$out"
gap=4.79885e-6
"$new/tools/cellgen/cellgen" --gap "$gap" --wall-mass 1e-12 --out cell.data >cellgen.log
for model in $models; do
  case $model in
    adaptive) vars=(-var hmode adaptive -var hfix 12.2e-6) ;;
    boundary) vars=(-var hmode fixed -var hfix 12.2e-6) ;;
    boundary-h14) vars=(-var hmode fixed -var hfix 14.3e-6) ;;
  esac
  [ -f "turgid.$model.restart" ] && continue    # made once per work folder
  printf 'include %s\nwrite_restart turgid.%s.restart\n' "$here/cell_model_speed.lmp" "$model" >ramp.lmp
  "$new/bin/lmp" -in ramp.lmp -var nsteps 0 -var bnd 1 -var gap "$gap" "${vars[@]}" -log "log.ramp.$model" >/dev/null
done
echo "| repeat | model | ranks | build | particles | loop time (s) | CPU use | p-steps/s/core (wall) | p-steps/s/core (CPU) | load (1 min) |"
echo "|---:|---|---:|---|---:|---:|---:|---:|---:|---:|"
for r in $(seq "$repeats"); do
  for model in $models; do
    hfix=12.2e-6
    [ "$model" = boundary-h14 ] && hfix=14.3e-6
    for np in ${NPS:-1 2}; do
      for b in old new; do
        build=$old
        [ "$b" = new ] && build=$new
        cmd=("$build/bin/lmp")
        [ "$np" = 1 ] || cmd=("${MPIEXEC:-mpirun}" -np "$np" "$build/bin/lmp")
        load=$(uptime | sed 's/.*load average: \([0-9.]*\).*/\1/')
        log=log.$model.np$np.$b.$r
        "${cmd[@]}" -in "$here/cell_model_timed.lmp" -var restart "turgid.$model.restart" \
          -var hfix "$hfix" -var nsteps "$nsteps" -log "$log" >/dev/null
        awk -v r="$r" -v b="$b" -v m="$model" -v np="$np" -v n="$nsteps" -v load="$load" '
          /^Loop time of/ { t = $4; a = $12 }
          /% CPU use with/ { c = $1 + 0 }
          END { printf "| %d | %s | %d | %s | %d | %.2f | %.1f %% | %.3g | %.3g | %s |\n", r, m, np, b,
                a, t, c, a * n / t / np, a * n / (t * c / 100) / np, load }' "$log"
      done
    done
  done
done
