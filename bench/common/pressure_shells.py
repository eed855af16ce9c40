# Radial pressure shells of a sealed cell from a profile dump (columns id type r P, r from the wall
# centre), each one particle spacing wide, dx = (4/3 pi R^3 / N_fluid)^(1/3) with R the mean wall
# radius, counted inwards from R; prints the shells and one summary line:
#   python3 pressure_shells.py profile.txt [label] [--out PREFIX]
# (--out: also PREFIXstd.txt and PREFIXworst.txt, the std/mean and the worst shell in %, one number
# each, for a LAMMPS file-style variable)
# SHELLS label: n, mean P, std/mean over all fluid, largest |shell mean / mean - 1| (shells with
# at least 10 atoms) and its shell (0 = next to the wall), first shell / mean - 1, and the split of
# the variance into between shells, sum_s n_s (Pbar_s - Pbar)^2 / N, and within shells,
# sum_s sum_i (P_i - Pbar_s)^2 / N (the two add to the variance), each as sqrt / mean
import math, statistics as st, sys
args = sys.argv[1:]
out = None
if "--out" in args:
    k = args.index("--out")
    out = args[k + 1]
    del args[k:k + 2]
rows = [l.split() for l in open(args[0]).readlines()[9:]]
label = args[1] if len(args) > 1 else ""
fl = [(float(r[2]), float(r[3])) for r in rows if r[1] == '1']
rw = st.mean(float(r[2]) for r in rows if r[1] == '2')
dx = (4.0 / 3.0 * math.pi * rw**3 / len(fl)) ** (1.0 / 3.0)
P = [p for _, p in fl]
mean = st.mean(P)
print(f"fluid {len(fl)}, wall radius {rw*1e6:.2f} um, spacing {dx*1e6:.2f} um, mean P {mean/1e3:.1f} kPa, std/mean {st.pstdev(P)/mean*100:.1f} %")
worst, iworst, first, between, within = 0.0, -1, None, 0.0, 0.0
for s in range(int(rw / dx) + 1):
    lo, hi = rw - (s + 1) * dx, rw - s * dx
    ps = [p for r, p in fl if lo <= r < hi]
    if not ps:
        continue
    dev = st.mean(ps) / mean - 1
    between += len(ps) * (st.mean(ps) - mean) ** 2 / len(P)
    within += len(ps) * st.pvariance(ps) / len(P)
    if first is None:
        first = dev
    if len(ps) >= 10 and abs(dev) > worst:
        worst, iworst = abs(dev), s
    print(f"  shell {max(lo,0)*1e6:6.1f}-{hi*1e6:6.1f} um: n={len(ps):5d} P={st.mean(ps)/1e3:7.1f} kPa ({dev*100:+.1f} %) std/mean {st.pstdev(ps)/st.mean(ps)*100:.1f} %")
print(f"SHELLS {label}: n {len(fl)}, mean P {mean/1e3:.1f} kPa, std/mean {st.pstdev(P)/mean*100:.1f} %, worst shell {worst*100:.1f} %, wall shell {first*100:+.1f} %, worst at shell {iworst}, between {math.sqrt(between)/mean*100:.1f} %, within {math.sqrt(within)/mean*100:.1f} %")
if out is not None:
    open(out + "std.txt", "w").write(f"{st.pstdev(P) / mean * 100:.6g}\n")
    open(out + "worst.txt", "w").write(f"{worst * 100:.6g}\n")
