#!/usr/bin/env python3
"""Area of each cell's wall triangles whose three corners lie above a plane, from a cellgen data file.

  exposed_area.py DATA AXIS CUT OUT

AXIS is x, y or z; a corner is above when its coordinate > CUT. Writes OUT: per cell in ascending
ID, its total wall area, then its exposed area (m^2), one number a line (LAMMPS's 'variable file'
reads a line per 'next'): the independent value that tests/fix_cell_turgor/
surface_group_dries_through_its_triangles_only.in compares fix cell/turgor's 'air ... surface' with.
"""
import sys


def sections(path):
    lines = open(path).read().split("\n")
    found, name = {}, None
    for line in lines:
        words = line.split("#")[0].split()
        if len(words) == 1 and words[0][0].isupper() and not words[0][0].isdigit():
            name = words[0]
            found[name] = []
        elif name and words:
            found[name].append(words)
    return found


def main(data, axis, cut, out):
    k = "xyz".index(axis)
    sec = sections(data)
    atoms = {int(w[0]): (int(w[1]), [float(v) for v in w[3:6]]) for w in sec["Atoms"]}
    total, exposed = {}, {}
    for w in sec["Angles"]:
        (cell, a), (_, b), (_, c) = (atoms[int(t)] for t in w[2:5])
        u = [b[d] - a[d] for d in range(3)]
        v = [c[d] - a[d] for d in range(3)]
        n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
        area = 0.5 * sum(x * x for x in n) ** 0.5
        total[cell] = total.get(cell, 0.0) + area
        if min(a[k], b[k], c[k]) > float(cut):
            exposed[cell] = exposed.get(cell, 0.0) + area
    with open(out, "w") as f:
        for cell in sorted(total):
            f.write(f"{total[cell]:.17g}\n{exposed.get(cell, 0.0):.17g}\n")


if __name__ == "__main__":
    main(*sys.argv[1:5])
