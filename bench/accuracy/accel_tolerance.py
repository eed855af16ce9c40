"""Tables of bench/accel_tolerance.sh. relax REF RUN...: t50, t20, tau, M/M0 and V at the end of
each run against REF. dry REF RUN: X/X0 against physical time, and its difference."""
import math
import sys


def load(name):
    return [[float(x) for x in line.split()] for line in open(name) if line.strip() and line[0] != "#"]


def crossing(rows, frac):
    g0 = rows[0][1]
    for a, b in zip(rows, rows[1:]):
        if b[1] < frac * g0 <= a[1]:
            # linear interpolation in log |psi_ext - psi_cell|
            w = math.log(a[1] / (frac * g0)) / math.log(a[1] / b[1])
            return a[0] + w * (b[0] - a[0])
    return float("nan")


def tau(rows, hi=0.6, lo=0.1):
    g0 = rows[0][1]
    pts = [(r[0], math.log(r[1])) for r in rows if lo * g0 < r[1] < hi * g0]
    n = len(pts)
    if n < 2:    # a run too short to relax to 60 % (TEND): no fit
        return float("nan")
    mt = sum(p[0] for p in pts) / n
    my = sum(p[1] for p in pts) / n
    b = sum((p[0] - mt) * (p[1] - my) for p in pts) / sum((p[0] - mt) ** 2 for p in pts)
    return -1.0 / b


def at(rows, t, col):
    for a, b in zip(rows, rows[1:]):
        if a[0] <= t <= b[0]:
            return a[col] + (b[col] - a[col]) * (t - a[0]) / (b[0] - a[0])
    return rows[-1][col]


def relax(ref, runs):
    r0 = load(ref)
    tend = min(r0[-1][0], *[load(f)[-1][0] for f in runs])
    base = [crossing(r0, 0.5), crossing(r0, 0.2), tau(r0), at(r0, tend, 3), at(r0, tend, 4)]
    print("| run | accel (last) | samples | t50 (s) | t20 (s) | tau (s) | M/M0 | V (m^3) | t50 | t20 | tau | M | V |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for f in [ref] + runs:
        r = load(f)
        v = [crossing(r, 0.5), crossing(r, 0.2), tau(r), at(r, tend, 3), at(r, tend, 4)]
        d = ["%+.2f %%" % (100 * (x / y - 1)) for x, y in zip(v, base)]
        print("| %s | %.4g | %d | %.1f | %.1f | %.1f | %.5f | %.5e | %s |" %
              (f[3:-4], r[-1][5], len(r), v[0], v[1], v[2], v[3], v[4], " | ".join(d)))


def dry(ref, run):
    a, b = load(ref), load(run)
    tend = min(a[-1][0], b[-1][0])
    print("| t (s) | X/X0 ref | X/X0 auto | difference |")
    print("|---:|---:|---:|---:|")
    worst = 0.0
    for k in range(1, 11):
        t = tend * k / 10
        xa, xb = at(a, t, 3), at(b, t, 3)
        worst = max(worst, abs(xb / xa - 1))
        print("| %.3g | %.5f | %.5f | %+.3f %% |" % (t, xa, xb, 100 * (xb / xa - 1)))
    print("max |difference| %.3f %%; output lines: ref %d, auto %d" % (100 * worst, len(a), len(b)))


if sys.argv[1] == "relax":
    relax(sys.argv[2], sys.argv[3:])
else:
    dry(sys.argv[2], sys.argv[3])
