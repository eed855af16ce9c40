#!/usr/bin/env python3
"""cellgen (one cell or a lattice of cells) refuses option values outside the ranges of
tools/cellgen/README.md (Usage) with a message naming the option, the range and the value, exit
status 2 and no data file: --gap below DX/4 (0, which put the fluid lattice on the wall's sphere,
1-2 um from wall particles; just below DX/4, with and without --dx) or not below the smallest
radius, a negative --gap without fluid, --wall-mass above the water filling a cell (1e300 was
accepted) or not positive, and --rho0 above 1e5 kg/m^3. The edges are accepted: --gap DX/4 with
--dx, the tests' smallest gap (3 um at R = 40 um, 250 fluid: 0.31 DX), --gap 0 without fluid, and
--wall-mass rho0 4/3 pi R^3 (rounded down to 6 digits). Usage: out_of_range_options_are_a_clear_error.py CELLGEN
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from cellgen_options import check  # noqa: E402

CASES = [
    (["--gap", "0"], "--gap must be in [DX/4, smallest radius) = [2.56345e-06, 7.5e-05) m "
     "(DX = 1.02538e-05 m, the fluid spacing), not 0"),
    (["--gap", "2e-6"], "--gap must be in [DX/4, smallest radius) = [2.49509e-06, 7.5e-05) m"),
    (["--dx", "10e-6", "--gap", "2.4e-6"],
     "--gap must be in [DX/4, smallest radius) = [2.5e-06, 7.5e-05) m (DX = 1e-05 m"),
    (["--gap", "80e-6"], "--gap must be in [DX/4, smallest radius), below 7.5e-05 m, not 8e-05"),
    (["--nfluid", "0", "--gap", "-1e-6"],
     "--gap must be in [0, smallest radius) = [0, 7.5e-05) m, not -1e-06"),
    (["--wall-mass", "1e300"], "--wall-mass must be in (0, rho0 4/3 pi R^3] = (0, 1.76715e-09] kg "
     "(the water filling a cell of radius R), not 1e+300"),
    (["--wall-mass", "-1e-12"], "--wall-mass must be in (0, rho0 4/3 pi R^3]"),
    (["--rho0", "1e300"], "--rho0 must be in (0, 100000] kg/m^3, not 1e+300"),
]
GOOD = [["--dx", "10e-6", "--gap", "2.5e-6"],
        ["--radius", "40e-6", "--nwall", "300", "--nfluid", "250", "--gap", "3e-6"],
        ["--nfluid", "0", "--gap", "0"],
        ["--wall-mass", "1.76714e-9"]]


if __name__ == "__main__":
    check([sys.argv[1]] + ["--nwall", "100"], CASES, GOOD, (2,))
