"""Reading LAMMPS text dumps (dump custom): one reader for tools/, bench/ and the examples' analyses.
  snapshots(path)        -> (step, columns, rows) of each snapshot
  positions(cols, rows)  -> {id: (x, y, z)} of one snapshot (x y z, or the unwrapped xu yu zu)
Scripts outside tools/ put this folder on sys.path first:
  sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))"""


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
