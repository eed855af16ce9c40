#!/usr/bin/env python3
"""cellgen --fluid-lattice shells (tools/cellgen/README.md, Fluid): checks the data files against the
cubic start of the same options, per cell: the same fluid count and masses; the outermost shell at
R - G and no fluid atom beyond it nor outside the wall (every triangle's plane); the shells one
spacing s apart from R - G down to the centre and their slabs filling the ball of radius R - G + s/2
at one number density (each shell within 3 % of N / V_fill); V_fill within 6 % of the cell volume;
the smallest distance between two fluid atoms at least 0.8 s; the same file for the same seed and
other rotations for another; bad options refused. Prints the numbers it checks.
  usage: test_fluid_shells.py path/to/cellgen"""
import math
import os
import subprocess
import sys
import tempfile

cellgen = sys.argv[1]
tmp = tempfile.mkdtemp()
failures = []


def check(ok, what):
    print(("  ok: " if ok else "  FAIL: ") + what)
    if not ok:
        failures.append(what)


def run(args, name):
    path = os.path.join(tmp, name)
    out = subprocess.run([cellgen, *args, "--out", path], capture_output=True, text=True)
    return path, out


def read(path):
    """comment line's R/DX/gap, per-cell fluid and wall positions, fluid masses, triangles"""
    lines = open(path).read().split("\n")
    head = dict(w.split("=") for w in lines[0].split("|")[-1].split() if "=" in w)
    section, atoms, tris, masses = None, {}, [], {}
    for line in lines[1:]:
        w = line.split()
        if not w:
            continue
        if w[0] in ("Masses", "Atoms", "Bonds", "Angles", "CellAtoms", "Dihedrals"):
            section = w[0]
            continue
        if section == "Atoms":
            atoms[int(w[0])] = (int(w[1]), int(w[2]), tuple(float(v) for v in w[3:6]))
        elif section == "Angles":
            tris.append(tuple(int(v) for v in w[2:5]))
        elif section == "CellAtoms":
            masses[int(w[0])] = float(w[1])
    cells = {}
    for i, (mol, typ, x) in atoms.items():
        c = cells.setdefault(mol, {"fluid": [], "wall": [], "mass": []})
        if typ == 1:
            c["fluid"].append(x)
            c["mass"].append(masses[i])
        else:
            c["wall"].append(x)
    return head, cells, atoms, tris


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def norm(a):
    return math.sqrt(a[0] ** 2 + a[1] ** 2 + a[2] ** 2)


def centre(points):
    return tuple(sum(p[d] for p in points) / len(points) for d in range(3))


def nearest(points, cut):
    """smallest distance between two points (bins of size cut; pairs beyond cut not seen)"""
    bins = {}
    for i, p in enumerate(points):
        bins.setdefault(tuple(int(math.floor(v / cut)) for v in p), []).append(i)
    best = math.inf
    for key, members in bins.items():
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    for j in bins.get((key[0] + dx, key[1] + dy, key[2] + dz), []):
                        for i in members:
                            if i < j:
                                best = min(best, norm(sub(points[i], points[j])))
    return best


def shells_of(radii, tol):
    """distinct radii (within tol) from the outside in, with their counts"""
    out = []
    for r in sorted(radii, reverse=True):
        if out and out[-1][0] - r < tol:
            out[-1][1] += 1
        else:
            out.append([r, 1])
    return out


def check_case(label, args):
    print(f"{label}: cellgen {' '.join(args)}")
    cub, out_c = run(args, "cubic.data")
    shl, out_s = run(args + ["--fluid-lattice", "shells"], "shells.data")
    check(out_c.returncode == 0 and out_s.returncode == 0, f"cellgen ran ({out_s.stderr.strip()})")
    if out_s.returncode != 0:
        return
    head, cells, atoms, tris = read(shl)
    _, cubic, _, _ = read(cub)
    R, G = float(head["R"]), float(head["gap"])
    for mol, c in sorted(cells.items()):
        fl, wall = c["fluid"], c["wall"]
        n = len(fl)
        check(n == len(cubic[mol]["fluid"]), f"cell {mol}: {n} fluid atoms, as the cubic start's {len(cubic[mol]['fluid'])}")
        check(all(abs(m / cm - 1) < 1e-12 for m, cm in zip(c["mass"], cubic[mol]["mass"])),
              f"cell {mol}: the fluid masses of the cubic start ({c['mass'][0]:.6g} kg)")
        xc = centre(wall)
        Rk = sum(norm(sub(w, xc)) for w in wall) / len(wall)    # this cell's radius
        radii = [norm(sub(x, xc)) for x in fl]
        outer = Rk - G
        check(abs(max(radii) - outer) < 1e-9 * Rk,
              f"cell {mol}: outermost shell at {max(radii) * 1e6:.4f} um = R - G = {outer * 1e6:.4f} um")
        # no atom outside the wall: inside every triangle's plane, by at least G / 2
        depth = math.inf
        for a, b, cc in tris:
            if atoms[a][0] != mol:
                continue
            pa, pb, pc = atoms[a][2], atoms[b][2], atoms[cc][2]
            u, v = sub(pb, pa), sub(pc, pa)
            nrm = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
            ln = norm(nrm)
            for x in fl:
                depth = min(depth, -sum(nrm[d] * (x[d] - pa[d]) for d in range(3)) / ln)
        check(depth > 0.5 * G, f"cell {mol}: every fluid atom {depth * 1e6:.3f} um or more inside every wall triangle (> G/2)")
        sh = shells_of(radii, 1e-9 * Rk)
        gaps = [sh[k][0] - sh[k + 1][0] for k in range(len(sh) - 1)]
        s = gaps[0] if gaps else 2 * outer
        check(all(abs(g - s) < 1e-9 * Rk for g in gaps) and sh[-1][0] < 0.51 * s,
              f"cell {mol}: {len(sh)} shells, {s * 1e6:.4f} um apart, the innermost at {sh[-1][0] * 1e6:.4f} um")
        fill = outer + 0.5 * s
        vfill = 4 / 3 * math.pi * fill ** 3
        vcell = 4 / 3 * math.pi * Rk ** 3
        check(abs(vfill / vcell - 1) < 0.06, f"cell {mol}: fill volume / cell volume = {vfill / vcell:.4f}")
        worst = 0.0
        for r, count in sh:
            lo, hi = max(r - 0.5 * s, 0.0), r + 0.5 * s
            if r > 0.51 * s:    # the centre point and the innermost shell are a handful of atoms
                worst = max(worst, abs(count / (4 / 3 * math.pi * (hi ** 3 - lo ** 3)) / (n / vfill) - 1))
        check(worst < 0.03, f"cell {mol}: number density of every shell within {worst * 100:.2f} % of N / V_fill")
        d = nearest(fl, 1.5 * s)
        # (0.816 s: four atoms in a ball of radius s, the innermost shell's tetrahedron at r = s/2)
        check(d >= 0.8 * s, f"cell {mol}: smallest fluid distance {d * 1e6:.3f} um = {d / s:.3f} s")


check_case("seed resolution", [])
check_case("coarse", ["--nwall", "300", "--nfluid", "450"])
check_case("fine", ["--nwall", "2562", "--nfluid", "3900"])
check_case("two cells of other radii", ["--nwall", "300", "--nfluid", "450", "--cells", "2", "1", "1",
                                        "--radius-spread", "0.2", "--seed", "3"])

print("seeds")
a, _ = run(["--nwall", "300", "--nfluid", "450", "--fluid-lattice", "shells"], "a.data")
b, _ = run(["--nwall", "300", "--nfluid", "450", "--fluid-lattice", "shells"], "b.data")
c, _ = run(["--nwall", "300", "--nfluid", "450", "--fluid-lattice", "shells", "--seed", "2"], "c.data")
body = lambda p: open(p).read().split("\n", 1)[1]
check(body(a) == body(b), "the same seed writes the same file")
fa, fc = read(a)[1][1]["fluid"], read(c)[1][1]["fluid"]
check(sorted(round(norm(x) * 1e12) for x in fa) == sorted(round(norm(x) * 1e12) for x in fc) and fa != fc,
      "another seed turns the shells (same radii, other positions)")

print("bad options")
for bad, message in ((["--fluid-lattice", "hex"], "--fluid-lattice must be cubic or shells"),
                     (["--fluid-lattice", "shells", "--elongation", "1.45"], "needs a spherical cell")):
    _, out = run(bad, "bad.data")
    check(out.returncode == 2 and message in out.stderr, f"{' '.join(bad)} refused: {out.stderr.splitlines()[0] if out.stderr else ''}")

print("FAILED: " + "; ".join(failures) if failures else "all checks passed")
sys.exit(1 if failures else 0)
