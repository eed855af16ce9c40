#!/usr/bin/env python3
"""The size limits of DEVELOPERS.md, checked on the repository (argument: its root):
every source file in src/ under 1000 lines, every function there under 100 (a body is counted from
its '{' at column 0 to its '}' at column 0, as clang-format lays out a function), every style page
doc/*.md (not doc/model.md) at most 300 lines, every examples/*/README.md at most 150, and no
tracker issue number ("issue 31") in the docs, notes, examples, tests or sources.
`structure_limits.py --selftest` shows each check failing on a made-up tree."""
import pathlib
import re
import sys
import tempfile

ISSUE = re.compile(r"(?<![A-Za-z])issues? #?\d+", re.IGNORECASE)


def functions(path):
    """(length, first line) of each column-0 function body of a C++ file."""
    out, start = [], None
    for k, line in enumerate(path.read_text().splitlines()):
        if line.startswith("{") and start is None:
            start = k
        elif line.startswith("}") and start is not None:
            out.append((k - start + 1, start + 1))
            start = None
    return out


def check(root):
    root = pathlib.Path(root)
    bad = []
    for f in sorted((root / "src").glob("*.[ch]*")):
        n = len(f.read_text().splitlines())
        if n >= 1000:
            bad.append(f"{f.relative_to(root)}: {n} lines (limit 999)")
        if f.suffix == ".cpp":
            for length, line in functions(f):
                if length > 100:
                    bad.append(f"{f.relative_to(root)}:{line}: a function of {length} lines (limit 100)")
    for f in sorted((root / "doc").glob("*.md")):
        n = len(f.read_text().splitlines())
        if f.name != "model.md" and n > 300:
            bad.append(f"{f.relative_to(root)}: {n} lines (a style page: limit 300)")
    for f in sorted((root / "examples").glob("*/README.md")):
        n = len(f.read_text().splitlines())
        if n > 150:
            bad.append(f"{f.relative_to(root)}: {n} lines (an example README: limit 150)")
    for pattern in ("doc/**/*.md", "examples/**/*", "tests/**/*.in", "src/*", "README.md", "DEVELOPERS.md"):
        for f in sorted(root.glob(pattern)):
            if f.is_file() and f.suffix in (".md", ".in", ".cpp", ".h", ".lmp", ".py", ".sh", ""):
                for k, line in enumerate(f.read_text(errors="replace").splitlines()):
                    if ISSUE.search(line):
                        bad.append(f"{f.relative_to(root)}:{k + 1}: a tracker issue number: {line.strip()[:80]}")
    return bad


def selftest():
    """Each limit on a made-up tree: the check must name it."""
    cases = {
        "src/long.cpp": ("x\n" * 1000, "1000 lines"),
        "src/f.cpp": ("void f()\n{\n" + "  ;\n" * 100 + "}\n", "a function of 102 lines"),
        "doc/pair_x.md": ("x\n" * 301, "a style page"),
        "examples/e/README.md": ("x\n" * 151, "an example README"),
        "doc/notes/n.md": ("as issue 31 says\n", "a tracker issue number"),
    }
    wrong = 0
    for path, (text, expect) in cases.items():
        with tempfile.TemporaryDirectory() as tmp:
            for d in ("src", "doc", "examples"):
                pathlib.Path(tmp, d).mkdir()
            f = pathlib.Path(tmp, path)
            f.parent.mkdir(parents=True, exist_ok=True)
            f.write_text(text)
            found = check(tmp)
            ok = any(expect in b for b in found)
            print(f"{'PASS' if ok else 'FAIL'} selftest {path}: {found or 'nothing found'}")
            wrong += not ok
    with tempfile.TemporaryDirectory() as tmp:
        for d in ("src", "doc", "examples"):
            pathlib.Path(tmp, d).mkdir()
        pathlib.Path(tmp, "doc/x.md").write_text("a tissue 13/13 and the issues of drying\n")
        found = check(tmp)
        print(f"{'PASS' if not found else 'FAIL'} selftest: 'tissue 13' is no issue number: {found or 'nothing found'}")
        wrong += bool(found)
    return 1 if wrong else 0


if __name__ == "__main__":
    if sys.argv[1:2] == ["--selftest"]:
        sys.exit(selftest())
    problems = check(sys.argv[1])
    for p in problems:
        print("FAIL", p)
    print(f"{'PASS' if not problems else 'FAIL'} size limits and no issue numbers: {len(problems)} problems")
    sys.exit(1 if problems else 0)
