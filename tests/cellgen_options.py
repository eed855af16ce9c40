"""Shared by the cellgen option tests: each bad option list must stop cellgen with an exit status
in `codes`, its message on stderr and no data file; each good one must write its file."""
import os
import subprocess
import sys
import tempfile


def check(command, cases, good, codes):
    """command: cellgen and the arguments every case shares (before --out); cases: (args,
    message) pairs that must fail; good: argument lists that must succeed. Exits 1 on a failure."""
    def run(args, out):
        return subprocess.run(command + ["--out", out] + args, stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, text=True)

    failed = 0
    with tempfile.TemporaryDirectory() as tmp:
        for i, (args, message) in enumerate(cases):
            out = os.path.join(tmp, f"bad{i}.data")
            p = run(args, out)
            ok = p.returncode in codes and message in p.stderr and not os.path.exists(out)
            print(("PASS" if ok else "FAIL"), " ".join(args), "->", p.returncode,
                  p.stderr.strip().splitlines()[0] if p.stderr.strip() else "(no message)")
            failed += not ok
        for i, args in enumerate(good):
            out = os.path.join(tmp, f"good{i}.data")
            p = run(args, out)
            ok = p.returncode == 0 and os.path.exists(out)
            print(("PASS" if ok else "FAIL"), " ".join(args), "accepted ->", p.returncode,
                  p.stderr.strip())
            failed += not ok
    sys.exit(1 if failed else 0)
