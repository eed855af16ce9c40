#!/usr/bin/env python3
"""The table of bench/speed/speed_against_error.sh, from the runs in the current folder: per TAG
dry_TAG.dat (in.drying's output lines), log.TAG (the drying run's thermo and loop time) and
TAG.time (ranks, wall-clock, load average at the start and end).
  speed_against_error.py [--nmed N] TAG... REF   (REF: the reference run's tag)"""
import argparse
import re
import statistics

XEND = 0.2


def rows(tag):
    """output lines of dry_TAG.dat as lists of floats"""
    return [[float(w) for w in line.split()] for line in open(f"dry_{tag}.dat") if not line.startswith("#")]


def crossing(r, col, value, xcol=1):
    """column xcol at the first output where column col falls to value, linear between outputs"""
    for a, b in zip(r, r[1:]):
        if b[col] <= value < a[col]:
            return a[xcol] + (value - a[col]) * (b[xcol] - a[xcol]) / (b[col] - a[col])
    return float("nan")


def results(tag):
    """turgor-loss X/X0, time (min) and section area at X/X0 = 0.2, drying steps, mean and min accel"""
    r = rows(tag)
    for w in r:
        w.append((w[7] + w[20] + w[23]) / 3)    # mean A/A0 of the planes z, x, y
    steps = r[-1][26] - r[0][26]
    return {"tlp": crossing(r, 3, 0.0), "t": crossing(r, 1, XEND, 0) / 60, "A": crossing(r, 1, XEND, len(r[0]) - 1),
            "steps": int(steps), "accel": r[-1][0] / (steps * 2e-8), "amin": min(w[27] for w in r[1:])}


def timing(tag, nmed):
    """atoms, drying loop time (s) and the median wall-clock of an output interval (s) over the
    first and the last nmed outputs of the drying run (the last thermo block of log.TAG)"""
    block, loop, atoms = [], 0.0, 0
    text = open(f"log.{tag}").read().splitlines()
    for i, line in enumerate(text):
        if line.startswith("Step CPU v_t"):
            block = []
            for w in (x.split() for x in text[i + 1:]):
                if not w or not w[0].isdigit():
                    break
                block.append((int(w[0]), float(w[1])))
        m = re.match(r"Loop time of (\S+) on \d+ procs for \d+ steps with (\d+) atoms", line)
        if m:
            loop, atoms = float(m.group(1)), int(m.group(2))
    d = [(b[1] - a[1]) / (b[0] - a[0]) for a, b in zip(block, block[1:])]    # s per step
    return atoms, loop, statistics.median(d[:nmed]), statistics.median(d[-nmed:])


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--nmed", type=int, default=8)
    p.add_argument("tags", nargs="+")
    a = p.parse_args()
    *tags, refname = a.tags
    ref = results(refname)
    print(f"| run | ranks | accel (mean; min) | drying steps | wall-clock (s) | drying loop (s) | particle-steps/s/core | "
          f"turgor-loss X/X0 (error) | t at X/X0 {XEND} (min) (error) | A/A0 at {XEND} (error) | "
          f"cost per particle-step turgid / dry (us), ratio | load average start, end |")
    print("|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---|")
    for tag in tags + [refname]:
        r = results(tag)
        np, wall, l0, l1 = open(f"{tag}.time").read().split()
        np = int(np)
        atoms, loop, c0, c1 = timing(tag, a.nmed)
        rate = atoms * r["steps"] / loop / np
        err = {k: "(ref)" if tag == refname else f"({r[k] / ref[k] - 1:+.1%})" for k in ("tlp", "t", "A")}
        print(f"| {tag} | {np} | {r['accel']:.3g}; {r['amin']:.3g} | {r['steps']} | {float(wall):.0f} | {loop:.0f} | "
              f"{rate:.3g} | {r['tlp']:.3f} {err['tlp']} | {r['t']:.1f} {err['t']} | {r['A']:.3f} {err['A']} | "
              f"{c0 * np / atoms * 1e6:.3f} / {c1 * np / atoms * 1e6:.3f}, {c1 / c0:.2f} | {l0}, {l1} |")


if __name__ == "__main__":
    main()
