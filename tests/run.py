#!/usr/bin/env python3
"""Run one cellsph test: a LAMMPS input whose '#:' header lines say how to run and judge it.

  #: ranks 1 2                      run on each of these MPI rank counts (default: 1)
  #: var NAME VALUE                 pass -var NAME VALUE to every run
  #: compare FILE RTOL ATOL         FILE must agree between all rank counts, number by number
  #: same FILE_A FILE_B RTOL ATOL   two files of one run must agree (e.g. before/after restart)
  #: error MESSAGE | NAME=VALUE ... a run with these -var settings must stop with an ERROR line
                                    containing MESSAGE (one line per bad input; a file with error
                                    lines runs only these)
  #: time SECONDS                   the test's normal run time on an idle 2-core machine (required
                                    for a test that runs on 2 or more ranks): its LAMMPS runs are
                                    killed, and the test fails, once they take longer than
                                    3 x SECONDS + 30 s in all, so that a hang fails within a few
                                    times the normal run time
  #: label NAME ...                 ctest labels besides the automatic ones (fast: the quick
                                    subset, `ctest -L fast`)
A normal run passes if LAMMPS exits 0 and prints no ERROR line and no NaN, and the checks of
tests/check.lmp, which it writes to checks.txt in the run's folder, hold at least one PASS line and
no FAIL line (or the test has compare/same lines instead). The screen is searched for no verdict:
the output of a command run by "shell" can interleave with LAMMPS's echo mid-line. Needs LMP (the
lmp to run) in the environment; CELLGEN and WRONGPLUGIN become -var cellgen/wrongplugin, MPIEXEC
is used when set. `run.py --selftest` checks the harness itself on six tiny inputs.
"""
import os
import pty
import re
import select
import shutil
import signal
import subprocess
import sys
import time

ENV = dict(os.environ, OMPI_MCA_rmaps_base_oversubscribe="1")
if os.geteuid() == 0:    # Open MPI refuses to run as root unless told it may
    ENV.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def directives(path):
    spec = {"ranks": ["1"], "var": [], "compare": [], "same": [], "error": [], "time": None,
            "label": []}
    with open(path) as f:
        for line in f:
            if not line.startswith("#:"):
                continue
            key, _, rest = line[2:].strip().partition(" ")
            if key == "ranks":
                spec["ranks"] = rest.split()
            elif key == "time":
                spec["time"] = float(rest)
            elif key == "label":
                spec["label"] += rest.split()
            elif key == "error":
                message, _, assigns = rest.rpartition(" | ")
                spec["error"].append((message.strip(), [a.split("=", 1) for a in assigns.split()]))
            elif key in spec:
                spec[key].append(rest.split())
            else:
                sys.exit(f"{path}: unknown directive '#: {key}'")
    return spec


# the moment (time.monotonic()) after which a test's LAMMPS runs are killed (#: time), or None
DEADLINE = None
TIMED_OUT = 124    # the exit code run_lammps gives a run it killed at the deadline


def left():
    return None if DEADLINE is None else max(DEADLINE - time.monotonic(), 0.0)


def kill(proc):
    """End a run and everything it started: mpirun puts each rank in a process group of its own,
    but all stay in the session the run leads."""
    try:
        os.killpg(proc.pid, signal.SIGKILL)
    except ProcessLookupError:
        pass
    subprocess.run(["pkill", "-KILL", "-s", str(proc.pid)])


def run_lammps(inp, workdir, ranks, variables, terminal=False):
    """Run LAMMPS; with terminal=True its output goes to a pseudo-terminal, so that it is
    line-buffered: since 2024 an error on one rank (error->one) ends LAMMPS in MPI_Abort, which
    loses whatever a pipe's buffer still holds, the error message included. A run still going at
    DEADLINE is killed with its ranks and gives TIMED_OUT."""
    os.makedirs(workdir, exist_ok=True)
    cmd = [os.environ["LMP"], "-in", inp, "-log", "log.lammps", "-echo", "screen"]
    if int(ranks) > 1:
        cmd = [os.environ.get("MPIEXEC", "mpirun"), "-np", ranks] + cmd
    for name, value in variables:
        cmd += ["-var", name, value]
    if not terminal:
        proc = subprocess.Popen(cmd, cwd=workdir, env=ENV, stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, text=True, start_new_session=True)
        try:
            out, _ = proc.communicate(timeout=left())
        except subprocess.TimeoutExpired:
            kill(proc)
            out, _ = proc.communicate()
            return TIMED_OUT, out
        return proc.returncode, out
    master, slave = pty.openpty()
    proc = subprocess.Popen(cmd, cwd=workdir, env=ENV, stdin=subprocess.DEVNULL, stdout=slave,
                            stderr=slave, start_new_session=True)
    os.close(slave)
    chunks = []
    timed_out = False
    while True:
        wait = left()
        if wait is not None and (wait <= 0 or not select.select([master], [], [], wait)[0]):
            kill(proc)
            timed_out = True
            break
        try:
            chunk = os.read(master, 65536)
        except OSError:    # EIO: the terminal's last writer has gone
            break
        if not chunk:
            break
        chunks.append(chunk)
    os.close(master)
    out = b"".join(chunks).decode(errors="replace").replace("\r\n", "\n")
    code = proc.wait()
    return (TIMED_OUT if timed_out else code), out


def is_nan(token):
    return token.lower().lstrip("+-") == "nan"


def verdicts(path):
    """The PASS and FAIL lines tests/check.lmp appended to this run's checks.txt."""
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [l.rstrip("\n") for l in f if l.startswith(("PASS", "FAIL"))]


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


def main(inp):
    inp = os.path.abspath(inp)
    tests = os.path.dirname(os.path.abspath(__file__))
    name = os.path.splitext(os.path.basename(inp))[0] if SELFTEST else \
        os.path.splitext(os.path.relpath(inp, tests))[0]
    base = os.path.join(os.environ.get("CELLSPH_TEST_DIR", os.getcwd()), name)
    shutil.rmtree(base, ignore_errors=True)
    spec = directives(inp)
    global DEADLINE
    DEADLINE = limit = None
    if spec["time"] is not None:    # #: time S: every run of the test together within 3 S + slack
        limit = 3.0 * spec["time"] + float(os.environ.get("CELLSPH_TIME_SLACK", "30"))
        DEADLINE = time.monotonic() + limit
    with open(inp) as f:
        quoted = [l.strip() for l in f if re.match(r"\s*variable\s+check\s+string.*'", l)]
    if quoted:    # check.lmp prints the name inside single quotes: newer LAMMPS stops there
        return report([f"a check name holds a single quote: {q}" for q in quoted])
    common = [("testdir", tests)] + [(v[0], " ".join(v[1:])) for v in spec["var"]]
    for name in ("cellgen", "wrongplugin"):
        if os.environ.get(name.upper()):
            common.append((name, os.environ[name.upper()]))
    failures = []

    for k, (message, assigns) in enumerate(spec["error"]):
        code, out = run_lammps(inp, os.path.join(base, f"error{k}"), "1", common + assigns,
                               terminal=True)
        errors = [l for l in out.splitlines() if l.startswith("ERROR")]
        if code == TIMED_OUT:
            return report([hung(limit, spec)])
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
        if code == TIMED_OUT:
            print(out[-2000:])
            return report([f"{ranks} rank(s): " + hung(limit, spec)])
        lines = out.splitlines()
        checks = verdicts(os.path.join(workdir, "checks.txt"))
        bad = [l for l in lines if l.startswith("ERROR") or any(is_nan(t) for t in l.split())]
        bad += [l for l in checks if l.startswith("FAIL")]
        print("\n".join([l for l in lines if l.startswith("ERROR")] + checks))
        if code != 0 or bad:
            failures.append(f"{ranks} rank(s): exit code {code}; " + "; ".join(bad[:5]))
        elif not any(l.startswith("PASS") for l in checks) and not (spec["compare"] or spec["same"]):
            failures.append(f"{ranks} rank(s): no PASS line in checks.txt (the test checked nothing)")
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


def hung(limit, spec):
    return (f"killed after {limit:.0f} s, 3 x its normal run time ({spec['time']:g} s, '#: time') "
            "+ slack: a hang (a rank waiting for a message that never comes) or a far slower machine")


def report(failures):
    for f in failures:
        print("FAIL", f)
    return 1 if failures else 0


# --selftest: the harness itself on six tiny inputs. A verdict printed on the screen only (as a
# "shell" command's output could) decides nothing; a failed check, a missing check, a NaN and a
# hang fail.
SELFTEST = False
CASES = {
    "screen_fail_line_is_ignored": (0, 'print "FAIL decoy on the screen"\n'
                                       'variable check string "one is one"\n'
                                       'variable value equal 1\nvariable limit equal 1\n'),
    "failed_check_fails": (1, 'variable check string "two is not one"\n'
                              'variable value equal 2\nvariable limit equal 1\n'),
    "failed_check_after_a_passed_one_fails": (1, 'variable check string "one is one"\n'
                                                 'variable value equal 1\nvariable limit equal 1\n'
                                                 'include CHECK\n'
                                                 'variable check string "two is not one"\n'
                                                 'variable value equal 2\n'),
    "no_check_fails": (1, 'print "PASS decoy on the screen"\n'),
    # rank 0 sleeps in "shell" while rank 1 waits for it in the next collective: the test is
    # killed, both ranks with it, at 3 x its '#: time' (CELLSPH_TIME_SLACK=0 here)
    "hang_on_2_ranks_is_killed_at_3_times_its_time": (1, '#: ranks 2\n#: time 1\n'
                                                         'shell sleep 60\n'
                                                         'variable check string "one is one"\n'
                                                         'variable value equal 1\n'
                                                         'variable limit equal 1\n'),
    "nan_fails": (1, 'variable x equal 1e308*10-1e308*10\nprint "x = $x"\n'
                     'variable check string "one is one"\n'
                     'variable value equal 1\nvariable limit equal 1\n'),
}


def selftest():
    import tempfile
    global SELFTEST
    SELFTEST = True
    tests = os.path.dirname(os.path.abspath(__file__))
    wrong = []
    with tempfile.TemporaryDirectory() as tmp:
        os.environ["CELLSPH_TEST_DIR"] = tmp
        os.environ["CELLSPH_TIME_SLACK"] = "0"
        for name, (want, body) in CASES.items():
            inp = os.path.join(tmp, name + ".in")
            check = f"include {tests}/check.lmp\n"
            with open(inp, "w") as f:
                f.write(body.replace("include CHECK\n", check) + (check if "check string" in body else ""))
            start = time.monotonic()
            got = main(inp)
            took = time.monotonic() - start
            # a killed run leaves no process behind (mpirun, its ranks, the sleep); on loaded cores
            # a killed process can take a moment to exit, so look again for up to 5 s
            for _ in range(50):
                left_over = subprocess.run(["pgrep", "-f", inp], stdout=subprocess.PIPE,
                                           text=True).stdout
                if not left_over.strip():
                    break
                time.sleep(0.1)
            ok = got == want and not left_over.strip() and took < 30
            print(f"{'PASS' if ok else 'FAIL'} selftest {name}: exit {got}, expected {want}, "
                  f"{took:.1f} s, processes left: {left_over.split() or 'none'}")
            if not ok:
                wrong.append(name)
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(selftest() if sys.argv[1:] == ["--selftest"] else main(sys.argv[1]))
