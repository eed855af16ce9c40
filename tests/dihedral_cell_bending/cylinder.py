#!/usr/bin/env python3
"""Write a LAMMPS data file (atom_style molecular) of a triangulated cylinder wall, periodic in z,
for the bending tests: N particles around at radius R, a nearly equilateral triangular lattice,
M rows along z in a periodic box (ring: M rings dz = (sqrt 3 / 2) s apart, s the chord between
neighbours of a ring, every other ring turned by half a step; axial: N lines along z of M points
2 s / sqrt 3 apart, every other line shifted by half a point). One dihedral per edge, a b c d with (a, b, c) and (d, c, b) the triangles
sharing the edge b-c, both with outward normal (b - a) x (c - a). Ends with the CellAtoms section
(rmass xref(3) aref) that cellsph inputs read with 'fix cellatoms ... CellAtoms'.

  usage: cylinder.py N M R FILE [ring|axial]
  ring (default): edges along the circumference; axial: edges along the axis (N, M even)
"""
import math
import sys


def main():
    n, m, radius, path = int(sys.argv[1]), int(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
    orientation = sys.argv[5] if len(sys.argv) > 5 else "ring"
    if n < 6 or m < 4 or n % 2 or m % 2 or orientation not in ("ring", "axial"):
        sys.exit("cylinder.py: need even N >= 6, even M >= 4, orientation ring or axial")
    step = 2 * math.pi / n
    # a triangular lattice of rows (every other row shifted by half a point), periodic both ways;
    # ring: rows are rings of N points, dz = (sqrt 3 / 2) x the chord of a ring step apart;
    # axial: rows are N lines along z, points a = 2 R sin(step / 2) / (sqrt 3 / 2) apart
    chord = 2 * radius * math.sin(step / 2)
    if orientation == "ring":
        rows, per_row, dz = m, n, math.sqrt(3) / 2 * chord
        length = m * dz
    else:
        rows, per_row, dz = n, m, chord / (math.sqrt(3) / 2)
        length = m * dz

    def index(r, p):
        return (r % rows) * per_row + (p % per_row)

    pos = []
    for r in range(rows):
        for p in range(per_row):
            t = p + 0.5 * (r % 2)
            phi, z = ((t * step, (r + 0.5) * dz) if orientation == "ring" else
                      (r * step, (t + 0.5) * dz))
            pos.append((radius * math.cos(phi), radius * math.sin(phi), z))

    def outward(t):
        a, b, c = (pos[k] for k in t)
        d1 = [b[0] - a[0], b[1] - a[1], b[2] - a[2]]
        d2 = [c[0] - a[0], c[1] - a[1], c[2] - a[2]]
        for d in (d1, d2):    # minimum image along the periodic z
            d[2] -= length * round(d[2] / length)
        nrm = (d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2],
               d1[0] * d2[1] - d1[1] * d2[0])
        return nrm[0] * a[0] + nrm[1] * a[1] > 0    # along the radial direction of a

    tris = []
    for j in range(rows):
        for i in range(per_row):
            if j % 2 == 0:
                pair = [(index(j, i), index(j, i + 1), index(j + 1, i)),
                        (index(j + 1, i), index(j, i + 1), index(j + 1, i + 1))]
            else:
                pair = [(index(j, i), index(j, i + 1), index(j + 1, i + 1)),
                        (index(j + 1, i), index(j, i), index(j + 1, i + 1))]
            for t in pair:
                tris.append(t if outward(t) else (t[0], t[2], t[1]))

    apex = {}
    for t in tris:
        for k in range(3):
            apex[(t[k], t[(k + 1) % 3])] = t[(k + 2) % 3]
    dihedrals = [(apex[(b, c)], b, c, apex[(c, b)]) for (b, c) in apex if b < c]
    assert len(dihedrals) == 3 * n * m and len(apex) == 6 * n * m

    with open(path, "w") as f:
        f.write(f"cylinder {orientation} N={n} M={m} R={radius!r} L={length!r} periodic in z\n\n")
        f.write(f"{n * m} atoms\n{len(dihedrals)} dihedrals\n1 atom types\n1 dihedral types\n\n")
        f.write(f"{-2 * radius!r} {2 * radius!r} xlo xhi\n{-2 * radius!r} {2 * radius!r} ylo yhi\n")
        f.write(f"0 {length!r} zlo zhi\n\nMasses\n\n1 1e-13\n\nAtoms # molecular\n\n")
        for k, p in enumerate(pos):
            f.write(f"{k + 1} 1 1 {p[0]!r} {p[1]!r} {p[2]!r}\n")
        f.write("\nDihedrals\n\n")
        for k, q in enumerate(dihedrals):
            f.write(f"{k + 1} 1 {q[0] + 1} {q[1] + 1} {q[2] + 1} {q[3] + 1}\n")
        f.write("\nCellAtoms # rmass xref(3) aref\n\n")
        for k, p in enumerate(pos):
            f.write(f"{k + 1} 1e-13 {p[0]!r} {p[1]!r} {p[2]!r} 0\n")
    print(f"cylinder.py: N={n} M={m} R={radius} L={length} dihedrals={len(dihedrals)}")


if __name__ == "__main__":
    main()
