#!/usr/bin/env python3
"""Write a LAMMPS data file of N tiny cells for bench/cell_reduction.sh.

  cell_reduction.py N OUT        prints the number of cells and of those split between 2 ranks

Each cell is the coarsest closed cell there is: a regular tetrahedron of 4 wall atoms (type 2,
4 outward wall triangles as angles) around 1 fluid atom (type 1), molecule ID = cell ID. The
cells sit on a cubic lattice of spacing a = 10 um in a periodic box of n x n x m sites, lattice
sites at multiples of a, so that the cells of the plane x = 0 straddle the periodic boundary and
those of the mid-plane x = n a / 2 the boundary between 2 ranks cut in x.
"""
import sys

A = 1e-5          # lattice spacing (m)
S = 0.15 * A      # tetrahedron corner offset: corners at (+-S, +-S, +-S), edge 2 sqrt(2) S


def main():
    n_cells, out = int(sys.argv[1]), sys.argv[2]
    n = 1
    while (n + 1) ** 3 <= n_cells:
        n += 1
    # n x n x m sites, m planes of n x n; the count is the nearest to N with m >= 1
    m = max(1, round(n_cells / (n * n)))
    corners = [(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)]
    faces = []
    for k in range(4):
        f = [j for j in range(4) if j != k]
        a, b, c = (corners[j] for j in f)
        u = [b[d] - a[d] for d in range(3)]
        w = [c[d] - a[d] for d in range(3)]
        nrm = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
        # outward: the normal points away from the centre, i.e. along a (the centre is 0)
        if sum(nrm[d] * a[d] for d in range(3)) < 0:
            f[1], f[2] = f[2], f[1]
        faces.append(f)
    ncell = n * n * m
    atoms, angles = [], []
    cell = 0
    for k in range(m):
        for j in range(n):
            for i in range(n):
                cell += 1
                base = len(atoms)
                x0 = (i * A, j * A, k * A)
                for cx in corners:
                    atoms.append((cell, 2, [x0[d] + S * cx[d] for d in range(3)]))
                atoms.append((cell, 1, list(x0)))
                for f in faces:
                    angles.append([base + 1 + v for v in f])
    lo = 0.0
    # cells whose atoms (wrapped into the box) lie on both sides of x = L/2, the cut of 2 ranks
    half, split = 0.5 * n * A, 0
    for k in range(0, len(atoms), 5):
        sides = {((x[0] - lo) % (n * A)) < half for _, _, x in atoms[k:k + 5]}
        split += len(sides) > 1
    with open(out, "w") as fp:
        fp.write(f"{ncell} tiny cells (bench/speed/cell_reduction.py)\n\n")
        fp.write(f"{len(atoms)} atoms\n2 atom types\n{len(angles)} angles\n1 angle types\n\n")
        fp.write(f"{lo} {lo + n * A} xlo xhi\n{lo} {lo + n * A} ylo yhi\n")
        fp.write(f"{lo} {lo + m * A} zlo zhi\n\nMasses\n\n1 1e-12\n2 1e-12\n\nAtoms # angle\n\n")
        for t, (mol, typ, x) in enumerate(atoms, 1):
            fp.write(f"{t} {mol} {typ} {x[0]:.10g} {x[1]:.10g} {x[2]:.10g}\n")
        fp.write("\nAngles\n\n")
        for t, (a, b, c) in enumerate(angles, 1):
            fp.write(f"{t} 1 {a} {b} {c}\n")
    print(ncell, split)


if __name__ == "__main__":
    main()
