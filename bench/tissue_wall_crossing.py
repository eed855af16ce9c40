#!/usr/bin/env python3
"""Walls of a tissue crossed into their neighbours (examples/tissue/README.md, Why a less
accelerated drying goes unstable): for each snapshot of a LAMMPS dump (columns id mol type x y z,
all atoms, periodic in x and y), the wall atoms of each cell that lie inside another cell's closed
wall, by the winding number of that cell's wall triangles (the data file's angles, as compute
cell/props column 16 does for fluid atoms).
  python3 bench/tissue_wall_crossing.py tissue.data settle.dump [walltype]
prints per snapshot: step, wall atoms inside another cell, of them with a junction bond (bond type
2), and the largest count for one (inside, intruder) pair of cells."""
import math
import sys


def read_data(path):
    """triangles (angles) and the atoms of junction bonds (bond type 2) of a cellgen data file"""
    tri, junction, sec = [], set(), None
    for line in open(path):
        s = line.split("#")[0].strip()
        if not s:
            continue
        if s[0].isalpha():
            sec = s.split()[0]
            continue
        p = s.split()
        if sec == "Angles":
            tri.append(tuple(int(v) for v in p[2:5]))
        elif sec == "Bonds" and p[1] == "2":
            junction.update((int(p[2]), int(p[3])))
    return tri, junction


def snapshots(path):
    """(step, box lengths x y, {id: (mol, type, x, y, z)}) of each snapshot"""
    with open(path) as f:
        lines = iter(f.read().splitlines())
    for line in lines:
        if not line.startswith("ITEM: TIMESTEP"):
            continue
        step = int(next(lines))
        next(lines)
        n = int(next(lines))
        next(lines)
        box = [[float(v) for v in next(lines).split()[:2]] for _ in range(3)]
        cols = next(lines).split()[2:]
        k = [cols.index(c) for c in ("id", "mol", "type", "x", "y", "z")]
        atoms = {}
        for _ in range(n):
            r = next(lines).split()
            atoms[int(r[k[0]])] = (int(float(r[k[1]])), int(r[k[2]]), float(r[k[3]]), float(r[k[4]]), float(r[k[5]]))
        yield step, (box[0][1] - box[0][0], box[1][1] - box[1][0]), atoms


def unwrap(tris, atoms, box):
    """the wall atoms of one cell's triangles, each placed by minimum image next to a mesh neighbour"""
    adj = {}
    for a, b, c in tris:
        for u, v in ((a, b), (b, c), (c, a)):
            adj.setdefault(u, set()).add(v)
            adj.setdefault(v, set()).add(u)
    start = next(iter(adj))
    pos = {start: list(atoms[start][2:])}
    todo = [start]
    while todo:
        u = todo.pop()
        for v in adj[u]:
            if v not in pos:
                q = list(atoms[v][2:])
                for d in range(2):
                    q[d] -= box[d] * round((q[d] - pos[u][d]) / box[d])
                pos[v] = q
                todo.append(v)
    return pos


def winding(p, tris, pos):
    """sum of the triangles' solid angles about p over 4 pi (Van Oosterom & Strackee 1983)"""
    s = 0.0
    for t in tris:
        r = [[pos[v][d] - p[d] for d in range(3)] for v in t]
        n = [math.sqrt(sum(x * x for x in v)) for v in r]
        dot = lambda u, v: sum(u[d] * v[d] for d in range(3))
        cr = (r[1][1] * r[2][2] - r[1][2] * r[2][1], r[1][2] * r[2][0] - r[1][0] * r[2][2],
              r[1][0] * r[2][1] - r[1][1] * r[2][0])
        den = n[0] * n[1] * n[2] + dot(r[0], r[1]) * n[2] + dot(r[0], r[2]) * n[1] + dot(r[1], r[2]) * n[0]
        s += 2.0 * math.atan2(dot(r[0], cr), den)
    return s / (4.0 * math.pi)


def crossed(atoms, box, tri, walltype, reach=40e-6):
    """{(cell, intruder cell): [wall atom ids of the intruder inside the cell's wall]}"""
    cells = sorted({a[0] for a in atoms.values() if a[1] == walltype})
    out = {}
    for c in cells:
        tris = [t for t in tri if t[0] in atoms and atoms[t[0]][0] == c]
        pos = unwrap(tris, atoms, box)
        lo = [min(p[d] for p in pos.values()) - reach for d in range(3)]
        hi = [max(p[d] for p in pos.values()) + reach for d in range(3)]
        for i, (mol, typ, x, y, z) in atoms.items():
            if mol == c or typ != walltype:
                continue
            for ix in (-1, 0, 1):
                for iy in (-1, 0, 1):
                    q = (x + ix * box[0], y + iy * box[1], z)
                    if not all(lo[d] <= q[d] <= hi[d] for d in range(3)):
                        continue
                    if min(sum((q[d] - p[d]) ** 2 for d in range(3)) for p in pos.values()) > reach**2:
                        continue
                    if abs(winding(q, tris, pos)) > 0.5:
                        out.setdefault((c, mol), []).append(i)
    return out


def main():
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    tri, junction = read_data(sys.argv[1])
    walltype = int(sys.argv[3]) if len(sys.argv) > 3 else 2
    print("# step, wall atoms inside another cell, of them with a junction bond, largest (cell <- intruder): count")
    for step, box, atoms in snapshots(sys.argv[2]):
        out = crossed(atoms, box, tri, walltype)
        ids = [i for v in out.values() for i in v]
        top = max(out.items(), key=lambda kv: len(kv[1])) if out else None
        print(step, len(ids), sum(1 for i in ids if i in junction),
              f"{top[0][0]} <- {top[0][1]}: {len(top[1])}" if top else "-", flush=True)


if __name__ == "__main__":
    main()
