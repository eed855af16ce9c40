#!/usr/bin/env python3
"""Summary of the drying example (run by run.sh in out/): for each run TAG (dry_TAG.dat,
intersections_TAG.txt, log.TAG, wall_TAG.dump, fluid_TAG.dump) the drying time, the
turgor loss point, the section descriptors (the mean and spread of the sections x, y, z through
the centroid) and volume at X/X0 = 0.5 and at the end against Karunasena et al. 2014 (dried Gala
apple: area -60 %, Feret -40 %, perimeter -30 %, roundness and elongation +5 %, compactness
unchanged), the checks: fluid outside the wall, wall self-intersections, water accounting, and
the fluid in tension (stability.TAG.txt, one line per snapshot): the nearest-neighbour distance of
the fluid atoms (min and mean, and the share of atoms within half the mean of another: clumping
by the tensile instability) and the share of wall atoms with a fluid atom within the adhesion's
reach (the protoplast held on the wall)."""
import math
import os
import re
import statistics
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from lammps_dump import positions, snapshots  # noqa: E402
from section_planes import at_x, mean_se, relative, x_by_step  # noqa: E402

# columns of dry_TAG.dat (in.drying)
COLS = ("t X X_db PT pi PW V A P F round elong compact wrink out free aw dMdt moved dMfluid "
        "Ax Px Fx Ay Py Fy").split()
APPLE = {"A": 0.4, "P": 0.7, "F": 0.6}


def rows(tag):
    with open(f"dry_{tag}.dat") as f:
        return [dict(zip(COLS, map(float, line.split()))) for line in f if not line.startswith("#")]


def at(rs, x):
    """the row where X/X0 first falls to x or below"""
    for r in rs:
        if r["X"] <= x:
            return r
    return rs[-1]


def planes(r, key):
    """mean and spread (standard deviation) of a descriptor over the sections x, y, z"""
    v = [r[key + s] for s in ("x", "y", "")]
    return statistics.mean(v), statistics.pstdev(v)


def grid(points, size):
    cells = {}
    for p in points:
        cells.setdefault(tuple(math.floor(c / size) for c in p), []).append(p)
    return cells


def near(cells, p, size):
    """the points of the 27 grid cells around p"""
    c = [math.floor(v / size) for v in p]
    for dx in (-1, 0, 1):
        for dy in (-1, 0, 1):
            for dz in (-1, 0, 1):
                yield from cells.get((c[0] + dx, c[1] + dy, c[2] + dz), ())


def stability(tag, reach, rs):
    """per wall and fluid snapshot: step, X/X0, the smallest and the mean fluid nearest-neighbour
    distance over dx = (M / (rho0 N))^(1/3), the spacing of N atoms at the water density with the
    fluid mass M of that moment (from M0 in log.TAG and the mass change of dry_TAG.dat), the share
    of fluid atoms within dx/2 of another, the share of wall atoms with fluid within reach"""
    with open(f"dry_{tag}.dat") as f:
        head = f.readline()
    tstep = float(re.search(r"accel (\S+),", head).group(1)) * float(re.search(r"dt (\S+),", head).group(1))
    with open(f"log.{tag}") as f:
        m0 = float(re.search(r"turgid cell: M0 = ([0-9.eE+-]+) kg", f.read()).group(1))
    out, first = [], None
    for (step, wc, wr), (_, fc, fr) in zip(snapshots(f"wall_{tag}.dump"), snapshots(f"fluid_{tag}.dump")):
        wall, fluid = positions(wc, wr), positions(fc, fr)
        first = step if first is None else first
        t = (step - first) * tstep
        row = next((r for r in rs if r["t"] >= t - 1e-6 * tstep), rs[-1])
        dm = row["dMfluid"]
        pts = list(fluid.values())
        dx = ((m0 + dm) / (1000.0 * len(pts))) ** (1 / 3)
        cells = grid(pts, 2.0 * dx)
        nn = [min(min((math.dist(p, q) for q in near(cells, p, 2.0 * dx) if q is not p),
                      default=2.0 * dx), 2.0 * dx) / dx for p in pts]
        fcells = grid(pts, reach)
        held = sum(any(math.dist(w, q) < reach for q in near(fcells, w, reach))
                   for w in wall.values()) / len(wall)
        out.append((step, row["X"], min(nn), statistics.mean(nn), sum(d < 0.5 for d in nn) / len(nn),
                    held))
    return out


def cuts(tag, rs, tlp):
    """cut_TAG_NAME.step for the pictures (run.sh, tools/cut_picture.py): the step, time (min) and
    X/X0 of the snapshots fresh (the first), tlp (the turgor loss point), half (X/X0 <= 0.5) and
    dry (the last)"""
    want = {"fresh": rs[0], "half": next((r for r in rs if r["X"] <= 0.5), None), "dry": rs[-1]}
    if tlp:
        want["tlp"] = tlp
    with open(f"dry_{tag}.dat") as f:
        head = f.readline()
    tstep = float(re.search(r"accel (\S+),", head).group(1)) * float(re.search(r"dt (\S+),", head).group(1))
    first = None
    for step, _, _ in snapshots(f"wall_{tag}.dump"):
        first = step if first is None else first
        t = (step - first) * tstep
        for name, r in want.items():
            if r is not None and abs(t - r["t"]) <= 1e-6 * tstep + 1e-9 * r["t"]:
                with open(f"cut_{tag}_{name}.step", "w") as f:
                    f.write(f"{step} {r['t'] / 60:.1f} {r['X']:.3f}\n")


def reach_of(tag):
    """the reach of the protoplast on the wall: h/2.5 + 0.45 h of the fluid's h (from the run's log)"""
    with open(f"log.{tag}") as f:
        log = f.read()
    h = float(re.search(r"pair_coeff\s+1 1 cell/sph [0-9.eE+-]+ [0-9.eE+-]+ [0-9.eE+-]+ ([0-9.eE+-]+)", log).group(1))
    return h / 2.5 + 0.45 * h


def first_line(path, default="n/a"):
    try:
        with open(path) as f:
            return f.readline().split()
    except OSError:
        return default


def wall_time(tag):
    try:
        with open(f"log.{tag}") as f:
            m = re.findall(r"Total wall time: (\d+):(\d+):(\d+)", f.read())
        h, mi, s = map(int, m[-1])
        return 3600 * h + 60 * mi + s
    except (OSError, IndexError):
        return float("nan")


def main(tags):
    print("drying of one turgid apple cell in air (in.drying); values relative to the turgid cell")
    print("section: plane z through the volume centroid (compute cell/shape); sections x, y, z; and the "
          "mean of 13 planes (tools/section_planes.lmp) +- its standard error")
    for tag in tags:
        rs = rows(tag)
        r0, half, end = rs[0], at(rs, 0.5), rs[-1]
        tlp = next((r for r in rs if r["PT"] <= 0.0), None)
        inter = first_line(f"intersections_{tag}.txt")
        acct = max(abs(r["moved"] - r["dMfluid"]) for r in rs) / abs(rs[-1]["dMfluid"] or 1)
        with open(f"dry_{tag}.dat") as f:
            print(f"\n{tag}: {f.readline().lstrip('# ').strip()}")
        print(f"  X/X0 = {end['X']:.3f} after {end['t'] / 60:.1f} min of physical time "
              f"(X = {end['X_db']:.3f} kg/kg); wall-clock {wall_time(tag)} s")
        if tlp:
            print(f"  turgor loss point (P_T <= 0): X/X0 = {tlp['X']:.3f} at {tlp['t'] / 60:.1f} min")
        cuts(tag, rs, tlp)
        print("  quantity          X/X0=0.5   end    apple (Karunasena 2014, dried)   sections x, y, z")
        for key, name in (("A", "section area"), ("P", "perimeter"), ("F", "Feret"), ("V", "volume")):
            ref = f"{APPLE[key]:.2f}" if key in APPLE else "-"
            if key in APPLE:
                (hm, hs), (em, es) = planes(half, key), planes(end, key)
                print(f"  {name:16s}  {hm:.3f}±{hs:.3f}  {em:.3f}±{es:.3f}   {ref}"
                      f"   {end[key + 'x']:.3f} {end[key + 'y']:.3f} {end[key]:.3f}")
            else:
                print(f"  {name:16s}  {half[key]:8.3f}  {end[key]:6.3f}   {ref}")
        try:
            series, xs = relative(f"sections_{tag}.dat"), x_by_step(f"log.{tag}")
        except OSError:
            series = None
        if series:
            # the 13-plane means per snapshot (planes_TAG.txt, for the figure) and at 0.5 and the end
            with open(f"planes_{tag}.txt", "w") as f:
                f.write("# X/X0 then the mean over 13 planes of A/A0 P/P0 F/F0 (tools/section_planes.lmp)\n")
                for step, a, p, fe in series:
                    if step in xs:
                        f.write("%.6f %.6f %.6f %.6f\n" % (xs[step], *(mean_se(v)[0] for v in (a, p, fe))))
            mid, fin = at_x(series, xs, 0.5), at_x(series, xs, end["X"])
            if mid and fin:
                for k, (key, name) in enumerate((("A", "section area"), ("P", "perimeter"), ("F", "Feret"))):
                    (hm, hs, _), (em, es, _) = mean_se(mid[k]), mean_se(fin[k])
                    print(f"  {name:16s}  {hm:.3f}±{hs:.3f}  {em:.3f}±{es:.3f}   {APPLE[key]:.2f}   13 planes")
        for key, name in (("round", "roundness"), ("elong", "elongation"), ("compact", "compactness")):
            print(f"  {name:16s}  {half[key] / r0[key]:8.3f}  {end[key] / r0[key]:6.3f}   "
                  f"{'1.05' if key != 'compact' else '1.00'}  (relative to the start)")
        print(f"  wrinkling (wall / hull area) {half['wrink']:.3f} at X/X0 = 0.5, {end['wrink']:.3f} at the end;"
              f" fluid-free volume {end['free']:.3f} of V at the end")
        print(f"  checks: fluid atoms outside the wall at most {max(r['out'] for r in rs):.0f}; "
              f"wall self-intersections at most {inter[0] if inter != 'n/a' else 'n/a'} triangle pairs; "
              f"|water moved - fluid mass change| / water lost at most {acct:.1e}")
        try:
            st = stability(tag, reach_of(tag), rs)
        except (OSError, AttributeError):
            continue
        with open(f"stability_{tag}.txt", "w") as f:
            f.write("# step X/X0 nn_min/dx nn_mean/dx share_within_dx/2 wall_share_held\n")
            for line in st:
                f.write("%d %.6f %.4f %.4f %.4f %.4f\n" % line)
        print(f"  fluid in tension ({len(st)} snapshots; dx = the spacing of the fluid mass at the "
              f"water density): nearest-neighbour distance at the start min {st[0][2]:.2f} dx, mean "
              f"{st[0][3]:.2f} dx; at the end min {st[-1][2]:.2f} dx, mean {st[-1][3]:.2f} dx; share of "
              f"fluid atoms within dx/2 of another at most {max(x[4] for x in st):.3f} (at the end "
              f"{st[-1][4]:.3f}); share of wall atoms with fluid within h/2.5 + 0.45 h at least "
              f"{min(x[5] for x in st):.3f} (at the end {st[-1][5]:.3f})")


if __name__ == "__main__":
    main(sys.argv[1:])
