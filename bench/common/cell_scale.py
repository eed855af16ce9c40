#!/usr/bin/env python3
"""The drying cell's set-up scaled to a cellgen cell from the seed's (1647 fluid atoms, mean wall
bond 8.62822 um): h and dt follow the fluid spacing, the contact size ws the wall spacing; uptake
steps a multiple of 500 (+ the 2000 sealed), so that the output intervals of drying end on the
run's last step; accel = tstep / dt for a physical time tstep (s) per MD step; an optional DTF
multiplies dt and divides the uptake steps (the same physical uptake time). TSTEP = aACCEL (e.g.
a3e6) fixes accel instead: the same mechanical lag at every resolution (tstep = accel x dt).
  cell_scale.py CELLGEN_LOG TSTEP [DTF]   prints: h dt ws nup accel"""
import re
import sys

log = open(sys.argv[1]).read()
nfluid = int(re.search(r"particles: (\d+) fluid", log).group(1))
bond = float(re.search(r"wall bond length: min \S+, mean (\S+),", log).group(1))
f = (1647 / nfluid) ** (1 / 3)
dtf = float(sys.argv[3]) if len(sys.argv) > 3 else 1.0
dt = 1e-8 * f * dtf
tstep = sys.argv[2]
accel = float(tstep[1:]) if tstep.startswith("a") else float(tstep) / dt
print(f"{12.2e-6 * f:.6g} {dt:.6g} {bond / 8.62822e-6:.6g} {500 * max(1, round(24 / (f * dtf)))} "
      f"{accel:.6g}")
