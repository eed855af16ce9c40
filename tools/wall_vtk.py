#!/usr/bin/env python3
"""Cell walls as surfaces for ParaView or OVITO: one legacy VTK file per dump snapshot.

  wall_vtk.py DATA DUMP [--out PREFIX] [--volume FILE]
  wall_vtk.py --selftest

DATA is the cellsph data file (tools/cellgen, or write_data): its Angles section gives the wall
triangles a b c (atom IDs) and its Atoms section each atom's molecule ID (the cell). DUMP is a LAMMPS
text dump holding at least the wall atoms (`dump ID wall custom N FILE id x y z`, or `xu yu zu`;
any number of snapshots). For each snapshot it writes PREFIX_<step>.vtk (default PREFIX: the dump's
name without its extension), a POLYDATA of the wall atoms and triangles with the cell of each
triangle as cell data ("cell") and every further numeric dump column as point data. ParaView opens
the numbered files as one time series (File > Open, PREFIX_..vtk); colour by "cell" to tell the
cells of a tissue apart.

--volume FILE writes the volume enclosed by each cell's triangles as read back from the written
file (divergence theorem,
V = |sum over triangles of x_a . (x_b x x_c)| / 6), one number per line, cell by cell in the order
of their molecule IDs, snapshot after snapshot: a LAMMPS file-style variable reads it (checks
against compute cell/props). Standard library only.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from lammps_dump import molecules, positions, read_triangles, snapshots  # noqa: E402


def read_walls(path):
    """(triangles [(a, b, c)], {atom id: molecule id}) of a cellsph data file"""
    return read_triangles(path), molecules(path)


def triple(a, b, c):
    """a . (b x c): six times the signed volume of the tetrahedron (0, a, b, c)"""
    return (a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
            a[2] * (b[0] * c[1] - b[1] * c[0]))


def enclosed_volumes(name):
    """{cell: volume enclosed by its triangles} of a written VTK file, read back from the file
    (divergence theorem)"""
    words = open(name).read().split()
    at = words.index("POINTS")
    n = int(words[at + 1])
    pts = [tuple(float(w) for w in words[at + 3 + 3 * k:at + 6 + 3 * k]) for k in range(n)]
    at = words.index("POLYGONS")
    m = int(words[at + 1])
    polys = [[int(w) for w in words[at + 4 + 4 * k:at + 7 + 4 * k]] for k in range(m)]
    at = words.index("CELL_DATA") + 7    # CELL_DATA m SCALARS cell int 1 LOOKUP_TABLE default
    cells = [int(w) for w in words[at + 1:at + 1 + m]]
    six = {}
    for (a, b, c), cell in zip(polys, cells):
        six[cell] = six.get(cell, 0.0) + triple(pts[a], pts[b], pts[c])
    return {cell: abs(v) / 6.0 for cell, v in sorted(six.items())}


def write_vtk(name, step, tris, mol, cols, rows, pos):
    """one snapshot as a legacy ASCII VTK POLYDATA"""
    ids = sorted({i for t in tris for i in t})
    missing = [i for i in ids if i not in pos]
    if missing:
        raise SystemExit(f"wall_vtk: step {step}: wall atom {missing[0]} of the triangles is not "
                         f"in the dump ({len(missing)} missing): dump the whole wall group")
    index = {i: k for k, i in enumerate(ids)}
    ci = cols.index("id")
    extra = [k for k, c in enumerate(cols) if c not in ("id", "x", "y", "z", "xu", "yu", "zu")]
    byid = {int(r[ci]): r for r in rows}
    with open(name, "w") as f:
        f.write(f"# vtk DataFile Version 3.0\ncellsph walls, step {step}\nASCII\n")
        f.write(f"DATASET POLYDATA\nPOINTS {len(ids)} double\n")
        f.writelines("%.9e %.9e %.9e\n" % pos[i] for i in ids)
        f.write(f"POLYGONS {len(tris)} {4 * len(tris)}\n")
        f.writelines(f"3 {index[a]} {index[b]} {index[c]}\n" for a, b, c in tris)
        f.write(f"CELL_DATA {len(tris)}\nSCALARS cell int 1\nLOOKUP_TABLE default\n")
        f.writelines(f"{mol.get(a, 0)}\n" for a, _, _ in tris)
        numeric = []
        for k in extra:
            try:
                numeric.append((cols[k], [float(byid[i][k]) for i in ids]))
            except ValueError:
                pass
        if numeric:
            f.write(f"POINT_DATA {len(ids)}\n")
        for label, values in numeric:
            f.write(f"SCALARS {label.replace('[', '_').replace(']', '')} double 1\n")
            f.write("LOOKUP_TABLE default\n")
            f.writelines("%.9e\n" % v for v in values)


def convert(data, dump, prefix, volume=None):
    tris, mol = read_walls(data)
    written, lines = [], []
    for step, cols, rows in snapshots(dump):
        pos = positions(cols, rows, dump)
        name = f"{prefix}_{step:010d}.vtk"
        write_vtk(name, step, tris, mol, cols, rows, pos)
        written.append(name)
        vols = enclosed_volumes(name)
        lines += ["%.15e" % v for v in vols.values()]
    if not written:
        raise SystemExit(f"wall_vtk: {dump} has no snapshot")
    if volume:
        with open(volume, "w") as f:
            f.write("\n".join(lines) + "\n")
    return written


def selftest():
    """a unit cube of 12 triangles (two cells: the second shifted) must enclose volume 1 each and
    give a file that lists every point and triangle; a missing atom must be refused"""
    import tempfile
    corners = [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    tris, pos, mol = [], {}, {}
    for cell in (1, 2):
        base = 8 * (cell - 1)
        for k, c in enumerate(corners):
            pos[base + k + 1] = (c[0] + 3.0 * (cell - 1), c[1], c[2])
            mol[base + k + 1] = cell
        for a, b, c, d in faces:
            tris += [(base + a + 1, base + b + 1, base + c + 1), (base + a + 1, base + c + 1,
                                                                  base + d + 1)]
    with tempfile.TemporaryDirectory() as tmp:
        data, dump = os.path.join(tmp, "c.data"), os.path.join(tmp, "c.dump")
        with open(data, "w") as f:
            f.write("cubes\n\n16 atoms\n24 angles\n\nAtoms # angle\n\n")
            f.writelines(f"{i} {mol[i]} 2 {p[0]} {p[1]} {p[2]}\n" for i, p in pos.items())
            f.write("\nAngles\n\n")
            f.writelines(f"{k + 1} 1 {a} {b} {c}\n" for k, (a, b, c) in enumerate(tris))
        with open(dump, "w") as f:
            f.write("ITEM: TIMESTEP\n7\nITEM: NUMBER OF ATOMS\n16\nITEM: BOX BOUNDS ff ff ff\n"
                    "0 1\n0 1\n0 1\nITEM: ATOMS id x y z c_s\n")
            f.writelines(f"{i} {p[0]} {p[1]} {p[2]} {0.5 * i}\n" for i, p in pos.items())
        vol = os.path.join(tmp, "v.txt")
        names = convert(data, dump, os.path.join(tmp, "w"), vol)
        text = open(names[0]).read()
        values = open(vol).read().split()
        ok = (len(names) == 1 and names[0].endswith("_0000000007.vtk") and
              "POINTS 16 double" in text and "POLYGONS 24 96" in text and
              "SCALARS c_s double 1" in text and len(values) == 2 and
              all(abs(float(v) - 1.0) < 1e-12 for v in values))
        with open(dump, "w") as f:
            f.write("ITEM: TIMESTEP\n7\nITEM: NUMBER OF ATOMS\n15\nITEM: BOX BOUNDS ff ff ff\n"
                    "0 1\n0 1\n0 1\nITEM: ATOMS id x y z\n")
            f.writelines(f"{i} {p[0]} {p[1]} {p[2]}\n" for i, p in pos.items() if i != 5)
        try:
            convert(data, dump, os.path.join(tmp, "m"))
            refused = False
        except SystemExit as e:
            refused = "wall atom 5" in str(e)
    print(f"wall_vtk selftest: cubes {'ok' if ok else 'WRONG'}, missing atom "
          f"{'refused' if refused else 'NOT refused'}")
    return 0 if ok and refused else 1


def main(argv):
    if argv[1:] == ["--selftest"]:
        return selftest()
    args, opts = [], {}
    it = iter(argv[1:])
    for a in it:
        if a in ("--out", "--volume"):
            opts[a] = next(it, None)
            if opts[a] is None:
                raise SystemExit(f"wall_vtk: {a} needs a value")
        elif a.startswith("--"):
            raise SystemExit(f"wall_vtk: unknown option {a} (expected --out PREFIX, --volume FILE)")
        else:
            args.append(a)
    if len(args) != 2:
        raise SystemExit(__doc__)
    prefix = opts.get("--out") or os.path.splitext(args[1])[0]
    names = convert(args[0], args[1], prefix, opts.get("--volume"))
    print(f"wall_vtk: {len(names)} files, {names[0]} ... {names[-1]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
