#!/usr/bin/env python3
"""Summary of the drying example (run by run.sh in out/): for each run TAG (dry_TAG.dat,
intersections_TAG.txt, log.TAG, wall_TAG.dump, fluid_TAG.dump), with the air, cooling and accel
that ran read from the first line of dry_TAG.dat (in.drying writes it), the drying time, the
turgor loss point, the section descriptors (the mean and spread of the sections x, y, z through
the centroid; the 13-plane means, with the perimeter of each section's convex hull: the outline
that bridges the folds) and volume at X/X0 = 0.5 and at the end against Karunasena et al. 2014 (dried Gala
apple: area -60 %, Feret -40 %, perimeter -30 %, roundness and elongation +5 %, compactness
unchanged), the checks: fluid outside the wall, wall self-intersections, water accounting, and
the fluid in tension (stability.TAG.txt, one line per snapshot): the nearest-neighbour distance of
the fluid atoms (min and mean, and the share of atoms within half the mean of another: clumping
by the tensile instability) and the share of wall atoms with a fluid atom within the adhesion's
reach (the protoplast held on the wall). It also writes figures.gp (gnuplot: fig_drying_curve.png,
fig_shrinkage.png, fig_tension.png, each run named by its air) and, for the pictures run.sh draws
with tools/cut_picture.py, cut_TAG_NAME.step: the step of the snapshot (matched to the output line
of the same step) and the picture's title, for NAME fresh, tlp (the turgor loss point), half
(X/X0 <= 0.5) and dry (the last).

  python3 analyse.py TAG...  (in the folder of the runs)"""
import math
import os
import re
import statistics
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from lammps_dump import grid, near, positions, snapshots  # noqa: E402
from section_planes import at_x, mean_se, relative, x_by_step  # noqa: E402

# columns of dry_TAG.dat (in.drying)
COLS = ("t X X_db PT pi PW V A P F round elong compact wrink out free aw dMdt moved dMfluid "
        "Ax Px Fx Ay Py Fy step accel Ts Wwall imbalance").split()
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


def stability(tag, reach, rs):
    """per wall and fluid snapshot: step, X/X0, the smallest and the mean fluid nearest-neighbour
    distance over dx = (M / (rho0 N))^(1/3), the spacing of N atoms at the water density with the
    fluid mass M of that moment (from M0 in log.TAG and the mass change of the output line of the
    same step), the share of fluid atoms within dx/2 of another, the share of wall atoms with fluid
    within reach"""
    with open(f"log.{tag}") as f:
        m0 = float(re.search(r"turgid cell: M0 = ([0-9.eE+-]+) kg", f.read()).group(1))
    by_step = {int(r["step"]): r for r in rs}
    out = []
    for (step, wc, wr), (_, fc, fr) in zip(snapshots(f"wall_{tag}.dump"), snapshots(f"fluid_{tag}.dump")):
        if step not in by_step:
            continue
        wall, fluid = positions(wc, wr), positions(fc, fr)
        row = by_step[step]
        dx = ((m0 + row["dMfluid"]) / (1000.0 * len(fluid))) ** (1 / 3)
        cells = grid(fluid, 2.0 * dx)
        nn = [min(min((math.dist(p, fluid[j]) for j in near(cells, p, 2.0 * dx) if j != i),
                      default=2.0 * dx), 2.0 * dx) / dx for i, p in fluid.items()]
        fcells = grid(fluid, reach)
        held = sum(any(math.dist(w, fluid[j]) < reach for j in near(fcells, w, reach))
                   for w in wall.values()) / len(wall)
        out.append((step, row["X"], min(nn), statistics.mean(nn), sum(d < 0.5 for d in nn) / len(nn),
                    held))
    return out


def conditions(tag):
    """the air, cooling and accel of a run, from the first line of dry_TAG.dat ("# drying at T =
    343.15 K, RH 0.15, h_m 0.02 m/s on 0.01 of the wall, cooling yes, accel auto 0.05, dt ..."):
    (short name for a legend, the whole text)"""
    with open(f"dry_{tag}.dat") as f:
        head = f.readline()
    m = re.search(r"T = (\S+) K, RH (\S+), h_m (\S+) m/s on (\S+) of the wall, cooling (\S+), "
                  r"accel (.*?), dt", head)
    if not m:
        return tag, f"{tag} (conditions not recorded)"
    t, rh, hm, area, cooling, accel = m.groups()
    short = f"{float(t) - 273.15:g} C, RH {rh}"
    surface = "surface cooled by evaporation" if cooling == "yes" else "surface at the air's T"
    return short, f"{short}, h_m {hm} m/s on {area} of the wall, {surface}, accel {accel}"


def cuts(tag, rs, tlp, name):
    """cut_TAG_NAME.step for the pictures (run.sh, tools/cut_picture.py): the step of the wall
    snapshot of the output line chosen by X/X0, and the picture's title: fresh (the first line),
    tlp (the turgor loss point), half (the first with X/X0 <= 0.5) and dry (the last)"""
    want = {"fresh": rs[0], "tlp": tlp, "half": next((r for r in rs if r["X"] <= 0.5), None),
            "dry": rs[-1]}
    what = {"fresh": "turgid", "tlp": "turgor loss point", "half": "half dry", "dry": "dry"}
    steps = {step for step, _, _ in snapshots(f"wall_{tag}.dump")}
    for key, r in want.items():
        if r is not None and int(r["step"]) in steps:
            with open(f"cut_{tag}_{key}.step", "w") as f:
                f.write(f"{int(r['step'])}\n{name}\\n{what[key]}, t = {r['t'] / 60:.1f} min, "
                        f"X/X0 = {r['X']:.3f}\n")


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


def dt_of(tag):
    """the run's time step (s), from the first line of dry_TAG.dat"""
    with open(f"dry_{tag}.dat") as f:
        return float(re.search(r"dt (\S+),", f.readline()).group(1))


def figures(tags, names):
    """figures.gp: the drying curves, the sections and the fluid in tension of every run, each
    named by its air (the legend) and the rest of its conditions (the title)"""
    def lines(fmt):
        return ", ".join(fmt.format(f=f"dry_{t}.dat", n=names[t], lc=i + 1) for i, t in enumerate(tags))
    # the conditions but the air (h_m, area, cooling, accel), if all runs share them
    rest = {conditions(t)[1].split(", ", 2)[-1] for t in tags}
    common = rest.pop() if len(rest) == 1 else "each run's conditions in summary.txt"
    apple = ("'-' using 1:2 with points pt 2 ps 3 lw 3 lc rgb 'black' title 'apple, dried: {0}'\n"
             "{1}\ne")
    planes = [t for t in tags if os.path.exists(f"planes_{t}.txt")]
    stab = [t for t in tags if os.path.exists(f"stability_{t}.txt")]

    def plane(col, what="13 planes", dt=2):
        return "".join(f", 'planes_{t}.txt' using 1:{col} with lines dt {dt} lw 3 lc {tags.index(t) + 1} "
                       f"title '{names[t]}, {what}'" for t in planes)
    gp = [
        "set terminal pngcairo size 1400,600 noenhanced font ',11'",
        "set output 'fig_drying_curve.png'",
        f"set multiplot layout 1,2 title \"Drying of one apple cell in air\\n{common}\"",
        "set grid", "set xlabel 'physical time (min)'", "set ylabel 'X / X0'", "set key top right",
        "plot " + lines("'{f}' using ($1/60):2 with lines lw 2 lc {lc} title '{n}'"),
        "set ylabel 'pressure (kPa)'", "set xlabel 'X / X0'", "set xrange [1:0]",
        "plot " + lines("'{f}' using 2:($4/1e3) with lines lw 2 lc {lc} title 'turgor P_T, {n}'") + ", " +
        lines("'{f}' using 2:($5/1e3) with lines dt 2 lc {lc} title 'osmotic pressure, {n}'"),
        "unset multiplot",
        "set terminal pngcairo size 1400,1000 noenhanced font ',11'", "set output 'fig_shrinkage.png'",
        "set multiplot layout 2,2 title \"Sections through the cell centre and volume against X/X0 "
        f"({common})\\ncrosses: Karunasena et al. 2014 (dried Gala apple)\"",
        "set xrange [1:0]", "set yrange [0:1.6]", "set ylabel 'relative to the turgid cell'",
        "set key bottom left",
        "set title 'section area (plane z; dashed: mean of 13 planes)'",
        "plot " + lines("'{f}' using 2:8 with lines lw 2 lc {lc} title '{n}'") + plane(2) + ", " +
        apple.format("-60 %", "0.2 0.4"),
        "set title 'perimeter (plane z; dashed: mean of 13 planes; dotted: their convex hulls)'",
        "plot " + lines("'{f}' using 2:9 with lines lw 2 lc {lc} title '{n}'") + plane(3) +
        plane(5, "hull, 13 planes", 3) + ", " +
        apple.format("-30 %", "0.2 0.7"),
        "set title 'Feret diameter (plane z; dashed: mean of 13 planes)'",
        "plot " + lines("'{f}' using 2:10 with lines lw 2 lc {lc} title '{n}'") + plane(4) + ", " +
        apple.format("-40 %", "0.2 0.6"),
        "set title 'volume (wall-enclosed; solid) and wrinkling (dashed)'",
        "plot " + lines("'{f}' using 2:7 with lines lw 2 lc {lc} title 'V/V0, {n}'") + ", " +
        lines("'{f}' using 2:14 with lines dt 2 lw 2 lc {lc} title 'wrinkling, {n}'") +
        ", x with lines dt 3 lc rgb 'gray' title 'V/V0 = X/X0'",
        "unset multiplot",
    ]
    if stab:
        def st(fmt):
            return ", ".join(fmt.format(f=f"stability_{t}.txt", n=names[t], lc=tags.index(t) + 1) for t in stab)
        gp += [
            "set terminal pngcairo size 1400,600 noenhanced font ',11'", "set output 'fig_tension.png'",
            f"set multiplot layout 1,2 title \"The fluid in tension ({common})\\ndx = spacing of the "
            "fluid mass at the water density\"",
            "set xrange [1:0]", "set yrange [0:1.05]", "set xlabel 'X / X0'", "set ylabel ''",
            "set key bottom left", "set title 'fluid nearest-neighbour distance / dx (solid: smallest; dashed: mean)'",
            "plot " + st("'{f}' using 2:3 with lines lw 2 lc {lc} title 'smallest, {n}'") + ", " +
            st("'{f}' using 2:4 with lines dt 2 lw 2 lc {lc} title 'mean, {n}'"),
            "set title 'solid: fluid atoms within dx/2 of another; dashed: wall atoms holding sap'",
            "plot " + st("'{f}' using 2:5 with lines lw 2 lc {lc} title 'within dx/2, {n}'") + ", " +
            st("'{f}' using 2:6 with lines dt 2 lw 2 lc {lc} title 'held, {n}'"),
            "unset multiplot",
        ]
    with open("figures.gp", "w") as f:
        f.write("\n".join(gp) + "\n")


def main(tags):
    print("drying of one turgid apple cell in air (in.drying); values relative to the turgid cell")
    names = {}
    print("section: plane z through the volume centroid (compute cell/shape); sections x, y, z; and the "
          "mean of 13 planes (tools/section_planes.lmp) +- its standard error")
    for tag in tags:
        rs = rows(tag)
        r0, half, end = rs[0], at(rs, 0.5), rs[-1]
        tlp = next((r for r in rs if r["PT"] <= 0.0), None)
        inter = first_line(f"intersections_{tag}.txt")
        acct = max(abs(r["moved"] - r["dMfluid"]) for r in rs) / abs(rs[-1]["dMfluid"] or 1)
        walls = any(r.get("Wwall", 0.0) for r in rs)
        if walls:  # wallwater: moved - dM_sap - W_wall stays at -W0 (the walls' first water)
            acct = max(abs(r["imbalance"] - r0["imbalance"]) for r in rs) / abs(rs[-1]["dMfluid"] or 1)
        short, whole = conditions(tag)
        names[tag] = short
        print(f"\n{tag}: {whole}")
        steps = int(end["step"] - r0["step"])
        print(f"  X/X0 = {end['X']:.3f} after {end['t'] / 60:.1f} min of physical time "
              f"(X = {end['X_db']:.3f} kg/kg), {steps} drying steps (mean accel "
              f"{end['t'] / (steps * dt_of(tag)):.3g}); surface at {rs[-1]['Ts'] - 273.15:.1f} C at "
              f"the end; wall-clock {wall_time(tag)} s")
        if tlp:
            print(f"  turgor loss point (P_T <= 0): X/X0 = {tlp['X']:.3f} at {tlp['t'] / 60:.1f} min")
        cuts(tag, rs, tlp, whole.split(", accel")[0].replace(", h_m", "\\nh_m"))
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
                f.write("# X/X0 then the mean over 13 planes of A/A0 P/P0 F/F0 H/H0 (H: the perimeter of "
                        "the section's convex hull; tools/section_planes.lmp)\n")
                for step, *values in series:
                    if step in xs:
                        f.write("%.6f" % xs[step] + "".join(" %.6f" % mean_se(v)[0] for v in values) + "\n")
            mid, fin = at_x(series, xs, 0.5), at_x(series, xs, end["X"])
            if mid and fin:
                for k, (key, name) in enumerate((("A", "section area"), ("P", "perimeter"), ("F", "Feret"),
                                                 ("P", "hull perimeter"))):
                    (hm, hs, _), (em, es, _) = mean_se(mid[k]), mean_se(fin[k])
                    print(f"  {name:16s}  {hm:.3f}±{hs:.3f}  {em:.3f}±{es:.3f}   {APPLE[key]:.2f}   13 planes")
        for key, name in (("round", "roundness"), ("elong", "elongation"), ("compact", "compactness")):
            print(f"  {name:16s}  {half[key] / r0[key]:8.3f}  {end[key] / r0[key]:6.3f}   "
                  f"{'1.05' if key != 'compact' else '1.00'}  (relative to the start)")
        print(f"  wrinkling (wall / hull area) {half['wrink']:.3f} at X/X0 = 0.5, {end['wrink']:.3f} at the end;"
              f" fluid-free volume {end['free']:.3f} of V at the end")
        print(f"  checks: fluid atoms outside the wall at most {max(r['out'] for r in rs):.0f}; "
              f"wall self-intersections at most {inter[0] if inter != 'n/a' else 'n/a'} triangle pairs; "
              f"|water moved - {'sap and wall water change (from the first output)' if walls else 'fluid mass change'}| / water lost at most {acct:.1e}")
        try:
            st = stability(tag, reach_of(tag), rs)
        except (OSError, AttributeError):
            st = None
        if not st:
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
    figures(tags, names)


if __name__ == "__main__":
    main(sys.argv[1:])
