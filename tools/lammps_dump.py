"""Reading LAMMPS text dumps (dump custom) and the wall of data files: one reader for tools/, bench/
and the examples' analyses.
  snapshots(path)        -> (step, columns, rows) of each snapshot
  positions(cols, rows)  -> {id: (x, y, z)} of one snapshot (x y z, or the unwrapped xu yu zu)
  read_triangles(path)   -> the wall triangles (a, b, c) of a data file's Angles section
  molecules(path)        -> {atom id: molecule id} of a data file's Atoms section (the cell)
  grid(points, size), near(cells, p, size)
                         -> the keys of {key: (x, y, z)} binned in cubes of edge size, and those
                            of the 27 cubes around p (neighbour searches within size)
Scripts outside tools/ put this folder on sys.path first:
  sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))"""
import math


def snapshots(path):
    """(step, columns, rows) of each snapshot of a LAMMPS text dump: the column names after
    'ITEM: ATOMS' and each atom's line split into words"""
    with open(path) as f:
        lines = iter(f.read().splitlines())
    for line in lines:
        if not line.startswith("ITEM: TIMESTEP"):
            continue
        step = int(next(lines).split()[0])
        head = next(lines)
        while not head.startswith("ITEM: NUMBER OF ATOMS"):
            head = next(lines)
        n = int(next(lines).split()[0])
        head = next(lines)
        while not head.startswith("ITEM: ATOMS"):
            head = next(lines)
        yield step, head.split()[2:], [next(lines).split() for _ in range(n)]


def positions(cols, rows, path="the dump"):
    """{id: (x, y, z)} of one snapshot"""
    try:
        ci = cols.index("id")
        cx = [cols.index(k) if k in cols else cols.index(k + "u") for k in ("x", "y", "z")]
    except ValueError:
        raise SystemExit(f"{path} needs columns id x y z (or xu yu zu), not: {' '.join(cols)}")
    return {int(r[ci]): tuple(float(r[c]) for c in cx) for r in rows}


def grid(points, size):
    """{cube: [keys]} of a dict key -> (x, y, z), cubes of edge size"""
    cells = {}
    for k, p in points.items():
        cells.setdefault(tuple(math.floor(c / size) for c in p), []).append(k)
    return cells


def near(cells, p, size):
    """the keys in the 27 cubes of grid(..., size) around p"""
    c = [math.floor(v / size) for v in p]
    for a in (-1, 0, 1):
        for b in (-1, 0, 1):
            for d in (-1, 0, 1):
                yield from cells.get((c[0] + a, c[1] + b, c[2] + d), ())


def data_section(path, name):
    """the rows (lists of words, comments dropped) of section NAME of a LAMMPS data file"""
    rows, inside = [], False
    with open(path) as f:
        for line in f:
            words = line.split("#")[0].split()
            if not words:
                continue
            if len(words) == 1 and words[0][0].isalpha():
                inside = words[0] == name
            elif inside:
                rows.append(words)
    return rows


def read_triangles(path):
    """the wall triangles (a, b, c) of the Angles section of a LAMMPS data file"""
    tris = [(int(r[2]), int(r[3]), int(r[4])) for r in data_section(path, "Angles")]
    if not tris:
        raise SystemExit(f"{path} has no Angles section (wall triangles)")
    return tris


def molecules(path):
    """{atom id: molecule id} of the Atoms section of a LAMMPS data file (atom_style angle or
    molecular: id mol type x y z)"""
    return {int(r[0]): int(r[1]) for r in data_section(path, "Atoms")}
