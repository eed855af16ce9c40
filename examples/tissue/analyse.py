#!/usr/bin/env python3
"""Figures and tables of examples/tissue (README.md) from the outputs of in.tissue in FOLDER:

  drying_curve.png   the slab's X/X0 against physical time
  profile.png        each cell's X/X0 against the depth of its centre below the top face, at
                     several times (the layer means joined): dry crust over a wet core
  shrinkage.png      cell volume V/V0 and section area A/A0 against the cell's X/X0, by depth layer
  porosity.png       the slab's space outside the cells against its X/X0
  summary.txt        the numbers behind them (per layer, per output time)
  cut_fresh.png, cut_half.png, cut_dry.png
                     the slab cut by the plane y through the middle of its box (tools/cut_picture.py
                     on tissue.data and fresh.dump, half.dump, dry.dump): each cell's wall outline,
                     the sap near the plane coloured by its cell's X/X0, a scale bar
and the data files plotted (gnuplot): curve.dat, profile_K.dat, shrink_L.dat, cut_NAME_fluid.dump.

  python3 analyse.py FOLDER
"""
import os
import re
import subprocess
import sys


def blocks(path):
    """fix ave/time mode vector file: {step: [[row values], ...]}"""
    out, step, left = {}, None, 0
    for line in open(path):
        if line.startswith("#"):
            continue
        w = line.split()
        if left == 0:
            step, left = int(w[0]), int(w[1])
            out[step] = []
        else:
            out[step].append([float(v) for v in w[1:]])
            left -= 1
    return out


def dump(path):
    """LAMMPS custom dump (one frame): box and rows id mol type x y z"""
    lines = open(path).read().split("\n")
    box = [[float(v) for v in lines[5 + k].split()[:2]] for k in range(3)]
    rows = [line.split() for line in lines[9:] if line.strip()]
    return box, [(int(r[1]), int(r[2]), float(r[3]), float(r[4]), float(r[5])) for r in rows]


def depth_layers(depth0, v0):
    """(number of layers, each cell's layer; 0 at the top) from the cells' centre depths and volumes:
    as many layers as the slab has cells across (the data file's name is not needed), of equal
    thickness from the shallowest to the deepest centre"""
    n = len(depth0)
    nlayer = max(2, round((max(depth0) - min(depth0)) / (sum(v0) / n) ** (1 / 3)) + 1)
    lo, hi = min(depth0), max(depth0) + 1e-12
    return nlayer, [min(nlayer - 1, int((d - lo) / (hi - lo) * nlayer)) for d in depth0]


def cut_picture(name, ids, cells, time_of, xslab_of, air_text):
    """cut_NAME.png (tools/cut_picture.py) of NAME.dump: the slab cut by the plane y through the
    middle of its box, each cell's wall outline, the sap within half a spacing of the plane
    coloured by its cell's X/X0 (cells.dat at the dump's step; 1 for the fresh slab), a scale bar,
    the air, time and slab X/X0 in the title; the sap's dump with that column: cut_NAME_fluid.dump"""
    with open(f"{name}.dump") as f:
        lines = f.read().splitlines()
    step = int(lines[1])
    ymid = sum(float(v) for v in lines[6].split()[:2]) / 2.0
    x_of = dict(zip(ids, (r[2] for r in cells[step]))) if step in cells else {}
    sap = [line.split() for line in lines[9:] if line.split()[2:3] == ["1"]]
    with open(f"cut_{name}_fluid.dump", "w") as f:
        f.write("\n".join(lines[:3] + [str(len(sap))] + lines[4:8]) + "\nITEM: ATOMS id mol x y z X\n")
        f.writelines(f"{i} {m} {x} {y} {z} {x_of.get(int(m), 1.0):.6f}\n" for i, m, _, x, y, z in sap)
    if step in time_of:
        state = f"t = {time_of[step]:.0f} s, slab X/X0 = {xslab_of[step]:.3f}"
    else:
        state = "before the drying, X/X0 = 1"
    what = {"fresh": "fresh", "half": "half dry", "dry": "dry"}[name]
    tool = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "cut_picture.py")
    subprocess.run([sys.executable, tool, "tissue.data", f"{name}.dump", "--fluid", f"cut_{name}_fluid.dump",
                    "--color", "X", "--crange", "0:1", "--clabel", "X/X0 of the cell (moisture)",
                    "--plane", "y", "--at", repr(ymid), "--slab", "12e-6", "--out", f"cut_{name}.png", "--title",
                    f"{air_text}\\n{what}, {state}; cut at y = the box's middle"], check=True)


def main(folder):
    os.chdir(folder)
    slab = [[float(v) for v in line.split()] for line in open("slab.dat") if not line.startswith("#")]
    # the air that ran (in.tissue's first line of slab.dat: "# air: T = 333.15 K, RH 0.1, h_m 0.02 m/s,
    # cooling yes")
    air = re.search(r"T = (\S+) K, RH (\S+), h_m (\S+) m/s(, cooling (\S+))?", open("slab.dat").readline())
    surface = {"yes": ", surface cooled", "no": ", surface at the air's T"}.get(air.group(5), "") if air else ""
    air_text = (f"{float(air.group(1)) - 273.15:.0f} C, RH {air.group(2)}, h_m {air.group(3)} m/s{surface}"
                if air else "air not recorded")
    cells = blocks("cells.dat")       # mass, volume, X/X0, turgor, X, section area, wall area
    centres = blocks("centres.dat")   # centre z of the wall atoms
    steps = sorted(set(cells) & set(centres))
    time_of = {int(r[6]): r[0] for r in slab}
    xslab_of = {int(r[6]): r[1] for r in slab}
    thick_of = {int(r[6]): r[2] for r in slab}
    broken_of = {int(r[6]): int(r[4]) for r in slab}
    # the box's lateral lengths over their values when drying starts (in.tissue's lateral 1)
    boxl_of = {int(r[6]): (r[7], r[8]) if len(r) > 8 else (1.0, 1.0) for r in slab}
    steps = [s for s in steps if s in time_of]
    box, fresh = dump("fresh.dump")
    area = (box[0][1] - box[0][0]) * (box[1][1] - box[1][0])
    ztop = max(a[4] for a in fresh if a[1] == 2)
    s0 = steps[0]
    n = len(cells[s0])
    depth0 = [ztop - centres[s0][c][0] for c in range(n)]
    v0 = [cells[s0][c][1] for c in range(n)]
    a0 = [cells[s0][c][5] for c in range(n)]
    nlayer, layer = depth_layers(depth0, v0)
    out = open("summary.txt", "w")

    def say(text):
        print(text)
        out.write(text + "\n")

    say(f"{n} cells in {nlayer} depth layers; box {area ** 0.5 * 1e6:.0f} um square; "
        f"slab {thick_of[s0] * 1e6:.0f} um thick at the start of drying")
    say("\n# drying curve: step, t (s), slab X/X0, thickness (um), space outside the cells, "
        "broken junctions, box Lx/Lx0")
    with open("curve.dat", "w") as f:
        f.write("# t[s] X/X0 thickness[m] space_outside_cells Lx/Lx0\n")
        for s in steps:
            lx, ly = boxl_of[s]
            phi = 1 - sum(r[1] for r in cells[s]) / (area * lx * ly * thick_of[s])
            f.write(f"{time_of[s]:.6e} {xslab_of[s]:.6f} {thick_of[s]:.6e} {phi:.6f} {lx:.6f}\n")
            say(f"{s} {time_of[s]:.2f} {xslab_of[s]:.4f} {thick_of[s] * 1e6:.1f} {phi:.4f} {broken_of[s]} {lx:.4f}")
    # moisture profile at up to five times: each cell (points) and the layer means (lines)
    pick = [steps[round(k * (len(steps) - 1) / 4)] for k in range(5)] if len(steps) >= 5 else steps
    say("\n# moisture profile: layer mean X/X0 (layer 1 at the top) at t (s)")
    say("t " + " ".join(f"L{k + 1}" for k in range(nlayer)))
    for i, s in enumerate(pick):
        x = [cells[s][c][2] for c in range(n)]
        depth = [ztop - centres[s][c][0] for c in range(n)]
        with open(f"profile_{i}.dat", "w") as f:
            f.write(f"# t = {time_of[s]:.1f} s: depth[um] X/X0 of each cell, then a blank line and the layer means\n")
            for c in range(n):
                f.write(f"{depth[c] * 1e6:.3f} {x[c]:.6f}\n")
            f.write("\n\n")
            means = []
            for k in range(nlayer):
                m = [c for c in range(n) if layer[c] == k]
                means.append((sum(depth[c] for c in m) / len(m), sum(x[c] for c in m) / len(m)) if m else None)
                if m:
                    f.write(f"{means[-1][0] * 1e6:.3f} {means[-1][1]:.6f}\n")
        say(f"{time_of[s]:.1f} " + " ".join(f"{p[1]:.3f}" if p else "-" for p in means))
    # shrinkage by layer: every cell at every output
    say("\n# shrinkage at the end, by layer: mean X/X0, V/V0, section A/A0")
    last = steps[-1]
    for k in range(nlayer):
        members = [c for c in range(n) if layer[c] == k]
        with open(f"shrink_{k + 1}.dat", "w") as f:
            f.write("# X/X0 V/V0 A/A0 (section through the centre, normal z) of the layer's cells\n")
            for s in steps:
                for c in members:
                    f.write(f"{cells[s][c][2]:.6f} {cells[s][c][1] / v0[c]:.6f} "
                            f"{cells[s][c][5] / a0[c] if a0[c] > 0 else float('nan'):.6f}\n")
        if members:
            say(f"layer {k + 1} ({len(members)} cells): "
                f"{sum(cells[last][c][2] for c in members) / len(members):.6f} "
                f"{sum(cells[last][c][1] / v0[c] for c in members) / len(members):.3f} "
                f"{sum(cells[last][c][5] / a0[c] for c in members if a0[c] > 0) / max(1, sum(a0[c] > 0 for c in members)):.3f}")
    profiles = ", ".join(f"'profile_{i}.dat' index 0 with points pt 7 ps 0.5 lc {i + 1} notitle, "
                         f"'profile_{i}.dat' index 1 with linespoints lw 2 lc {i + 1} "
                         f"title 't = {time_of[s]:.0f} s'" for i, s in enumerate(pick))
    layers_v = ", ".join(f"'shrink_{k + 1}.dat' using 1:2 with points pt 7 ps 0.4 title 'layer {k + 1}'"
                         for k in range(nlayer))
    layers_a = ", ".join(f"'shrink_{k + 1}.dat' using 1:3 with points pt 7 ps 0.4 title 'layer {k + 1}'"
                         for k in range(nlayer))
    script = f"""set terminal pngcairo size 700,500 noenhanced font ",11"
set grid
set output 'drying_curve.png'
set xlabel 'physical time (s)'; set ylabel 'slab X/X0'
set title 'Drying curve: {air_text}, top face'
plot 'curve.dat' using 1:2 with linespoints lw 2 pt 7 notitle
set output 'profile.png'
set xlabel 'depth of the cell centre below the top face (um)'; set ylabel 'cell X/X0'
set title 'Moisture profile (points: cells; lines: layer means)'
set key bottom right
plot {profiles}
set output 'porosity.png'
set xlabel 'slab X/X0'; set ylabel 'space outside the cells, 1 - sum V / (A H)'
set title 'Intercellular space against moisture'
set xrange [*:*] reverse
plot 'curve.dat' using 2:4 with linespoints lw 2 pt 7 notitle
set xrange [*:*] noreverse
set terminal pngcairo size 1200,500 noenhanced font ",11"
set output 'shrinkage.png'
set multiplot layout 1,2 title 'Cell shrinkage by depth layer (layer 1 at the top)'
set xlabel 'cell X/X0'; set ylabel 'V/V0'; set title ''
set key top left
plot {layers_v}, x with lines dt 2 lc black title 'V/V0 = X/X0'
set ylabel 'section area A/A0'
plot {layers_a}, x**(2./3) with lines dt 2 lc black title '(X/X0)^(2/3)'
unset multiplot
"""
    open("plots.gp", "w").write(script)
    subprocess.run(["gnuplot", "plots.gp"], check=True)
    ids = sorted({a[0] for a in fresh if a[0] > 0})    # cell IDs, in the order of cells.dat's rows
    for name in ("fresh", "half", "dry"):
        if os.path.exists(f"{name}.dump"):
            cut_picture(name, ids, cells, time_of, xslab_of, air_text)
    if os.path.exists("final.txt"):
        f = open("final.txt").read().split()
        say(f"\nend: t = {float(f[0]):.1f} s, slab X/X0 = {float(f[1]):.4f}, thickness "
            f"{float(f[2]) * 1e6:.1f} um, broken junctions {f[3]}, water moved {float(f[4]):.4e} kg, "
            f"fluid mass change {float(f[5]):.4e} kg")
    out.close()


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else ".")
