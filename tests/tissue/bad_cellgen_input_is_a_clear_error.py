#!/usr/bin/env python3
"""cellgen tissue refuses bad input with a message naming the option and the value, exit status 1
or 2, and no data file: porosity outside [0, 0.5) (0.5, 0.7, -0.1, 1e-9 below 0, not a number) and
cells too small for the resolution (--size 40e-6 --dx 10e-6; the default 160 um cells at
--dx 30e-6 and at --dx 16e-6 with a --junction-gap of 40e-6). The edges of the range are accepted:
porosity 0 and 0.45 write the files. Usage: bad_cellgen_input_is_a_clear_error.py CELLGEN
"""
import os
import subprocess
import sys
import tempfile

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
]
GOOD = [["--porosity", "0", "--dx", "16e-6"], ["--porosity", "0.45", "--dx", "16e-6"]]


def run(cellgen, args, out):
    cmd = [cellgen, "tissue", "--cells", "2", "2", "2", "--out", out] + args
    return subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def main(cellgen):
    failed = 0
    with tempfile.TemporaryDirectory() as tmp:
        for i, (args, message) in enumerate(CASES):
            out = os.path.join(tmp, f"bad{i}.data")
            p = run(cellgen, args, out)
            ok = p.returncode in (1, 2) and message in p.stderr and not os.path.exists(out)
            print(("PASS" if ok else "FAIL"), " ".join(args), "->", p.returncode,
                  p.stderr.strip().splitlines()[0] if p.stderr.strip() else "(no message)")
            failed += not ok
        for i, args in enumerate(GOOD):
            out = os.path.join(tmp, f"good{i}.data")
            p = run(cellgen, args, out)
            ok = p.returncode == 0 and os.path.exists(out)
            print(("PASS" if ok else "FAIL"), " ".join(args), "accepted ->", p.returncode)
            failed += not ok
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main(sys.argv[1])
