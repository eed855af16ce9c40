#!/usr/bin/env python3
"""Summary of the drying example (run by run.sh in out/): for each run TAG (dry_TAG.dat,
tlp_TAG.txt, intersections_TAG.txt, log.TAG) the drying time, the turgor loss point, the section
descriptors and volume at X/X0 = 0.5 and at the end against Karunasena et al. 2014 (dried Gala
apple: area -60 %, Feret -40 %, perimeter -30 %, roundness and elongation +5 %, compactness
unchanged), and the checks: fluid outside the wall, wall self-intersections, water accounting."""
import re
import sys

# columns of dry_TAG.dat (in.drying)
COLS = ("t X X_db PT pi PW V A P F round elong compact wrink out free aw dMdt moved dMfluid").split()
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
    print("drying of one turgid apple cell in air, RH 0.15 (in.drying); values relative to the turgid cell")
    print("section: plane z through the volume centroid (compute cell/shape)")
    for tag in tags:
        rs = rows(tag)
        r0, half, end = rs[0], at(rs, 0.5), rs[-1]
        tlp = first_line(f"tlp_{tag}.txt")
        inter = first_line(f"intersections_{tag}.txt")
        acct = max(abs(r["moved"] - r["dMfluid"]) for r in rs) / abs(rs[-1]["dMfluid"] or 1)
        print(f"\n{tag}: X/X0 = {end['X']:.3f} after {end['t'] / 60:.1f} min of physical time "
              f"(X = {end['X_db']:.3f} kg/kg); wall-clock {wall_time(tag)} s")
        if tlp != "n/a":
            print(f"  turgor loss point (P_T <= 0): X/X0 = {float(tlp[1]):.3f} at {float(tlp[0]) / 60:.1f} min")
        print("  quantity          X/X0=0.5   end    apple (Karunasena 2014, dried)")
        for key, name in (("A", "section area"), ("P", "perimeter"), ("F", "Feret"), ("V", "volume")):
            ref = f"{APPLE[key]:.2f}" if key in APPLE else "-"
            print(f"  {name:16s}  {half[key]:8.3f}  {end[key]:6.3f}   {ref}")
        for key, name in (("round", "roundness"), ("elong", "elongation"), ("compact", "compactness")):
            print(f"  {name:16s}  {half[key] / r0[key]:8.3f}  {end[key] / r0[key]:6.3f}   "
                  f"{'1.05' if key != 'compact' else '1.00'}  (relative to the start)")
        print(f"  wrinkling (wall / hull area) {half['wrink']:.3f} at X/X0 = 0.5, {end['wrink']:.3f} at the end;"
              f" fluid-free volume {end['free']:.3f} of V at the end")
        print(f"  checks: fluid atoms outside the wall at most {max(r['out'] for r in rs):.0f}; "
              f"wall self-intersections at most {inter[0] if inter != 'n/a' else 'n/a'} triangle pairs; "
              f"|water moved - fluid mass change| / water lost at most {acct:.1e}")


if __name__ == "__main__":
    main(sys.argv[1:])
