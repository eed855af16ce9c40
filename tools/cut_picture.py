#!/usr/bin/env python3
"""A section picture of cells, as in a micrograph: wall outlines, fluid coloured by a quantity.

  cut_picture.py DATA WALLDUMP --out PIC.png [options]
  cut_picture.py --selftest

DATA is the cellsph data file (its Angles section: the wall triangles; Atoms: each atom's cell).
WALLDUMP is a LAMMPS text dump of the wall atoms (`id x y z` or `id xu yu zu`; other atoms may be
in it). The last snapshot is drawn (or --step N). In a periodic box (the dump's box bounds) each
cell is made whole: its wall atoms are joined through its triangles' edges by the nearest image,
and its fluid atoms (with a `mol` column in the fluid dump) put nearest to its wall's centre. The
plane normal to x, y or z (--plane, default z) cuts every wall triangle: the pieces are the wall's
outline in the section, one colour per cell (a tissue cut shows each cell). The picture's axes:
y-z for the plane x, x-z for y, x-y for z; a periodic box's edges across the picture are dashed.
Options:
  --at VALUE           the plane's position (m); default: the centre of the volume the walls enclose
  --fluid DUMP         fluid atoms (id x y z and the coloured column, same step), those within
                       --slab of the plane drawn as dots coloured by --color
  --color COLUMN       dump column of the fluid's colour, with --cscale (multiplies it, default 1),
                       --clabel (the colour bar's label, e.g. "SPH pressure (kPa)"), --crange LO:HI
  --slab WIDTH         half width of the fluid slab drawn (m), default 8e-6
  --title TEXT         the picture's title: the conditions, time and X/X0 (the caller knows them)
  --bar LENGTH         scale bar length (m), default: a round length near a fifth of the picture
  --frame SIZE         the width and height shown (m), centred on the outline (default: the
                       outline and a margin): pictures of one cell at different states to scale
  --measure FILE       also write each cell's outline length and enclosed area (m, m^2), one
                       number a line (a LAMMPS file-style variable reads it): length, then area,
                       cell by cell in the order of their molecule IDs; compute cell/shape's
                       perimeter and area when the plane passes through the cell's centre
Needs gnuplot (pngcairo), installed by tools/setup.sh.
"""
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from lammps_dump import positions, snapshots  # noqa: E402
from wall_vtk import read_walls, triple  # noqa: E402

AXES = {"x": (0, 1, 2), "y": (1, 0, 2), "z": (2, 0, 1)}    # normal, then the picture's u, v


def last_snapshot(path, step=None):
    """(step, columns, rows) of the snapshot at step (default: the last one)"""
    found = None
    for snap in snapshots(path):
        if step is None or snap[0] == step:
            found = snap
    if found is None:
        raise SystemExit(f"cut_picture: {path} has no snapshot" +
                         (f" at step {step}" if step is not None else ""))
    return found


def box_of(path, step):
    """[(lo, hi, periodic)] of x, y, z from the BOX BOUNDS of the dump's snapshot at step"""
    with open(path) as f:
        lines = iter(f.read().splitlines())
    for line in lines:
        if line.startswith("ITEM: TIMESTEP") and int(next(lines).split()[0]) == step:
            for head in lines:
                if head.startswith("ITEM: BOX BOUNDS"):
                    flags = head.split()[3:] if len(head.split()) > 3 else ["ff"] * 3
                    return [(*map(float, next(lines).split()[:2]), flags[k] == "pp") for k in range(3)]
    return [(0.0, 0.0, False)] * 3


def nearest(p, ref, box):
    """the image of p nearest to ref in the box's periodic dimensions"""
    return tuple(c - (hi - lo) * round((c - r) / (hi - lo)) if per else c
                 for c, r, (lo, hi, per) in zip(p, ref, box))


def whole(tris, pos, box):
    """positions with every cell whole in a periodic box: from each cell's first atom on, the atoms
    joined through the triangles' edges, each put at the image nearest to its neighbour"""
    if not any(per for _, _, per in box):
        return pos
    links = {}
    for tri in tris:
        for k in range(3):
            links.setdefault(tri[k], []).extend((tri[(k + 1) % 3], tri[(k + 2) % 3]))
    out = dict(pos)
    done = set()
    for start in links:
        if start in done:
            continue
        done.add(start)
        todo = [start]
        while todo:
            i = todo.pop()
            for j in links[i]:
                if j not in done:
                    done.add(j)
                    out[j] = nearest(pos[j], out[i], box)
                    todo.append(j)
    return out


def volume_centre(tris, pos):
    """the centre of the volume the triangles enclose (tetrahedra with the origin)"""
    vol, first = 0.0, [0.0, 0.0, 0.0]
    for a, b, c in tris:
        pa, pb, pc = pos[a], pos[b], pos[c]
        v = triple(pa, pb, pc) / 6.0    # signed volume of the tetrahedron (0, a, b, c)
        vol += v
        for k in range(3):
            first[k] += v * (pa[k] + pb[k] + pc[k]) / 4.0    # its centroid (0 + a + b + c) / 4
    if vol == 0.0:
        raise SystemExit("cut_picture: the walls enclose no volume")
    return [f / vol for f in first]


def cut(tris, mol, pos, plane, at):
    """the wall's pieces in the section, [(cell, start, end)] in the picture's (u, v): each from
    where its triangle's edge goes down through the plane to where one goes up, so that with
    outward-wound triangles every cell's outline runs counter-clockwise (clockwise for the plane y,
    whose picture axes x, z turn the other way about y)"""
    n, u, v = AXES[plane]
    pieces = []
    for tri in tris:
        d = [pos[i][n] - at for i in tri]
        down = up = None
        for k in range(3):
            i, j = k, (k + 1) % 3
            if (d[i] < 0.0) != (d[j] < 0.0):
                s = d[i] / (d[i] - d[j])    # where the edge i-j crosses the plane, from i
                pi, pj = pos[tri[i]], pos[tri[j]]
                point = (pi[u] + s * (pj[u] - pi[u]), pi[v] + s * (pj[v] - pi[v]))
                if d[i] >= 0.0:
                    down = point
                else:
                    up = point
        if down is not None and up is not None:
            pieces.append((mol.get(tri[0], 0), down, up))
    return pieces


def measure(tris, mol, pos, plane, at):
    """{cell: (outline length, enclosed area)} of the section"""
    out = {}
    for cell, p, q in cut(tris, mol, pos, plane, at):
        length, area = out.get(cell, (0.0, 0.0))
        # Green's theorem: area = sum over the closed outline of (u dv - v du) / 2
        out[cell] = (length + math.dist(p, q), area + (p[0] * q[1] - p[1] * q[0]) / 2.0)
    return {c: (length, abs(area)) for c, (length, area) in sorted(out.items())}


def nice_length(span):
    """a round length (1, 2 or 5 x 10^k) near a fifth of span"""
    target = span / 5.0
    k = math.floor(math.log10(target))
    return min((m * 10 ** k for m in (1, 2, 5, 10)), key=lambda x: abs(math.log(x / target)))


def draw(pieces, dots, opts, out, edges=()):
    """the picture with gnuplot: outlines per cell, dots coloured, colour bar, scale bar, title,
    the periodic box's edges at u = edges (dashed)"""
    us = [p[1][0] for p in pieces] + [p[2][0] for p in pieces]
    vs = [p[1][1] for p in pieces] + [p[2][1] for p in pieces]
    if not us:
        raise SystemExit("cut_picture: the plane misses every wall (give --at inside the cells)")
    lo_u, hi_u, lo_v, hi_v = min(us), max(us), min(vs), max(vs)
    if opts.get("frame"):    # a fixed width and height about the outline's middle
        mid_u, mid_v, half = 0.5 * (lo_u + hi_u), 0.5 * (lo_v + hi_v), 0.5 * opts["frame"] / 1.16
        lo_u, hi_u, lo_v, hi_v = mid_u - half, mid_u + half, mid_v - half, mid_v + half
    pad = 0.08 * max(hi_u - lo_u, hi_v - lo_v)
    bar = opts.get("bar") or nice_length(hi_u - lo_u)
    # 800 px high for a round section, up to 1600 for a tall one (a slab's cut)
    height = int(min(1600, max(800, 100 + 700 * (hi_v - lo_v) / (hi_u - lo_u))))
    um = 1e6
    with tempfile.TemporaryDirectory() as tmp:
        walls, fluid = os.path.join(tmp, "walls.dat"), os.path.join(tmp, "fluid.dat")
        with open(walls, "w") as f:
            f.writelines("%.6f %.6f %.6f %.6f %d\n" % (p[0] * um, p[1] * um, (q[0] - p[0]) * um,
                                                         (q[1] - p[1]) * um, cell % 8 + 1)
                         for cell, p, q in pieces)
        with open(fluid, "w") as f:
            f.writelines("%.6f %.6f %.9g\n" % (a * um, b * um, c) for a, b, c in dots)
        x0, y0 = (lo_u - 0.5 * pad) * um, (lo_v - 0.5 * pad) * um
        label = f"{bar * um:g} µm"
        script = [
            f"set terminal pngcairo size 900,{height} noenhanced font 'Sans,12'", f"set output '{out}'",
            "set size ratio -1", "unset key", "unset tics", "set cbtics", "unset border",
            f"set xrange [{(lo_u - pad) * um}:{(hi_u + pad) * um}]",
            f"set yrange [{(lo_v - pad) * um}:{(hi_v + pad) * um}]",
            f"set title \"{opts.get('title', '')}\"",
            f"set arrow from {x0},{y0} to {x0 + bar * um},{y0} nohead lw 4 lc rgb 'black' front",
            f"set label \"{label}\" at {x0 + 0.5 * bar * um},{y0 + 0.35 * pad * um} center front",
            "set palette defined (0 '#440154', 0.25 '#3b528b', 0.5 '#21918c', 0.75 '#5ec962', 1 '#fde725')",
            f"set cblabel \"{opts.get('clabel', '')}\"",
        ]
        if opts.get("crange"):
            script.append(f"set cbrange [{opts['crange']}]")
        script += [f"set arrow from {e * um},{(lo_v - pad) * um} to {e * um},{(hi_v + pad) * um} nohead "
                   "dt 2 lc rgb 'gray50' back" for e in edges]
        plots = [f"'{walls}' using 1:2:3:4:5 with vectors nohead lw 2.5 lc variable"]
        if dots:
            plots.insert(0, f"'{fluid}' using 1:2:3 with points pt 7 ps 0.6 lc palette")
        else:
            script.append("unset colorbox")
        script.append("plot " + ", ".join(plots))
        gp = os.path.join(tmp, "cut.gp")
        with open(gp, "w") as f:
            f.write("\n".join(script) + "\n")
        subprocess.run(["gnuplot", gp], check=True)


def picture(data, walldump, out, opts):
    tris, mol = read_walls(data)
    step, cols, rows = last_snapshot(walldump, opts.get("step"))
    box = box_of(walldump, step)
    pos = whole(tris, positions(cols, rows, walldump), box)
    missing = [i for t in tris for i in t if i not in pos]
    if missing:
        raise SystemExit(f"cut_picture: wall atom {missing[0]} is not in {walldump} at step {step}")
    plane = opts.get("plane", "z")
    n, u, v = AXES[plane]
    at = opts["at"] if "at" in opts else volume_centre(tris, pos)[n]
    pieces = cut(tris, mol, pos, plane, at)
    dots = []
    if opts.get("fluid"):
        fstep, fcols, frows = last_snapshot(opts["fluid"], step)
        column = opts.get("color")
        if column not in fcols:
            raise SystemExit(f"cut_picture: --color {column} is not a column of {opts['fluid']} "
                             f"({' '.join(fcols)})")
        fpos = positions(fcols, frows, opts["fluid"])
        ci, cc = fcols.index("id"), fcols.index(column)
        cm = fcols.index("mol") if "mol" in fcols else None
        centre = {}
        for i in {i for t in tris for i in t}:    # each cell's wall centre, for its fluid's image
            c = centre.setdefault(mol.get(i, 0), [0.0, 0.0, 0.0, 0])
            c[:3] = [a + b for a, b in zip(c[:3], pos[i])]
            c[3] += 1
        scale, slab = opts.get("cscale", 1.0), opts.get("slab", 8e-6)
        for r in frows:
            p = fpos[int(r[ci])]
            c = centre.get(int(r[cm])) if cm is not None else None
            if c:
                p = nearest(p, [a / c[3] for a in c[:3]], box)
            if abs(p[n] - at) <= slab:
                dots.append((p[u], p[v], float(r[cc]) * scale))
    if out:
        edges = [box[u][k] for k in (0, 1)] if box[u][2] else []
        draw(pieces, dots, opts, out, edges)
    if opts.get("measure"):
        with open(opts["measure"], "w") as f:
            f.writelines("%.15e\n%.15e\n" % m for m in measure(tris, mol, pos, plane, at).values())
    return pieces, dots


def selftest():
    """an octahedron |x| + |y| + |z| = 1 cut at z = 0 is the square of side sqrt(2): length
    4 sqrt(2), area 2, at the volume centre 0; at z = 0.5 half of it"""
    pos = {1: (1, 0, 0), 2: (0, 1, 0), 3: (-1, 0, 0), 4: (0, -1, 0), 5: (0, 0, 1), 6: (0, 0, -1)}
    tris = [(1, 2, 5), (2, 3, 5), (3, 4, 5), (4, 1, 5), (2, 1, 6), (3, 2, 6), (4, 3, 6), (1, 4, 6)]
    mol = {i: 1 for i in pos}
    centre = volume_centre(tris, pos)
    m0 = measure(tris, mol, pos, "z", centre[2])[1]
    m1 = measure(tris, mol, pos, "z", 0.5)[1]
    ok = (max(abs(c) for c in centre) < 1e-15 and abs(m0[0] - 4 * math.sqrt(2)) < 1e-12 and
          abs(m0[1] - 2.0) < 1e-12 and abs(m1[0] - 2 * math.sqrt(2)) < 1e-12 and
          abs(m1[1] - 0.5) < 1e-12 and len(cut(tris, mol, pos, "x", 0.25)) == 4)
    # in a box periodic in x and y, [-1.5, 1.5) square, the octahedron moved by 1 in x and y is cut
    # by both faces: its vertices beyond them wrapped back; made whole, its section is the same
    box = [(-1.5, 1.5, True), (-1.5, 1.5, True), (-5.0, 5.0, False)]
    wrapped = {i: tuple((c + 1.0 + 1.5) % 3.0 - 1.5 if k < 2 else c for k, c in enumerate(p))
               for i, p in pos.items()}
    m2 = measure(tris, mol, whole(tris, wrapped, box), "z", 0.0)[1]
    ok_box = (abs(m2[0] - 4 * math.sqrt(2)) < 1e-12 and abs(m2[1] - 2.0) < 1e-12 and
              nearest((-1.4, 1.4, 0.0), (1.0, -1.0, 0.0), box) == (1.6, -1.6, 0.0))
    print(f"cut_picture selftest: octahedron sections {'ok' if ok else 'WRONG'}, made whole across "
          f"periodic faces {'ok' if ok_box else 'WRONG'}")
    return 0 if ok and ok_box else 1


def main(argv):
    if argv[1:] == ["--selftest"]:
        return selftest()
    kinds = {"--at": float, "--fluid": str, "--color": str, "--cscale": float, "--clabel": str,
             "--crange": str, "--slab": float, "--title": str, "--bar": float, "--plane": str,
             "--measure": str, "--out": str, "--step": int, "--frame": float}
    args, opts = [], {}
    it = iter(argv[1:])
    for a in it:
        if a in kinds:
            value = next(it, None)
            if value is None:
                raise SystemExit(f"cut_picture: {a} needs a value")
            try:
                opts[a[2:]] = kinds[a](value)
            except ValueError:
                raise SystemExit(f"cut_picture: {a} {value}: not a {kinds[a].__name__}")
        elif a.startswith("--"):
            raise SystemExit(f"cut_picture: unknown option {a} (see cut_picture.py's header)")
        else:
            args.append(a)
    if len(args) != 2 or not (opts.get("out") or opts.get("measure")):
        raise SystemExit(__doc__)
    if opts.get("plane", "z") not in AXES:
        raise SystemExit(f"cut_picture: --plane {opts['plane']}: expected x, y or z")
    if opts.get("fluid") and not opts.get("color"):
        raise SystemExit("cut_picture: --fluid needs --color COLUMN (the quantity the dots show)")
    picture(args[0], args[1], opts.get("out"), opts)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
