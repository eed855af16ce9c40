#!/usr/bin/env python3
"""Contact patch of a cell wall pressed by a flat plate, from a LAMMPS dump of the wall atoms.

  contact_area.py DATAFILE DUMPFILE [OUTFILE]

(OUTFILE ending in .lmp: LAMMPS 'variable NAME equal VALUE' lines for the last frame instead, NAME =
n_lo A_in_lo A_trib_lo A_out_lo A_hull_lo and the same with _hi, for 'include OUTFILE'.)

DATAFILE: a LAMMPS data file with the wall triangles as angles (a b c, tools/cellgen, write_data).
DUMPFILE: dump custom of the wall atoms 'id x y z touch' (touch = 0 free, 1 lower plate, 2 upper
plate: the atom is pressed by that plate), any number of frames. Writes one line per frame:

  step  n_lo A_in_lo A_trib_lo A_out_lo A_hull_lo  n_hi A_in_hi A_trib_hi A_out_hi A_hull_hi

n: wall atoms in contact; areas (m^2) projected on the plate (the xy plane):
  A_in   triangles whose three corners touch: the patch the contacting atoms span (a lower bound
         of the contact patch: the contact line lies beyond its outer ring of contacting atoms)
  A_out  triangles with at least one corner touching (an upper bound: the contact line lies before
         the first ring of free atoms)
  A_trib each triangle counted with the fraction of its corners that touch, sum over triangles of
         (n_touch/3) A: the tributary area of the contacting atoms, i.e. the share of a uniform
         pressure on the triangles that is lumped onto them (each corner of a triangle carries a third
         of the load on it). P * A_trib is the pressure load on the contacting atoms.
  A_hull the convex hull of the contacting atoms' (x, y) (close to A_in for a convex patch)
Only the Python standard library is used.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from lammps_dump import snapshots  # noqa: E402


def triangles(path):
    tris, section = [], None
    with open(path) as f:
        for line in f:
            s = line.split("#")[0].strip()
            if not s:
                continue
            w = s.split()
            if w[0].isalpha() or (len(w) == 1 and not w[0][0].isdigit()):
                section = w[0]
                continue
            if section == "Angles" and len(w) == 5:
                tris.append((int(w[2]), int(w[3]), int(w[4])))
    if not tris:
        sys.exit(f"{path}: no Angles section (the wall triangles)")
    return tris


def frames(path):
    """(step, {id: (x, y)}, {id: touch}) of each snapshot of the dump 'id x y v_touch'"""
    for step, cols, rows in snapshots(path):
        ii, ix, iy, it = (cols.index(k) for k in ("id", "x", "y", "v_touch"))
        yield (step, {int(w[ii]): (float(w[ix]), float(w[iy])) for w in rows},
               {int(w[ii]): int(float(w[it])) for w in rows})


def hull_area(points):
    pts = sorted(set(points))
    if len(pts) < 3:
        return 0.0

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    h = lower[:-1] + upper[:-1]
    return 0.5 * abs(sum(h[i][0] * h[i - 1][1] - h[i - 1][0] * h[i][1] for i in range(len(h))))


def areas(tris, pos, touch, plate):
    a_in = a_trib = a_out = 0.0
    for a, b, c in tris:
        k = (touch[a] == plate) + (touch[b] == plate) + (touch[c] == plate)
        if k == 0:
            continue
        (xa, ya), (xb, yb), (xc, yc) = pos[a], pos[b], pos[c]
        ap = 0.5 * abs((xb - xa) * (yc - ya) - (yb - ya) * (xc - xa))  # projected on the plate
        a_out += ap
        a_trib += ap * k / 3.0
        if k == 3:
            a_in += ap
    contact = [pos[i] for i, t in touch.items() if t == plate]
    return len(contact), a_in, a_trib, a_out, hull_area(contact)


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    tris = triangles(sys.argv[1])
    out = open(sys.argv[3], "w") if len(sys.argv) == 4 else sys.stdout
    if len(sys.argv) == 4 and sys.argv[3].endswith(".lmp"):
        last = None
        for last in frames(sys.argv[2]):
            pass
        if last is None:
            sys.exit(f"{sys.argv[2]}: no frame")
        step, pos, touch = last
        for plate, side in ((1, "lo"), (2, "hi")):
            for name, value in zip(("n", "A_in", "A_trib", "A_out", "A_hull"), areas(tris, pos, touch, plate)):
                out.write(f"variable {name}_{side} equal {value:.12e}\n")
        return
    out.write("# step n_lo A_in_lo A_trib_lo A_out_lo A_hull_lo n_hi A_in_hi A_trib_hi A_out_hi A_hull_hi (m^2)\n")
    for step, pos, touch in frames(sys.argv[2]):
        lo = areas(tris, pos, touch, 1)
        hi = areas(tris, pos, touch, 2)
        out.write(f"{step} {lo[0]} " + " ".join(f"{x:.8e}" for x in lo[1:]) +
                  f" {hi[0]} " + " ".join(f"{x:.8e}" for x in hi[1:]) + "\n")


if __name__ == "__main__":
    main()
