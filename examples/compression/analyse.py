#!/usr/bin/env python3
"""Tables of the compression scene (run.sh), from out/: analyse.py SPEED... (m/s; the last is the
reference for rate independence, the one with hold_*.dat is the hold).

Writes fd_v<SPEED>.dat (one line per output step of compression and pause):
  delta[m] strain F[N] P_W[Pa] P_T[Pa] A_in A_trib A_out A_hull[m^2] V/V0 KE[J] time[s] n_contact
and holdfd_v<SPEED>.dat (the hold):
  t_phys[s] F[N] P_W[Pa] P_T[Pa] A_in A_trib[m^2] V/V0 M/M0 pi[Pa] A_out[m^2] n_contact fluid_outside
    fluid_free_volume[m^3]
F = the plate force (mean of the two plates), areas the mean of the two plates (contact_area.py),
V0 the turgid cell's volume. Prints the summary tables (README.md).
"""
import math
import os
import sys


def rows(path):
    with open(path) as f:
        return [[float(x) for x in l.split()] for l in f if l.strip() and not l.startswith("#")]


def interp(xs, ys, x):
    for i in range(1, len(xs)):
        if xs[i - 1] <= x <= xs[i] and xs[i] > xs[i - 1]:
            w = (x - xs[i - 1]) / (xs[i] - xs[i - 1])
            return ys[i - 1] + w * (ys[i] - ys[i - 1])
    return None


def compression(tag):
    comp = rows(f"compress_{tag}.dat")
    area = {int(r[0]): r for r in rows(f"area_{tag}.txt")}
    V0 = comp[0][9]
    out = []
    for r in comp:
        a = area.get(int(r[0]))
        if a is None:
            continue
        F = (r[5] - r[4]) / 2
        mean = lambda i: (a[i] + a[i + 5]) / 2
        out.append(dict(delta=r[2], strain=r[3], F=F, PW=r[7], PT=r[6], Ain=mean(2), Atrib=mean(3),
                        Aout=mean(4), Ahull=mean(5), VV0=r[9] / V0, KE=r[16],
                        t=r[1], n=(a[1] + a[6]) / 2, outside=r[12], free=r[13], A=r[10]))
    with open(f"fd_{tag}.dat", "w") as f:
        f.write("# delta[m] strain F[N] P_W[Pa] P_T[Pa] A_in[m2] A_trib[m2] A_out[m2] A_hull[m2] "
                "V/V0 KE[J] time[s] n_contact\n")
        for d in out:
            f.write(" ".join(f"{d[k]:.8e}" for k in ("delta", "strain", "F", "PW", "PT", "Ain", "Atrib",
                                                     "Aout", "Ahull", "VV0", "KE", "t", "n")) + "\n")
    return out, V0


def main():
    tags = [f"v{s}" for s in sys.argv[1:]]
    data = {t: compression(t) for t in tags}
    ref = tags[-1]
    d, V0 = data[ref]
    nmax = max(i for i, x in enumerate(d) if x["strain"] <= d[-1]["strain"] - 1e-9 or i == 0)
    imax = next(i for i, x in enumerate(d) if x["strain"] >= 0.5 - 1e-6)
    print(open("turgid.txt").read().strip())
    print()
    print(f"## Plate force against turgor x contact area ({ref}, sealed; areas: mean of the two plates)")
    print()
    print("| strain | delta (um) | F (mN) | P_W (kPa) | n contact | A_in | A_trib | A_out | A_hull (1e-9 m^2) "
          "| F/(P_W A_trib) - 1 | half band (A_out-A_in)/2A_trib | F/(P_W A_in) - 1 | V/V0 |")
    print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    marks = [0.1, 0.2, 0.3, 0.4, 0.5]
    picked = [min(d[:imax + 1], key=lambda x: abs(x["strain"] - m)) for m in marks] + [d[-1]]
    for k, x in enumerate(picked):
        label = f"{x['strain']:.3f}" + (" (end of pause)" if k == len(picked) - 1 else "")
        print(f"| {label} | {x['delta']*1e6:.1f} | {x['F']*1e3:.4f} | {x['PW']/1e3:.1f} | {x['n']:.0f} "
              f"| {x['Ain']*1e9:.3f} | {x['Atrib']*1e9:.3f} | {x['Aout']*1e9:.3f} | {x['Ahull']*1e9:.3f} "
              f"| {x['F']/(x['PW']*x['Atrib'])-1:+.4f} | {(x['Aout']-x['Ain'])/(2*x['Atrib']):.4f} "
              f"| {x['F']/(x['PW']*x['Ain'])-1:+.4f} | {x['VV0']:.5f} |")
    band = [x for x in d[:imax + 1] if x["strain"] >= 0.1]
    dev = [x["F"] / (x["PW"] * x["Atrib"]) - 1 for x in band]
    inside = sum(1 for x in band if x["Ain"] <= x["F"] / x["PW"] <= x["Aout"])
    print()
    print(f"strain 0.1-0.5, {len(band)} output steps: F/(P_W A_trib) - 1 from {min(dev):+.4f} to {max(dev):+.4f} "
          f"(mean {sum(dev)/len(dev):+.4f}); F/P_W within [A_in, A_out] at {inside} of {len(band)}")
    print(f"fluid outside the wall: max {max(x['outside'] for x in d):.0f}; "
          f"V/V0 at 50 %: {d[imax]['VV0']:.5f}; fluid-free volume {d[0]['free']*1e18:.1f} -> {d[imax]['free']*1e18:.1f} um^3 "
          f"(fluid volume change {((d[imax]['VV0']*V0 - d[imax]['free']) / (V0 - d[0]['free']) - 1)*100:+.3f} %)")

    print()
    print(f"## Rate independence (reference {ref})")
    print()
    print("| speed (m/s) | steps | max abs F/F_ref - 1, strain 0.1-0.5 | at 0.25 | at 0.5 | KE at 50 % (J) | F after pause / F at 50 % - 1 |")
    print("|---:|---:|---:|---:|---:|---:|---:|")
    rs = [x["strain"] for x in d[:imax + 1]]
    rf = [x["F"] for x in d[:imax + 1]]
    for t in tags:
        dd, _ = data[t]
        im = next(i for i, x in enumerate(dd) if x["strain"] >= 0.5 - 1e-6)
        devs, at = [], {}
        for x in dd[:im + 1]:
            if x["strain"] < 0.1:
                continue
            f = interp(rs, rf, x["strain"])
            if f:
                devs.append(abs(x["F"] / f - 1))
        for s in (0.25, 0.5):
            fv = interp([x["strain"] for x in dd[:im + 1]], [x["F"] for x in dd[:im + 1]], s - 1e-9)
            at[s] = fv / interp(rs, rf, s - 1e-9) - 1
        steps = int(round(dd[im]["t"] / 2e-8))
        print(f"| {t[1:]} | {steps} | {max(devs) if t != ref else 0:.4f} | {at[0.25]:+.4f} | {at[0.5]:+.4f} "
              f"| {dd[im]['KE']:.2e} | {dd[-1]['F']/dd[im]['F']-1:+.4f} |")

    for t in tags:
        if not os.path.exists(f"hold_{t}.dat"):
            continue
        hold = rows(f"hold_{t}.dat")
        area = {int(r[0]): r for r in rows(f"areahold_{t}.txt")}
        M00 = 1.0
        h = []
        for r in hold:
            a = area.get(int(r[0]))
            if a is None:
                continue
            h.append(dict(t=r[1], F=(r[3] - r[2]) / 2, PW=r[5], PT=r[4], Ain=(a[2] + a[7]) / 2,
                          Atrib=(a[3] + a[8]) / 2, VV0=r[7] / V0, MM0=r[9] / M00, pi=r[6],
                          Aout=(a[4] + a[9]) / 2, n=(a[1] + a[6]) / 2, outside=r[10], free=r[11],
                          V=r[7], A=r[8]))
        # the first line: the end of the sealed pause (the hold starts there)
        e = data[t][0][-1]
        h.insert(0, dict(t=0.0, F=e["F"], PW=e["PW"], PT=e["PT"], Ain=e["Ain"], Atrib=e["Atrib"], VV0=e["VV0"],
                         MM0=1.0, pi=2e5, Aout=e["Aout"], n=e["n"], outside=e["outside"], free=e["free"],
                         V=e["VV0"] * V0, A=e["A"]))
        t0 = h[0]["t"]
        with open(f"holdfd_{t}.dat", "w") as f:
            f.write("# t_phys[s] F[N] P_W[Pa] P_T[Pa] A_in[m2] A_trib[m2] V/V0 M/M0 pi[Pa] A_out[m2] "
                    "n_contact fluid_outside fluid_free_volume[m3]\n")
            for x in h:
                f.write(" ".join(f"{v:.8e}" for v in (x["t"] - t0, x["F"], x["PW"], x["PT"], x["Ain"], x["Atrib"],
                                                      x["VV0"], x["MM0"], x["pi"], x["Aout"], x["n"],
                                                      x["outside"], x["free"])) + "\n")
        a, b = h[0], h[-1]
        print()
        print(f"## Hold ({t}: plates at rest at 50 %, L_P = 1e-13 m/(s Pa), van 't Hoff pi)")
        print()
        print("| | t (s) | F (mN) | P_T (kPa) | P_W (kPa) | pi (kPa) | V/V0 | M/M0 | A_trib (1e-9 m^2) | F/(P_W A_trib) - 1 |")
        print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
        for name, x in (("start (end of the pause)", a), ("end", b)):
            print(f"| {name} | {x['t']-t0:.0f} | {x['F']*1e3:.4f} | {x['PT']/1e3:.1f} | {x['PW']/1e3:.1f} | {x['pi']/1e3:.1f} "
                  f"| {x['VV0']:.5f} | {x['MM0']:.5f} | {x['Atrib']*1e9:.3f} | {x['F']/(x['PW']*x['Atrib'])-1:+.4f} |")
        # relaxation time: fit of ln(P_T - pi) while P_T - pi falls from 50 % to 5 % of its start
        g0 = a["PT"] - a["pi"]
        pts = [(x["t"] - t0, math.log(x["PT"] - x["pi"])) for x in h if 0.05 * g0 <= x["PT"] - x["pi"] <= 0.5 * g0]
        if len(pts) >= 3:
            n = len(pts)
            mx = sum(p[0] for p in pts) / n
            my = sum(p[1] for p in pts) / n
            slope = sum((p[0] - mx) * (p[1] - my) for p in pts) / sum((p[0] - mx) ** 2 for p in pts)
            tau = -1 / slope
            # Boyle-van 't Hoff: dV/dt = -L_P A (P - pi), tau = V / (L_P A (eps + pi)), eps = V dP/dV
            # (secant over the hold), pi at the end
            eps = b["V"] * (a["PT"] - b["PT"]) / (a["V"] - b["V"])
            taulaw = b["V"] / (1e-13 * b["A"] * (eps + b["pi"]))
            print()
            print(f"relaxation: P_T - pi fell from {g0/1e3:.1f} kPa to {(b['PT']-b['pi'])/1e3:.2f} kPa; fitted tau = {tau:.0f} s "
                  f"(ln(P_T - pi), {n} points between 50 and 5 % of the start); eps = V dP/dV = {eps/1e6:.2f} MPa "
                  f"(secant over the hold), tau_law = V / (L_P A (eps + pi)) = {taulaw:.0f} s, tau / tau_law = {tau/taulaw:.3f}")
        F50 = a["F"] - 0.5 * (a["F"] - b["F"])
        t50 = next(x["t"] - t0 for x in h if x["F"] <= F50)
        print(f"force: {a['F']*1e3:.4f} -> {b['F']*1e3:.4f} mN ({b['F']/a['F']-1:+.4f}), half of the drop after {t50:.0f} s; "
              f"fluid outside the wall: max {max(x['outside'] for x in h):.0f}; "
              f"F/(P_W A_trib) - 1 over the hold: {min(x['F']/(x['PW']*x['Atrib'])-1 for x in h):+.4f} to "
              f"{max(x['F']/(x['PW']*x['Atrib'])-1 for x in h):+.4f}")


if __name__ == "__main__":
    main()
