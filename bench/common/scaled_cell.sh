# Sourced by the wall-boundary benches (needs $build). scaled_cell NWALL NFLUID [cellgen options]
# writes cell.data (wall mass 1e-12 kg) and cellgen.log in the current folder and sets, from
# cellgen's report: dx, gap, nwall, nfluid; and what follows the resolution: h = 12.2 um x DX /
# 9.59755 um (the seed's h/dx = 1.27), dt = 1e-8 s x the same ratio, ws = sqrt(1092 / nwall) (the
# wall spacing against the seed's, for the wall-wall contact size).
scaled_cell() {
  local want_wall=$1 want_fluid=$2
  shift 2
  "$build/tools/cellgen/cellgen" --nwall "$want_wall" --nfluid "$want_fluid" --wall-mass 1e-12 "$@" \
    --out cell.data >cellgen.log
  local line
  line=$(head -1 cellgen.log)
  dx=$(sed -E 's/.*DX = ([0-9.e+-]+) m.*/\1/' <<<"$line")
  gap=$(sed -E 's/.*gap = ([0-9.e+-]+) m.*/\1/' <<<"$line")
  nfluid=$(sed -nE 's/^particles: ([0-9]+) fluid.*/\1/p' cellgen.log)
  nwall=$(sed -nE 's/.*: ([0-9]+) wall particles per cell.*/\1/p' cellgen.log)
  h=$(python3 -c "print(12.2e-6*$dx/9.59755e-6)")
  dt=$(python3 -c "print(1e-8*$dx/9.59755e-6)")
  ws=$(python3 -c "print((1092/$nwall)**0.5)")
}
