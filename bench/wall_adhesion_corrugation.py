#!/usr/bin/env python3
"""Scan points for bench/wall_adhesion_corrugation.lmp: directions from the cell centre (a
Fibonacci sphere of N points), each put at depth d inside the triangulated wall of a cellgen data
file (along the ray: r = r_surface - d), written as LAMMPS create_atoms lines.
   wall_adhesion_corrugation.py cell.data N d out.lmp
With 'table log...' it instead reduces the per-atom energies of the runs (see the .sh)."""
import math
import sys


def read_data(path):
    atoms, angles, sec = {}, [], None
    for line in open(path):
        s = line.split("#")[0].split()
        if not s:
            continue
        if s[0] in ("Atoms", "Angles", "Bonds", "Masses", "CellAtoms", "Velocities", "Dihedrals"):
            sec = s[0]
            continue
        if sec == "Atoms" and len(s) >= 6:
            atoms[int(s[0])] = (int(s[2]), [float(v) for v in s[3:6]])
        elif sec == "Angles" and len(s) == 5:
            angles.append([int(v) for v in s[2:5]])
    return atoms, angles


def ray_hit(u, tri):
    """distance t > 0 along unit u from the origin to triangle tri (3 points), or None"""
    a, b, c = tri
    e1 = [b[k] - a[k] for k in range(3)]
    e2 = [c[k] - a[k] for k in range(3)]
    p = [u[1] * e2[2] - u[2] * e2[1], u[2] * e2[0] - u[0] * e2[2], u[0] * e2[1] - u[1] * e2[0]]
    det = sum(e1[k] * p[k] for k in range(3))
    if abs(det) < 1e-30:
        return None
    s = [-a[k] for k in range(3)]
    uu = sum(s[k] * p[k] for k in range(3)) / det
    if uu < -1e-12 or uu > 1 + 1e-12:
        return None
    q = [s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2], s[0] * e1[1] - s[1] * e1[0]]
    vv = sum(u[k] * q[k] for k in range(3)) / det
    if vv < -1e-12 or uu + vv > 1 + 1e-12:
        return None
    t = sum(e2[k] * q[k] for k in range(3)) / det
    return t if t > 0 else None


def main():
    path, n, d, out = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
    atoms, angles = read_data(path)
    tris = [[atoms[i][1] for i in t] for t in angles]
    golden = math.pi * (3.0 - math.sqrt(5.0))
    with open(out, "w") as f:
        for k in range(n):
            z = 1.0 - 2.0 * (k + 0.5) / n
            r = math.sqrt(1.0 - z * z)
            u = [r * math.cos(golden * k), r * math.sin(golden * k), z]
            t = min(h for h in (ray_hit(u, tri) for tri in tris) if h is not None)
            f.write("create_atoms 1 single %.17g %.17g %.17g units box\n" % tuple(u[j] * (t - d) for j in range(3)))


if __name__ == "__main__":
    main()
