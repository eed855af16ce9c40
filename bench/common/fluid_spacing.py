#!/usr/bin/env python3
"""Clumping of the fluid of a cell, measured against each atom's own spacing (as
examples/drying/analyse.py; bench/drying_clump.sh, which ran it, was removed 2026-12-07): for each
snapshot of a LAMMPS dump 'id type x y z mass d_rho'
(type 1 fluid, 2 wall) the nearest fluid neighbour distance r_i of each fluid atom over its own
spacing s_i = (m_i/rho_i)^(1/3) (the volume the atom stands for), its quantiles and the share of
atoms with r_i/s_i < 0.5 (clumped), the same share against the one spacing of the fluid's mass at
the water density dx = (M/(rho0 N))^(1/3) (the old measure), and the clumped share near the wall
(nearest wall atom within REACH) and in the interior.
  fluid_spacing.py DUMP [REACH] [--rho0 1000] [--every K] [--wall H] [--last]
One line per snapshot:
  step N q05 q25 q50 (r/s) share(r/s<0.5) share(r/dx<0.5) s/dx near: n share interior: n share
With --wall H instead: the first fluid layer (atoms whose nearest wall atom is closer than H/2,
H the smoothing length: the layer held at the contact range H/2.5) and how it sits on the wall
atoms: the number of wall atoms holding 1, 2, ... of its atoms as their nearest, the clumped atoms
of the layer and how many of them have their nearest fluid neighbour on the same wall atom.
--last: the last snapshot only."""
import argparse
import collections
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from lammps_dump import snapshots  # noqa: E402


def nearest(points, others, size):
    """the distance from each point to the nearest of others (not itself), at most size"""
    cells = {}
    for k, p in enumerate(others):
        cells.setdefault(tuple(math.floor(c / size) for c in p), []).append(k)
    out = []
    for p in points:
        c = [math.floor(v / size) for v in p]
        best = size
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    for k in cells.get((c[0] + dx, c[1] + dy, c[2] + dz), ()):
                        q = others[k]
                        if q is p:
                            continue
                        best = min(best, math.dist(p, q))
        out.append(best)
    return out


def quantile(v, f):
    v = sorted(v)
    return v[min(len(v) - 1, int(f * len(v)))]


def wall_layer(pf, pw, s, h):
    """how the first fluid layer sits on the wall atoms (see the module's text)"""
    near = [min((math.dist(p, q), k) for k, q in enumerate(pw)) for p in pf]
    nn = [min((math.dist(p, q), j) for j, q in enumerate(pf) if j != i) for i, p in enumerate(pf)]
    layer = [i for i in range(len(pf)) if near[i][0] < 0.5 * h]
    per_wall = collections.Counter(near[i][1] for i in layer)
    clumped = [i for i in layer if nn[i][0] < 0.5 * s[i]]
    same = sum(near[nn[i][1]][1] == near[i][1] for i in clumped)
    hist = dict(sorted(collections.Counter(per_wall.values()).items()))
    return (f"layer {len(layer)} fluid atoms on {len(per_wall)} of {len(pw)} wall atoms, wall atoms "
            f"holding k of them {{k: count}} {hist}; {len(clumped)} clumped, {same} of them with "
            f"their nearest fluid neighbour on the same wall atom")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("dump")
    ap.add_argument("reach", type=float, nargs="?", default=0.0)
    ap.add_argument("--rho0", type=float, default=1000.0)
    ap.add_argument("--every", type=int, default=1)
    ap.add_argument("--wall", type=float, default=0.0)
    ap.add_argument("--last", action="store_true")
    a = ap.parse_args()
    snaps = list(snapshots(a.dump))
    if a.last:
        snaps = snaps[-1:]
    if not a.wall:
        print("# step N q05 q25 q50(r/s) share(r/s<0.5) share(r/dx<0.5) s/dx near_n near_share int_n int_share")
    for k, (step, cols, rows) in enumerate(snaps):
        if k % a.every:
            continue
        c = {n: i for i, n in enumerate(cols)}
        fl = [r for r in rows if int(r[c["type"]]) == 1]
        wl = [r for r in rows if int(r[c["type"]]) == 2]
        pf = [tuple(float(r[c[x]]) for x in "xyz") for r in fl]
        pw = [tuple(float(r[c[x]]) for x in "xyz") for r in wl]
        # s_i = (m_i / rho_i)^(1/3), the atom's own spacing
        s = [(float(r[c["mass"]]) / float(r[c["d_rho"]])) ** (1 / 3) for r in fl]
        # dx = (M / (rho0 N))^(1/3), the spacing of the fluid mass at the water density
        dx = (sum(float(r[c["mass"]]) for r in fl) / (a.rho0 * len(fl))) ** (1 / 3)
        if a.wall:
            print(f"step {step}: {wall_layer(pf, pw, s, a.wall)}")
            continue
        nn = nearest(pf, pf, 2.0 * max(s))
        ratio = [d / si for d, si in zip(nn, s)]
        clumped = [x < 0.5 for x in ratio]
        line = (f"{step} {len(fl)} {quantile(ratio, 0.05):.3f} {quantile(ratio, 0.25):.3f} "
                f"{quantile(ratio, 0.5):.3f} {sum(clumped) / len(fl):.4f} "
                f"{sum(d < 0.5 * dx for d in nn) / len(fl):.4f} {sum(s) / len(s) / dx:.4f}")
        if a.reach > 0 and pw:
            dw = nearest(pf, pw, a.reach)
            near = [cl for cl, d in zip(clumped, dw) if d < a.reach]
            far = [cl for cl, d in zip(clumped, dw) if d >= a.reach]
            line += (f" {len(near)} {sum(near) / max(1, len(near)):.4f}"
                     f" {len(far)} {sum(far) / max(1, len(far)):.4f}")
        print(line, flush=True)


if __name__ == "__main__":
    main()
