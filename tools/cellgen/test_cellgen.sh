#!/usr/bin/env bash
# Runs a cellgen binary and checks invariants of the data files it writes.
#   usage: tools/cellgen/test_cellgen.sh path/to/cellgen
# Exits non-zero if any check fails.
set -euo pipefail
bin=${1:?usage: test_cellgen.sh path/to/cellgen}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failed=0

# check_data FILE WALL_PER_CELL FLUID_TARGET FLUID_TOL VOLUME_TOL SINGLE_CELL GEODESIC RHO0 WALL_MASS AXES
# FLUID_TOL / VOLUME_TOL are relative; 0 skips the fluid-count / volume-accuracy test.
# AXES = "a b c": ellipsoidal cells of these semi-axes (all cells alike): every wall particle on the
# ellipsoid, every fluid particle inside it shrunk by 1 - gap / c_min, the volume against 4/3 pi a b c,
# fluid masses rho0 (4/3 pi a b c) / M_k, the wall's total mass rho0 (ellipsoid area) 1 um (the
# area by quadrature, to 1e-5) and the triangulated area within VOLUME_TOL of the ellipsoid's.
# GEODESIC = 1: every cell's wall has exactly 12 particles with 5 bonds and all others 6.
# Every per-atom mass must equal its documented formula (tools/cellgen/README.md, Masses), with R_k
# the cell's wall radius: fluid rho0 (4/3 pi R_k^3) / M_k; wall WALL_MASS, or rho0 (4 pi R_k^2 1 um)
# / N_k when WALL_MASS is 0.
check_data() {
  awk -v wall_expect="$2" -v fluid_target="$3" -v fluid_tol="$4" -v vol_tol="$5" '
    function fail(msg) { print "  FAIL: " msg; bad++ }
    function ekey(i, j) { return (i < j) ? i " " j : j " " i }
    function abs(v) { return v < 0 ? -v : v }
    NR == 1 { if (match($0, /gap=[^ ]+/)) gap = substr($0, RSTART + 4, RLENGTH - 4) + 0; next }
    /^[ \t]*$/ { next }
    section == "" && $2 == "atoms" { h_atoms = $1; next }
    section == "" && $2 == "bonds" { h_bonds = $1; next }
    section == "" && $2 == "angles" { h_angles = $1; next }
    $1 == "Masses" || $1 == "Atoms" || $1 == "Bonds" || $1 == "Angles" || $1 == "CellAtoms" ||
      $1 == "Dihedrals" { section = $1; next }
    section == "Masses" { tmass[$1] = $2 }
    section == "Atoms" {
      n_atoms++; mol[$1] = $2; type[$1] = $3; x[$1] = $4; y[$1] = $5; z[$1] = $6; xs[$1] = $4 " " $5 " " $6
      if ($2 > nmol) nmol = $2
      if ($3 == 2) { nv[$2]++; wx[$2] += $4; wy[$2] += $5; wz[$2] += $6 }
      else { nfl[$2]++; cx[$2] += $4; cy[$2] += $5; cz[$2] += $6 }
    }
    section == "Bonds" {
      n_bonds++; ne[mol[$3]]++; deg[$3]++; deg[$4]++
      if (bond[ekey($3, $4)]++) fail("duplicate bond " $3 "-" $4)
    }
    section == "Angles" {
      n_angles++; nf[mol[$3]]++; ta[n_angles] = $3; tb[n_angles] = $4; tc[n_angles] = $5
      tri_edge[ekey($3, $4)]++; tri_edge[ekey($4, $5)]++; tri_edge[ekey($5, $3)]++
      if (dir[$3 " " $4]++ || dir[$4 " " $5]++ || dir[$5 " " $3]++) fail("edge twice in one direction")
    }
    section == "CellAtoms" {
      n_cell++
      if ($3 " " $4 " " $5 != xs[$1]) fail("CellAtoms xref differs from position of atom " $1)
      if ($2 <= 0) fail("non-positive mass of atom " $1)
      amass[$1] = $2
      if (nmol_single && abs($2 / tmass[type[$1]] - 1) > 1e-9) fail("per-atom mass != type mass")
    }
    END {
      pi = atan2(0, -1)
      if (n_atoms != h_atoms || n_cell != h_atoms) fail("atom counts " n_atoms "/" n_cell " vs header " h_atoms)
      if (n_bonds != h_bonds) fail("bond count " n_bonds " vs header " h_bonds)
      if (n_angles != h_angles) fail("angle count " n_angles " vs header " h_angles)
      for (k in tri_edge) if (tri_edge[k] != 2) { fail("edge " k " in " tri_edge[k] " triangles"); break }
      for (k in tri_edge) if (!(k in bond)) { fail("triangle edge " k " is not a bond"); break }
      for (k in bond) if (!(k in tri_edge)) { fail("bond " k " is not a triangle edge"); break }
      for (m = 1; m <= nmol; m++) {
        if (nv[m] - ne[m] + nf[m] != 2) fail("cell " m ": V-E+F = " nv[m] - ne[m] + nf[m])
        if (nv[m] != wall_expect) fail("cell " m ": " nv[m] " wall particles, expected " wall_expect)
        if (fluid_tol > 0 && abs(nfl[m] / fluid_target - 1) > fluid_tol) fail("cell " m ": " nfl[m] " fluid")
        # centre: the fluid centroid, or the wall centroid for walls only
        if (nfl[m] > 0) { cx[m] /= nfl[m]; cy[m] /= nfl[m]; cz[m] /= nfl[m] }
        else { cx[m] = wx[m] / nv[m]; cy[m] = wy[m] / nv[m]; cz[m] = wz[m] / nv[m] }
      }
      for (i in type) {
        m = mol[i]; dx = x[i] - cx[m]; dy = y[i] - cy[m]; dz = z[i] - cz[m]
        if (type[i] == 2) rad[m] += sqrt(dx * dx + dy * dy + dz * dz) / nv[m]
      }
      if (axes != "") {
        split(axes, sa, " "); cmin = sa[1]; if (sa[2] < cmin) cmin = sa[2]; if (sa[3] < cmin) cmin = sa[3]
        shrink = (1 - gap / cmin) ^ 2
        for (i in type) {
          m = mol[i]; q = ((x[i] - cx[m]) / sa[1]) ^ 2 + ((y[i] - cy[m]) / sa[2]) ^ 2 + ((z[i] - cz[m]) / sa[3]) ^ 2
          if (type[i] == 2 && abs(q - 1) > 1e-9) { fail("wall atom " i " off the ellipsoid: " q); break }
          if (type[i] == 1 && q > shrink * (1 + 1e-9)) { fail("fluid atom " i " outside the ellipsoid shrunk by the gap"); break }
        }
      } else
      for (i in type) {
        m = mol[i]; dx = x[i] - cx[m]; dy = y[i] - cy[m]; dz = z[i] - cz[m]
        if (type[i] == 1 && sqrt(dx * dx + dy * dy + dz * dz) > rad[m] - gap + 1e-9 * rad[m])
          { fail("fluid atom " i " outside R - gap"); break }
      }
      for (t = 1; t <= n_angles; t++) {
        a = ta[t]; b = tb[t]; c = tc[t]; m = mol[a]
        ax = x[a] - cx[m]; ay = y[a] - cy[m]; az = z[a] - cz[m]
        bx = x[b] - cx[m]; by = y[b] - cy[m]; bz = z[b] - cz[m]
        qx = x[c] - cx[m]; qy = y[c] - cy[m]; qz = z[c] - cz[m]
        # signed tetrahedron volume a . (b x c) / 6 (divergence theorem)
        v6 = ax * (by * qz - bz * qy) + ay * (bz * qx - bx * qz) + az * (bx * qy - by * qx)
        vol[m] += v6 / 6
        if (v6 <= 0) inward++
        # |(b - a) x (c - a)| / 2
        ux = bx - ax; uy = by - ay; uz = bz - az; wx2 = qx - ax; wy2 = qy - ay; wz2 = qz - az
        tarea[m] += sqrt((uy * wz2 - uz * wy2) ^ 2 + (uz * wx2 - ux * wz2) ^ 2 + (ux * wy2 - uy * wx2) ^ 2) / 2
      }
      if (inward) fail(inward " triangle(s) not outward")
      if (axes != "") {
        # ellipsoid area: midpoint rule over r = (a sin t cos p, b sin t sin p, c cos t),
        # |r_t x r_p| = sin t sqrt(b^2 c^2 sin^2 t cos^2 p + a^2 c^2 sin^2 t sin^2 p + a^2 b^2 cos^2 t)
        nt = 600; np = 1200; earea = 0
        for (it = 0; it < nt; it++) {
          t = (it + 0.5) * pi / nt; st = sin(t); ct = cos(t)
          for (ip = 0; ip < np; ip++) {
            p = (ip + 0.5) * 2 * pi / np; cp = cos(p); sp = sin(p)
            earea += st * sqrt((sa[2] * sa[3] * st * cp) ^ 2 + (sa[1] * sa[3] * st * sp) ^ 2 + (sa[1] * sa[2] * ct) ^ 2)
          }
        }
        earea *= (pi / nt) * (2 * pi / np)
        for (i in type) {
          m = mol[i]
          if (type[i] == 2) { wmass[m] += amass[i]; continue }
          expect = rho0 * 4 / 3 * pi * sa[1] * sa[2] * sa[3] / nfl[m]
          if (abs(amass[i] / expect - 1) > 1e-9) { fail("mass of fluid atom " i " " amass[i] ", formula gives " expect); break }
        }
        for (m = 1; m <= nmol; m++) {
          if (wall_mass > 0) { if (abs(wmass[m] / (wall_mass * nv[m]) - 1) > 1e-9) fail("cell " m ": wall mass") }
          else if (abs(wmass[m] / (rho0 * earea * 1e-6) - 1) > 1e-5) fail("cell " m ": wall mass " wmass[m] " vs rho0 area 1 um " rho0 * earea * 1e-6)
          if (abs(tarea[m] / earea - 1) > vol_tol) fail("cell " m ": mesh area " tarea[m] " vs ellipsoid " earea)
        }
      } else
      for (i in type) {
        m = mol[i]
        if (type[i] == 1) expect = rho0 * 4 / 3 * pi * rad[m] ^ 3 / nfl[m]
        else expect = wall_mass > 0 ? wall_mass : rho0 * 4 * pi * rad[m] ^ 2 * 1e-6 / nv[m]
        if (abs(amass[i] / expect - 1) > 1e-9) {
          fail("mass of atom " i " (type " type[i] ") " amass[i] ", formula gives " expect); break
        }
      }
      if (geodesic) {
        for (i in type) if (type[i] == 2) { if (deg[i] == 5) n5[mol[i]]++; else if (deg[i] != 6) other++ }
        if (other) fail(other " wall particle(s) with neither 5 nor 6 bonds")
        for (m = 1; m <= nmol; m++) if (n5[m] != 12) fail("cell " m ": " n5[m] + 0 " particles with 5 bonds, expected 12")
      }
      for (m = 1; m <= nmol; m++) {
        exact = axes != "" ? 4 / 3 * pi * sa[1] * sa[2] * sa[3] : 4 / 3 * pi * rad[m] ^ 3
        if (vol[m] <= 0) fail("cell " m ": enclosed volume " vol[m] " <= 0")
        if (vol_tol > 0 && abs(vol[m] / exact - 1) > vol_tol) fail("cell " m ": volume ratio " vol[m] / exact)
        if (m == 1) exact1 = exact
      }
      printf "  %d cell(s), %d atoms, %d bonds, %d triangles, gap %g, cell 1 volume / exact %.12f\n", nmol, n_atoms, n_bonds, n_angles, gap, vol[1] / exact1
      exit bad > 0
    }' nmol_single="$6" geodesic="${7:-0}" rho0="${8:-1000}" wall_mass="${9:-0}" axes="${10:-}" "$1"
}

# check_dihedrals FILE: with --dihedrals, the header counts the dihedrals (one type), the Atoms
# section is tagged molecular, every wall bond b-c is the middle of exactly one dihedral a b c d and
# no dihedral has another middle, and (a, b, c) and (d, c, b) are wall triangles as written in
# Angles (up to cyclic order, so both outward: the orientation is consistent); Dihedrals comes
# before CellAtoms.
check_dihedrals() {
  awk '
    function fail(msg) { print "  FAIL: " msg; bad++ }
    function ekey(i, j) { return (i < j) ? i " " j : j " " i }
    /^[ \t]*$/ { next }
    section == "" && $2 == "dihedrals" { h_dih = $1; next }
    section == "" && $2 == "dihedral" && $3 == "types" { h_types = $1; next }
    $1 == "Atoms" { section = $1; style = $3; next }
    $1 == "Masses" || $1 == "Bonds" || $1 == "Angles" || $1 == "Dihedrals" || $1 == "CellAtoms" {
      # LAMMPS 29 Sep 2021 reads no section after the fix section CellAtoms
      if ($1 == "Dihedrals" && section == "CellAtoms") fail("Dihedrals after CellAtoms")
      section = $1; next
    }
    section == "Bonds" { bond[ekey($3, $4)] = 1; n_bonds++ }
    section == "Angles" { tri[$3 " " $4 " " $5] = tri[$4 " " $5 " " $3] = tri[$5 " " $3 " " $4] = 1 }
    section == "Dihedrals" {
      n_dih++
      if ($2 != 1) fail("dihedral " $1 " has type " $2)
      k = ekey($4, $5)
      if (!(k in bond)) fail("dihedral " $1 ": middle " k " is not a bond")
      if (mid[k]++) fail("edge " k " is the middle of two dihedrals")
      if (!(($3 " " $4 " " $5) in tri)) fail("dihedral " $1 ": (a, b, c) = " $3 " " $4 " " $5 " is not an outward triangle")
      if (!(($6 " " $5 " " $4) in tri)) fail("dihedral " $1 ": (d, c, b) = " $6 " " $5 " " $4 " is not an outward triangle")
      if ($3 == $6) fail("dihedral " $1 ": a = d")
    }
    END {
      if (style != "molecular") fail("Atoms section tagged " style ", expected molecular")
      if (h_types != 1) fail("dihedral types " h_types ", expected 1")
      if (n_dih != h_dih) fail("dihedral count " n_dih " vs header " h_dih)
      if (n_dih != n_bonds) fail(n_dih " dihedrals for " n_bonds " bonds")
      for (k in bond) if (!(k in mid)) { fail("bond " k " has no dihedral"); break }
      printf "  %d dihedrals, one per bond, both triangles outward\n", n_dih
      exit bad > 0
    }' "$1"
}

# run_dihedrals NAME WALL_PER_CELL -- cellgen args...: --dihedrals adds the Dihedrals section and
# changes nothing else (the file without --dihedrals, minus the header lines and the Atoms tag)
run_dihedrals() {
  local name=$1 wall=$2
  shift 3
  echo "[$name] cellgen --dihedrals $*"
  if "$bin" "$@" --dihedrals --out "$tmp/$name.data" >"$tmp/$name.log" 2>&1 &&
    "$bin" "$@" --out "$tmp/$name-plain.data" >/dev/null 2>&1 &&
    check_data "$tmp/$name.data" "$wall" 0 0 0.03 0 "$([[ " $* " == *" --mesh spiral "* ]] && echo 0 || echo 1)" &&
    check_dihedrals "$tmp/$name.data" &&
    cmp -s <(awk '$1 == "Dihedrals" { skip = 1 } $1 == "CellAtoms" { skip = 0 } !skip && NR > 1 && NF && $2 != "dihedrals" &&
                 !($2 == "dihedral" && $3 == "types") && $1 != "Atoms"' "$tmp/$name.data") \
           <(awk 'NR > 1 && NF && $1 != "Atoms"' "$tmp/$name-plain.data"); then
    echo "  ok"
  else
    echo "  FAIL (or the file differs from the one without --dihedrals beyond the dihedrals)"
    cat "$tmp/$name.log"
    failed=1
  fi
}

# run NAME WALL_PER_CELL FLUID_TARGET FLUID_TOL VOLUME_TOL SINGLE_CELL -- cellgen args...
# Without --mesh spiral the wall must be a geodesic icosahedron (12 five-bonded particles).
run() {
  local name=$1 wall=$2 fluid=$3 ftol=$4 vtol=$5 single=$6 geodesic=1 rho0=1000 wmass=0
  shift 7
  case " $* " in *" --mesh spiral "*) geodesic=0 ;; esac
  local args=("$@") k radius=75e-6 elong="" axes=""
  for ((k = 0; k + 1 < ${#args[@]}; k++)); do
    case ${args[k]} in
      --rho0) rho0=${args[k + 1]} ;; --wall-mass) wmass=${args[k + 1]} ;; --radius) radius=${args[k + 1]} ;;
      --ellipsoid) axes=${args[k + 1]//:/ } ;; --elongation) elong=${args[k + 1]} ;;
    esac
  done
  # --elongation E: prolate along x, a/b = E, volume of the sphere of radius R: a = R E^(2/3), b = c = R E^(-1/3)
  [ -z "$elong" ] || axes=$(awk -v r="$radius" -v e="$elong" 'BEGIN { printf "%.17g %.17g %.17g", r * e ^ (2 / 3), r * e ^ (-1 / 3), r * e ^ (-1 / 3) }')
  echo "[$name] cellgen $*"
  if "$bin" "$@" --out "$tmp/$name.data" >"$tmp/$name.log" 2>&1 &&
    check_data "$tmp/$name.data" "$wall" "$fluid" "$ftol" "$vtol" "$single" "$geodesic" "$rho0" "$wmass" "$axes" >"$tmp/$name.check"; then
    cat "$tmp/$name.check"
    echo "  ok"
  else
    cat "$tmp/$name.log" "$tmp/$name.check" 2>/dev/null
    failed=1
  fi
}

# expect_error NAME -- cellgen args...: cellgen must refuse these arguments
expect_error() {
  local name=$1
  shift 2
  echo "[$name] cellgen $* (must fail)"
  if "$bin" "$@" --out "$tmp/$name.data" >"$tmp/$name.log" 2>&1; then
    echo "  FAIL: exit status 0"
    failed=1
  else
    echo "  ok: $(head -n 1 "$tmp/$name.log")"
  fi
}

# icosahedral (default): 10 T + 2 wall particles, T = h^2 + hk + k^2 closest to --nwall
run default 1092 1624 0.05 0.03 1 --
run fine 4002 5000 0.05 0.03 1 -- --nwall 4000 --nfluid 5000 --rho0 1100
run tiny 12 10 0 0 1 -- --nwall 12 --nfluid 10 --radius 1e-5
run lattice 312 0 0 0.03 0 -- --cells 3 2 2 --radius-spread 0.2 --seed 7 --nwall 300 --dx 12e-6
run gap 492 0 0 0.03 1 -- --nwall 500 --dx 8e-6 --gap 10e-6 --wall-mass 1e-12
run walls-only 1092 0 0 0.03 1 -- --nfluid 0
# spiral: exactly --nwall particles
run spiral 1091 1624 0.05 0.03 1 -- --mesh spiral
run spiral-lattice 300 0 0 0.03 0 -- --mesh spiral --cells 2 1 2 --nwall 300 --dx 12e-6
run spiral-tiny 4 10 0 0 1 -- --mesh spiral --nwall 4 --nfluid 10 --radius 1e-5
# ellipsoids (all cells alike: no --radius-spread): the sphere mesh mapped onto the ellipsoid
run ellipsoid 1092 1624 0.05 0.03 1 -- --elongation 1.45
run ellipsoid-triaxial 792 300 0 0.03 1 -- --ellipsoid 30e-6:20e-6:15e-6 --nwall 800 --nfluid 300
run ellipsoid-lattice 312 0 0 0.03 0 -- --ellipsoid 12e-6:10e-6:8e-6 --nwall 300 --dx 2e-6 --cells 2 2 1 --wall-mass 1e-13
run ellipsoid-spiral 300 0 0 0.03 1 -- --mesh spiral --nwall 300 --dx 8e-6 --elongation 2
run ellipsoid-conformal 1092 1624 0.05 0.03 1 -- --elongation 1.45 --map conformal
run ellipsoid-conformal-oblate 312 0 0 0.03 1 -- --ellipsoid 20e-6:20e-6:12e-6 --nwall 300 --dx 3e-6 --map conformal

# angle_change SPHERE.data MAPPED.data: the largest change of a triangle's angle (degrees) between two
# files with the same atoms and triangles
angle_change() {
  awk 'function ang(x1, y1, z1, x2, y2, z2, x3, y3, z3,   ux, uy, uz, vx, vy, vz, cx, cy, cz) {
      ux = x2 - x1; uy = y2 - y1; uz = z2 - z1; vx = x3 - x1; vy = y3 - y1; vz = z3 - z1
      cx = uy * vz - uz * vy; cy = uz * vx - ux * vz; cz = ux * vy - uy * vx
      return atan2(sqrt(cx * cx + cy * cy + cz * cz), ux * vx + uy * vy + uz * vz) * 180 / atan2(0, -1)
    }
    FNR == 1 { f++ }
    /^[ \t]*$/ { next }
    $1 == "Atoms" || $1 == "Bonds" || $1 == "Angles" || $1 == "CellAtoms" || $1 == "Masses" { sec = $1; next }
    sec == "Atoms" && NF >= 6 { X[f, $1] = $4; Y[f, $1] = $5; Z[f, $1] = $6 }
    sec == "Angles" && NF == 5 && f == 1 { n++; A[n] = $3; B[n] = $4; C[n] = $5 }
    END {
      for (t = 1; t <= n; t++) for (k = 0; k < 3; k++) {
        i = k == 0 ? A[t] : k == 1 ? B[t] : C[t]; j = k == 0 ? B[t] : k == 1 ? C[t] : A[t]; l = k == 0 ? C[t] : k == 1 ? A[t] : B[t]
        d = ang(X[1, i], Y[1, i], Z[1, i], X[1, j], Y[1, j], Z[1, j], X[1, l], Y[1, l], Z[1, l]) - \
            ang(X[2, i], Y[2, i], Z[2, i], X[2, j], Y[2, j], Z[2, j], X[2, l], Y[2, l], Z[2, l])
        if (d < 0) d = -d; if (d > worst) worst = d
      }
      printf "%.6f\n", worst
    }' "$1" "$2"
}

echo "[conformal map] triangle angles kept: the largest change from the sphere mesh's below 2 deg at 1092 particles, falling below 0.6 x that at 4002 (first order); the affine map changes them by more than 15 deg"
for nw in 1091 4000; do
  "$bin" --nwall $nw --nfluid 0 --out "$tmp/s$nw.data" >/dev/null
  "$bin" --nwall $nw --nfluid 0 --elongation 1.45 --map conformal --out "$tmp/c$nw.data" >/dev/null
  "$bin" --nwall $nw --nfluid 0 --elongation 1.45 --out "$tmp/a$nw.data" >/dev/null
done
c1=$(angle_change "$tmp/s1091.data" "$tmp/c1091.data")
c4=$(angle_change "$tmp/s4000.data" "$tmp/c4000.data")
a1=$(angle_change "$tmp/s1091.data" "$tmp/a1091.data")
if awk -v c1="$c1" -v c4="$c4" -v a1="$a1" 'BEGIN { exit !(c1 < 2 && c4 < 0.6 * c1 && a1 > 15) }'; then
  echo "  ok: conformal $c1 (1092), $c4 (4002); affine $a1 (1092)"
else
  echo "  FAIL: conformal $c1 (1092), $c4 (4002); affine $a1 (1092)"
  failed=1
fi

echo "[ellipsoid volume] x -> (a x, b y, c z) scales volumes by abc: the mesh's V / (4/3 pi a b c) is the sphere mesh's V / (4/3 pi R^3)"
vs=$(sed -n 's/.*volume \/ exact \([0-9.]*\).*/\1/p' "$tmp/default.check")
ve=$(sed -n 's/.*volume \/ exact \([0-9.]*\).*/\1/p' "$tmp/ellipsoid.check")
if [ -n "$vs" ] && awk -v s="$vs" -v e="$ve" 'BEGIN { d = s - e; exit !(d < 1e-10 && d > -1e-10) }'; then
  echo "  ok: $vs (sphere) vs $ve (ellipsoid)"
else
  echo "  FAIL: sphere $vs, ellipsoid $ve"
  failed=1
fi

# --dihedrals (dihedral_style cell/bending): one dihedral per wall edge, orientation consistent
run_dihedrals dihedrals 1092 -- --nfluid 0
run_dihedrals dihedrals-fluid-lattice 312 -- --cells 2 1 1 --nwall 300 --dx 12e-6
run_dihedrals dihedrals-spiral 300 -- --mesh spiral --nwall 300 --dx 12e-6

echo "[geodesic class] the (h, k) chosen for --nwall (nearest 10T+2; ties: class I, smaller k)"
for c in "4 1 0 12" "27 1 1 32" "37 2 0 42" "300 5 1 312" "500 7 0 492" "912 9 1 912" \
  "1091 7 5 1092" "1472 11 2 1472" "4000 20 0 4002" "10000 30 3 9992"; do
  set -- $c
  line=$("$bin" --nwall "$1" --nfluid 0 --out "$tmp/class.data" | grep '^wall mesh:' || true)
  if [[ "$line" == *"(h, k) = ($2, $3)"*": $4 wall particles per cell"* ]]; then
    echo "  ok: --nwall $1 -> ($2, $3), $4"
  else
    echo "  FAIL: --nwall $1: expected ($2, $3), $4; got: $line"
    failed=1
  fi
done

echo "[walls only] the Masses section holds a positive, finite mass for the absent fluid type"
"$bin" --nfluid 0 --nwall 300 --out "$tmp/w.data" >/dev/null
if awk '$1 == "Masses" { s = 1; next } s && NF == 2 { if (!($2 > 0 && $2 < 1)) bad = 1; n++ } s && n == 2 { exit }
  END { exit bad || n != 2 }' "$tmp/w.data"; then echo "  ok"; else echo "  FAIL: bad Masses"; failed=1; fi

echo "[determinism] same seed, same file (apart from the comment line naming it)"
"$bin" --cells 2 2 1 --radius-spread 0.1 --seed 3 --nwall 200 --out "$tmp/a.data" >/dev/null
"$bin" --cells 2 2 1 --radius-spread 0.1 --seed 3 --nwall 200 --out "$tmp/b.data" >/dev/null
if cmp -s <(tail -n +2 "$tmp/a.data") <(tail -n +2 "$tmp/b.data"); then echo "  ok"; else echo "  FAIL: outputs differ"; failed=1; fi

echo "[margin] the box reaches F R beyond the cells on each side (default F = 0.5)"
for c in "default 0.5" "1 1" "2.5 2.5"; do
  set -- $c
  margin=()
  [ "$1" = default ] || margin=(--margin "$1")
  "$bin" --radius 20e-6 --nwall 200 --nfluid 50 --cells 2 1 1 "${margin[@]}" --out "$tmp/m.data" >/dev/null
  # cells 2R(1.05) apart along x: x from -(1.05 R + R + F R) to +, y and z from -(R + F R) to +
  if awk -v f="$2" 'function abs(v) { return v < 0 ? -v : v }
    $3 == "xlo" { x = $1; xx = $2 } $3 == "ylo" { y = $1; yy = $2 } $3 == "zlo" { z = $1; zz = $2 }
    END { r = 20e-6; ex = 1.05 * r + r + f * r; ey = r + f * r
      exit !(abs(x + ex) < 1e-12 * ex && abs(xx - ex) < 1e-12 * ex && abs(y + ey) < 1e-12 * ey &&
             abs(yy - ey) < 1e-12 * ey && abs(z + ey) < 1e-12 * ey && abs(zz - ey) < 1e-12 * ey) }' "$tmp/m.data"; then
    echo "  ok: --margin $1: $(grep -m1 xlo "$tmp/m.data")"
  else
    echo "  FAIL: --margin $1: box $(grep -E 'lo .*hi' "$tmp/m.data" | tr '\n' ' ')"
    failed=1
  fi
done

expect_error overlap -- --cells 2 1 1 --spacing 100e-6
expect_error badnumber -- --radius 75um
expect_error unknown -- --bogus 1
expect_error twod -- --2d
expect_error gap-too-large -- --gap 80e-6
expect_error bad-mesh -- --mesh cubic
expect_error margin-zero -- --margin 0
expect_error margin-negative -- --margin -1
expect_error margin-not-a-number -- --margin 1R
expect_error ellipsoid-two-axes -- --ellipsoid 3e-5:2e-5
expect_error ellipsoid-negative-axis -- --ellipsoid 3e-5:-2e-5:1e-5
expect_error ellipsoid-and-radius -- --ellipsoid 3e-5:2e-5:1e-5 --radius 1e-5
expect_error ellipsoid-and-elongation -- --ellipsoid 3e-5:2e-5:1e-5 --elongation 1.5
expect_error elongation-below-1 -- --elongation 0.5
expect_error ellipsoid-gap-too-large -- --ellipsoid 3e-5:2e-5:1e-5 --gap 1.2e-5
expect_error conformal-triaxial -- --ellipsoid 3e-5:2e-5:1e-5 --map conformal
expect_error conformal-sphere -- --map conformal
expect_error bad-map -- --elongation 1.45 --map stretched

if [ "$failed" -ne 0 ]; then
  echo "test_cellgen: FAILED"
  exit 1
fi
echo "test_cellgen: all checks passed"
