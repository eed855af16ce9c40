#!/usr/bin/env python3
"""cellgen tissue refuses bad input with a message naming the option and the value, exit status 1
or 2, and no data file: porosity outside [0, 0.5) (0.5, 0.7, -0.1, 1e-9 below 0, not a number),
cells too small for the resolution (--size 40e-6 --dx 10e-6; the default 160 um cells at
--dx 30e-6 and at --dx 16e-6 with a --junction-gap of 40e-6), and values outside the ranges of
README.md (Tissue mode): --gap below DX/4 (0, which put the fluid on the wall, and just below),
--wall-dx outside [D/1000, D/2] (1e300 and 1e-300 were accepted), --wall-mass above the water
filling a cell of diameter D (1e300 was accepted) and --rho0 above 1e5 kg/m^3. The edges of the
ranges are accepted: porosity 0 and 0.45, --gap DX/4, --wall-dx D/2 and --wall-mass rho0 pi D^3/6
(rounded down to 6 digits) write the files. Usage: tissue_bad_input_is_a_clear_error.py CELLGEN
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from cellgen_options import check  # noqa: E402

CASES = [
    (["--porosity", "0.5"], "--porosity must be in [0, 0.5), not 0.5"),
    (["--porosity", "0.7"], "--porosity must be in [0, 0.5), not 0.7"),
    (["--porosity", "-0.1"], "--porosity must be in [0, 0.5), not -0.1"),
    (["--porosity", "-1e-9"], "--porosity must be in [0, 0.5), not -1e-09"),
    (["--porosity", "abc"], "--porosity"),
    (["--size", "40e-6", "--dx", "10e-6"],
     "cells too small for the resolution: the smallest cell"),
    (["--size", "40e-6", "--dx", "10e-6"], "--size 4e-05 needs --dx <="),
    (["--dx", "30e-6"], "--dx is 3e-05"),
    (["--dx", "16e-6", "--junction-gap", "40e-6"], "--junction-gap 4e-05"),
    (["--dx", "16e-6", "--gap", "0"],
     "--gap must be >= DX/4 = 4e-06 m (DX = 1.6e-05 m, the fluid spacing), not 0"),
    (["--dx", "16e-6", "--gap", "3.9e-6"], "--gap must be >= DX/4 = 4e-06 m"),
    (["--wall-dx", "1e300"],
     "--wall-dx must be in [D/1000, D/2] = [1.6e-07, 8e-05] m (D = --size 0.00016 m), not 1e+300"),
    (["--wall-dx", "1e-300"], "--wall-dx must be in [D/1000, D/2] = [1.6e-07, 8e-05] m"),
    (["--wall-mass", "1e300"],
     "--wall-mass must be in (0, rho0 pi D^3/6] = (0, 2.14466e-09] kg (the water filling a cell of "
     "diameter --size), not 1e+300"),
    (["--wall-mass", "0"], "--wall-mass must be in (0, rho0 pi D^3/6]"),
    (["--rho0", "1e300"], "--rho0 must be in (0, 100000] kg/m^3, not 1e+300"),
]
GOOD = [["--porosity", "0", "--dx", "16e-6"], ["--porosity", "0.45", "--dx", "16e-6"],
        ["--dx", "16e-6", "--gap", "4e-6"],
        ["--dx", "16e-6", "--wall-dx", "80e-6", "--junction-gap", "10e-6"],
        ["--dx", "16e-6", "--wall-mass", "2.14466e-9"]]


if __name__ == "__main__":
    check([sys.argv[1]] + ["tissue", "--cells", "2", "2", "2"], CASES, GOOD, (1, 2))
