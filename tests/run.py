#!/usr/bin/env python3
"""Run one cellsph test: a LAMMPS input whose '#:' header lines say how to run and judge it.

  #: ranks 1 2                      run on each of these MPI rank counts (default: 1)
  #: var NAME VALUE                 pass -var NAME VALUE to every run
  #: compare FILE RTOL ATOL         FILE must agree between all rank counts, number by number
  #: same FILE_A FILE_B RTOL ATOL   two files of one run must agree (e.g. before/after restart)
  #: error MESSAGE | NAME=VALUE ... a run with these -var settings must stop with an ERROR line
                                    containing MESSAGE (one line per bad input; a file with error
                                    lines runs only these)
A normal run passes if LAMMPS exits 0, prints no ERROR and no FAIL line, and prints a PASS line
(from tests/check.lmp) or the test has compare/same lines. Needs LMP (the lmp to run) in the
environment; CELLGEN and WRONGPLUGIN become -var cellgen/wrongplugin, MPIEXEC is used when set.
"""
import os
import re
import shutil
import subprocess
import sys

ENV = dict(os.environ, OMPI_MCA_rmaps_base_oversubscribe="1")
if os.geteuid() == 0:    # Open MPI refuses to run as root unless told it may
    ENV.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def directives(path):
    spec = {"ranks": ["1"], "var": [], "compare": [], "same": [], "error": []}
    with open(path) as f:
        for line in f:
            if not line.startswith("#:"):
                continue
            key, _, rest = line[2:].strip().partition(" ")
            if key == "ranks":
                spec["ranks"] = rest.split()
            elif key == "error":
                message, _, assigns = rest.rpartition(" | ")
                spec["error"].append((message.strip(), [a.split("=", 1) for a in assigns.split()]))
            elif key in spec:
                spec[key].append(rest.split())
            else:
                sys.exit(f"{path}: unknown directive '#: {key}'")
    return spec


def run_lammps(inp, workdir, ranks, variables):
    os.makedirs(workdir, exist_ok=True)
    cmd = [os.environ["LMP"], "-in", inp, "-log", "log.lammps", "-echo", "screen"]
    if int(ranks) > 1:
        cmd = [os.environ.get("MPIEXEC", "mpirun"), "-np", ranks] + cmd
    for name, value in variables:
        cmd += ["-var", name, value]
    proc = subprocess.run(cmd, cwd=workdir, env=ENV, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True)
    return proc.returncode, proc.stdout


def numbers(path):
    with open(path) as f:
        return [tok for line in f for tok in line.split()]


def files_agree(a, b, rtol, atol):
    for path in (a, b):
        if not os.path.exists(path):
            return f"{path} was not written"
    ta, tb = numbers(a), numbers(b)
    if len(ta) != len(tb):
        return f"{a} and {b} differ in length ({len(ta)} vs {len(tb)} fields)"
    worst = 0.0
    for x, y in zip(ta, tb):
        try:
            fx, fy = float(x), float(y)
        except ValueError:
            if x != y:
                return f"{a} and {b} differ: '{x}' vs '{y}'"
            continue
        if fx != fx or fy != fy:
            return f"NaN in {a} or {b}"
        err = abs(fx - fy)
        if err > atol + rtol * max(abs(fx), abs(fy)):
            return f"{a} and {b} differ: {fx!r} vs {fy!r} (|diff| {err:.3g})"
        worst = max(worst, err / max(abs(fx), abs(fy), 1e-300))
    print(f"PASS {a} == {b} (largest relative difference {worst:.3g})")
    return None


def main():
    inp = os.path.abspath(sys.argv[1])
    tests = os.path.dirname(os.path.abspath(__file__))
    name = os.path.splitext(os.path.relpath(inp, tests))[0]
    base = os.path.join(os.environ.get("CELLSPH_TEST_DIR", os.getcwd()), name)
    shutil.rmtree(base, ignore_errors=True)
    spec = directives(inp)
    common = [("testdir", tests)] + [(v[0], " ".join(v[1:])) for v in spec["var"]]
    for name in ("cellgen", "wrongplugin"):
        if os.environ.get(name.upper()):
            common.append((name, os.environ[name.upper()]))
    failures = []

    for k, (message, assigns) in enumerate(spec["error"]):
        code, out = run_lammps(inp, os.path.join(base, f"error{k}"), "1", common + assigns)
        errors = [l for l in out.splitlines() if l.startswith("ERROR")]
        if code == 0 or not any(message in l for l in errors):
            failures.append(f"bad input {assigns} should stop with '{message}'; got: {errors or 'no error'}")
        else:
            print(f"PASS bad input {assigns}: {errors[0]}")
    if spec["error"]:
        return report(failures)

    dirs = {}
    for ranks in spec["ranks"]:
        workdir = os.path.join(base, f"np{ranks}")
        code, out = run_lammps(inp, workdir, ranks, common)
        dirs[ranks] = workdir
        lines = out.splitlines()
        bad = [l for l in lines if l.startswith(("ERROR", "FAIL")) or "nan" in l.split()]
        print("\n".join(l for l in lines if l.startswith(("PASS", "FAIL", "ERROR"))))
        if code != 0 or bad:
            failures.append(f"{ranks} rank(s): exit code {code}; " + "; ".join(bad[:5]))
        elif not any(l.startswith("PASS") for l in lines) and not (spec["compare"] or spec["same"]):
            failures.append(f"{ranks} rank(s): no PASS line (the test checked nothing)")
        for fa, fb, rtol, atol in spec["same"]:
            msg = files_agree(os.path.join(workdir, fa), os.path.join(workdir, fb),
                              float(rtol), float(atol))
            if msg:
                failures.append(f"{ranks} rank(s): {msg}")
    for fname, rtol, atol in spec["compare"]:
        first = dirs[spec["ranks"][0]]
        for ranks in spec["ranks"][1:]:
            msg = files_agree(os.path.join(first, fname), os.path.join(dirs[ranks], fname),
                              float(rtol), float(atol))
            if msg:
                failures.append(msg)
    return report(failures)


def report(failures):
    for f in failures:
        print("FAIL", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
