#!/usr/bin/env python3
"""A closed, outward wall whose section by the plane z through its centre is a star polygon:

  star_prism.py N R r H OUT

the prism of height H over the N-pointed star with tips at radius R (angles 2 pi k / N) and notches
at radius r (angles between), centred at the origin: 4 N side atoms (each star vertex at z = -H/2
and +H/2), one centre atom per cap, the side quads split into two triangles and each cap a fan from
its centre, every triangle an angle a b c with (b - a) x (c - a) outward; one fluid atom at the
centre. Every side quad is a vertical rectangle, so the section by z = 0 is the star exactly.
Written as the atom_style angle data file OUT with the CellAtoms section of tools/cellgen (rmass,
xref, aref)."""
import math
import sys


def main(n, big, small, height, out):
    star = [(big if k % 2 == 0 else small) * f(math.pi * k / n) for k in range(2 * n)
            for f in (math.cos, math.sin)]
    pts = [(star[2 * k], star[2 * k + 1]) for k in range(2 * n)]
    atoms = [(0.0, 0.0, 0.0)]                                          # 1: fluid
    atoms += [(x, y, -height / 2) for x, y in pts]                     # 2 .. 2n+1: bottom
    atoms += [(x, y, height / 2) for x, y in pts]                      # 2n+2 .. 4n+1: top
    atoms += [(0.0, 0.0, -height / 2), (0.0, 0.0, height / 2)]         # cap centres
    m = 2 * n
    bot = [2 + k for k in range(m)]
    top = [2 + m + k for k in range(m)]
    cb, ct = 2 + 2 * m, 3 + 2 * m
    tris = []
    for k in range(m):
        j = (k + 1) % m
        # side: (B_k, B_j, T_j) and (B_k, T_j, T_k), normal e x z outward for a counter-clockwise star
        tris += [(bot[k], bot[j], top[j]), (bot[k], top[j], top[k])]
        # caps: normal +z on top, -z below
        tris += [(ct, top[k], top[j]), (cb, bot[j], bot[k])]
    ext = 1.5 * max(big, height)
    with open(out, "w") as f:
        f.write(f"star prism N={n} R={big} r={small} H={height}\n\n{len(atoms)} atoms\n"
                f"{len(tris)} angles\n2 atom types\n1 angle types\n\n")
        for a in "xyz":
            f.write(f"{-ext} {ext} {a}lo {a}hi\n")
        f.write("\nMasses\n\n1 1e-12\n2 1e-13\n\nAtoms # angle\n\n")
        for i, (x, y, z) in enumerate(atoms, 1):
            f.write(f"{i} 1 {1 if i == 1 else 2} {x!r} {y!r} {z!r}\n")
        f.write("\nAngles\n\n")
        for i, (a, b, c) in enumerate(tris, 1):
            f.write(f"{i} 1 {a} {b} {c}\n")
        f.write("\nCellAtoms # rmass xref(3) aref\n\n")
        for i, (x, y, z) in enumerate(atoms, 1):
            f.write(f"{i} {1e-12 if i == 1 else 1e-13} {x!r} {y!r} {z!r} 0\n")


if __name__ == "__main__":
    main(int(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]), sys.argv[5])
