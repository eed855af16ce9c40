# Radial pressure shells one particle spacing wide of a profile dump (id type r P):
#   python3 pressure_shells.py profile.txt DX
import sys, statistics as st
f=sys.argv[1]; dx=float(sys.argv[2])
rows=[l.split() for l in open(f).readlines()[9:]]
fl=[(float(r[2]),float(r[3])) for r in rows if r[1]=='1']
rw=st.mean(float(r[2]) for r in rows if r[1]=='2')
P=[p for _,p in fl]; mean=st.mean(P)
print(f"fluid {len(fl)}, wall radius {rw*1e6:.2f} um, mean P {mean/1e3:.1f} kPa, std/mean {st.pstdev(P)/mean*100:.1f} %")
nsh=int(rw/dx)+1
for s in range(nsh):
    lo=rw-(s+1)*dx; hi=rw-s*dx
    ps=[p for r,p in fl if lo<=r<hi]
    if ps: print(f"  shell {max(lo,0)*1e6:6.1f}-{hi*1e6:6.1f} um: n={len(ps):4d} P={st.mean(ps)/1e3:7.1f} kPa ({(st.mean(ps)/mean-1)*100:+.1f} %) std/mean {st.pstdev(ps)/st.mean(ps)*100:.1f} %")
