#!/usr/bin/env python3
"""potentials/README.md quotes the values of the parameter files: check every quote against them.

  potentials_readme.py POTENTIALS_DIR            check README.md against the *.cellsph files
  potentials_readme.py POTENTIALS_DIR --selftest check that each check fails when its quote is off

1. The Keys table: every row's apple-seed and apple columns equal the files' values (numbers as
   numbers, words as words; — for a key the file does not have), and the table has a row for
   every key of both files.
2. Numbers in the prose (QUOTES below): each pattern must occur exactly once in the README; a
   number copied from a file must equal it, a number derived from the files (a limit-point
   pressure, a pull, a cutoff) must equal the formula rounded to the digits quoted.
A README sentence rewritten so that a pattern no longer matches fails too: update QUOTES with it.
Exit status 0 if all agree; else each mismatch is printed as a FAIL line.
"""
import math
import os
import re
import sys
from decimal import Decimal

FILES = {"apple-seed": "apple-seed.cellsph", "apple": "apple.cellsph"}
LIMIT = 6.0 / 7.0 * 7.0 ** (-1.0 / 6.0)    # thin Neo-Hookean sphere: P_max = LIMIT 2 G t0 / R0
NUM = r"([0-9][0-9.]*(?:e-?[0-9]+)?)"


def exact(f):
    return (f, "exact")


def rounded(f):
    return (f, "rounded")


# (pattern with one group per number, file, [(value from the file's keys p, how compared)])
QUOTES = [
    (r"Table 1 with an effective wall thickness t0 = " + NUM + r" µm, so that the wall holds "
     + NUM + r" kPa", "apple",
     [exact(lambda p: p["wall_t0"] * 1e6), exact(lambda p: p["turgor_P"] / 1e3)]),
    (r"a wall–fluid range r0 = " + NUM + r" µm that keeps", "apple-seed",
     [exact(lambda p: p["wallfluid_r0"] * 1e6)]),
    (r"generate cells with `cellgen --gap " + NUM + r"`", "apple-seed",
     [exact(lambda p: p["wallfluid_r0"])]),
    (r"2\.5e-6 \(good\) and 2\.5e-7 \(too slow\); the values vary per run, " + NUM
     + r" is the\s+default here", "apple", [exact(lambda p: p["turgor_LP"])]),
    (r"2\.5e-6 \(good\) and 2\.5e-7 \(too slow\); the values vary per run, " + NUM
     + r" is the\s+default here", "apple-seed", [exact(lambda p: p["turgor_LP"])]),
    (r"fluid spacing 8\.75 µm with the gap r0 = " + NUM + r" µm of apple-seed\.cellsph",
     "apple-seed", [exact(lambda p: p["wallfluid_r0"] * 1e6)]),
    (r"With Table 1 \(G t0 = " + NUM + r" N/m,\s+R0 = " + NUM + r" µm\) that maximum is " + NUM
     + r" kPa: the seed's wall has no turgid equilibrium at its own\s+P_T = " + NUM + " kPa",
     "apple-seed",
     [rounded(lambda p: p["wall_G"] * p["wall_t0"]), exact(lambda p: p["cell_R0"] * 1e6),
      rounded(lambda p: LIMIT * 2 * p["wall_G"] * p["wall_t0"] / p["cell_R0"] / 1e3),
      exact(lambda p: p["turgor_P"] / 1e3)]),
    (r"Holding 200 kPa needs\s+G t0 >= " + NUM + r" kPa · " + NUM + r" µm / \(2 · 0\.6197\) = "
     + NUM + r" N/m, i\.e\. t0 >= " + NUM + r" µm at the seed's G = " + NUM + " MPa", "apple",
     [exact(lambda p: p["turgor_P"] / 1e3), exact(lambda p: p["cell_R0"] * 1e6),
      rounded(lambda p: p["turgor_P"] * p["cell_R0"] / (2 * LIMIT)),
      rounded(lambda p: p["turgor_P"] * p["cell_R0"] / (2 * LIMIT) / p["wall_G"] * 1e6),
      exact(lambda p: p["wall_G"] / 1e6)]),
    (r"With t0 = " + NUM + r" µm\s+\(G t0 = " + NUM + r" N/m\)", "apple",
     [exact(lambda p: p["wall_t0"] * 1e6), rounded(lambda p: p["wall_G"] * p["wall_t0"])]),
    (r"\(1/3\) dP/dlambda = 4 G t0 / R0 = " + NUM + " MPa", "apple",
     [rounded(lambda p: 4 * p["wall_G"] * p["wall_t0"] / p["cell_R0"] / 1e6)]),
    (r"F_load = P A / N_wall = " + NUM + r" kPa · 4 pi \(" + NUM + r" µm\)² / (1092) =\s+\*\*"
     + NUM + r" N\*\*", "apple",
     [exact(lambda p: p["turgor_P"] / 1e3), exact(lambda p: p["cell_R0"] * 1e6),
      exact(lambda p: 1092),
      rounded(lambda p: p["turgor_P"] * 4 * math.pi * p["cell_R0"] ** 2 / 1092)]),
    (r"r0 = " + NUM + r" µm, f0 = " + NUM + r" N m \(f0 ∝ r0", "apple-seed",
     [exact(lambda p: p["wallfluid_r0"] * 1e6), exact(lambda p: p["wallfluid_f0"])]),
    (r"rc = ra \+ " + NUM + r" µm = " + NUM + r" µm\s+reaches the first fluid layer", "apple-seed",
     [rounded(lambda p: (p["adhesion_rc"] - p["adhesion_ra"]) * 1e6),
      exact(lambda p: p["adhesion_rc"] * 1e6)]),
    (r"alpha = " + NUM + r" /m puts\s+the strongest pull at ra \+ ln2/alpha = " + NUM + " µm",
     "apple-seed",
     [exact(lambda p: p["adhesion_alpha"]),
      rounded(lambda p: (p["adhesion_ra"] + math.log(2) / p["adhesion_alpha"]) * 1e6)]),
    (r"D = " + NUM + r" J makes the peak pull alpha D / 2 = " + NUM + " N", "apple-seed",
     [exact(lambda p: p["adhesion_D"]),
      rounded(lambda p: p["adhesion_alpha"] * p["adhesion_D"] / 2)]),
    (r"sigma = " + NUM + r" µm puts the WCA cutoff 2\^\(1/6\) sigma = " + NUM + " µm", "apple",
     [exact(lambda p: p["wallwall_sigma"] * 1e6),
      rounded(lambda p: 2 ** (1 / 6) * p["wallwall_sigma"] * 1e6)]),
    (r"eps = " + NUM + r" J carries", "apple", [exact(lambda p: p["wallwall_eps"])]),
    (r"With `turgor_solids` = " + NUM + r" \(apple is about 14 % solids, wet basis\)\s+the fresh "
     r"cell's moisture content is X0 = \(1 − " + NUM + r"\)/" + NUM + r" = " + NUM + " kg/kg",
     "apple",
     [exact(lambda p: p["turgor_solids"]), exact(lambda p: p["turgor_solids"]),
      exact(lambda p: p["turgor_solids"]),
      rounded(lambda p: (1 - p["turgor_solids"]) / p["turgor_solids"])]),
    (r"Arrhenius with `turgor_Ea` = " + NUM + r" kJ/mol[\s\S]*?L_P at 60 °C is " + NUM
     + r" × its 25 °C value", "apple",
     [exact(lambda p: p["turgor_Ea"] / 1e3),
      rounded(lambda p: math.exp(-p["turgor_Ea"] / 8.314462618 * (1 / 333.15 - 1 / 298.15)))]),
    (r"Xm = " + NUM + r" kg/kg lies inside", "apple", [exact(lambda p: p["turgor_gab_Xm"])]),
    (r"C = " + NUM + r" and K = " + NUM + r" are typical", "apple",
     [exact(lambda p: p["turgor_gab_C"]), exact(lambda p: p["turgor_gab_K"])]),
    (r"equilibrium moisture content at a_w = 0\.3 is X = " + NUM + r" kg/kg, and a_w = 1 is "
     r"reached at\s+X = " + NUM + " kg/kg", "apple",
     [rounded(lambda p: gab(p, 0.3)), rounded(lambda p: gab(p, 1.0))]),
    (r"takes over from van 't Hoff at X = " + NUM + r" \(X/X0 = " + NUM + r"\) at any temperature",
     "apple", [rounded(lambda p: gab_takeover(p)),
               rounded(lambda p: gab_takeover(p) * p["turgor_solids"] / (1 - p["turgor_solids"]))]),
    (r"The strength\s+sigma_c = " + NUM + r" MPa sits", "apple",
     [exact(lambda p: p["lamella_sigma"] / 1e6)]),
    (r"The stiffness K = " + NUM + r" Pa/m is", "apple", [exact(lambda p: p["lamella_K"])]),
    (r"opens by sigma_c / K = " + NUM + " nm", "apple",
     [rounded(lambda p: p["lamella_sigma"] / p["lamella_K"] * 1e9)]),
    (r"A = √3/2 · \((8\.63) µm\)² = " + NUM + " m²", "apple",
     [exact(lambda p: 8.63), rounded(lambda p: math.sqrt(3) / 2 * 8.63e-6 ** 2)]),
    (r"A = √3/2 · \(8\.63 µm\)² = " + NUM + " m²", "apple", [exact(lambda p: p["lamella_area"])]),
    (r"k = K A = " + NUM + " N/m", "apple",
     [rounded(lambda p: p["lamella_K"] * p["lamella_area"])]),
    (r"breaks at sigma_c A = " + NUM + " N", "apple",
     [rounded(lambda p: p["lamella_sigma"] * p["lamella_area"])]),
]


def gab(p, a):
    """GAB isotherm X(a) of the file's turgor_gab_* keys (doc/model.md 5.10)."""
    y = p["turgor_gab_K"] * a
    return p["turgor_gab_Xm"] * p["turgor_gab_C"] * y / ((1 - y) * (1 - y + p["turgor_gab_C"] * y))


def gab_takeover(p):
    """X where the GAB sorption pressure -(R T/V_w) ln a(X) meets van 't Hoff's pi0 (T/Tref) X0/X
    (doc/model.md 5.10): T cancels; pi0 at Tref = 298.15 K (fix cell/turgor's default), bisection
    between X -> 0 (sorption larger) and X(a = 1) (sorption 0)."""
    r_vw = 8.314462618 / 18.07e-6 * 298.15     # R Tref / V_w (src/cell_water.h)
    x0 = (1 - p["turgor_solids"]) / p["turgor_solids"]
    xm, c, k = p["turgor_gab_Xm"], p["turgor_gab_C"], p["turgor_gab_K"]

    def excess(x):                              # sorption - van 't Hoff, both at Tref
        b = xm * c - x * (c - 2)
        a = 2 * x / (b + math.sqrt(b * b + 4 * x * x * (c - 1))) / k
        return -r_vw * math.log(a) - p["turgor_pi0"] * x0 / x

    lo, hi = 1e-6, gab(p, 1.0)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if excess(mid) > 0 else (lo, mid)
    return 0.5 * (lo + hi)


def read_params(path):
    params = {}
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].split()
            if line:
                params[line[0]] = line[1]
    return params


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def same_value(quoted, value):
    """A quoted table value equals the file's: as numbers if both are, else as words."""
    a, b = number(quoted), number(value)
    return a == b if a is not None and b is not None else quoted == value


def agrees(quoted, expected, how):
    q = Decimal(quoted)
    if how == "exact":
        return abs(float(q) - expected) <= 1e-12 * abs(expected)
    half = Decimal(10) ** q.as_tuple().exponent / 2    # half a unit of the last digit quoted
    return abs(float(q) - expected) <= float(half) * (1 + 1e-9)


def keys_table(readme):
    """The header and the rows of the Keys table ('| key | unit | ...'); None if absent."""
    lines = readme.splitlines()
    head = next((i for i, l in enumerate(lines) if l.startswith("| key | unit |")), None)
    if head is None:
        return None, []
    rows = []
    for line in lines[head + 2:]:
        if not line.startswith("|"):
            break
        rows.append(line)
    return lines[head], rows


def check_table(readme, params):
    failures = []
    header, rows = keys_table(readme)
    if header is None:
        return ["README has no '| key | unit | ...' table"]
    columns = [c.strip() for c in header.strip("|").split("|")]
    seen = set()
    for line in rows:
        cells = [c.strip() for c in line.strip("|").split("|")]
        keys = re.findall(r"`([a-zA-Z0-9_]+)`", cells[0])
        for name in FILES:
            quoted = [v.strip() for v in cells[columns.index(name)].split(",")]
            if len(quoted) != len(keys):
                failures.append(f"table row {keys}: {len(quoted)} values in column {name}")
                continue
            for key, value in zip(keys, quoted):
                seen.add(key)
                if value == "—":    # the file has no such key
                    if key in params[name]:
                        failures.append(f"table row '{key}', column {name}: README —, "
                                        f"{FILES[name]} {params[name][key]}")
                elif key not in params[name]:
                    failures.append(f"table row '{key}': not a key of {FILES[name]}")
                elif not same_value(value, params[name][key]):
                    failures.append(f"table row '{key}', column {name}: README {value}, "
                                    f"{FILES[name]} {params[name][key]}")
    for name in FILES:
        for key in sorted(set(params[name]) - seen):
            failures.append(f"{FILES[name]} key '{key}' has no row in the README's Keys table")
    return failures


def check_quotes(readme, params, quotes=QUOTES):
    failures = []
    for pattern, name, expect in quotes:
        found = list(re.finditer(pattern, readme))
        if len(found) != 1:
            failures.append(f"README quote /{pattern}/ found {len(found)} times, expected once "
                            "(sentence changed? update tests/potentials_readme.py)")
            continue
        values = {k: number(v) for k, v in params[name].items()}
        for k, (f, how) in enumerate(expect):
            quoted, expected = found[0].group(k + 1), f(values)
            if not agrees(quoted, expected, how):
                failures.append(f"README quotes {quoted} in '{found[0].group(0)}'; "
                                f"{FILES[name]} gives {expected:.6g} ({how})")
    return failures


def selftest(readme, params):
    """Each check must fail when the number it checks is off by one in its last digit."""
    problems = []
    count = 0

    def bump(text):    # the quoted number with its last digit changed
        digits = [i for i, c in enumerate(text) if c.isdigit()]
        i = digits[-1] if "e" not in text else text.index("e") - 1
        return text[:i] + str((int(text[i]) + 1) % 10) + text[i + 1:]

    for quote in QUOTES:
        m = re.search(quote[0], readme)
        if not m:
            problems.append(f"selftest: /{quote[0]}/ does not match the README")
            continue
        for g in range(1, len(m.groups()) + 1):
            wrong = readme[:m.start(g)] + bump(m.group(g)) + readme[m.end(g):]
            count += 1
            if not check_quotes(wrong, params, [quote]):
                problems.append(f"selftest: quote {m.group(g)} changed to {bump(m.group(g))} "
                                f"in '{m.group(0)}' was not caught")
    header, rows = keys_table(readme)
    columns = [c.strip() for c in header.split("|")]
    for line in rows:
        for name in FILES:
            cells = line.split("|")
            col = columns.index(name)
            if number(cells[col].split(",")[0]) is None:
                continue
            cells[col] = " " + bump(cells[col].strip()) + " "
            count += 1
            if not check_table(readme.replace(line, "|".join(cells)), params):
                problems.append(f"selftest: {name} column of '{line}' changed, not caught")
    print(f"selftest: {count} quoted numbers changed one at a time, "
          f"{count - len(problems)} caught")
    return problems


def main():
    if len(sys.argv) not in (2, 3) or (len(sys.argv) == 3 and sys.argv[2] != "--selftest"):
        sys.exit(__doc__)
    folder = sys.argv[1]
    with open(os.path.join(folder, "README.md")) as f:
        readme = f.read()
    params = {name: read_params(os.path.join(folder, file)) for name, file in FILES.items()}
    if len(sys.argv) == 3:
        failures = selftest(readme, params)
    else:
        failures = check_table(readme, params) + check_quotes(readme, params)
    for line in failures:
        print("FAIL", line)
    if not failures and len(sys.argv) == 3:
        print("PASS every changed number was caught")
    elif not failures:
        print("PASS potentials/README.md agrees with", ", ".join(FILES.values()))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
