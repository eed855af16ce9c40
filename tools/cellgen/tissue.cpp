// cellgen tissue: Voronoi cells (Voro++) shrunk and rounded to a set porosity, each with its wall
// mesh and fluid, the junction bonds between facing walls, and the tissue's statistics. See
// README.md "Tissue mode" and doc/model.md §10.6.
#include "tissue.h"

#include "cli.h"
#include "datafile.h"
#include "geometry.h"
#include "tissue_geometry.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace cellgen {

namespace {

  constexpr const char *kVersion = "cellgen 1.0 tissue";
  constexpr double kPi = 3.14159265358979323846;
  constexpr int kSmoothing = 30;           // spring relaxation passes of each wall mesh
  constexpr int kLloydSteps = 1000;        // at most this many Lloyd steps towards the CV
  constexpr int kCorrections = 4;          // remeshings to bring the mesh to the porosity
  constexpr double kMaxRounding = 0.95;    // rounding radius at most this share of the inradius

  constexpr const char *kUsage =
      "usage: cellgen tissue (--cells NX NY NZ | --count N) [--size D=160e-6] [--cv 0.2]\n"
      "               [--porosity 0.2] [--periodic xyz | --slab x|y|z] [--junction-gap G]\n"
      "               [--dx DX=D/16] [--gap G=DX/2] [--wall-dx L=DX] [--rho0 1000]\n"
      "               [--wall-mass MW] [--seed 1] [--margin F=0.5] [--dihedrals] --out FILE.data\n"
      "--gap G: the fluid at least G inside the wall, G >= DX/4 (and the cells deep enough).\n"
      "--wall-dx L: D/1000 <= L <= D/2. --wall-mass MW: 0 < MW <= rho0 pi D^3/6 (the water\n"
      "            filling a cell of diameter D); --rho0: at most 1e5.\n"
      "--dihedrals: also write one dihedral per wall edge (atom_style molecular), for\n"
      "            dihedral_style cell/bending.\n"
      "Writes FILE.data, FILE.junctions and FILE.stats. SI units. See tools/cellgen/README.md.\n";

  struct Options {
    std::optional<std::array<long, 3>> cells;
    std::optional<long> count;
    double size = 160e-6;
    double cv = 0.2;
    double porosity = 0.2;
    std::array<bool, 3> periodic{true, true, true};
    std::optional<double> junctionGap, dx, gap, wallDx, wallMass;
    double rho0 = 1000;
    double margin = 0.5;
    std::uint64_t seed = 1;
    bool dihedrals = false;
    std::string out;
  };

  // Reads option values, naming the option and the word in every error.
  class Args {
   public:
    Args(int argc, char **argv) : words_(argv + 1, argv + argc) {}
    bool done() const { return pos_ >= words_.size(); }
    std::string option() { return option_ = words_[pos_++]; }
    std::string word()
    {
      if (done()) throw UsageError(option_ + " needs a value");
      return words_[pos_++];
    }
    double real()
    {
      return number<double>("a finite number", [](const std::string &s, size_t *used) {
        const double v = std::stod(s, used);
        if (!std::isfinite(v)) *used = 0;
        return v;
      });
    }
    long integer()
    {
      return number<long>("an integer",
                          [](const std::string &s, size_t *used) { return std::stol(s, used); });
    }

   private:
    // the next word as a T, all of it read by parse(word, &characters used)
    template <class T, class F> T number(const char *what, F parse)
    {
      const std::string s = word();
      size_t used = 0;
      T v{};
      try {
        v = parse(s, &used);
      } catch (const std::logic_error &) {
        used = 0;
      }
      if (used == 0 || used != s.size())
        throw UsageError(option_ + ": not " + what + ": '" + s + "'");
      return v;
    }

    std::vector<std::string> words_;
    size_t pos_ = 0;
    std::string option_;
  };

  std::array<bool, 3> periodicAxes(const std::string &axes, const std::string &option)
  {
    std::array<bool, 3> p{false, false, false};
    if (axes == "none") return p;
    for (char c : axes) {
      if (c < 'x' || c > 'z' || p[c - 'x'])
        throw UsageError(option + " must be a set of x, y, z (or none), not '" + axes + "'");
      p[c - 'x'] = true;
    }
    return p;
  }

  using Handler = std::function<void(Args &, Options &)>;

  const std::map<std::string, Handler> &handlers()
  {
    static const std::map<std::string, Handler> h = {
        {"--cells",
         [](Args &a, Options &o) {
           std::array<long, 3> c{};
           for (long &n : c) n = a.integer();
           o.cells = c;
         }},
        {"--count", [](Args &a, Options &o) { o.count = a.integer(); }},
        {"--size", [](Args &a, Options &o) { o.size = a.real(); }},
        {"--cv", [](Args &a, Options &o) { o.cv = a.real(); }},
        {"--porosity", [](Args &a, Options &o) { o.porosity = a.real(); }},
        {"--periodic",
         [](Args &a, Options &o) { o.periodic = periodicAxes(a.word(), "--periodic"); }},
        {"--slab",
         [](Args &a, Options &o) {
           const std::string axis = a.word();
           if (axis != "x" && axis != "y" && axis != "z")
             throw UsageError("--slab must be x, y or z, not '" + axis + "'");
           o.periodic = {true, true, true};
           o.periodic[axis[0] - 'x'] = false;
         }},
        {"--junction-gap", [](Args &a, Options &o) { o.junctionGap = a.real(); }},
        {"--dx", [](Args &a, Options &o) { o.dx = a.real(); }},
        {"--gap", [](Args &a, Options &o) { o.gap = a.real(); }},
        {"--wall-dx", [](Args &a, Options &o) { o.wallDx = a.real(); }},
        {"--rho0", [](Args &a, Options &o) { o.rho0 = a.real(); }},
        {"--wall-mass", [](Args &a, Options &o) { o.wallMass = a.real(); }},
        {"--seed", [](Args &a, Options &o) { o.seed = static_cast<std::uint64_t>(a.integer()); }},
        {"--margin", [](Args &a, Options &o) { o.margin = a.real(); }},
        {"--out", [](Args &a, Options &o) { o.out = a.word(); }},
        {"--dihedrals", [](Args &, Options &o) { o.dihedrals = true; }},
    };
    return h;
  }

  void validate(const Options &o)
  {
    require(o.cells.has_value() != o.count.has_value(),
            "give one of --cells NX NY NZ or --count N");
    if (o.cells)
      for (long c : *o.cells)
        require(c >= 1 && c <= 100, "--cells: each count must be in [1, 100], not " + show(c));
    if (o.count) require(*o.count >= 1 && *o.count <= 100000, "--count must be in [1, 1e5]");
    require(o.size > 0, "--size must be positive, not " + show(o.size));
    require(o.cv >= 0 && o.cv < 1, "--cv must be in [0, 1), not " + show(o.cv));
    require(o.porosity >= 0 && o.porosity < 0.5,
            "--porosity must be in [0, 0.5), not " + show(o.porosity));
    require(!o.dx || *o.dx > 0, "--dx must be positive, not " + show(o.dx.value_or(0)));
    // the fluid at least a quarter of its spacing inside the wall (README.md, Tissue mode); at
    // most the cells' depth less one DX, checked with the cells (checkResolution)
    const double dx = o.dx.value_or(o.size / 16.0);
    require(!o.gap || *o.gap >= 0.25 * dx,
            "--gap must be >= DX/4 = " + show(0.25 * dx) + " m (DX = " + show(dx) +
                " m, the fluid spacing), not " + show(o.gap.value_or(0)));
    // a wall mesh of about 3.6e6 particles per cell (L = D/1000) to the 12 of the coarsest
    // (L = D/2, beyond which the mesh no longer follows --wall-dx)
    require(!o.wallDx || (*o.wallDx >= o.size / 1000 && *o.wallDx <= o.size / 2),
            "--wall-dx must be in [D/1000, D/2] = [" + show(o.size / 1000) + ", " +
                show(o.size / 2) + "] m (D = --size " + show(o.size) + " m), not " +
                show(o.wallDx.value_or(0)));
    require(!o.junctionGap || *o.junctionGap >= 0,
            "--junction-gap must be >= 0, not " + show(o.junctionGap.value_or(0)));
    require(o.rho0 > 0 && o.rho0 <= kRho0Max,
            "--rho0 must be in (0, " + show(kRho0Max) + "] kg/m^3, not " + show(o.rho0));
    // a wall particle at most as heavy as the water filling a cell of diameter D
    const double cellMass = o.rho0 * kPi / 6.0 * o.size * o.size * o.size;
    require(!o.wallMass || (*o.wallMass > 0 && *o.wallMass <= cellMass),
            "--wall-mass must be in (0, rho0 pi D^3/6] = (0, " + show(cellMass) +
                "] kg (the water filling a cell of diameter --size), not " +
                show(o.wallMass.value_or(0)));
    require(o.margin > 0 && o.margin <= 1000, "--margin must be in (0, 1000]");
    require(!o.out.empty(), "--out FILE is required");
  }

  Options parse(int argc, char **argv)
  {
    Options o;
    Args args(argc, argv);
    while (!args.done()) {
      const std::string opt = args.option();
      const auto h = handlers().find(opt);
      if (h == handlers().end()) throw UsageError("unknown option '" + opt + "'");
      h->second(args, o);
    }
    validate(o);
    return o;
  }

  // ---- the resolved set-up -------------------------------------------------------------------

  struct Setup {
    Box box;
    int n = 0;
    double dx = 0, gap = 0, wallDx = 0, junctionGap = 0;
  };

  Setup setup(const Options &o)
  {
    Setup s;
    // a cell's volume is that of the sphere of diameter --size
    const double cellVolume = kPi / 6.0 * o.size * o.size * o.size;
    Vec3 len;
    if (o.cells) {
      s.n = static_cast<int>((*o.cells)[0] * (*o.cells)[1] * (*o.cells)[2]);
      for (int d = 0; d < 3; ++d) len[d] = (*o.cells)[d] * std::cbrt(cellVolume);
    } else {
      s.n = static_cast<int>(*o.count);
      len = Vec3::Constant(std::cbrt(s.n * cellVolume));
    }
    s.box.lo = Vec3::Zero();
    s.box.hi = len;
    s.box.periodic = o.periodic;
    s.dx = o.dx.value_or(o.size / 16.0);
    s.gap = o.gap.value_or(0.5 * s.dx);
    s.wallDx = o.wallDx.value_or(s.dx);
    s.junctionGap = o.junctionGap.value_or(s.wallDx);
    return s;
  }

  // ---- shrinking and rounding to the porosity ----------------------------------------------

  // Rounding of cell i at parameter alpha: rho_i = eps + alpha (inradius_i - eps).
  double rounding(const InBall &b, double eps, double alpha)
  {
    return eps + alpha * (b.radius - eps);
  }

  std::vector<RoundedCell> roundCells(const std::vector<VoronoiCell> &cells,
                                      const std::vector<InBall> &balls, double eps, double alpha)
  {
    std::vector<RoundedCell> out;
    for (size_t i = 0; i < cells.size(); ++i)
      out.emplace_back(cells[i], balls[i], rounding(balls[i], eps, alpha), eps);
    return out;
  }

  // Porosity of the exact bodies: 1 - sum of the outer volumes (P opened by rho_i) / box volume.
  double exactPorosity(const std::vector<VoronoiCell> &cells, const std::vector<InBall> &balls,
                       double eps, double alpha, double boxVolume)
  {
    double v = 0;
    for (const RoundedCell &c : roundCells(cells, balls, eps, alpha))
      v += c.parallelVolume(c.rounding() + eps);
    return 1.0 - v / boxVolume;
  }

  // The alpha in [0, kMaxRounding] whose exact porosity is `target` (bisection; 0 below).
  double solveRounding(const std::vector<VoronoiCell> &cells, const std::vector<InBall> &balls,
                       double eps, double target, double boxVolume, double requested)
  {
    if (exactPorosity(cells, balls, eps, 0, boxVolume) >= target) return 0;
    const double top = exactPorosity(cells, balls, eps, kMaxRounding, boxVolume);
    if (top < target)
      throw UsageError("--porosity " + show(requested) + " is not reachable: rounding the cells " +
                       "of this tessellation gives at most " + show(top));
    double lo = 0, hi = kMaxRounding;
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      (exactPorosity(cells, balls, eps, mid, boxVolume) < target ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }

  // ---- walls and fluid -----------------------------------------------------------------------

  struct CellMesh {
    std::vector<Vec3> wall;
    const Surface *unit = nullptr;
    MeshMeasure measure;
  };

  class UnitMeshes {
   public:
    const Surface &get(const GeodesicClass &c)
    {
      auto it = cache_.find({c.h, c.k});
      if (it == cache_.end())
        it = cache_.emplace(std::make_pair(c.h, c.k), icosahedralSurface(c)).first;
      return it->second;
    }

   private:
    std::map<std::pair<int, int>, Surface> cache_;
  };

  std::vector<CellMesh> meshCells(const std::vector<RoundedCell> &cells, double wallDx, double eps,
                                  UnitMeshes &units)
  {
    std::vector<CellMesh> out;
    for (const RoundedCell &c : cells) {
      // a hexagonal mesh of spacing l covers area S with 2 S / (sqrt(3) l^2) points
      const double area = c.parallelArea(c.rounding());
      const long target = std::lround(2.0 * area / (std::sqrt(3.0) * wallDx * wallDx));
      CellMesh m;
      m.unit = &units.get(chooseGeodesic(std::max(12L, target)));
      m.wall = wallOnCell(*m.unit, c, kSmoothing);
      m.measure = meshMeasure(m.wall, m.unit->triangles, m.unit->edges, eps);
      out.push_back(std::move(m));
    }
    return out;
  }

  double meshPorosity(const std::vector<CellMesh> &meshes, double boxVolume, bool outer)
  {
    double v = 0;
    for (const CellMesh &m : meshes) v += outer ? m.measure.parallel : m.measure.volume;
    return 1.0 - v / boxVolume;
  }

  // ---- junctions -------------------------------------------------------------------------------

  struct Junction {
    int i, j;    // 0-based cells
    std::array<int, 3> image;
    double area;
    int bonds = 0;
  };

  // Wall particles of a cell on the flat facet of face f (on the plane eps inside the face).
  std::vector<int> facetParticles(const CellMesh &m, const VoronoiFace &f, double eps, double tol)
  {
    std::vector<int> out;
    for (size_t k = 0; k < m.wall.size(); ++k)
      if (std::abs(f.normal.dot(m.wall[k] - f.polygon[0]) + eps) < tol)
        out.push_back(static_cast<int>(k));
    return out;
  }

  int matchingFace(const VoronoiCell &cj, int i, const std::array<int, 3> &image)
  {
    for (size_t g = 0; g < cj.faces.size(); ++g)
      if (cj.faces[g].neighbour == i && cj.faces[g].image[0] == -image[0] &&
          cj.faces[g].image[1] == -image[1] && cj.faces[g].image[2] == -image[2])
        return static_cast<int>(g);
    throw std::runtime_error("Voronoi face without its twin in the neighbouring cell");
  }

  struct JunctionSet {
    std::vector<Junction> faces;              // one entry per face, from both sides
    std::vector<std::array<int, 2>> bonds;    // global wall particle indices
  };

  Vec3 shiftOf(const std::array<int, 3> &image, const Vec3 &len)
  {
    return Vec3(image[0] * len[0], image[1] * len[1], image[2] * len[2]);
  }

  int nearest(const Vec3 &x, const std::vector<Vec3> &set)
  {
    int best = -1;
    double d = INFINITY;
    for (size_t k = 0; k < set.size(); ++k)
      if ((set[k] - x).squaredNorm() < d) {
        d = (set[k] - x).squaredNorm();
        best = static_cast<int>(k);
      }
    return best;
  }

  // Junction pairs (index in wall a, index in wall b) across one face: each particle of a's facet
  // with its nearest particle of wall b, when that one's nearest on wall a is it again (mutual
  // nearest neighbours) and they are at most `cutoff` apart.
  std::vector<std::array<int, 2>> pairFacets(const std::vector<int> &facet,
                                             const std::vector<Vec3> &a, const std::vector<Vec3> &b,
                                             double cutoff)
  {
    std::vector<std::array<int, 2>> out;
    for (int p : facet) {
      const int q = nearest(a[p], b);
      if (nearest(b[q], a) == p && (a[p] - b[q]).norm() <= cutoff) out.push_back({p, q});
    }
    return out;
  }

  // The face between cells i != j (image of j) and its twin share one key, (lower cell, higher
  // cell, image seen from the lower); `second` says whether this side is the one that owns it.
  std::pair<std::array<int, 5>, bool> faceKey(const Junction &jn)
  {
    const bool own = jn.i < jn.j;
    const int sign = own ? 1 : -1;
    return {{std::min(jn.i, jn.j), std::max(jn.i, jn.j), sign * jn.image[0], sign * jn.image[1],
             sign * jn.image[2]},
            own};
  }

  JunctionSet junctions(const std::vector<VoronoiCell> &cells, const std::vector<RoundedCell> &rc,
                        const std::vector<CellMesh> &meshes, const std::vector<int> &wallOffset,
                        const Setup &s)
  {
    const double eps = 0.5 * s.junctionGap, tol = 1e-9 * s.box.length().maxCoeff();
    const Vec3 len = s.box.length();
    JunctionSet out;
    std::map<std::array<int, 5>, int> bondsOf;
    std::map<std::array<int, 5>, double> areaOf;
    for (size_t i = 0; i < cells.size(); ++i)
      for (size_t f = 0; f < cells[i].faces.size(); ++f) {
        const VoronoiFace &face = cells[i].faces[f];
        // a junction joins two cells: none on free faces or on a face with the cell's own image
        if (face.neighbour < 0 || face.neighbour == static_cast<int>(i)) continue;
        const int j = face.neighbour;
        const int g = matchingFace(cells[j], static_cast<int>(i), face.image);
        const Vec3 shift = shiftOf(face.image, len);
        Junction jn{static_cast<int>(i), j, face.image, 0.0};
        out.faces.push_back(jn);
        // each pair of faces is measured and bonded once, from the side that owns its key
        const auto [k, first] = faceKey(jn);
        if (!first) continue;
        std::vector<Vec3> other = rc[j].facet(g);
        for (Vec3 &x : other) x += shift;
        areaOf[k] = overlapArea(rc[i].facet(static_cast<int>(f)), other, face.normal);
        if (areaOf[k] > 0) {
          std::vector<Vec3> wallJ = meshes[j].wall;
          for (Vec3 &x : wallJ) x += shift;
          const auto pairs = pairFacets(facetParticles(meshes[i], face, eps, tol), meshes[i].wall,
                                        wallJ, s.junctionGap + s.wallDx);
          for (const auto &pq : pairs)
            out.bonds.push_back({wallOffset[i] + pq[0], wallOffset[j] + pq[1]});
          bondsOf[k] = static_cast<int>(pairs.size());
        }
      }
    // both sides of a face get the owner's area and bond count; faces without contact are dropped
    std::vector<Junction> kept;
    for (Junction &jn : out.faces) {
      const auto k = faceKey(jn).first;
      jn.area = areaOf.at(k);
      const auto it = bondsOf.find(k);
      jn.bonds = it == bondsOf.end() ? 0 : it->second;
      if (jn.area > 0) kept.push_back(jn);
    }
    out.faces.swap(kept);
    return out;
  }

  // ---- the system ------------------------------------------------------------------------------

  struct Tissue {
    System sys;
    std::vector<int> wallOffset;    // index of each cell's first wall particle
    std::vector<long> fluidCount;
    JunctionSet junctions;
  };

  void appendCell(Tissue &t, int molecule, const std::vector<Vec3> &fluid, const CellMesh &m,
                  const Options &o)
  {
    // fluid fills the volume enclosed by the wall mesh at the reference density (as one cell)
    const double fluidMass = o.rho0 * m.measure.volume / fluid.size();
    // a 1 um wall shell at the reference density shared equally (as one cell)
    const double wallMass = o.wallMass.value_or(o.rho0 * m.measure.area * 1e-6 / m.wall.size());
    for (const Vec3 &x : fluid) t.sys.particles.push_back({molecule, kFluid, x, fluidMass});
    const int offset = static_cast<int>(t.sys.particles.size());
    t.wallOffset.push_back(offset);
    for (const Vec3 &x : m.wall) t.sys.particles.push_back({molecule, kWall, x, wallMass});
    for (const Edge &e : m.unit->edges) t.sys.bonds.push_back({offset + e[0], offset + e[1]});
    for (const Tri &tr : m.unit->triangles)
      t.sys.triangles.push_back({offset + tr[0], offset + tr[1], offset + tr[2]});
    t.fluidCount.push_back(static_cast<long>(fluid.size()));
  }

  // The data file's box: the tissue's, reaching `margin` beyond it along the free axes.
  void setBox(System &sys, const Box &box, double margin)
  {
    for (int d = 0; d < 3; ++d) {
      const double m = box.periodic[d] ? 0.0 : margin;
      sys.lo[d] = box.lo[d] - m;
      sys.hi[d] = box.hi[d] + m;
    }
  }

  void checkResolution(const std::vector<InBall> &balls, const Setup &s, const Options &o)
  {
    const auto small = std::min_element(balls.begin(), balls.end(),
                                        [](auto &a, auto &b) { return a.radius < b.radius; });
    // the wall's inscribed ball (radius r_in - eps) must hold a fluid ball two spacings across
    const double inner = small->radius - 0.5 * s.junctionGap;
    if (inner < 2.0 * s.dx || inner - s.gap < s.dx)
      throw UsageError("cells too small for the resolution: the smallest cell (cell " +
                       std::to_string(small - balls.begin() + 1) + ", inscribed radius " +
                       show(small->radius) + " m) leaves " + show(inner) + " m inside its wall; " +
                       "--size " + show(o.size) + " needs --dx <= " + show(0.5 * inner) +
                       " (--dx is " + show(s.dx) + ", --junction-gap " + show(s.junctionGap) + ")");
  }

  // ---- statistics ------------------------------------------------------------------------------

  struct Summary {
    double mean = 0, min = INFINITY, max = -INFINITY, cv = 0;
  };

  Summary summarise(const std::vector<double> &v)
  {
    Summary s;
    if (v.empty()) return s;
    for (double x : v) {
      s.mean += x / v.size();
      s.min = std::min(s.min, x);
      s.max = std::max(s.max, x);
    }
    double var = 0;
    for (double x : v) var += (x - s.mean) * (x - s.mean) / v.size();
    s.cv = std::sqrt(var) / s.mean;
    return s;
  }

  // Descriptors of a cell section (ImageJ conventions: the fitted ellipse has the section's area
  // and the axis ratio of its second moments).
  struct Section {
    double area, feret, major, minor;
  };

  Section describe(const std::vector<Eigen::Vector2d> &p)
  {
    double a = 0, cx = 0, cy = 0, sxx = 0, syy = 0, sxy = 0;
    for (size_t k = 0; k < p.size(); ++k) {
      const Eigen::Vector2d &u = p[k], &v = p[(k + 1) % p.size()];
      const double w = u[0] * v[1] - v[0] * u[1];
      // polygon area, first and second moments (Green's theorem)
      a += 0.5 * w;
      cx += (u[0] + v[0]) * w / 6.0;
      cy += (u[1] + v[1]) * w / 6.0;
      sxx += (u[0] * u[0] + u[0] * v[0] + v[0] * v[0]) * w / 12.0;
      syy += (u[1] * u[1] + u[1] * v[1] + v[1] * v[1]) * w / 12.0;
      sxy += (u[0] * v[1] + 2 * u[0] * u[1] + 2 * v[0] * v[1] + v[0] * u[1]) * w / 24.0;
    }
    cx /= a;
    cy /= a;
    Eigen::Matrix2d m;
    m << sxx / a - cx * cx, sxy / a - cx * cy, sxy / a - cx * cy, syy / a - cy * cy;
    const Eigen::Vector2d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(m).eigenvalues();
    double feret = 0;
    for (const auto &u : p)
      for (const auto &v : p) feret = std::max(feret, (u - v).norm());
    // ellipse of the same area whose axis ratio is that of the second moments
    const double ratio = std::sqrt(ev[1] / ev[0]);
    const double major = std::sqrt(4.0 * std::abs(a) / kPi * ratio);
    return {std::abs(a), feret, major, major / ratio};
  }

  // The closed loop where the plane z = z0 cuts a wall mesh (empty if it does not).
  std::vector<Eigen::Vector2d> cut(const std::vector<Vec3> &x, const std::vector<Tri> &tri,
                                   int axis, double z0)
  {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    std::map<Edge, std::vector<Edge>> links;
    std::map<Edge, Eigen::Vector2d> point;
    for (const Tri &t : tri) {
      std::vector<Edge> crossed;
      for (int i = 0; i < 3; ++i) {
        const int a = t[i], b = t[(i + 1) % 3];
        if ((x[a][axis] > z0) == (x[b][axis] > z0)) continue;
        const Edge e{std::min(a, b), std::max(a, b)};
        const double s = (z0 - x[e[0]][axis]) / (x[e[1]][axis] - x[e[0]][axis]);
        const Vec3 p = x[e[0]] + s * (x[e[1]] - x[e[0]]);
        point[e] = Eigen::Vector2d(p[u], p[v]);
        crossed.push_back(e);
      }
      if (crossed.size() == 2) {
        links[crossed[0]].push_back(crossed[1]);
        links[crossed[1]].push_back(crossed[0]);
      }
    }
    std::vector<Eigen::Vector2d> loop;
    if (links.empty()) return loop;
    Edge prev = links.begin()->first, cur = links.begin()->second[0];
    loop.push_back(point[prev]);
    while (cur != links.begin()->first && loop.size() <= links.size()) {
      loop.push_back(point[cur]);
      const std::vector<Edge> &nb = links[cur];
      const Edge next = nb[0] == prev ? nb[1] : nb[0];
      prev = cur;
      cur = next;
    }
    return loop;
  }

  std::vector<Section> midSections(const std::vector<CellMesh> &meshes, const Box &box, int axis)
  {
    const double len = box.length()[axis];
    // a plane just off the middle, so that no wall particle lies on it
    const double z0 = box.lo[axis] + len * (0.5 + 1e-7 * kPi);
    std::vector<Section> out;
    for (const CellMesh &m : meshes)
      for (int k = box.periodic[axis] ? -1 : 0; k <= (box.periodic[axis] ? 1 : 0); ++k) {
        const std::vector<Eigen::Vector2d> loop =
            cut(m.wall, m.unit->triangles, axis, z0 + k * len);
        if (loop.size() >= 3) {
          out.push_back(describe(loop));
          break;
        }
      }
    return out;
  }

  struct Stats {
    std::vector<std::string> lines;
    void add(const std::string &key, const std::string &value, const std::string &note = "")
    {
      char buf[512];
      std::snprintf(buf, sizeof buf, "%-26s = %-34s%s%s", key.c_str(), value.c_str(),
                    note.empty() ? "" : "  # ", note.c_str());
      lines.emplace_back(buf);
    }
  };

  std::string fmt(const char *f, double a, double b = 0, double c = 0, double d = 0)
  {
    char buf[256];
    std::snprintf(buf, sizeof buf, f, a, b, c, d);
    return buf;
  }

  struct Built {
    Setup setup;
    UnitMeshes units;    // the wall meshes point into it
    std::vector<VoronoiCell> voronoi;
    std::vector<RoundedCell> rounded;
    std::vector<CellMesh> meshes;
    Tissue tissue;
    double alpha = 0, exact = 0;
    int lloydSteps = 0;
  };

  Stats statistics(const Built &b, const Options &o)
  {
    Stats st;
    const Box &box = b.setup.box;
    const double boxVolume = box.length().prod();
    st.add("cells", std::to_string(b.voronoi.size()));
    st.add("box", fmt("%.6g %.6g %.6g", box.length()[0], box.length()[1], box.length()[2]),
           std::string("m; periodic ") + (box.periodic[0] ? "x" : "") +
               (box.periodic[1] ? "y" : "") + (box.periodic[2] ? "z" : ""));
    st.add("porosity_requested", fmt("%.4f", o.porosity));
    st.add("porosity_achieved", fmt("%.4f", meshPorosity(b.meshes, boxVolume, true)),
           "1 - sum V_cell / V_box, V_cell inside the outer surface (junction gap / 2 outside the "
           "wall mesh)");
    st.add("porosity_exact_bodies", fmt("%.4f", b.exact), "the same for the exact rounded bodies");
    st.add("space_outside_walls", fmt("%.4f", meshPorosity(b.meshes, boxVolume, false)),
           "1 - sum V_wall_mesh / V_box (includes the junction gaps)");
    st.add("rounding_alpha", fmt("%.4f", b.alpha), "rho_i = eps + alpha (inradius_i - eps)");
    std::vector<double> nbVor, nbJunc, volVor, volCell, deq;
    int selfFaces = 0;
    std::vector<int> juncCount(b.voronoi.size(), 0);
    for (const Junction &j : b.tissue.junctions.faces) ++juncCount[j.i];
    for (size_t i = 0; i < b.voronoi.size(); ++i) {
      int nb = 0;
      for (const VoronoiFace &f : b.voronoi[i].faces) {
        nb += f.neighbour >= 0;
        selfFaces += f.neighbour == static_cast<int>(i);
      }
      nbVor.push_back(nb);
      nbJunc.push_back(juncCount[i]);
      volVor.push_back(b.voronoi[i].volume);
      volCell.push_back(b.meshes[i].measure.parallel);
      deq.push_back(std::cbrt(6.0 * b.meshes[i].measure.parallel / kPi));
    }
    const Summary sv = summarise(nbVor), sj = summarise(nbJunc), vv = summarise(volVor),
                  vc = summarise(volCell), sd = summarise(deq);
    st.add("neighbours_voronoi", fmt("%.2f (%g..%g)", sv.mean, sv.min, sv.max),
           "mean (range) faces shared with another cell");
    st.add("neighbours_junction", fmt("%.2f (%g..%g)", sj.mean, sj.min, sj.max),
           "mean (range) faces with a contact area > 0");
    st.add("self_image_faces", std::to_string(selfFaces),
           "faces of a cell with its own periodic image (no junction there)");
    st.add("volume_cv_voronoi", fmt("%.4f", vv.cv),
           "requested " + show(o.cv) + " after " + std::to_string(b.lloydSteps) + " Lloyd steps");
    st.add("volume_cv_cells", fmt("%.4f", vc.cv));
    st.add("equivalent_diameter", fmt("%.4g (%.4g..%.4g)", sd.mean, sd.min, sd.max),
           "m, (6 V_cell / pi)^(1/3)");
    const std::vector<Section> sec = midSections(b.meshes, box, 2);
    std::vector<double> area, feret, round, elong, compact;
    for (const Section &s : sec) {
      area.push_back(s.area);
      feret.push_back(s.feret);
      round.push_back(4.0 * s.area / (kPi * s.major * s.major));
      elong.push_back(s.major / s.minor);
      compact.push_back(std::sqrt(4.0 * s.area / kPi) / s.major);
    }
    st.add("section_cells", std::to_string(sec.size()), "walls cut by the mid-plane normal to z");
    st.add("section_area_um2", fmt("%.0f", summarise(area).mean * 1e12), "apple 20000");
    st.add("section_feret_um", fmt("%.1f", summarise(feret).mean * 1e6), "apple 160");
    st.add("section_roundness", fmt("%.3f", summarise(round).mean), "apple 0.76");
    st.add("section_elongation", fmt("%.3f", summarise(elong).mean), "apple 1.45");
    st.add("section_compactness", fmt("%.3f", summarise(compact).mean), "apple 0.84");
    return st;
  }

  // ---- output ----------------------------------------------------------------------------------

  void writeJunctions(const std::string &path, const Tissue &t, const Setup &s)
  {
    File f = openOut(path);
    std::fprintf(f.get(),
                 "# cellgen tissue junctions: one line per face shared by two walls, from each "
                 "side\n# junction gap %.15g m\n# cell_i cell_j image_x image_y image_z area_m2 "
                 "bonds\n",
                 s.junctionGap);
    for (const Junction &j : t.junctions.faces)
      std::fprintf(f.get(), "%d %d %d %d %d %.15g %d\n", j.i + 1, j.j + 1, j.image[0], j.image[1],
                   j.image[2], j.area, j.bonds);
    closeOut(f, path);
  }

  void writeStats(const std::string &path, const Stats &st)
  {
    File f = openOut(path);
    for (const std::string &l : st.lines) std::fprintf(f.get(), "%s\n", l.c_str());
    closeOut(f, path);
  }

  // ---- the run ---------------------------------------------------------------------------------

  Built build(const Options &o)
  {
    Built b;
    b.setup = setup(o);
    const Setup &s = b.setup;
    const double boxVolume = s.box.length().prod();
    const double eps = 0.5 * s.junctionGap;
    const std::vector<Vec3> seeds =
        relaxedSeeds(s.n, s.box, o.cv, o.seed, kLloydSteps, b.lloydSteps);
    b.voronoi = tessellate(seeds, s.box);
    std::vector<InBall> balls;
    for (const VoronoiCell &c : b.voronoi) balls.push_back(largestInscribedBall(c));
    checkResolution(balls, s, o);
    b.alpha = solveRounding(b.voronoi, balls, eps, o.porosity, boxVolume, o.porosity);
    b.rounded = roundCells(b.voronoi, balls, eps, b.alpha);
    b.meshes = meshCells(b.rounded, s.wallDx, eps, b.units);
    // the mesh's porosity differs from the exact bodies': aim the exact bodies off by that
    // difference, a few times (fixed-point iteration on the target)
    double aim = o.porosity;
    for (int it = 0; it < kCorrections && b.alpha > 0; ++it) {
      const double error = meshPorosity(b.meshes, boxVolume, true) - o.porosity;
      if (std::abs(error) < 1e-4) break;
      aim -= error;
      b.alpha = solveRounding(b.voronoi, balls, eps, aim, boxVolume, o.porosity);
      b.rounded = roundCells(b.voronoi, balls, eps, b.alpha);
      b.meshes = meshCells(b.rounded, s.wallDx, eps, b.units);
    }
    b.exact = exactPorosity(b.voronoi, balls, eps, b.alpha, boxVolume);
    if (b.alpha == 0 && meshPorosity(b.meshes, boxVolume, true) > o.porosity)
      std::cerr << "cellgen tissue: note: --porosity " << o.porosity << " is below the lowest "
                << "this junction gap and wall mesh give, "
                << meshPorosity(b.meshes, boxVolume, true) << " (unrounded cells)\n";
    for (size_t i = 0; i < b.voronoi.size(); ++i) {
      const std::vector<Vec3> fluid =
          fluidInWall(b.rounded[i], b.meshes[i].wall, b.meshes[i].unit->triangles, s.dx, s.gap);
      if (fluid.empty())
        throw UsageError("cells too small for the resolution: cell " + std::to_string(i + 1) +
                         " holds no fluid at --dx " + show(s.dx) + " and --gap " + show(s.gap));
      appendCell(b.tissue, static_cast<int>(i + 1), fluid, b.meshes[i], o);
    }
    b.tissue.junctions = junctions(b.voronoi, b.rounded, b.meshes, b.tissue.wallOffset, s);
    setBox(b.tissue.sys, s.box, o.margin * o.size);
    return b;
  }

  std::string commandLine(int argc, char **argv)
  {
    std::string s;
    for (int i = 0; i < argc; ++i) s += std::string(i > 0 ? " " : "") + argv[i];
    return s;
  }

  void run(const Options &o, const std::string &args)
  {
    const auto start = std::chrono::steady_clock::now();
    const Built b = build(o);
    const Setup &s = b.setup;
    long fluid = 0;
    for (long n : b.tissue.fluidCount) fluid += n;
    const long wall = static_cast<long>(b.tissue.sys.particles.size()) - fluid;
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  " | DX=%.15g gap=%.15g junction_gap=%.15g cells=%d fluid=%ld wall=%ld "
                  "junction_bonds=%zu",
                  s.dx, s.gap, s.junctionGap, s.n, fluid, wall, b.tissue.junctions.bonds.size());
    // the data file of one cell (README.md "Output"), with bond type 2 for the junctions
    DataExtras extras;
    extras.bondTypes = 2;
    extras.junctions = b.tissue.junctions.bonds;
    if (o.dihedrals) extras.dihedrals = wallDihedrals(b.tissue.sys);
    writeData(o.out, b.tissue.sys, std::string(kVersion) + " | args: " + args + buf, extras);
    writeJunctions(o.out + ".junctions", b.tissue, s);
    Stats st = statistics(b, o);
    const SurfaceStats edges = [&] {
      Surface all;
      for (const Particle &p : b.tissue.sys.particles) all.points.push_back(p.x);
      all.edges = b.tissue.sys.bonds;
      return surfaceStats(all);
    }();
    const Summary fl =
        summarise(std::vector<double>(b.tissue.fluidCount.begin(), b.tissue.fluidCount.end()));
    st.add("particles",
           fmt("%.0f fluid (%.0f..%.0f per cell), %.0f wall", fluid, fl.min, fl.max, wall));
    st.add("wall_bond_length", fmt("%.3g %.3g %.3g", edges.minEdge, edges.meanEdge, edges.maxEdge),
           "m, min mean max (--wall-dx " + show(s.wallDx) + ")");
    st.add("junction_bonds", std::to_string(b.tissue.junctions.bonds.size()));
    if (o.dihedrals)
      st.add("dihedrals", std::to_string(extras.dihedrals.size()), "one per wall bond");
    st.add("resolution", fmt("dx %.4g gap %.4g junction_gap %.4g", s.dx, s.gap, s.junctionGap),
           "m");
    writeStats(o.out + ".stats", st);
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    for (const std::string &l : st.lines) std::printf("%s\n", l.c_str());
    std::printf("wrote %s, %s.junctions, %s.stats in %.2f s\n", o.out.c_str(), o.out.c_str(),
                o.out.c_str(), elapsed.count());
  }

}    // namespace

int tissueMain(int argc, char **argv)
{
  return runMain(argc, argv, "cellgen tissue", kUsage,
                 [&] { run(parse(argc, argv), commandLine(argc, argv)); });
}

}    // namespace cellgen
