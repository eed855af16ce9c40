#!/usr/bin/env python3
"""Does a cell wall pass through itself? Tests every pair of wall triangles for intersection.

  wall_self_intersection.py DATA DUMP [--out FILE] [--quiet]
  wall_self_intersection.py --selftest

DATA is the cellsph data file (tools/cellgen, or write_data): its Angles section gives the wall
triangles a b c (atom IDs). DUMP is a LAMMPS text dump (`dump ID wall custom N FILE id x y z`, or
`xu yu zu`; any number of snapshots) holding at least the wall atoms. For each snapshot it prints
the timestep and the number of intersecting triangle pairs, and writes the largest count over all
snapshots to FILE (`--out`, one number: for `variable n file FILE` in a LAMMPS input). Exit status
0 when no snapshot has an intersection, 1 when one has, 2 on bad input.

The test. Two triangles that share no vertex intersect (generic position: not coplanar) exactly
when an edge of one crosses the other: the intersection of two non-coplanar triangles is a segment
whose ends lie on edges of the triangles. So each pair costs six segment-triangle tests
(Moller & Trumbore 1997), each strict: a crossing must lie inside the triangle and inside the
edge by more than a relative 1e-9 of the edge length. Two triangles sharing one vertex intersect
beyond that vertex when the edge opposite it in one crosses the other (tested, the same way); two
sharing an edge (wall neighbours) are skipped: they could only meet by folding flat onto each
other, which the wall's bending and contact forbid long before. Not detected: crossings exactly on an
edge or vertex (measure zero for simulated positions; the constructed cases avoid symmetry planes). Candidate pairs come from a
uniform grid of cell size the longest triangle extent, their bounding boxes overlapping. A closed
wall that does not cross itself gives 0; a wall pushed through itself gives a positive count
(--selftest builds both). Standard library only.
"""
import math
import sys

from lammps_dump import positions, read_triangles, snapshots


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


EPS = 1e-9


def segment_crosses(p, q, a, b, c):
    """True if the segment p-q crosses the triangle a b c strictly inside both (Moller-Trumbore)"""
    d = sub(q, p)
    e1, e2 = sub(b, a), sub(c, a)
    s = cross(d, e2)
    det = dot(e1, s)
    scale = math.sqrt(dot(d, d) * dot(e1, e1) * dot(e2, e2))
    if abs(det) <= 1e-12 * scale:
        return False    # parallel (or coplanar: not detected, see the header)
    inv = 1.0 / det
    w = sub(p, a)
    u = dot(w, s) * inv
    if u <= EPS or u >= 1 - EPS:
        return False
    r = cross(w, e1)
    v = dot(d, r) * inv
    if v <= EPS or u + v >= 1 - EPS:
        return False
    t = dot(e2, r) * inv
    return EPS < t < 1 - EPS


def triangles_intersect(ta, tb, x):
    """ta, tb: vertex ID triples; x: positions"""
    shared = set(ta) & set(tb)
    if len(shared) >= 2:
        return False
    pa = [x[i] for i in ta]
    pb = [x[i] for i in tb]
    if not shared:
        for (u, v) in ((0, 1), (1, 2), (2, 0)):
            if segment_crosses(pa[u], pa[v], *pb) or segment_crosses(pb[u], pb[v], *pa):
                return True
        return False
    s = shared.pop()
    oa = [x[i] for i in ta if i != s]
    ob = [x[i] for i in tb if i != s]
    return segment_crosses(oa[0], oa[1], *pb) or segment_crosses(ob[0], ob[1], *pa)


def count_intersections(tris, x):
    boxes = []
    ext = 0.0
    for t in tris:
        p = [x[i] for i in t]
        lo = tuple(min(q[k] for q in p) for k in range(3))
        hi = tuple(max(q[k] for q in p) for k in range(3))
        boxes.append((lo, hi))
        ext = max(ext, max(hi[k] - lo[k] for k in range(3)))
    if ext <= 0:
        return 0
    grid = {}
    for n, (lo, hi) in enumerate(boxes):
        i0 = [math.floor(lo[k] / ext) for k in range(3)]
        i1 = [math.floor(hi[k] / ext) for k in range(3)]
        for i in range(i0[0], i1[0] + 1):
            for j in range(i0[1], i1[1] + 1):
                for k in range(i0[2], i1[2] + 1):
                    grid.setdefault((i, j, k), []).append(n)
    seen = set()
    hits = 0
    for members in grid.values():
        for ia in range(len(members)):
            a = members[ia]
            la, ha = boxes[a]
            for b in members[ia + 1:]:
                key = (a, b) if a < b else (b, a)
                if key in seen:
                    continue
                seen.add(key)
                lb, hb = boxes[b]
                if any(ha[k] < lb[k] or hb[k] < la[k] for k in range(3)):
                    continue
                if triangles_intersect(tris[a], tris[b], x):
                    hits += 1
    return hits


def icosphere(level):
    """a closed, outward triangulated unit sphere (the subdivided icosahedron): positions, triangles"""
    g = (1 + 5 ** 0.5) / 2
    v = [(-1, g, 0), (1, g, 0), (-1, -g, 0), (1, -g, 0), (0, -1, g), (0, 1, g), (0, -1, -g),
         (0, 1, -g), (g, 0, -1), (g, 0, 1), (-g, 0, -1), (-g, 0, 1)]
    v = [tuple(c / math.sqrt(dot(p, p)) for c in p) for p in v]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
         (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9),
         (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(level):
        mid = {}

        def m(i, j):
            key = (min(i, j), max(i, j))
            if key not in mid:
                p = tuple((v[i][k] + v[j][k]) / 2 for k in range(3))
                r = math.sqrt(dot(p, p))
                v.append(tuple(c / r for c in p))
                mid[key] = len(v) - 1
            return mid[key]
        nf = []
        for a, b, c in f:
            ab, bc, ca = m(a, b), m(b, c), m(c, a)
            nf += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        f = nf
    x = {i + 1: p for i, p in enumerate(v)}
    return x, [(a + 1, b + 1, c + 1) for a, b, c in f]


def selftest():
    """constructed cases: each must give the expected answer, or the test fails"""
    ok = True

    def check(what, got, want):
        nonlocal ok
        good = (got > 0) == want
        ok &= good
        print(f"{'PASS' if good else 'FAIL'} {what}: {got} intersecting pairs")
    x, tris = icosphere(2)
    check("closed sphere (162 vertices, 320 triangles)", count_intersections(tris, x), False)
    top = max(x, key=lambda i: x[i][2])
    dent = dict(x)
    dent[top] = (0.07, 0.11, 0.2)    # pushed in, not through the far side: a dent
    check("sphere dented to 0.2 R", count_intersections(tris, dent), False)
    through = dict(x)
    through[top] = (0.07, 0.11, -1.3)    # pushed through the opposite wall (off the mesh's symmetry planes)
    check("one vertex pushed through the opposite wall", count_intersections(tris, through), True)
    # two separate triangles crossing like a chain link, and one pair that only touch at a vertex
    xy = {1: (0, 0, 0), 2: (1, 0, 0), 3: (0, 1, 0), 4: (0.2, 0.2, -0.5), 5: (0.2, 0.2, 0.5),
          6: (1.5, 1.5, 0.3)}
    check("two crossing triangles", count_intersections([(1, 2, 3), (4, 5, 6)], xy), True)
    xy2 = dict(xy)
    xy2.update({4: (2, 2, -0.5), 5: (2, 2, 0.5)})
    check("two separate triangles", count_intersections([(1, 2, 3), (4, 5, 6)], xy2), False)
    # triangles sharing a vertex: folded through each other, and merely hinged
    xs = {1: (0, 0, 0), 2: (1, 0, 0), 3: (0, 1, 0), 4: (0.3, 0.35, -0.5), 5: (0.2, 0.15, 0.5)}
    check("two triangles sharing a vertex, one through the other",
          count_intersections([(1, 2, 3), (1, 4, 5)], xs), True)
    xs.update({4: (-0.6, -0.6, -0.5), 5: (-0.4, -0.3, 0.5)})
    check("two triangles sharing a vertex, apart", count_intersections([(1, 2, 3), (1, 4, 5)], xs), False)
    return 0 if ok else 1


def main(argv):
    if argv[1:] == ["--selftest"]:
        return selftest()
    args = [a for a in argv[1:] if not a.startswith("--")]
    out = None
    if "--out" in argv:
        out = argv[argv.index("--out") + 1]
        args.remove(out)
    if len(args) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    tris = read_triangles(args[0])
    worst, nsnap = 0, 0
    for step, cols, rows in snapshots(args[1]):
        pos = positions(cols, rows, args[1])
        missing = [i for t in tris for i in t if i not in pos]
        if missing:
            raise SystemExit(f"wall_self_intersection: step {step}: wall atom {missing[0]} not in the dump")
        n = count_intersections(tris, pos)
        nsnap += 1
        worst = max(worst, n)
        if "--quiet" not in argv:
            print(f"step {step}: {n} intersecting triangle pairs")
    if nsnap == 0:
        raise SystemExit(f"wall_self_intersection: {args[1]} has no snapshot")
    print(f"{nsnap} snapshots, {len(tris)} triangles: at most {worst} intersecting triangle pairs")
    if out:
        with open(out, "w") as f:
            f.write(f"{worst}\n")
    return 1 if worst else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
