#include "geometry.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace cellgen {

namespace {

  constexpr double kPi = 3.14159265358979323846;

  // ---- golden-spiral points and their relaxation -------------------------------------------

  // Buckets points of the cube [-1, 1]^3 into cubic bins no smaller than the cutoff.
  class BinGrid {
   public:
    BinGrid(const std::vector<Vec3> &points, double cutoff) :
        m_(std::max(1, static_cast<int>(2.0 / cutoff))), width_(2.0 / m_)
    {
      std::vector<int> bins(points.size());
      start_.assign(static_cast<size_t>(m_) * m_ * m_ + 1, 0);
      for (size_t i = 0; i < points.size(); ++i) {
        bins[i] = index(bin(points[i][0]), bin(points[i][1]), bin(points[i][2]));
        ++start_[bins[i] + 1];
      }
      std::partial_sum(start_.begin(), start_.end(), start_.begin());
      members_.resize(points.size());
      std::vector<int> fill(start_.begin(), start_.end() - 1);
      for (size_t i = 0; i < points.size(); ++i) members_[fill[bins[i]]++] = static_cast<int>(i);
    }

    // Calls f(j) for every point j in the 27 bins around x.
    template <class F> void forNear(const Vec3 &x, F &&f) const
    {
      const int bx = bin(x[0]), by = bin(x[1]), bz = bin(x[2]);
      for (int i = std::max(bx - 1, 0); i <= std::min(bx + 1, m_ - 1); ++i)
        for (int j = std::max(by - 1, 0); j <= std::min(by + 1, m_ - 1); ++j)
          for (int k = std::max(bz - 1, 0); k <= std::min(bz + 1, m_ - 1); ++k) {
            const int b = index(i, j, k);
            for (int s = start_[b]; s < start_[b + 1]; ++s) f(members_[s]);
          }
    }

   private:
    int bin(double c) const { return std::clamp(static_cast<int>((c + 1.0) / width_), 0, m_ - 1); }
    int index(int i, int j, int k) const { return (i * m_ + j) * m_ + k; }

    int m_;
    double width_;
    std::vector<int> start_, members_;
  };

  // Nearest-neighbour distance of a hexagonal lattice of n points covering the unit sphere's area.
  double hexSpacing(size_t n)
  {
    return std::sqrt(8.0 * kPi / (std::sqrt(3.0) * n));
  }

  // Short-range repulsion tapered to zero at the cutoff rc: sum of d/r * (rc - r)^2 / (rc r).
  std::vector<Vec3> repulsion(const std::vector<Vec3> &points, double cutoff)
  {
    const BinGrid grid(points, cutoff);
    std::vector<Vec3> push(points.size(), Vec3::Zero());
    for (size_t i = 0; i < points.size(); ++i)
      grid.forNear(points[i], [&](int j) {
        const Vec3 d = points[i] - points[j];
        const double r = d.norm();
        if (r > 0.0 && r < cutoff) push[i] += d * ((cutoff - r) * (cutoff - r) / (cutoff * r * r));
      });
    return push;
  }

  // ---- exact orientation and the incremental convex hull -----------------------------------

  using IPoint = std::array<std::int64_t, 3>;
  __extension__ typedef __int128 Int128;

  // Sign of (p - a) . ((b - a) x (c - a)). Coordinates are below 2^39 in magnitude, so differences
  // stay below 2^40, the 2x2 minors below 2^81 and the determinant below 2^123: exact in __int128.
  int orientation(const IPoint &a, const IPoint &b, const IPoint &c, const IPoint &p)
  {
    const std::int64_t u0 = b[0] - a[0], u1 = b[1] - a[1], u2 = b[2] - a[2];
    const std::int64_t v0 = c[0] - a[0], v1 = c[1] - a[1], v2 = c[2] - a[2];
    const std::int64_t w0 = p[0] - a[0], w1 = p[1] - a[1], w2 = p[2] - a[2];
    const Int128 m0 = static_cast<Int128>(u1) * v2 - static_cast<Int128>(u2) * v1;
    const Int128 m1 = static_cast<Int128>(u2) * v0 - static_cast<Int128>(u0) * v2;
    const Int128 m2 = static_cast<Int128>(u0) * v1 - static_cast<Int128>(u1) * v0;
    const Int128 det = m0 * w0 + m1 * w1 + m2 * w2;
    return (det > 0) - (det < 0);
  }

  // Snaps points into the integer cube |x| < 2^39 after scaling the farthest point to 1.
  std::vector<IPoint> snapPoints(const std::vector<Vec3> &points)
  {
    double extent = 0.0;
    for (const Vec3 &x : points) extent = std::max(extent, x.cwiseAbs().maxCoeff());
    const double scale = std::ldexp(1.0, 39) * (1.0 - 1e-12) / extent;
    std::vector<IPoint> snapped;
    snapped.reserve(points.size());
    for (const Vec3 &x : points)
      snapped.push_back(
          {std::llround(x[0] * scale), std::llround(x[1] * scale), std::llround(x[2] * scale)});
    return snapped;
  }

  template <class Key> int argmax(size_t n, Key &&key)
  {
    int best = 0;
    for (size_t i = 1; i < n; ++i)
      if (key(i) > key(best)) best = static_cast<int>(i);
    return best;
  }

  // Quickhull-style incremental hull: every face keeps the unprocessed points above it; a point is
  // added by removing the faces it sees and coning their horizon to it.
  class Hull {
   public:
    explicit Hull(const std::vector<Vec3> &points) : pts_(snapPoints(points))
    {
      const std::array<int, 4> simplex = initialSimplex(points);
      buildSimplex(simplex);
      assignInitial(simplex);
      run();
    }

    std::vector<Tri> triangles() const
    {
      std::vector<Tri> out;
      for (const Face &f : faces_)
        if (f.alive) out.push_back(f.v);
      return out;
    }

   private:
    struct Face {
      explicit Face(const Tri &vertices) : v(vertices) {}
      Tri v;
      std::array<int, 3> nb{-1, -1, -1};    // nb[i] lies across edge v[i] -> v[i+1]
      std::vector<int> outside;
      int visibleFrom = -1;
      bool alive = true;
    };

    bool above(int f, int p) const
    {
      const Tri &v = faces_[f].v;
      return orientation(pts_[v[0]], pts_[v[1]], pts_[v[2]], pts_[p]) > 0;
    }

    std::array<int, 4> initialSimplex(const std::vector<Vec3> &x) const
    {
      const int a = 0;
      const int b = argmax(x.size(), [&](size_t i) { return (x[i] - x[a]).squaredNorm(); });
      const Vec3 ab = x[b] - x[a];
      const int c =
          argmax(x.size(), [&](size_t i) { return (x[i] - x[a]).cross(ab).squaredNorm(); });
      const Vec3 n = ab.cross(x[c] - x[a]);
      const int d = argmax(x.size(), [&](size_t i) { return std::abs((x[i] - x[a]).dot(n)); });
      if (orientation(pts_[a], pts_[b], pts_[c], pts_[d]) == 0)
        throw std::runtime_error("convexHull: all points are coplanar");
      return {a, b, c, d};
    }

    void buildSimplex(const std::array<int, 4> &s)
    {
      for (int skip = 0; skip < 4; ++skip) {
        Tri v{};
        for (int i = 0, k = 0; i < 4; ++i)
          if (i != skip) v[k++] = s[i];
        if (orientation(pts_[v[0]], pts_[v[1]], pts_[v[2]], pts_[s[skip]]) > 0)
          std::swap(v[1], v[2]);
        faces_.emplace_back(v);
      }
      std::map<std::pair<int, int>, int> byEdge;
      for (int f = 0; f < 4; ++f)
        for (int i = 0; i < 3; ++i) byEdge[{faces_[f].v[i], faces_[f].v[(i + 1) % 3]}] = f;
      for (Face &f : faces_)
        for (int i = 0; i < 3; ++i) f.nb[i] = byEdge.at({f.v[(i + 1) % 3], f.v[i]});
    }

    // Points go to their faces in a fixed pseudo-random order, so insertion order is randomised.
    void assignInitial(const std::array<int, 4> &simplex)
    {
      std::vector<int> order(pts_.size());
      std::iota(order.begin(), order.end(), 0);
      std::shuffle(order.begin(), order.end(), std::mt19937_64(12345));
      for (int p : order) {
        if (std::find(simplex.begin(), simplex.end(), p) != simplex.end()) continue;
        for (int f = 0; f < 4; ++f)
          if (above(f, p)) {
            faces_[f].outside.push_back(p);
            break;
          }
      }
    }

    void run()
    {
      std::vector<int> pending{0, 1, 2, 3};
      while (!pending.empty()) {
        const int f = pending.back();
        pending.pop_back();
        if (!faces_[f].alive || faces_[f].outside.empty()) continue;
        const int p = faces_[f].outside.back();
        const std::vector<int> visible = visibleFaces(f, p);
        const std::vector<int> cone = addCone(visible, p);
        reassign(visible, cone, p);
        for (int g : cone)
          if (!faces_[g].outside.empty()) pending.push_back(g);
      }
    }

    // Faces seen from p, grown from face f0 (the visible region of a convex hull is connected).
    std::vector<int> visibleFaces(int f0, int p)
    {
      std::vector<int> visible{f0};
      faces_[f0].visibleFrom = p;
      for (size_t k = 0; k < visible.size(); ++k)
        for (int n : faces_[visible[k]].nb)
          if (faces_[n].visibleFrom != p && above(n, p)) {
            faces_[n].visibleFrom = p;
            visible.push_back(n);
          }
      return visible;
    }

    // New faces (a, b, p) on every horizon edge a -> b, linked to each other and to the old hull.
    std::vector<int> addCone(const std::vector<int> &visible, int p)
    {
      std::vector<int> cone;
      std::unordered_map<int, int> startsAt, endsAt;
      for (int f : visible)
        for (int i = 0; i < 3; ++i) {
          const int n = faces_[f].nb[i];
          if (faces_[n].visibleFrom == p) continue;
          const int a = faces_[f].v[i], b = faces_[f].v[(i + 1) % 3];
          const int g = static_cast<int>(faces_.size());
          faces_.emplace_back(Tri{a, b, p});
          faces_[g].nb[0] = n;
          std::replace(faces_[n].nb.begin(), faces_[n].nb.end(), f, g);
          startsAt[a] = g;
          endsAt[b] = g;
          cone.push_back(g);
        }
      for (int g : cone) {
        faces_[g].nb[1] = startsAt.at(faces_[g].v[1]);
        faces_[g].nb[2] = endsAt.at(faces_[g].v[0]);
      }
      return cone;
    }

    // Points above a removed face are either above a new face or inside the new hull.
    void reassign(const std::vector<int> &visible, const std::vector<int> &cone, int p)
    {
      for (int f : visible) {
        std::vector<int> outside;
        outside.swap(faces_[f].outside);
        faces_[f].alive = false;
        for (int q : outside) {
          if (q == p) continue;
          const auto g = std::find_if(cone.begin(), cone.end(), [&](int c) { return above(c, q); });
          if (g != cone.end()) faces_[*g].outside.push_back(q);
        }
      }
    }

    std::vector<IPoint> pts_;
    std::vector<Face> faces_;
  };

  // Throws unless the triangles form a closed, consistently oriented surface of genus 0 on n points.
  void checkClosedSphere(const std::vector<Tri> &triangles, const std::vector<Edge> &edges, int n)
  {
    std::vector<Edge> directed;
    for (const Tri &t : triangles)
      for (int i = 0; i < 3; ++i) directed.push_back({t[i], t[(i + 1) % 3]});
    std::sort(directed.begin(), directed.end());
    const bool uniqueDirected =
        std::adjacent_find(directed.begin(), directed.end()) == directed.end();
    const long euler = static_cast<long>(n) - static_cast<long>(edges.size()) +
        static_cast<long>(triangles.size());
    if (!uniqueDirected || 2 * edges.size() != directed.size() || euler != 2)
      throw std::runtime_error("sphereSurface: triangulation is not a closed sphere (V-E+F=" +
                               std::to_string(euler) + ")");
  }

  // counts[s] = number of lattice points (i, j, l) with i^2 + j^2 + l^2 <= s, for s = 0 .. k^2.
  std::vector<long> latticeBallCounts(int k)
  {
    const long maxS = static_cast<long>(k) * k;
    std::vector<long> counts(maxS + 1, 0);
    for (int i = -k; i <= k; ++i)
      for (int j = -k; j <= k; ++j)
        for (int l = -k; l <= k; ++l) {
          const long s =
              static_cast<long>(i) * i + static_cast<long>(j) * j + static_cast<long>(l) * l;
          if (s <= maxS) ++counts[s];
        }
    std::partial_sum(counts.begin(), counts.end(), counts.begin());
    return counts;
  }

  // Uniform in [-1, 1] from the top 53 bits of one Mersenne-twister draw (portable, deterministic).
  double uniformSigned(std::mt19937_64 &rng)
  {
    return 2.0 * static_cast<double>(rng() >> 11) * 0x1.0p-53 - 1.0;
  }

  void appendCell(System &sys, const Surface &unit, const CellSpec &cell, int molecule,
                  const BuildParams &params, std::mt19937_64 &rng)
  {
    const double r = cell.radius;
    const bool sphere = params.shape == Vec3::Ones();
    std::vector<Vec3> fluid = !params.withFluid ? std::vector<Vec3>()
        : sphere ? fluidLattice(r - params.spacing.gap, params.spacing.dx)
                 : fluidEllipsoid(r * params.shape, params.spacing.gap, params.spacing.dx);
    // --fluid-lattice shells: as many points (so the same masses), on spheres from R - G inwards
    if (params.shells && !fluid.empty())
      fluid = fluidShells(static_cast<long>(fluid.size()), r - params.spacing.gap, rng).points;
    if (fluid.empty() && params.withFluid)
      throw std::runtime_error("cell " + std::to_string(molecule) + " has no fluid particle");
    // fluid fills the volume 4/3 pi R^3 enclosed by the wall at the reference density (an
    // ellipsoid's R is the equal-volume radius: 4/3 pi R^3 = 4/3 pi a b c)
    const double fluidMass =
        params.rho0 * 4.0 / 3.0 * kPi * r * r * r / std::max<size_t>(fluid.size(), 1);
    // wall shell of area 4 pi R^2 (ellipsoid: its exact area) and the given thickness at the
    // reference density
    const double shellArea = sphere ? 4.0 * kPi * r * r : ellipsoidArea(r * params.shape);
    const double wallMass = params.wallMass.value_or(params.rho0 * shellArea *
                                                     params.wallThickness / unit.points.size());
    for (const Vec3 &x : fluid)
      sys.particles.push_back({molecule, kFluid, cell.centre + x, fluidMass});
    const int offset = static_cast<int>(sys.particles.size());
    for (const Vec3 &x : unit.points)
      sys.particles.push_back({molecule, kWall, cell.centre + r * x, wallMass});
    for (const Edge &e : unit.edges) sys.bonds.push_back({offset + e[0], offset + e[1]});
    for (const Tri &t : unit.triangles)
      sys.triangles.push_back({offset + t[0], offset + t[1], offset + t[2]});
  }

}    // namespace

std::vector<Vec3> fibonacciSphere(int n)
{
  const double golden = kPi * (3.0 - std::sqrt(5.0));    // golden angle
  std::vector<Vec3> points;
  points.reserve(n);
  for (int i = 0; i < n; ++i) {
    // equal-area bands in z, golden-angle steps in azimuth
    const double z = 1.0 - (2.0 * i + 1.0) / n;
    const double rho = std::sqrt(1.0 - z * z);
    points.emplace_back(rho * std::cos(golden * i), rho * std::sin(golden * i), z);
  }
  return points;
}

void relaxOnSphere(std::vector<Vec3> &points, int iterations)
{
  const double spacing = hexSpacing(points.size());
  const double cutoff = 2.5 * spacing;
  const double step = 0.1 * spacing;
  for (int it = 0; it < iterations; ++it) {
    const std::vector<Vec3> push = repulsion(points, cutoff);
    for (size_t i = 0; i < points.size(); ++i) {
      // keep the tangential part only, then project back onto the sphere
      const Vec3 tangential = push[i] - push[i].dot(points[i]) * points[i];
      points[i] = (points[i] + step * tangential).normalized();
    }
  }
}

std::vector<Tri> convexHull(const std::vector<Vec3> &points)
{
  if (points.size() < 4) throw std::runtime_error("convexHull: need at least 4 points");
  return Hull(points).triangles();
}

std::vector<Edge> uniqueEdges(const std::vector<Tri> &triangles)
{
  std::vector<Edge> edges;
  edges.reserve(3 * triangles.size());
  for (const Tri &t : triangles)
    for (int i = 0; i < 3; ++i)
      edges.push_back({std::min(t[i], t[(i + 1) % 3]), std::max(t[i], t[(i + 1) % 3])});
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

Surface sphereSurface(std::vector<Vec3> points)
{
  Surface s;
  s.points = std::move(points);
  s.triangles = convexHull(s.points);
  s.edges = uniqueEdges(s.triangles);
  checkClosedSphere(s.triangles, s.edges, static_cast<int>(s.points.size()));
  for (const Tri &t : s.triangles) {
    const Vec3 &a = s.points[t[0]];
    if ((s.points[t[1]] - a).cross(s.points[t[2]] - a).dot(a) <= 0.0)
      throw std::runtime_error("sphereSurface: inward triangle");
  }
  return s;
}

Surface spiralSurface(int n)
{
  std::vector<Vec3> points = fibonacciSphere(n);
  relaxOnSphere(points, 40);
  return sphereSurface(std::move(points));
}

GeodesicClass chooseGeodesic(long n)
{
  // candidates T up to the first class-I T beyond the target: h^2 >= (n - 2) / 10
  const int hmax = static_cast<int>(std::ceil(std::sqrt(std::max(0.0, (n - 2) / 10.0)))) + 1;
  GeodesicClass best;
  auto worse = [n](const GeodesicClass &a, const GeodesicClass &b) {
    // true if b is preferred to a: closer to n, then class I, then smaller k, then smaller T
    const long da = std::labs(a.points() - n), db = std::labs(b.points() - n);
    if (db != da) return db < da;
    if ((b.k == 0) != (a.k == 0)) return b.k == 0;
    if (b.k != a.k) return b.k < a.k;
    return b.triangulationNumber() < a.triangulationNumber();
  };
  for (int h = 1; h <= hmax; ++h)
    for (int k = 0; k <= h; ++k) {
      const GeodesicClass c{h, k};
      if (worse(best, c)) best = c;
    }
  return best;
}

std::vector<Vec3> geodesicSphere(const GeodesicClass &c)
{
  const double t = 0.5 * (1.0 + std::sqrt(5.0));    // golden ratio
  const std::array<Vec3, 12> v = {Vec3(-1, t, 0), Vec3(1, t, 0), Vec3(-1, -t, 0), Vec3(1, -t, 0),
                                  Vec3(0, -1, t), Vec3(0, 1, t), Vec3(0, -1, -t), Vec3(0, 1, -t),
                                  Vec3(t, 0, -1), Vec3(t, 0, 1), Vec3(-t, 0, -1), Vec3(-t, 0, 1)};
  std::array<Tri, 20> faces = {Tri{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                               {1, 5, 9},     {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                               {3, 9, 4},     {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                               {4, 9, 5},     {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  // every face counter-clockwise seen from outside, so that all faces carry the same chirality
  for (Tri &f : faces)
    if ((v[f[1]] - v[f[0]]).cross(v[f[2]] - v[f[0]]).dot(v[f[0]]) < 0.0) std::swap(f[1], f[2]);

  const long h = c.h, k = c.k, T = c.triangulationNumber();
  std::vector<Vec3> points;
  for (const Vec3 &x : v) points.push_back(x.normalized());
  std::map<std::array<long, 3>, int> edgePoints;    // (lower vertex, upper vertex, its weight)
  std::vector<Vec3> interior;
  for (const Tri &f : faces) {
    // Lattice point i e1 + j e2 (e1, e2 unit vectors 60 degrees apart) in the face triangle with
    // corners 0, (h, k) and (-k, h + k) (the first rotated by 60 degrees); its barycentric
    // weights are n0/T, n1/T, n2/T: inside or on the triangle iff all are >= 0 (exact integers).
    for (long i = -k; i <= h; ++i)
      for (long j = 0; j <= h + k; ++j) {
        const long n1 = (h + k) * i + k * j, n2 = h * j - k * i, n0 = T - n1 - n2;
        if (n0 < 0 || n1 < 0 || n2 < 0) continue;
        const std::array<long, 3> w = {n0, n1, n2};
        const int zeros = (n0 == 0) + (n1 == 0) + (n2 == 0);
        if (zeros == 2) continue;    // an icosahedron vertex, already listed
        const Vec3 x = (static_cast<double>(n0) * v[f[0]] + static_cast<double>(n1) * v[f[1]] +
                        static_cast<double>(n2) * v[f[2]]) /
            static_cast<double>(T);
        if (zeros == 0) {
          interior.push_back(x.normalized());
          continue;
        }
        // on an edge shared with the neighbouring face: keep one copy, named by its end vertices
        const int m0 = n0 == 0 ? 1 : 0, m1 = n2 == 0 ? 1 : 2;    // the two nonzero weights
        const bool lowerFirst = f[m0] < f[m1];
        const long a = lowerFirst ? f[m0] : f[m1], b = lowerFirst ? f[m1] : f[m0];
        const long wa = lowerFirst ? w[m0] : w[m1];
        if (edgePoints.emplace(std::array<long, 3>{a, b, wa}, 0).second) {
          // recompute from the ordered pair, so both faces would give the same coordinates
          const Vec3 y = (static_cast<double>(wa) * v[a] + static_cast<double>(T - wa) * v[b]) /
              static_cast<double>(T);
          points.push_back(y.normalized());
        }
      }
  }
  points.insert(points.end(), interior.begin(), interior.end());
  if (static_cast<long>(points.size()) != c.points())
    throw std::runtime_error("geodesicSphere: " + std::to_string(points.size()) +
                             " points for (h, k) = (" + std::to_string(c.h) + ", " +
                             std::to_string(c.k) + "), expected " + std::to_string(c.points()));
  return points;
}

Surface icosahedralSurface(const GeodesicClass &c)
{
  return sphereSurface(geodesicSphere(c));
}

SurfaceStats surfaceStats(const Surface &surface)
{
  SurfaceStats st;
  st.minEdge = INFINITY;
  for (const Edge &e : surface.edges) {
    const double len = (surface.points[e[0]] - surface.points[e[1]]).norm();
    st.minEdge = std::min(st.minEdge, len);
    st.maxEdge = std::max(st.maxEdge, len);
    st.meanEdge += len / surface.edges.size();
  }
  for (const Tri &t : surface.triangles) {
    const Vec3 &a = surface.points[t[0]], &b = surface.points[t[1]], &c = surface.points[t[2]];
    st.area += 0.5 * (b - a).cross(c - a).norm();
    // divergence theorem: each triangle adds the signed volume of its tetrahedron with the origin
    st.volume += a.dot(b.cross(c)) / 6.0;
  }
  std::vector<int> degree(surface.points.size(), 0);
  for (const Edge &e : surface.edges) {
    ++degree[e[0]];
    ++degree[e[1]];
  }
  for (int z : degree) {
    if (static_cast<size_t>(z) >= st.valence.size()) st.valence.resize(z + 1, 0);
    ++st.valence[z];
  }
  return st;
}

FluidSpacing chooseSpacing(double radius, long target, std::optional<double> gap)
{
  // a lattice ball of target points has radius about (3 target / 4 pi)^(1/3) spacings
  const double rhoGuess = std::cbrt(3.0 * static_cast<double>(target) / (4.0 * kPi));
  const std::vector<long> counts = latticeBallCounts(static_cast<int>(std::ceil(2 * rhoGuess)) + 2);
  long best = 0;
  for (long s = 1; s < static_cast<long>(counts.size()); ++s)
    if (std::labs(counts[s] - target) < std::labs(counts[best] - target)) best = s;
  // squared radius halfway between the integers best and best + 1, so rounding cannot matter
  const double rho = std::sqrt(best + 0.5);
  if (gap) return {(radius - *gap) / rho, *gap};
  // R - DX/2 = rho DX
  const double dx = radius / (rho + 0.5);
  return {dx, 0.5 * dx};
}

std::vector<Vec3> fluidLattice(double radius, double dx)
{
  std::vector<Vec3> points;
  if (radius < 0.0) return points;
  const int k = static_cast<int>(radius / dx) + 1;
  const double limit = (radius / dx) * (radius / dx);
  for (int i = -k; i <= k; ++i)
    for (int j = -k; j <= k; ++j)
      for (int l = -k; l <= k; ++l)
        if (static_cast<double>(i * i + j * j + l * l) <= limit)
          points.emplace_back(dx * i, dx * j, dx * l);
  return points;
}

double shellSpacing(long count, double outer)
{
  // the spacing s that fills the ball of radius outer + s/2 with count points, count s^3 =
  // 4/3 pi (outer + s/2)^3, then outer / s rounded to a multiple of 1/2 so that the slabs end at 0
  const double c = std::cbrt(4.0 * kPi / (3.0 * static_cast<double>(count)));
  return 2.0 * outer / std::max(1.0, std::round(2.0 * (1.0 - 0.5 * c) / c));
}

FluidShells fluidShells(long count, double outer, std::mt19937_64 &rng)
{
  FluidShells f;
  if (outer <= 0.0 || count <= 0) return f;
  f.spacing = shellSpacing(count, outer);
  const double s = f.spacing;
  const double halves = std::round(2.0 * outer / s);
  const bool centre = static_cast<long>(halves) % 2 == 0;    // outer / s an integer
  f.shells = static_cast<int>(std::ceil(0.5 * halves));
  std::vector<double> radius(f.shells), share(f.shells);
  double total = 0.0;
  for (int k = 0; k < f.shells; ++k) {
    radius[k] = outer - k * s;
    // the slab [r - s/2, r + s/2] (volume / (4/3 pi)); r - s/2 = 0 for the innermost shell
    const double lo = std::max(radius[k] - 0.5 * s, 0.0), hi = radius[k] + 0.5 * s;
    share[k] = hi * hi * hi - lo * lo * lo;
    total += share[k];
  }
  // the centre point holds the rest, [0, s/2]; largest remainders give each shell its count
  const long onShells = count - (centre ? 1 : 0);
  std::vector<long> n(f.shells);
  std::vector<std::pair<double, int>> remainder(f.shells);
  long placed = 0;
  for (int k = 0; k < f.shells; ++k) {
    const double exact = onShells * share[k] / total;
    n[k] = static_cast<long>(std::floor(exact));
    placed += n[k];
    remainder[k] = {exact - n[k], -k};
  }
  std::sort(remainder.begin(), remainder.end(), std::greater<>());
  for (long i = 0; i < onShells - placed; ++i) ++n[-remainder[i].second];
  if (centre) f.points.emplace_back(Vec3::Zero());
  const auto unit = [&rng] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  for (int k = 0; k < f.shells; ++k) {
    if (n[k] == 0) continue;
    std::vector<Vec3> shell = fibonacciSphere(static_cast<int>(n[k]));
    relaxOnSphere(shell, 40);
    // uniform random rotation: the unit quaternion of Shoemake (1992) from three uniforms
    const double u1 = unit(), u2 = 2.0 * kPi * unit(), u3 = 2.0 * kPi * unit();
    const Eigen::Quaterniond q(std::sqrt(u1) * std::cos(u3), std::sqrt(1.0 - u1) * std::sin(u2),
                               std::sqrt(1.0 - u1) * std::cos(u2), std::sqrt(u1) * std::sin(u3));
    const Eigen::Matrix3d turn = q.toRotationMatrix();
    for (const Vec3 &x : shell) f.points.emplace_back(radius[k] * (turn * x));
  }
  return f;
}

Surface ellipsoidSurface(const Surface &unitSphere, const Vec3 &axes)
{
  Surface s = unitSphere;
  for (Vec3 &x : s.points) x = x.cwiseProduct(axes);
  return s;
}

Surface conformalSpheroidSurface(const Surface &unitSphere, const Vec3 &axes)
{
  // the axis of revolution k: the semi-axis that differs from the two equal others
  int k = -1;
  for (int d = 0; d < 3; ++d) {
    const double u = axes[(d + 1) % 3], v = axes[(d + 2) % 3];
    if (std::abs(u - v) <= 1e-12 * std::max(u, v)) k = d;
  }
  if (k < 0) throw std::runtime_error("the conformal map needs a spheroid (two equal semi-axes)");
  const double a = axes[k], b = axes[(k + 1) % 3];
  // G on a grid of phi in [0, pi] (trapezoidal rule, smooth integrand: 0 at both ends), 0 at pi/2
  const int n = 8192;
  const double h = kPi / n;
  const auto g = [a, b](double t) {
    const double s = std::sin(t), c = std::cos(t);
    return s > 0.0 ? (std::sqrt(a * a * s * s + b * b * c * c) - b) / (b * s) : 0.0;
  };
  std::vector<double> G(n + 1, 0.0);
  for (int i = 1; i <= n; ++i) G[i] = G[i - 1] + 0.5 * h * (g((i - 1) * h) + g(i * h));
  const double mid = G[n / 2];
  for (double &v : G) v -= mid;
  const auto Gat = [&](double phi) {
    const int i = std::min(static_cast<int>(phi / h), n - 1);
    const double f = phi / h - i;
    return (1.0 - f) * G[i] + f * G[i + 1];
  };

  std::vector<Vec3> points;
  points.reserve(unitSphere.points.size());
  const Vec3 e = Vec3::Unit(k);
  for (const Vec3 &x : unitSphere.points) {
    const Vec3 side = x - x[k] * e;
    const double rho = side.norm(), theta = std::atan2(rho, x[k]);
    double phi = theta;
    if (rho > 0.0) {
      // ln tan(phi/2) + G(phi) increases with phi: bisection to the sphere's isothermal latitude
      const double target = std::log(std::tan(0.5 * theta));
      double lo = 0.0, hi = kPi;
      for (int it = 0; it < 100; ++it) {
        const double m = 0.5 * (lo + hi);
        (std::log(std::tan(0.5 * m)) + Gat(m) < target ? lo : hi) = m;
      }
      phi = 0.5 * (lo + hi);
    }
    points.push_back(a * std::cos(phi) * e + (rho > 0.0 ? b * std::sin(phi) / rho : 0.0) * side);
  }
  // the sphere's triangles on the mapped points: the same topology (not always the points' hull)
  Surface out = unitSphere;
  out.points = std::move(points);
  for (const Tri &t : out.triangles) {
    const Vec3 &p = out.points[t[0]];
    if ((out.points[t[1]] - p).cross(out.points[t[2]] - p).dot(p) <= 0.0)
      throw std::runtime_error("conformalSpheroidSurface: a triangle turned inward");
  }
  return out;
}

std::vector<Vec3> fluidEllipsoid(const Vec3 &axes, double gap, double dx)
{
  // x inside the ellipsoid E scaled by f = 1 - gap / c_min about its centre is at least gap from
  // the surface of E: the ball of radius (1 - f) c_min around x lies in f E + (1 - f) E = E
  const double f = 1.0 - gap / axes.minCoeff();
  std::vector<Vec3> points;
  if (f <= 0.0) return points;
  const Vec3 inner = f * axes;
  const int k = static_cast<int>(inner.maxCoeff() / dx) + 1;
  for (int i = -k; i <= k; ++i)
    for (int j = -k; j <= k; ++j)
      for (int l = -k; l <= k; ++l) {
        const Vec3 x(dx * i, dx * j, dx * l);
        if (x.cwiseQuotient(inner).squaredNorm() <= 1.0) points.push_back(x);
      }
  return points;
}

double ellipsoidArea(const Vec3 &axes)
{
  // a >= b >= c: S = 2 pi c^2 + 2 pi a b / sin(phi) (E(phi, k) sin^2(phi) + F(phi, k) cos^2(phi)),
  // cos(phi) = c / a, k^2 = a^2 (b^2 - c^2) / (b^2 (a^2 - c^2))
  Vec3 s = axes;
  std::sort(s.data(), s.data() + 3, std::greater<double>());
  const double a = s[0], b = s[1], c = s[2];
  if (a - c <= 1e-14 * a) return 4.0 * kPi * a * a;
  const double phi = std::acos(c / a);
  const double k = std::sqrt(a * a * (b * b - c * c) / (b * b * (a * a - c * c)));
  const double sn = std::sin(phi), cs = std::cos(phi);
  return 2.0 * kPi * c * c +
      2.0 * kPi * a * b / sn * (std::ellint_2(k, phi) * sn * sn + std::ellint_1(k, phi) * cs * cs);
}

std::vector<CellSpec> cellLattice(const std::array<int, 3> &counts, double spacing, double radius,
                                  double spread, std::uint64_t seed)
{
  std::mt19937_64 rng(seed);
  std::vector<CellSpec> cells;
  for (int k = 0; k < counts[2]; ++k)
    for (int j = 0; j < counts[1]; ++j)
      for (int i = 0; i < counts[0]; ++i) {
        const Vec3 centre = spacing *
            Vec3(i - 0.5 * (counts[0] - 1), j - 0.5 * (counts[1] - 1), k - 0.5 * (counts[2] - 1));
        cells.push_back({centre, radius * (1.0 + spread * uniformSigned(rng))});
      }
  return cells;
}

void checkNoOverlap(const std::vector<CellSpec> &cells, double extent)
{
  for (size_t i = 0; i < cells.size(); ++i)
    for (size_t j = i + 1; j < cells.size(); ++j)
      if ((cells[i].centre - cells[j].centre).norm() <=
          extent * (cells[i].radius + cells[j].radius))
        throw std::runtime_error("cells " + std::to_string(i + 1) + " and " +
                                 std::to_string(j + 1) + " overlap; increase --spacing");
}

System buildSystem(const Surface &unit, const std::vector<CellSpec> &cells,
                   const BuildParams &params)
{
  System sys;
  sys.lo = Vec3::Constant(INFINITY);
  sys.hi = Vec3::Constant(-INFINITY);
  // the shells' rotations: a stream of its own, apart from the radius spread's (cellLattice)
  std::mt19937_64 rng(params.seed ^ 0x9e3779b97f4a7c15ULL);
  for (size_t k = 0; k < cells.size(); ++k) {
    appendCell(sys, unit, cells[k], static_cast<int>(k + 1), params, rng);
    sys.lo = sys.lo.cwiseMin(cells[k].centre - cells[k].radius * params.shape);
    sys.hi = sys.hi.cwiseMax(cells[k].centre + cells[k].radius * params.shape);
  }
  sys.lo -= Vec3::Constant(params.boxMargin);
  sys.hi += Vec3::Constant(params.boxMargin);
  return sys;
}

std::vector<double> bondAreaShares(const System &sys)
{
  std::vector<double> area(sys.particles.size(), 0.0), share(sys.particles.size(), 0.0);
  std::vector<int> degree(sys.particles.size(), 0);
  for (const Tri &t : sys.triangles) {
    const Vec3 &a = sys.particles[t[0]].x, &b = sys.particles[t[1]].x, &c = sys.particles[t[2]].x;
    const double third = (b - a).cross(c - a).norm() / 6.0;    // one third of the triangle area
    for (int v : t) area[v] += third;
  }
  for (const Edge &e : sys.bonds) {
    ++degree[e[0]];
    ++degree[e[1]];
  }
  for (size_t i = 0; i < share.size(); ++i)
    if (degree[i] > 0) share[i] = area[i] / degree[i];
  return share;
}

std::vector<Quad> wallDihedrals(const System &sys)
{
  // third vertex of the triangle holding each directed edge (i, j)
  std::map<std::pair<int, int>, int> apex;
  for (const Tri &t : sys.triangles)
    for (int k = 0; k < 3; ++k)
      if (!apex.emplace(std::make_pair(t[k], t[(k + 1) % 3]), t[(k + 2) % 3]).second)
        throw std::runtime_error("wall edge in two triangles in the same direction");
  std::vector<Quad> quads;
  quads.reserve(sys.bonds.size());
  for (const Edge &e : sys.bonds) {
    const auto forward = apex.find({e[0], e[1]}), backward = apex.find({e[1], e[0]});
    if (forward == apex.end() || backward == apex.end())
      throw std::runtime_error("wall edge " + std::to_string(e[0] + 1) + "-" +
                               std::to_string(e[1] + 1) + " is not shared by two triangles");
    // (a, b, c) holds b -> c, (d, c, b) holds c -> b
    quads.push_back({forward->second, e[0], e[1], backward->second});
  }
  return quads;
}

}    // namespace cellgen
