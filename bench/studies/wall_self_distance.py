#!/usr/bin/env python3
"""How near does a cell wall come to itself? The range of pair cell/wall selftriangles.

  bench/studies/wall_self_distance.py DATA DUMP [--range R]

DATA is the cellsph data file (its Angles section: the wall triangles a b c, outward), DUMP a
LAMMPS text dump of the wall atoms (`id x y z`, any number of snapshots). For each snapshot it
prints the wall edges (min, mean, max), the smallest distance from a wall atom to a triangle of
its 2-ring (triangles that share a vertex with the atom's own triangles but not the atom: on a
smooth wall about a triangle height), the smallest distance to a triangle farther out (3-ring and
beyond: a fold), and, with --range R (m), the number of wall atoms within R of a triangle they are
not a vertex of and how many of them are behind the face of their nearest such triangle (the
selftriangles stop, doc/pair_cell_wall.md). Closest point: Ericson 2005 §5.1.5. Standard library.
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from lammps_dump import positions, read_triangles, snapshots    # noqa: E402


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def closest(p, a, b, c):
    """closest point of triangle a b c to p and whether it is inside the face (Ericson 5.1.5)"""
    ab, ac, ap = sub(b, a), sub(c, a), sub(p, a)
    d1, d2 = dot(ab, ap), dot(ac, ap)
    if d1 <= 0 and d2 <= 0:
        return a, False
    bp = sub(p, b)
    d3, d4 = dot(ab, bp), dot(ac, bp)
    if d3 >= 0 and d4 <= d3:
        return b, False
    vc = d1 * d4 - d3 * d2
    if vc <= 0 and d1 >= 0 and d3 <= 0:
        v = d1 / (d1 - d3)
        return (a[0] + v * ab[0], a[1] + v * ab[1], a[2] + v * ab[2]), False
    cp = sub(p, c)
    d5, d6 = dot(ab, cp), dot(ac, cp)
    if d6 >= 0 and d5 <= d6:
        return c, False
    vb = d5 * d2 - d1 * d6
    if vb <= 0 and d2 >= 0 and d6 <= 0:
        w = d2 / (d2 - d6)
        return (a[0] + w * ac[0], a[1] + w * ac[1], a[2] + w * ac[2]), False
    va = d3 * d6 - d5 * d4
    if va <= 0 and (d4 - d3) >= 0 and (d5 - d6) >= 0:
        w = (d4 - d3) / ((d4 - d3) + (d5 - d6))
        return (b[0] + w * (c[0] - b[0]), b[1] + w * (c[1] - b[1]), b[2] + w * (c[2] - b[2])), False
    den = 1.0 / (va + vb + vc)
    v, w = vb * den, vc * den
    return (a[0] + ab[0] * v + ac[0] * w, a[1] + ab[1] * v + ac[1] * w,
            a[2] + ab[2] * v + ac[2] * w), True


def main(argv):
    args = [a for a in argv if not a.startswith("--")]
    rng = float(argv[argv.index("--range") + 1]) if "--range" in argv else None
    if rng is not None:
        args.remove(argv[argv.index("--range") + 1])
    data, dump = args
    tris = read_triangles(data)
    ids = sorted({v for t in tris for v in t})
    ring1 = {i: set() for i in ids}    # triangles of each atom
    for k, t in enumerate(tris):
        for v in t:
            ring1[v].add(k)
    ring2 = {}
    for i in ids:
        verts = {v for k in ring1[i] for v in tris[k]}
        ring2[i] = {k for v in verts for k in ring1[v]} - ring1[i]
    print("# step edge_min edge_mean edge_max d_2ring_min d_far_min"
          + (" within_range behind" if rng else ""))
    for step, cols, rows in snapshots(dump):
        x = positions(cols, rows, dump)
        edges = []
        for a, b, c in tris:
            for p, q in ((a, b), (b, c), (c, a)):
                if p < q:
                    edges.append(math.dist(x[p], x[q]))
        lmax = max(edges)
        cell = 2.5 * lmax
        grid = {}
        for k, t in enumerate(tris):
            lo = [min(x[v][d] for v in t) for d in range(3)]
            hi = [max(x[v][d] for v in t) for d in range(3)]
            for gx in range(math.floor(lo[0] / cell), math.floor(hi[0] / cell) + 1):
                for gy in range(math.floor(lo[1] / cell), math.floor(hi[1] / cell) + 1):
                    for gz in range(math.floor(lo[2] / cell), math.floor(hi[2] / cell) + 1):
                        grid.setdefault((gx, gy, gz), []).append(k)
        d2min = dfar = math.inf
        within = behind = 0
        for i in ids:
            p = x[i]
            g = tuple(math.floor(p[d] / cell) for d in range(3))
            near = set()
            for dx in (-1, 0, 1):
                for dy in (-1, 0, 1):
                    for dz in (-1, 0, 1):
                        near.update(grid.get((g[0] + dx, g[1] + dy, g[2] + dz), ()))
            best = None
            for k in near - ring1[i]:
                a, b, c = (x[v] for v in tris[k])
                q, face = closest(p, a, b, c)
                d = math.dist(p, q)
                if k in ring2[i]:
                    d2min = min(d2min, d)
                else:
                    dfar = min(dfar, d)
                if rng and d < rng and (best is None or d < best[0]):
                    best = (d, face and dot(cross(sub(b, a), sub(c, a)), sub(p, q)) <= 0)
            if best:
                within += 1
                behind += best[1]
        line = f"{step} {min(edges):.4g} {sum(edges) / len(edges):.4g} {lmax:.4g} {d2min:.4g} {dfar:.4g}"
        print(line + (f" {within} {behind}" if rng else ""))


if __name__ == "__main__":
    main(sys.argv[1:])
