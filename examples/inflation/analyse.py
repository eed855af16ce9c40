#!/usr/bin/env python3
"""Tables of the inflation example (run by run.sh in out/): summary.txt (Fig. 5 runs) and
physiological.txt (relaxation time against V / (A L_P (eps + pi)))."""
import math
import re

RHOW = 1000.0           # density of the water crossing the wall (fix cell/turgor default), kg/m^3
GT0 = 18e6 * 1e-6       # G t0 of potentials/apple.cellsph, N/m


def series(tag):
    """columns of mass_TAG.dat: t, M/M0, P_T, pi, lambda_area, lambda_volume, |psi imbalance|, P_L,
    P_SPH"""
    rows = []
    with open(f"mass_{tag}.dat") as f:
        for line in f:
            if not line.startswith("#"):
                rows.append([float(v) for v in line.split()])
    return rows


def final(tag):
    """final_TAG.txt: final LP t M/M0 P_T pi lambda_area lambda_volume hk P_L P_SPH"""
    with open(f"final_{tag}.txt") as f:
        v = f.read().split()
    keys = ["LP", "t", "m", "P", "pi", "lam", "lamv", "hk", "PL", "PS"]
    return dict(zip(keys, map(float, v[1:])))


def fresh(tag):
    """M0, V0, A0 from the 'fresh cell:' line of TAG.log"""
    with open(f"{tag}.log") as f:
        for line in f:
            if line.startswith("fresh cell:"):
                nums = re.findall(r"= ([-+0-9.eE]+)", line)
                return float(nums[0]), float(nums[1]), float(nums[2])
    raise SystemExit(f"{tag}.log has no 'fresh cell:' line")


def t_frac(rows, mend, frac):
    """first time at which M/M0 - 1 reaches frac (M_end/M0 - 1)"""
    for r in rows:
        if r[1] - 1 >= frac * (mend - 1):
            return r[0]
    return float("nan")


def membrane_eps(lam, r0):
    """eps = V dP/dV = (lam/3) dP/dlam of P = (2 G t0 / R0)(1/lam - 1/lam^7)"""
    return lam / 3 * 2 * GT0 / r0 * (-lam**-2 + 7 * lam**-8)


def fit(xs, ys):
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    sxx = sum((x - mx) ** 2 for x in xs)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx


def summary():
    lines = ["# Fig. 5 runs (apple set, pi = 200 kPa fixed, pure water, dt = 2e-8 s, N = 10, accel 1)",
             "# P_T: turgor (the fluid's load on the wall, what fix cell/turgor balances against pi); "
             "P_L: the turgor the wall carries (bond virial); P_SPH: mean SPH pressure",
             "# t50, t90: time to 50 and 90 % of the run's own uptake; overshoot: max M / final M - 1; "
             "hk: stiffness of the transfer step (an explicit update is unstable above 2)",
             "# L_P      t_end[s]   M/M0      P_T[kPa]  P_L[kPa]  P_SPH[kPa] lam_area  lam_vol   t50[s]     "
             "t90[s]     overshoot  hk"]
    for lp in ["2.5e-4", "2.5e-5", "2.5e-6", "2.5e-7"]:
        tag = f"LP{lp}"
        rows, f = series(tag), final(tag)
        over = max(r[1] for r in rows) / f["m"] - 1
        lines.append(f"{lp:8s} {f['t']:10.3e} {f['m']:9.5f} {f['P'] / 1e3:9.2f} {f['PL'] / 1e3:9.2f} {f['PS'] / 1e3:10.2f} {f['lam']:9.5f} "
                     f"{f['lamv']:9.5f} {t_frac(rows, f['m'], 0.5):10.3e} "
                     f"{t_frac(rows, f['m'], 0.9):10.3e} {over:9.1e} {f['hk']:8.3g}")
    ms = [final(f"LP{lp}")["m"] for lp in ["2.5e-4", "2.5e-5", "2.5e-6", "2.5e-7"]]
    lams = [final(f"LP{lp}")["lam"] for lp in ["2.5e-4", "2.5e-5", "2.5e-6", "2.5e-7"]]
    lines.append(f"# spread over L_P, (max - min)/mean: steady M/M0 "
                 f"{(max(ms) - min(ms)) / (sum(ms) / 4):.2e}, area stretch "
                 f"{(max(lams) - min(lams)) / (sum(lams) / 4):.2e}")
    _, _, a0 = fresh("LP2.5e-6")
    r0 = math.sqrt(a0 / (4 * math.pi))
    lo, hi = 1.0, 7 ** (1 / 6)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        p = 2 * GT0 / r0 * (1 / mid - mid**-7)
        lo, hi = (mid, hi) if p < 2e5 else (lo, mid)
    lines.append(f"# thin Neo-Hookean membrane at 200 kPa (R0 = {r0:.4e} m from the wall area): "
                 f"lambda = {lo:.5f}")
    return "\n".join(lines) + "\n"


def physiological(tags):
    lines = ["# physiological L_P = 1e-13 m/(s Pa), van 't Hoff pi = pi0 M0/M, time-scale bridging",
             "# tau_sim: least-squares fit of ln(pi - P_T) against t over pi - P_T = 40 ... 4 kPa (above the size of the SPH rearrangement jumps, ~1 kPa)",
             "# tau_law = V / (A L_P (eps + pi)) at the end of the run, eps = V dP/dV of the membrane "
             "law at the final area stretch",
             "# accel    t_end[s] (min)     M/M0(1200s) M/M0(2400s) M/M0(end)  P_T[kPa]  pi[kPa]   "
             "lambda    tau_sim[s] tau_law[s] eps[MPa] tau_sim/tau_law"]
    for tag, accel in tags:
        rows, f = series(tag), final(tag)
        _, v0, a0 = fresh(tag)
        win = [r for r in rows if 4e3 < r[3] - r[2] < 4e4]
        tau_sim = -1 / fit([r[0] for r in win], [math.log(r[3] - r[2]) for r in win])
        r0 = math.sqrt(a0 / (4 * math.pi))
        eps = membrane_eps(f["lam"], r0)
        vol, area, pi = v0 * f["lamv"] ** 3, a0 * f["lam"] ** 2, f["pi"]
        tau_law = vol / (area * 1e-13 * (eps + pi))

        def at(t):
            return min(rows, key=lambda r: abs(r[0] - t))[1]
        lines.append(
            f"{accel:8s} {f['t']:8.0f} ({f['t'] / 60:4.1f})  {at(1200):10.5f}  {at(2400):10.5f} "
            f"{f['m']:10.5f} {f['P'] / 1e3:9.2f} {pi / 1e3:9.2f} {f['lam']:9.5f} {tau_sim:9.1f} "
            f"{tau_law:10.1f} {eps / 1e6:8.3f} {tau_sim / tau_law:8.3f}")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    import sys
    if "summary" in sys.argv:
        open("summary.txt", "w").write(summary())
    if "physiological" in sys.argv:
        open("physiological.txt", "w").write(
            physiological([("phys4e7", "4e7"), ("phys1e7", "1e7"), ("phys2.5e6", "2.5e6")]))
