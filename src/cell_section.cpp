/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
------------------------------------------------------------------------- */

#include "cell_section.h"

#include "math_const.h"

#include <algorithm>
#include <cmath>
#include <utility>

using LAMMPS_NS::tagint;

namespace {

using Key = std::pair<tagint, tagint>;    // a cut edge: (ID below the plane, ID above)

// the piece of the section inside one triangle, from its edge going down through the plane to
// its edge going up (so the cell is on the left seen along n): the section runs counter-clockwise
struct Piece {
  Key from, to;
  double u, v;    // the point on the edge 'from', in the plane's axes
};

double dot(const double *a, const double *b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// z component of (b - a) x (c - a) for 2-D points (x y pairs)
double turn(const double *a, const double *b, const double *c)
{
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

// the ellipse of ImageJ's "Fit ellipse" from Green's sums over the section's curves (2 A, 6 A (cu, cv),
// 12 (Iuu, Ivv), 24 Iuv): its axis ratio from the central second moments, its size from the area
void fit_ellipse(double a2, double su, double sv, double suu, double svv, double suv,
                 CellSection::Shape &shape)
{
  if (!(shape.area > 0.0)) return;
  // central second moments per area; the axis ratio from their eigenvalues, the size from the
  // area: major minor pi / 4 = A
  const double cu = su / (3.0 * a2), cv = sv / (3.0 * a2);
  const double muu = suu / (6.0 * a2) - cu * cu, mvv = svv / (6.0 * a2) - cv * cv;
  const double muv = suv / (12.0 * a2) - cu * cv;
  const double mean = 0.5 * (muu + mvv), dev = std::hypot(0.5 * (muu - mvv), muv);
  const double l1 = mean + dev, l2 = mean - dev;
  if (l2 > 0.0) {
    const double ratio = std::sqrt(l1 / l2);
    shape.major = std::sqrt(4.0 * shape.area * ratio / LAMMPS_NS::MathConst::MY_PI);
    shape.minor = std::sqrt(4.0 * shape.area / (ratio * LAMMPS_NS::MathConst::MY_PI));
  }
}

// calipers of the convex hull (counter-clockwise x y pairs), with its area and perimeter: the
// largest width is the longest vertex pair, the smallest is attained with a hull edge on one jaw
void calipers(const std::vector<double> &hull, CellSection::Shape &shape)
{
  const int h = (int) hull.size() / 2;
  double hull2 = 0.0, hullp = 0.0, feret2 = 0.0, minwidth = INFINITY;
  for (int i = 0; i < h; i++) {
    const double *q = &hull[2 * i], *r = &hull[2 * ((i + 1) % h)];
    hull2 += q[0] * r[1] - r[0] * q[1];
    const double len = std::hypot(r[0] - q[0], r[1] - q[1]);
    // hull perimeter: the sum of its edges' lengths (doc/compute_cell_shape.md, column 17)
    hullp += len;
    double width = 0.0;
    for (int j = 0; j < h; j++) {
      const double *w = &hull[2 * j];
      feret2 = std::max(feret2, (w[0] - q[0]) * (w[0] - q[0]) + (w[1] - q[1]) * (w[1] - q[1]));
      if (len > 0.0) width = std::max(width, turn(q, r, w) / len);
    }
    if (len > 0.0) minwidth = std::min(minwidth, width);
  }
  shape.convex_area = 0.5 * hull2;
  shape.convex_perimeter = hullp;
  shape.feret = std::sqrt(feret2);
  shape.minferet = std::isfinite(minwidth) ? minwidth : 0.0;
}

}    // namespace

namespace CellSection {

std::vector<double> convex_hull(std::vector<double> points)
{
  const int n = (int) points.size() / 2;
  if (n < 3) return points;
  std::vector<int> order(n);
  for (int i = 0; i < n; i++) order[i] = i;
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return points[2 * a] < points[2 * b] ||
        (points[2 * a] == points[2 * b] && points[2 * a + 1] < points[2 * b + 1]);
  });
  // lower hull left to right, then upper hull right to left, keeping only left turns
  std::vector<int> hull(2 * n);
  int k = 0;
  const auto add = [&](int i, int keep) {
    while (k > keep &&
           turn(&points[2 * hull[k - 2]], &points[2 * hull[k - 1]], &points[2 * i]) <= 0.0)
      k--;
    hull[k++] = i;
  };
  for (int m = 0; m < n; m++) add(order[m], 1);
  const int lower = k;
  for (int m = n - 2; m >= 0; m--) add(order[m], lower);
  k--;    // the first point closes the upper hull
  std::vector<double> out(2 * (size_t) k);
  for (int m = 0; m < k; m++) {
    out[2 * m] = points[2 * hull[m]];
    out[2 * m + 1] = points[2 * hull[m] + 1];
  }
  return out;
}

bool measure(const double *tri, const tagint *ids, int ntri, const double *p, const double *n,
             const double *e1, const double *e2, Shape &shape)
{
  shape = Shape();
  // each atom's height above the plane, once per atom ID: a corner's copies in its triangles
  // differ by round-off, and must fall on the same side
  std::vector<std::pair<tagint, int>> corner(3 * (size_t) ntri);
  for (int k = 0; k < 3 * ntri; k++) corner[k] = {ids[k], k};
  std::sort(corner.begin(), corner.end());
  std::vector<double> height(3 * (size_t) ntri);
  double d[3];
  for (size_t k = 0; k < corner.size(); k++) {
    const size_t head = k > 0 && corner[k].first == corner[k - 1].first ? k - 1 : k;
    if (head == k) {
      const double *x = tri + 3 * corner[k].second;
      for (int dim = 0; dim < 3; dim++) d[dim] = x[dim] - p[dim];
      height[corner[k].second] = dot(n, d);
    } else {
      height[corner[k].second] = height[corner[head].second];
      corner[k].second = corner[head].second;
    }
  }

  std::vector<Piece> pieces;
  for (int t = 0; t < ntri; t++) {
    const double *x = tri + 9 * t;
    const tagint *id = ids + 3 * t;
    const double *s = &height[3 * (size_t) t];
    bool above[3];
    for (int k = 0; k < 3; k++) above[k] = s[k] >= 0.0;
    if (above[0] == above[1] && above[1] == above[2]) continue;
    Piece piece{};
    for (int k = 0; k < 3; k++) {
      const int j = (k + 1) % 3;
      if (above[k] && !above[j]) {
        // edge k -> j goes down: the section enters here; point x_j + s_j/(s_j - s_k) (x_k - x_j)
        piece.from = {id[j], id[k]};
        const double f = s[j] / (s[j] - s[k]);
        for (int dim = 0; dim < 3; dim++)
          d[dim] = x[3 * j + dim] + f * (x[3 * k + dim] - x[3 * j + dim]) - p[dim];
        piece.u = dot(e1, d);
        piece.v = dot(e2, d);
      } else if (!above[k] && above[j])
        piece.to = {id[k], id[j]};
    }
    pieces.push_back(piece);
  }
  if (pieces.empty()) return true;

  // chain the pieces: each cut edge is where one piece ends and the next begins
  std::sort(pieces.begin(), pieces.end(),
            [](const Piece &a, const Piece &b) { return a.from < b.from; });
  for (size_t k = 1; k < pieces.size(); k++)
    if (pieces[k].from == pieces[k - 1].from) return false;
  std::vector<char> used(pieces.size(), 0);
  std::vector<double> points;
  // Green's theorem over the closed curves: 2 A, 6 A (cu, cv), 12 (Iuu, Ivv), 24 Iuv
  double a2 = 0.0, su = 0.0, sv = 0.0, suu = 0.0, svv = 0.0, suv = 0.0;
  for (size_t first = 0; first < pieces.size(); first++) {
    if (used[first]) continue;
    shape.loops++;
    size_t k = first;
    do {
      if (used[k]) return false;    // runs into another curve: not a closed surface
      used[k] = 1;
      const Piece &a = pieces[k];
      auto next = std::lower_bound(pieces.begin(), pieces.end(), a.to,
                                   [](const Piece &q, const Key &key) { return q.from < key; });
      if (next == pieces.end() || next->from != a.to) return false;
      const Piece &b = *next;
      points.insert(points.end(), {a.u, a.v});
      const double cr = a.u * b.v - b.u * a.v;
      a2 += cr;
      su += (a.u + b.u) * cr;
      sv += (a.v + b.v) * cr;
      suu += (a.u * a.u + a.u * b.u + b.u * b.u) * cr;
      svv += (a.v * a.v + a.v * b.v + b.v * b.v) * cr;
      suv += (a.u * b.v + 2.0 * a.u * a.v + 2.0 * b.u * b.v + b.u * a.v) * cr;
      shape.perimeter += std::hypot(b.u - a.u, b.v - a.v);
      k = next - pieces.begin();
    } while (k != first);
  }

  shape.area = 0.5 * a2;
  fit_ellipse(a2, su, sv, suu, svv, suv, shape);
  calipers(convex_hull(points), shape);
  return true;
}

}    // namespace CellSection
