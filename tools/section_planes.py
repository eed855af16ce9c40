"""Section descriptors over 13 planes (the output of tools/section_planes.lmp): one reader for bench/
and the examples' analyses.
  relative(path)        -> [(step, A, P, F, H)], each a list of 13 values relative to the same
                           plane's section in the file's first snapshot (the turgid cell); H the
                           perimeter of the section's convex hull
  x_by_step(log)        -> {step: X/X0} from the thermo lines "Step CPU v_t v_X ..." of a drying run
  at_x(series, xs, x)   -> the 13-value lists of (A, P, F, H) interpolated at X/X0 = x
  mean_se(values)       -> (mean, standard error std/sqrt(n), std)
Scripts outside tools/ put this folder on sys.path first (as for lammps_dump.py)."""
import math


def relative(path):
    """per snapshot after the first: (step, A, P, F, H) relative to the first snapshot, plane by
    plane (4 values per plane; files of 3 values per plane, before the hull perimeter, give no H)"""
    rows = []
    with open(path) as f:
        for line in f:
            if not line.startswith("#"):
                rows.append([float(v) for v in line.split()])
    ref = rows[0]
    k = (len(ref) - 1) // 13
    return [(int(r[0]),) + tuple([r[i] / ref[i] for i in range(j, len(r), k)] for j in range(1, k + 1))
            for r in rows[1:]]


def x_by_step(log):
    """{step: X/X0} from the thermo lines of a drying run's log (columns Step CPU v_t v_X ...)"""
    out, cols = {}, None
    with open(log) as f:
        for line in f:
            w = line.split()
            if w[:4] == ["Step", "CPU", "v_t", "v_X"]:
                cols = len(w)
            elif cols and len(w) == cols:
                try:
                    out[int(w[0])] = float(w[3])
                except ValueError:
                    cols = None
    return out


def at_x(series, xs, x):
    """(A, P, F, H) lists at X/X0 = x, interpolated between the snapshots that bracket it (X falling);
    a run that stopped within 1e-3 above x gives its last snapshot; None if x was not reached"""
    pts = [(xs[s[0]], s) for s in series if s[0] in xs]
    for (xa, a), (xb, b) in zip(pts, pts[1:]):
        if xa >= x >= xb:
            w = (xa - x) / (xa - xb) if xa > xb else 0.0
            return tuple([u + w * (v - u) for u, v in zip(a[k], b[k])] for k in range(1, len(a)))
    if pts and x >= pts[-1][0] - 1e-3:
        return tuple(pts[-1][1][1:])
    return None


def mean_se(values):
    """mean, its standard error (std / sqrt n; the planes are not independent, so a guide) and std"""
    n = len(values)
    m = sum(values) / n
    sd = math.sqrt(sum((v - m) ** 2 for v in values) / (n - 1))
    return m, sd / math.sqrt(n), sd
