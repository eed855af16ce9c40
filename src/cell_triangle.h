/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   closest point of a wall triangle to a point, with its barycentric coordinates: the contact of
   a fluid atom with its cell's wall (pair cell/sph wall boundary, doc/pair_cell_sph.md)
------------------------------------------------------------------------- */

#ifndef LMP_CELL_TRIANGLE_H
#define LMP_CELL_TRIANGLE_H

#include <cmath>

namespace CellTriangle {

struct Foot {
  double p[3];    // the closest point of the triangle
  double l[3];    // its barycentric coordinates on the vertices a, b, c
  bool face;      // true if p is inside the face (not on an edge or a vertex)
};

inline double dot(const double *u, const double *v)
{
  return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}

inline void cross(const double *u, const double *v, double *w)
{
  w[0] = u[1] * v[2] - u[2] * v[1];
  w[1] = u[2] * v[0] - u[0] * v[2];
  w[2] = u[0] * v[1] - u[1] * v[0];
}

// solid angle Omega of triangle (a, b, c) seen from the origin, positive if the origin is behind
// the face ((b - a) x (c - a) points away from it), and dOmega/da, /db, /dc (Van Oosterom &
// Strackee, IEEE Trans. Biomed. Eng. 30, 125, 1983): tan(Omega/2) = N / D,
// N = a . (b x c), D = |a||b||c| + (a.b)|c| + (a.c)|b| + (b.c)|a|
// (len: |a|, |b|, |c|, given by the caller, which shares them between triangles)
inline void solid_angle(const double *a, const double *b, const double *c, const double *len,
                        double &omega, double (&grad)[3][3])
{
  const double *v[3] = {a, b, c};
  double bxc[3];
  cross(b, c, bxc);
  const double n = dot(a, bxc);
  const double d =
      len[0] * len[1] * len[2] + dot(a, b) * len[2] + dot(a, c) * len[1] + dot(b, c) * len[0];
  omega = 2.0 * atan2(n, d);
  // dOmega/du = 2 (D dN/du - N dD/du) / (N^2 + D^2), u, v, w = a, b, c cyclic:
  // dN/du = v x w, dD/du = (|v||w| + v.w) u/|u| + |w| v + |v| w
  const double k = 2.0 / (n * n + d * d);
  for (int i = 0; i < 3; i++) {
    const double *u = v[i], *p = v[(i + 1) % 3], *q = v[(i + 2) % 3];
    const double lu = len[i], lp = len[(i + 1) % 3], lq = len[(i + 2) % 3];
    double pxq[3];
    cross(p, q, pxq);
    const double cu = (lp * lq + dot(p, q)) / lu;
    for (int dim = 0; dim < 3; dim++)
      grad[i][dim] = k * (d * pxq[dim] - n * (cu * u[dim] + lq * p[dim] + lp * q[dim]));
  }
}

// closest point of triangle (a, b, c) to x, by the Voronoi region of x among the vertices, edges
// and the face (Ericson, Real-Time Collision Detection, 2005, section 5.1.5)
inline Foot closest(const double *x, const double *a, const double *b, const double *c)
{
  const double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double ac[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double ax[3] = {x[0] - a[0], x[1] - a[1], x[2] - a[2]};
  const double d1 = dot(ab, ax), d2 = dot(ac, ax);
  const auto at = [&](double la, double lb, double lc, bool face) {
    Foot f{{la * a[0] + lb * b[0] + lc * c[0], la * a[1] + lb * b[1] + lc * c[1],
            la * a[2] + lb * b[2] + lc * c[2]},
           {la, lb, lc},
           face};
    return f;
  };
  if (d1 <= 0.0 && d2 <= 0.0) return at(1.0, 0.0, 0.0, false);
  const double bx[3] = {x[0] - b[0], x[1] - b[1], x[2] - b[2]};
  const double d3 = dot(ab, bx), d4 = dot(ac, bx);
  if (d3 >= 0.0 && d4 <= d3) return at(0.0, 1.0, 0.0, false);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double t = d1 / (d1 - d3);
    return at(1.0 - t, t, 0.0, false);
  }
  const double cx[3] = {x[0] - c[0], x[1] - c[1], x[2] - c[2]};
  const double d5 = dot(ab, cx), d6 = dot(ac, cx);
  if (d6 >= 0.0 && d5 <= d6) return at(0.0, 0.0, 1.0, false);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double t = d2 / (d2 - d6);
    return at(1.0 - t, 0.0, t, false);
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return at(0.0, 1.0 - t, t, false);
  }
  const double denom = 1.0 / (va + vb + vc);
  const double lb = vb * denom, lc = vc * denom;
  return at(1.0 - lb - lc, lb, lc, true);
}

}    // namespace CellTriangle

#endif
