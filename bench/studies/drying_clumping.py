#!/usr/bin/env python3
"""Why does the sap of the drying example clump? Reader of drying_clumping.sh's outputs.

  bench/studies/drying_clumping.py DIR TAG [--every K]

Measures, at every K-th snapshot (default 1) of the fluid and wall dumps of run TAG in DIR
(cell.data, log.TAG, dry_TAG.dat, pb_TAG.dat: step and the background pressure P_b of compute
pair cell/sph [3]; fluid_TAG.dump: id x y z d_pressure d_h d_rho d_omega mass; wall_TAG.dump),
for the clumped fluid atoms (nearest fluid neighbour within dx/2, dx = (M / (rho0 N))^(1/3) the
spacing of the fluid mass at the water density, as examples/drying/analyse.py) against the other
fluid atoms:
  Pabs  = P_b + P, the local absolute pressure (the pair force is repulsive while it is > 0)
  h/dx  the atom's smoothing length (h adaptive) over dx
  d1/dx the distance to the nearest wall triangle; d2/dx the distance to the nearest triangle
        facing that one (outward normals at more than 90 degrees: the other side of a fold)
        (both capped at 2 dx)
        and the share of atoms with d2 < dx that are behind that triangle too (a pocket of fluid
        between two sheets, not beside a ridge of wall)
  Omega the grad-h factor of h adaptive that divides the atom's pressure term (its smallest)
  gamma the kernel fraction inside the cell, sum_j m_j W(r_ij, h_i) / rho_i (the dumped density is
        the sum over gamma, doc/model.md §3.2; pair cell/sph floors it at 0.25 and then applies no
        wall-boundary force to the atom)
  S     for a clumped atom and its nearest neighbour j, the sign of the pair's pressure force:
        (P_b + P_i)/(Omega_i rho_i^2) + (P_b + P_j)/(Omega_j rho_j^2) < 0 is an attraction
        (doc/model.md §3.4, the kernel gradients of h_i and h_j taken equal)
and, for the atoms that are clumped at one analysed snapshot and were not at the one before (the
onsets), their state at the snapshot before, against all atoms not clumped there: what an atom
looked like just before it paired up. Snapshots where X/X0 did not change since the previous
output line are accel auto's holds (no water moved). Standard library only."""
import math
import os
import re
import statistics
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "tools"))
sys.path.insert(0, here)
from lammps_dump import grid, near, positions, read_triangles, snapshots  # noqa: E402
from wall_self_distance import closest, cross, dot, sub  # noqa: E402

RHO0 = 1000.0


def wall_distances(p, wall, wcells, size, tris_of, tris):
    """d1: distance of p to its nearest wall triangle within size; d2: to the nearest triangle whose
    outward normal points against that one's (a fold's other side); both capped at size; pocket:
    p is behind that other triangle too (fluid between two sheets, not beside a ridge of wall)"""
    cand = {t for w in near(wcells, p, size) for t in tris_of.get(w, ())}
    best = []
    for t in cand:
        a, b, c = (wall[v] for v in tris[t])
        q, _ = closest(p, a, b, c)
        n = cross(sub(b, a), sub(c, a))
        best.append((math.dist(p, q), n, q))
    if not best:
        return size, size, False
    best.sort(key=lambda x: x[0])
    d1, n1, _ = best[0]
    other = next(((d, n, q) for d, n, q in best[1:] if dot(n, n1) < 0.0), None)
    if other is None:
        return min(d1, size), size, False
    return min(d1, size), min(other[0], size), dot(sub(p, other[2]), other[1]) < 0.0


def kernel_sum(i, fl, cells, size):
    """sum_j m_j W(r_ij, h_i) over the fluid atoms, i included (Wendland C2, doc/model.md §3.1-3.2)"""
    a = fl[i]
    h = a["h"]
    total = 0.0
    for j in near(cells, a["x"], size):
        q = math.dist(a["x"], fl[j]["x"]) / h
        if q < 2.0:
            total += fl[j]["m"] * 21.0 / (16.0 * math.pi * h ** 3) * (1 - q / 2) ** 4 * (1 + 2 * q)
    return total


def measure(fl, wall, tris_of, tris, pb):
    """per atom: (clumped, nn partner, Pabs, h/dx, d1/dx, d2/dx, Omega, gamma, pocket) and dx"""
    pos = {i: a["x"] for i, a in fl.items()}
    dx = (sum(a["m"] for a in fl.values()) / (RHO0 * len(fl))) ** (1 / 3)
    cells = grid(pos, dx)
    wcells = grid(wall, 2.0 * dx)
    ksize = 2.0 * max(a["h"] for a in fl.values())
    kcells = grid(pos, ksize)
    out = {}
    for i, a in fl.items():
        nn, part = 2.0 * dx, None
        for j in near(cells, a["x"], dx):
            if j != i:
                d = math.dist(a["x"], pos[j])
                if d < nn:
                    nn, part = d, j
        d1, d2, pocket = wall_distances(a["x"], wall, wcells, 2.0 * dx, tris_of, tris)
        gamma = kernel_sum(i, fl, kcells, ksize) / a["rho"]
        out[i] = (nn < 0.5 * dx, part, pb + a["P"], a["h"] / dx, d1 / dx, d2 / dx, a["om"], gamma,
                  pocket)
    return out, dx


def stats(vals):
    """mean, min and the share below 0 (Pabs), or mean and the share below 1 (distances)"""
    return statistics.mean(vals), min(vals), sum(v < 0 for v in vals) / len(vals)


def fmt_group(rows):
    """Pabs mean min share<0 | h/dx mean | d1/dx mean, share < 0.5 | d2/dx mean, share < 1, share
    in a pocket within 1 | Omega min | gamma mean, share at the floor 0.25"""
    if not rows:
        return "      -" * 13
    pm, pmin, pneg = stats([r[2] for r in rows])
    h = statistics.mean(r[3] for r in rows)
    d1 = [r[4] for r in rows]
    d2 = [r[5] for r in rows]
    return (f"{pm / 1e3:7.1f} {pmin / 1e3:7.1f} {pneg:6.3f} {h:6.3f} {statistics.mean(d1):6.3f} "
            f"{sum(d < 0.5 for d in d1) / len(d1):6.3f} {statistics.mean(d2):6.3f} "
            f"{sum(d < 1.0 for d in d2) / len(d2):6.3f} "
            f"{sum(r[5] < 1.0 and r[8] for r in rows) / len(rows):6.3f} {min(r[6] for r in rows):6.3f} "
            f"{statistics.mean(r[7] for r in rows):6.3f} {sum(r[7] <= 0.25 for r in rows) / len(rows):6.3f}")


def read_fluid(cols, rows):
    ci = {k: cols.index(k) for k in ("id", "x", "y", "z", "d_pressure", "d_h", "d_rho", "d_omega",
                                     "mass")}
    return {int(r[ci["id"]]): {"x": tuple(float(r[ci[k]]) for k in "xyz"),
                               "P": float(r[ci["d_pressure"]]), "h": float(r[ci["d_h"]]),
                               "rho": float(r[ci["d_rho"]]), "om": float(r[ci["d_omega"]]),
                               "m": float(r[ci["mass"]])} for r in rows}


def main(argv):
    if len(argv) < 3:
        raise SystemExit(__doc__)
    folder, tag = argv[1], argv[2]
    every = int(argv[argv.index("--every") + 1]) if "--every" in argv else 1
    tris = read_triangles(os.path.join(folder, "cell.data"))
    tris_of = {}
    for t, tri in enumerate(tris):
        for v in tri:
            tris_of.setdefault(v, []).append(t)
    with open(os.path.join(folder, f"pb_{tag}.dat")) as f:
        pbs = {int(w[0]): float(w[1]) for w in (ln.split() for ln in f if not ln.startswith("#"))}
    with open(os.path.join(folder, f"dry_{tag}.dat")) as f:
        dry = [ln.split() for ln in f if not ln.startswith("#")]
    xs = {int(r[26]): float(r[1]) for r in dry}    # step -> X/X0 (columns of in.drying's fix out)
    hold, prev = {}, None
    for r in dry:
        hold[int(r[26])] = prev is not None and float(r[1]) == prev
        prev = float(r[1])
    print(f"# drying_clumping {folder} {tag}: per snapshot; groups clumped (nearest fluid atom "
          "within dx/2) | other fluid atoms; columns per group: Pabs = P_b + P mean, min (kPa), share "
          "< 0 | h/dx | d1/dx (wall) mean, share < 0.5 | d2/dx (fold's other side) mean, share < 1, "
          "share < 1 in a pocket | Omega (h adaptive) min | gamma (kernel inside) mean, share <= 0.25")
    print("# step   X/X0 hold  P_b[kPa] share  pairs_attr |  clumped: Pabs  min  neg  h/dx  d1  d1<.5"
          "  d2  d2<1 pock  Om  gam g<.25 | others: same")
    last, onset_before, base_before = None, [], []
    hold_new = {True: [0, 0], False: [0, 0]}    # hold: [new clumps, snapshots]
    steps = [s for s, _, _ in snapshots(os.path.join(folder, f"wall_{tag}.dump"))]
    wall_iter = snapshots(os.path.join(folder, f"wall_{tag}.dump"))
    for k, ((step, fc, fr), (wstep, wc, wr)) in enumerate(
            zip(snapshots(os.path.join(folder, f"fluid_{tag}.dump")), wall_iter)):
        if step != wstep or step not in pbs or step not in xs:
            continue
        if k % every and step != steps[-1]:
            continue
        fl = read_fluid(fc, fr)
        m, dx = measure(fl, positions(wc, wr), tris_of, tris, pbs[step])
        cl = [r for r in m.values() if r[0]]
        ot = [r for r in m.values() if not r[0]]
        attr = 0
        for i, r in m.items():
            if r[0]:
                j = r[1]
                s = (m[i][2] / (fl[i]["om"] * fl[i]["rho"] ** 2) +
                     m[j][2] / (fl[j]["om"] * fl[j]["rho"] ** 2))
                attr += s < 0.0
        share = len(cl) / len(m)
        print(f"{step:6d} {xs[step]:.4f} {int(hold[step]):4d} {pbs[step] / 1e3:9.1f} {share:.4f} "
              f"{attr / max(1, len(cl)):6.3f}   | {fmt_group(cl)} | {fmt_group(ot)}", flush=True)
        if last is not None:
            new = [i for i, r in m.items() if r[0] and not last[i][0]]
            onset_before += [last[i] for i in new]
            base_before += [r for r in last.values() if not r[0]]
            hold_new[hold[step]][0] += len(new)
            hold_new[hold[step]][1] += 1
        last = m
    print("# the state one analysed snapshot before an atom paired up (onsets) against all atoms "
          "not clumped then: Pabs mean min (kPa) share<0 | h/dx | d1/dx share<.5 | d2/dx share<1 pocket "
          "| Omega min | gamma mean, share <= 0.25")
    print(f"onsets ({len(onset_before)})         {fmt_group(onset_before)}")
    print(f"not clumped ({len(base_before)})  {fmt_group(base_before)}")
    for h, name in ((True, "hold"), (False, "transfer")):
        n, s = hold_new[h]
        print(f"# new clumped atoms per analysed snapshot ending in a {name}: {n / max(1, s):.2f} "
              f"({n} in {s} snapshots)")


if __name__ == "__main__":
    main(sys.argv)
