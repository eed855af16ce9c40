#!/usr/bin/env python3
"""The bridging error of examples/tissue's drying (tissue_bridging.sh): each in.tissue output folder
against the last one given (the least bridged run) over their common physical time.

  python3 tissue_bridging.py RUN... REFERENCE

Per run: steps, wall-clock (wallclock.txt), physical time reached, accel range, the longest wall
edge over the shortest longest one (slab.dat's column 10), broken junctions; against the reference:
the top layer's mean X/X0 (examples/tissue/analyse.py's depth layers) at each of the run's outputs
against the reference's at the same time (linear in t), its largest relative difference, and the
largest relative difference of the water it lost (1 - X/X0, where the reference's is >= 0.05); the
layer moisture profile (layer means) at the last common output, its largest relative difference.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples", "tissue"))
from analyse import blocks, depth_layers, dump  # noqa: E402


def series(folder):
    """(t, accel, edge, broken, step rows of slab.dat; layer means of X/X0 at each of them)"""
    slab = [[float(v) for v in line.split()] for line in open(f"{folder}/slab.dat") if not line.startswith("#")]
    cells, centres = blocks(f"{folder}/cells.dat"), blocks(f"{folder}/centres.dat")
    _, fresh = dump(f"{folder}/fresh.dump")
    ztop = max(a[4] for a in fresh if a[1] == 2)
    rows = [r for r in slab if int(r[6]) in cells and int(r[6]) in centres]
    s0 = int(rows[0][6])
    depth0 = [ztop - c[0] for c in centres[s0]]
    nlayer, layer = depth_layers(depth0, [c[1] for c in cells[s0]])
    means = []
    for r in rows:
        x = [c[2] for c in cells[int(r[6])]]
        means.append([sum(x[c] for c in range(len(x)) if layer[c] == k) / max(1, layer.count(k))
                      for k in range(nlayer)])
    return rows, means


def at(t, rows, values):
    """values (one per row) at physical time t, linear between the rows' times"""
    ts = [r[0] for r in rows]
    for i in range(1, len(ts)):
        if ts[i] >= t:
            w = (t - ts[i - 1]) / (ts[i] - ts[i - 1]) if ts[i] > ts[i - 1] else 1.0
            return [a + w * (b - a) for a, b in zip(values[i - 1], values[i])]
    return values[-1]


def main(folders):
    ref_rows, ref_means = series(folders[-1])
    tref = ref_rows[-1][0]
    print("# run: steps, wall-clock, t_end (s), accel min-max, longest edge ratio max, broken junctions, "
          "top-layer X/X0 at the end, layer means at the end (top first)")
    for f in folders:
        rows, means = series(f)
        clock = open(f"{f}/wallclock.txt").read().strip() if os.path.exists(f"{f}/wallclock.txt") else "-"
        edge = max(r[9] for r in rows) if len(rows[0]) > 9 else float("nan")
        print(f"{f}: {int(rows[-1][6] - rows[0][6])} steps, {clock}, t_end {rows[-1][0]:.1f}, accel "
              f"{min(r[3] for r in rows):.3g}-{max(r[3] for r in rows):.3g}, edge {edge:.3f}, broken "
              f"{int(rows[-1][4])}, top {means[-1][0]:.4f}, layers " + " ".join(f"{m:.3f}" for m in means[-1]))
    print(f"\n# against {folders[-1]} up to t = {tref:.1f} s (its end): top-layer X/X0 largest relative "
          "difference |dX|/X_ref, of the water lost |dX|/(1 - X_ref) (1 - X_ref >= 0.05), at t; "
          "layer profile at the last common output: largest |dX|/X_ref and its layer")
    for f in folders[:-1]:
        rows, means = series(f)
        common = [(r, m) for r, m in zip(rows, means) if r[0] <= tref]
        worst_x, worst_lost, t_x, t_lost = 0.0, 0.0, 0.0, 0.0
        for r, m in common:
            ref = at(r[0], ref_rows, ref_means)
            d = abs(m[0] - ref[0])
            if d / ref[0] > worst_x:
                worst_x, t_x = d / ref[0], r[0]
            if 1 - ref[0] >= 0.05 and d / (1 - ref[0]) > worst_lost:
                worst_lost, t_lost = d / (1 - ref[0]), r[0]
        r, m = common[-1]
        ref = at(r[0], ref_rows, ref_means)
        prof = [abs(a - b) / b for a, b in zip(m, ref)]
        k = prof.index(max(prof))
        print(f"{f}: top layer {100 * worst_x:.2f} % (t = {t_x:.1f} s), water lost {100 * worst_lost:.2f} % "
              f"(t = {t_lost:.1f} s); profile at t = {r[0]:.1f} s: {100 * prof[k]:.2f} % (layer {k + 1}); "
              "run " + " ".join(f"{v:.4f}" for v in m) + " against " + " ".join(f"{v:.4f}" for v in ref))


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    main(sys.argv[1:])
