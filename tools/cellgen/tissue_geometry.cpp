#include "tissue_geometry.h"

#include <voro++/voro++.hh>

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>

namespace cellgen {

namespace {

  constexpr double kPi = 3.14159265358979323846;
  constexpr double kStep = 1.0 / 3.0;    // spring relaxation step (stable for six bonds)

  Vec3 at(const std::vector<double> &v, size_t i)
  {
    return Vec3(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
  }

  // Newell's normal of a polygon (twice its vector area).
  Vec3 newellNormal(const std::vector<Vec3> &p)
  {
    Vec3 n = Vec3::Zero();
    for (size_t k = 0; k < p.size(); ++k) n += p[k].cross(p[(k + 1) % p.size()]);
    return n;
  }

  // The faces of a Voro++ cell as vertex loops, turned counter-clockwise seen from outside.
  std::vector<std::vector<int>> faceLoops(voro::voronoicell_neighbor &c, const std::vector<Vec3> &x)
  {
    std::vector<int> fv;
    c.face_vertices(fv);
    std::vector<std::vector<int>> loops;
    for (size_t k = 0; k < fv.size(); k += fv[k] + 1) {
      std::vector<int> loop(fv.begin() + k + 1, fv.begin() + k + 1 + fv[k]);
      std::vector<Vec3> p;
      for (int v : loop) p.push_back(x[v]);
      Vec3 mean = Vec3::Zero();
      for (const Vec3 &q : p) mean += q / p.size();
      // the cell lies on the side of the face opposite to its outward normal
      Vec3 inner = Vec3::Zero();
      for (const Vec3 &q : x) inner += q / x.size();
      if (newellNormal(p).dot(mean - inner) < 0) std::reverse(loop.begin(), loop.end());
      loops.push_back(loop);
    }
    return loops;
  }

  std::vector<Vec3> cellVertices(voro::voronoicell_neighbor &c, const Vec3 &origin)
  {
    std::vector<double> v;
    c.vertices(origin[0], origin[1], origin[2], v);
    std::vector<Vec3> x;
    for (size_t i = 0; i < v.size() / 3; ++i) x.push_back(at(v, i));
    return x;
  }

  int blocks(double length, double total, int n)
  {
    // about five particles per Voro++ block
    return std::max(1, static_cast<int>(std::round(length / std::cbrt(5.0 * total / n))));
  }

  // Farthest root of a t^2 - 2 b t + c = 0 (a > 0), or -inf without real roots.
  double farRoot(double a, double b, double c)
  {
    const double disc = b * b - a * c;
    if (a <= 0 || disc < 0) return -INFINITY;
    return (b + std::sqrt(disc)) / a;
  }

  // Closest point to p on the segment ab.
  Vec3 closestOnSegment(const Vec3 &p, const Vec3 &a, const Vec3 &b)
  {
    const Vec3 d = b - a;
    const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    return a + t * d;
  }

  // Distance from p to a convex planar polygon with unit normal n (counter-clockwise about n).
  double polygonDistance(const Vec3 &p, const std::vector<Vec3> &poly, const Vec3 &n)
  {
    const double h = (p - poly[0]).dot(n);
    const Vec3 q = p - h * n;
    bool inside = true;
    for (size_t k = 0; k < poly.size() && inside; ++k)
      inside = (poly[(k + 1) % poly.size()] - poly[k]).cross(q - poly[k]).dot(n) >= 0;
    if (inside) return std::abs(h);
    double best = INFINITY;
    for (size_t k = 0; k < poly.size(); ++k)
      best = std::min(best, (p - closestOnSegment(p, poly[k], poly[(k + 1) % poly.size()])).norm());
    return best;
  }

  // Distance from p to the triangle abc (closest point by Voronoi regions, Ericson 2005 §5.1.5).
  double triangleDistance(const Vec3 &p, const Vec3 &a, const Vec3 &b, const Vec3 &c)
  {
    const Vec3 n = (b - a).cross(c - a);
    const double n2 = n.squaredNorm();
    const Vec3 q = p - (p - a).dot(n) / n2 * n;
    // barycentric sign tests of the projection
    if ((b - a).cross(q - a).dot(n) >= 0 && (c - b).cross(q - b).dot(n) >= 0 &&
        (a - c).cross(q - c).dot(n) >= 0)
      return std::abs((p - a).dot(n)) / std::sqrt(n2);
    return std::min({(p - closestOnSegment(p, a, b)).norm(), (p - closestOnSegment(p, b, c)).norm(),
                     (p - closestOnSegment(p, c, a)).norm()});
  }

  // The polyhedron P shrunk by rho about the centre, cut from a box by the shifted face planes.
  Polytope shrunkPolytope(const VoronoiCell &cell, const Vec3 &centre, double rho)
  {
    double reach = 0;
    for (const VoronoiFace &f : cell.faces)
      for (const Vec3 &v : f.polygon) reach = std::max(reach, (v - centre).norm());
    voro::voronoicell_neighbor c;
    c.init(-2 * reach, 2 * reach, -2 * reach, 2 * reach, -2 * reach, 2 * reach);
    for (size_t f = 0; f < cell.faces.size(); ++f) {
      const VoronoiFace &face = cell.faces[f];
      // plane n . y = h - rho relative to the centre: Voro++ cuts at half the vector w
      const Vec3 w = 2.0 * (face.normal.dot(face.polygon[0] - centre) - rho) * face.normal;
      if (!c.nplane(w[0], w[1], w[2], w.squaredNorm(), static_cast<int>(f)))
        throw std::runtime_error("shrinking a cell by " + std::to_string(rho) + " m removed it");
    }
    Polytope q;
    q.vertices = cellVertices(c, Vec3::Zero());
    q.faces = faceLoops(c, q.vertices);
    std::vector<int> nb;
    c.neighbors(nb);
    q.faceId = nb;
    std::map<Edge, std::vector<int>> edgeFaces;
    for (size_t k = 0; k < q.faces.size(); ++k) {
      std::vector<Vec3> p;
      for (int v : q.faces[k]) p.push_back(q.vertices[v]);
      const Vec3 n = newellNormal(p);
      q.normals.push_back(n.normalized());
      q.area += 0.5 * n.norm();
      for (size_t i = 0; i < q.faces[k].size(); ++i) {
        const int a = q.faces[k][i], b = q.faces[k][(i + 1) % q.faces[k].size()];
        edgeFaces[{std::min(a, b), std::max(a, b)}].push_back(static_cast<int>(k));
      }
    }
    q.volume = c.volume();
    for (const auto &[e, fs] : edgeFaces) {
      if (fs.size() != 2) throw std::runtime_error("shrunk cell is not a closed polytope");
      const double psi = std::acos(std::clamp(q.normals[fs[0]].dot(q.normals[fs[1]]), -1.0, 1.0));
      q.edges.push_back(e);
      // Steiner: the edge's wedge adds t^2 L psi / 2 to the parallel volume
      q.meanCurvature += 0.5 * (q.vertices[e[0]] - q.vertices[e[1]]).norm() * psi;
    }
    return q;
  }

  double cv(const std::vector<double> &v)
  {
    const double mean = std::accumulate(v.begin(), v.end(), 0.0) / v.size();
    double var = 0;
    for (double x : v) var += (x - mean) * (x - mean) / v.size();
    return std::sqrt(var) / mean;
  }

}    // namespace

std::vector<VoronoiCell> tessellate(const std::vector<Vec3> &seeds, const Box &box)
{
  const Vec3 len = box.length();
  const double total = len.prod();
  const int n = static_cast<int>(seeds.size());
  voro::container con(box.lo[0], box.hi[0], box.lo[1], box.hi[1], box.lo[2], box.hi[2],
                      blocks(len[0], total, n), blocks(len[1], total, n), blocks(len[2], total, n),
                      box.periodic[0], box.periodic[1], box.periodic[2], 8);
  for (int i = 0; i < n; ++i) con.put(i, seeds[i][0], seeds[i][1], seeds[i][2]);
  std::vector<VoronoiCell> cells(seeds.size());
  std::vector<bool> done(seeds.size(), false);
  voro::c_loop_all loop(con);
  voro::voronoicell_neighbor c;
  if (loop.start()) do {
      if (!con.compute_cell(c, loop)) continue;
      const int id = loop.pid();
      double px, py, pz;
      loop.pos(px, py, pz);
      VoronoiCell &cell = cells[id];
      cell.seed = Vec3(px, py, pz);
      cell.volume = c.volume();
      double cx, cy, cz;
      c.centroid(cx, cy, cz);
      cell.centroid = cell.seed + Vec3(cx, cy, cz);
      const std::vector<Vec3> x = cellVertices(c, cell.seed);
      std::vector<int> nb;
      c.neighbors(nb);
      const std::vector<std::vector<int>> loops = faceLoops(c, x);
      for (size_t k = 0; k < loops.size(); ++k) {
        VoronoiFace f;
        for (int v : loops[k]) f.polygon.push_back(x[v]);
        const Vec3 nn = newellNormal(f.polygon);
        f.normal = nn.normalized();
        f.offset = f.normal.dot(f.polygon[0] - cell.seed);
        f.neighbour = nb[k] >= 0 ? nb[k] : -1;
        if (f.neighbour >= 0) {
          // the neighbour's image is the mirror image of this seed in the face (a bisector)
          const Vec3 image = cell.seed + 2.0 * f.offset * f.normal - seeds[f.neighbour];
          for (int d = 0; d < 3; ++d)
            f.image[d] = box.periodic[d] ? static_cast<int>(std::lround(image[d] / len[d])) : 0;
        }
        cell.faces.push_back(std::move(f));
      }
      done[id] = true;
    } while (loop.inc());
  if (std::find(done.begin(), done.end(), false) != done.end())
    throw std::runtime_error("Voro++ did not compute every cell");
  return cells;
}

double volumeCV(const std::vector<VoronoiCell> &cells)
{
  std::vector<double> v;
  for (const VoronoiCell &c : cells) v.push_back(c.volume);
  return cv(v);
}

std::vector<Vec3> relaxedSeeds(int n, const Box &box, double targetCV, std::uint64_t seed,
                               int maxSteps, int &steps)
{
  std::mt19937_64 rng(seed);
  const Vec3 len = box.length();
  std::vector<Vec3> seeds;
  for (int i = 0; i < n; ++i) {
    Vec3 x;
    // uniform in [lo, hi) from the top 53 bits of one draw per coordinate
    for (int d = 0; d < 3; ++d)
      x[d] = box.lo[d] + len[d] * (static_cast<double>(rng() >> 11) * 0x1.0p-53);
    seeds.push_back(x);
  }
  // a fraction beta of Lloyd's step: every seed towards the centroid of its cell (Lloyd 1982)
  auto step = [&](const std::vector<VoronoiCell> &cells, double beta) {
    std::vector<Vec3> next(seeds);
    for (int i = 0; i < n; ++i) {
      next[i] += beta * (cells[i].centroid - cells[i].seed);
      for (int d = 0; d < 3; ++d)
        if (box.periodic[d]) next[i][d] -= len[d] * std::floor((next[i][d] - box.lo[d]) / len[d]);
    }
    return next;
  };
  for (steps = 0; steps < maxSteps; ++steps) {
    const std::vector<VoronoiCell> cells = tessellate(seeds, box);
    if (volumeCV(cells) <= targetCV) break;
    std::vector<Vec3> full = step(cells, 1.0);
    if (volumeCV(tessellate(full, box)) > targetCV) {
      seeds.swap(full);
      continue;
    }
    // the full step passes the target: bisect the fraction of it that lands on the target
    double lo = 0, hi = 1;
    for (int it = 0; it < 30; ++it) {
      const double mid = 0.5 * (lo + hi);
      (volumeCV(tessellate(step(cells, mid), box)) > targetCV ? lo : hi) = mid;
    }
    seeds = step(cells, hi);
    ++steps;
    break;
  }
  return seeds;
}

InBall largestInscribedBall(const VoronoiCell &cell)
{
  // Linear programme: maximise t with n_f . x + t <= D_f; its optimum is a vertex where four
  // constraints are active, so every set of four faces is tried (Chebyshev centre).
  const size_t nf = cell.faces.size();
  std::vector<double> D(nf);
  for (size_t f = 0; f < nf; ++f) D[f] = cell.faces[f].normal.dot(cell.faces[f].polygon[0]);
  InBall best{cell.centroid, -INFINITY};
  for (size_t a = 0; a < nf; ++a)
    for (size_t b = a + 1; b < nf; ++b)
      for (size_t c = b + 1; c < nf; ++c)
        for (size_t d = c + 1; d < nf; ++d) {
          Eigen::Matrix4d m;
          Eigen::Vector4d rhs;
          const size_t idx[4] = {a, b, c, d};
          for (int r = 0; r < 4; ++r) {
            m.row(r) << cell.faces[idx[r]].normal.transpose(), 1.0;
            rhs[r] = D[idx[r]];
          }
          const Eigen::FullPivLU<Eigen::Matrix4d> lu(m);
          if (!lu.isInvertible()) continue;
          const Eigen::Vector4d s = lu.solve(rhs);
          if (s[3] <= best.radius) continue;
          const Vec3 x = s.head<3>();
          bool feasible = true;
          for (size_t f = 0; f < nf && feasible; ++f)
            feasible = cell.faces[f].normal.dot(x) + s[3] <= D[f] + 1e-12 * std::abs(D[f]) + 1e-18;
          if (feasible) best = {x, s[3]};
        }
  if (!(best.radius > 0)) throw std::runtime_error("no inscribed ball found for a cell");
  return best;
}

RoundedCell::RoundedCell(const VoronoiCell &cell, const InBall &ball, double rho, double eps) :
    centre_(ball.centre), r_(rho - eps), core_(shrunkPolytope(cell, ball.centre, rho))
{
  for (size_t k = 0; k < core_.faces.size(); ++k)
    planeOffset_.push_back(core_.normals[k].dot(core_.vertices[core_.faces[k][0]]));
}

double RoundedCell::parallelVolume(double t) const
{
  // Steiner's formula for a convex polytope
  return core_.volume + t * core_.area + t * t * core_.meanCurvature + 4.0 / 3.0 * kPi * t * t * t;
}

double RoundedCell::parallelArea(double t) const
{
  return core_.area + 2.0 * t * core_.meanCurvature + 4.0 * kPi * t * t;
}

double RoundedCell::rayExit(const Vec3 &u) const
{
  // The body is the union of the core, a prism on each face, a cylinder on each edge and a ball
  // on each vertex; the ray from the centre leaves it at the farthest exit of these pieces.
  double exitCore = INFINITY;
  for (size_t k = 0; k < core_.faces.size(); ++k) {
    const double nu = core_.normals[k].dot(u);
    if (nu > 0) exitCore = std::min(exitCore, planeOffset_[k] / nu);
  }
  double best = exitCore;
  if (r_ <= 0) return best;
  for (size_t k = 0; k < core_.faces.size(); ++k) {
    const Vec3 &n = core_.normals[k];
    const double nu = n.dot(u);
    if (nu <= 0) continue;
    const double t = (planeOffset_[k] + r_) / nu;
    const Vec3 q = t * u - r_ * n;
    const std::vector<int> &loop = core_.faces[k];
    bool inside = true;
    for (size_t i = 0; i < loop.size() && inside; ++i) {
      const Vec3 &a = core_.vertices[loop[i]], &b = core_.vertices[loop[(i + 1) % loop.size()]];
      inside = (b - a).cross(q - a).dot(n) >= 0;
    }
    if (inside) best = std::max(best, t);
  }
  for (const Edge &e : core_.edges) {
    const Vec3 &a = core_.vertices[e[0]];
    const Vec3 d = core_.vertices[e[1]] - a;
    const double len = d.norm();
    if (len <= 0) continue;
    const Vec3 ed = d / len;
    const Vec3 up = u - u.dot(ed) * ed, ap = a - a.dot(ed) * ed;
    // |t u_perp - a_perp|^2 = r^2
    const double t = farRoot(up.squaredNorm(), up.dot(ap), ap.squaredNorm() - r_ * r_);
    const double s = (t * u - a).dot(ed);
    if (std::isfinite(t) && s >= 0 && s <= len) best = std::max(best, t);
  }
  for (const Vec3 &v : core_.vertices)
    best = std::max(best, farRoot(1.0, u.dot(v), v.squaredNorm() - r_ * r_));
  return best;
}

double RoundedCell::depth(const Vec3 &x) const
{
  const Vec3 y = x - centre_;
  double inside = INFINITY;
  for (size_t k = 0; k < core_.faces.size(); ++k)
    inside = std::min(inside, planeOffset_[k] - core_.normals[k].dot(y));
  if (inside >= 0) return r_ + inside;
  // outside the core: the nearest core point lies on a face that faces y
  double dist = INFINITY;
  for (size_t k = 0; k < core_.faces.size(); ++k) {
    if (core_.normals[k].dot(y) <= planeOffset_[k]) continue;
    std::vector<Vec3> poly;
    for (int v : core_.faces[k]) poly.push_back(core_.vertices[v]);
    dist = std::min(dist, polygonDistance(y, poly, core_.normals[k]));
  }
  return r_ - dist;
}

std::vector<Vec3> RoundedCell::facet(int f) const
{
  std::vector<Vec3> out;
  for (size_t k = 0; k < core_.faces.size(); ++k)
    if (core_.faceId[k] == f) {
      for (int v : core_.faces[k])
        out.push_back(centre_ + core_.vertices[v] + r_ * core_.normals[k]);
      break;
    }
  return out;
}

MeshMeasure meshMeasure(const std::vector<Vec3> &x, const std::vector<Tri> &tri,
                        const std::vector<Edge> &edges, double t)
{
  MeshMeasure m;
  const Vec3 o = x[0];
  std::map<Edge, std::vector<int>> edgeTri;
  for (size_t k = 0; k < tri.size(); ++k) {
    const Vec3 a = x[tri[k][0]] - o, b = x[tri[k][1]] - o, c = x[tri[k][2]] - o;
    // divergence theorem: the signed volume of the tetrahedron with the origin
    m.volume += a.dot(b.cross(c)) / 6.0;
    m.area += 0.5 * (b - a).cross(c - a).norm();
    for (int i = 0; i < 3; ++i) {
      const int p = tri[k][i], q = tri[k][(i + 1) % 3];
      edgeTri[{std::min(p, q), std::max(p, q)}].push_back(static_cast<int>(k));
    }
  }
  double wedge = 0;
  for (const Edge &e : edges) {
    const std::vector<int> &ts = edgeTri.at(e);
    const Tri &t1 = tri[ts[0]], &t2 = tri[ts[1]];
    const Vec3 n1 = (x[t1[1]] - x[t1[0]]).cross(x[t1[2]] - x[t1[0]]).normalized();
    const Vec3 n2 = (x[t2[1]] - x[t2[0]]).cross(x[t2[2]] - x[t2[0]]).normalized();
    int opposite = t2[0];
    for (int v : t2)
      if (v != e[0] && v != e[1]) opposite = v;
    const double psi = std::acos(std::clamp(n1.dot(n2), -1.0, 1.0));
    // convex edge: the other triangle's far vertex lies below this triangle's plane
    const double sign = (x[opposite] - x[t1[0]]).dot(n1) <= 0 ? 1.0 : -1.0;
    wedge += 0.5 * (x[e[0]] - x[e[1]]).norm() * psi * sign;
  }
  // Steiner's formula on the mesh
  m.parallel = m.volume + t * m.area + t * t * wedge + 4.0 / 3.0 * kPi * t * t * t;
  return m;
}

namespace {
  bool folded(const std::vector<Vec3> &x, const std::vector<Tri> &tri, const Vec3 &c)
  {
    for (const Tri &t : tri)
      if ((x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).dot(x[t[0]] - c) <= 0) return true;
    return false;
  }

  // Puts back the old positions of every triangle that is folded in `next`, until none is.
  void keepUnfolded(std::vector<Vec3> &next, const std::vector<Vec3> &old,
                    const std::vector<Tri> &tri, const Vec3 &c)
  {
    for (bool changed = true; changed;) {
      changed = false;
      for (const Tri &t : tri)
        if ((next[t[1]] - next[t[0]]).cross(next[t[2]] - next[t[0]]).dot(next[t[0]] - c) <= 0)
          for (int v : t)
            if (next[v] != old[v]) {
              next[v] = old[v];
              changed = true;
            }
    }
  }
}    // namespace

std::vector<Vec3> wallOnCell(const Surface &unit, const RoundedCell &cell, int iterations)
{
  const Vec3 &c = cell.centre();
  std::vector<Vec3> x;
  for (const Vec3 &u : unit.points) x.push_back(c + cell.rayExit(u) * u);
  std::vector<std::vector<int>> nb(unit.points.size());
  for (const Edge &e : unit.edges) {
    nb[e[0]].push_back(e[1]);
    nb[e[1]].push_back(e[0]);
  }
  for (int it = 0; it < iterations; ++it) {
    double mean = 0;
    for (const Edge &e : unit.edges) mean += (x[e[0]] - x[e[1]]).norm() / unit.edges.size();
    std::vector<Vec3> next(x.size());
    for (size_t i = 0; i < x.size(); ++i) {
      Vec3 push = Vec3::Zero();
      for (int j : nb[i]) {
        const Vec3 d = x[j] - x[i];
        // tension-only linear springs of rest length the mean edge pull the sparse parts together
        push += std::max(0.0, 1.0 - mean / d.norm()) * d * kStep;
      }
      const Vec3 u = (x[i] + push - c).normalized();
      next[i] = c + cell.rayExit(u) * u;
    }
    // points of a triangle that the step would fold (seen from the centre) stay where they were
    keepUnfolded(next, x, unit.triangles, c);
    x.swap(next);
  }
  // the radial map keeps every triangle outward: det(a - c, b - c, e - c) scales by positive radii
  if (folded(x, unit.triangles, c)) throw std::runtime_error("wall mesh folded");
  return x;
}

std::vector<Vec3> fluidInWall(const RoundedCell &cell, const std::vector<Vec3> &wall,
                              const std::vector<Tri> &tri, double dx, double gap)
{
  const Vec3 &c = cell.centre();
  double reach = 0, longest = 0;
  for (const Vec3 &p : wall) reach = std::max(reach, (p - c).norm());
  std::vector<Vec3> centroid;
  std::vector<double> radius;
  for (const Tri &t : tri) {
    const Vec3 m = (wall[t[0]] + wall[t[1]] + wall[t[2]]) / 3.0;
    double r = 0;
    for (int i = 0; i < 3; ++i) {
      r = std::max(r, (wall[t[i]] - m).norm());
      longest = std::max(longest, (wall[t[i]] - wall[t[(i + 1) % 3]]).norm());
    }
    centroid.push_back(m);
    radius.push_back(r);
  }
  std::vector<Vec3> out;
  const int k = static_cast<int>(reach / dx) + 1;
  for (int i = -k; i <= k; ++i)
    for (int j = -k; j <= k; ++j)
      for (int l = -k; l <= k; ++l) {
        const Vec3 y = c + dx * Vec3(i, j, l);
        const double d = cell.depth(y);
        if (d < gap) continue;
        // the mesh lies inside the body within one edge length of its surface: exact test there
        if (d < gap + longest) {
          bool ok = true;
          for (size_t t = 0; t < tri.size() && ok; ++t) {
            const Vec3 &a = wall[tri[t][0]], &b = wall[tri[t][1]], &e = wall[tri[t][2]];
            if ((y - centroid[t]).norm() - radius[t] < gap)
              ok = triangleDistance(y, a, b, e) >= gap;
            // star-shaped from the centre: y is inside iff below the triangle its ray crosses
            const Vec3 v = y - c;
            if (ok && (a - c).cross(b - c).dot(v) >= 0 && (b - c).cross(e - c).dot(v) >= 0 &&
                (e - c).cross(a - c).dot(v) >= 0)
              ok = (y - a).dot((b - a).cross(e - a)) < 0;
          }
          if (!ok) continue;
        }
        out.push_back(y);
      }
  return out;
}

double overlapArea(const std::vector<Vec3> &a, const std::vector<Vec3> &b, const Vec3 &n)
{
  if (a.size() < 3 || b.size() < 3) return 0;
  const Vec3 e1 = (std::abs(n[0]) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
  const Vec3 e2 = n.cross(e1);
  using P2 = Eigen::Vector2d;
  auto flat = [&](const std::vector<Vec3> &p) {
    std::vector<P2> q;
    for (const Vec3 &x : p) q.emplace_back(x.dot(e1), x.dot(e2));
    double s = 0;
    for (size_t k = 0; k < q.size(); ++k) {
      const P2 &u = q[k], &v = q[(k + 1) % q.size()];
      s += u[0] * v[1] - u[1] * v[0];
    }
    if (s < 0) std::reverse(q.begin(), q.end());
    return q;
  };
  auto cross = [](const P2 &u, const P2 &v) { return u[0] * v[1] - u[1] * v[0]; };
  std::vector<P2> poly = flat(a);
  const std::vector<P2> clip = flat(b);
  // Sutherland-Hodgman clipping of one convex polygon by the other's edges
  for (size_t k = 0; k < clip.size() && !poly.empty(); ++k) {
    const P2 &p = clip[k], &q = clip[(k + 1) % clip.size()];
    std::vector<P2> next;
    for (size_t i = 0; i < poly.size(); ++i) {
      const P2 &s = poly[i], &t = poly[(i + 1) % poly.size()];
      const double ss = cross(q - p, s - p), st = cross(q - p, t - p);
      if (ss >= 0) next.push_back(s);
      if ((ss >= 0) != (st >= 0)) next.push_back(s + (t - s) * (ss / (ss - st)));
    }
    poly.swap(next);
  }
  double area = 0;
  for (size_t k = 0; k < poly.size(); ++k) area += cross(poly[k], poly[(k + 1) % poly.size()]);
  return 0.5 * std::abs(area);
}

}    // namespace cellgen
