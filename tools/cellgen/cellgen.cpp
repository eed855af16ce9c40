// cellgen: writes the initial geometry of cellsph plant cells (fluid-filled spheres bounded by a
// triangulated wall) as a LAMMPS data file for atom_style angle (molecular with --dihedrals).
// See README.md.
#include "cli.h"
#include "datafile.h"
#include "geometry.h"
#include "tissue.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace cellgen;

constexpr const char *kVersion = "cellgen 1.0";
constexpr double kPi = 3.14159265358979323846;

constexpr const char *kUsage =
    "usage: cellgen [--radius R=75e-6] [--nwall N=1091] [--mesh icosahedral|spiral]\n"
    "               [--nfluid M=1624] [--dx DX] [--gap G] [--rho0 1000] [--wall-mass MW]\n"
    "               [--cells NX NY NZ] [--spacing S] [--radius-spread F] [--seed 1]\n"
    "               [--margin F=0.5] [--ellipsoid A:B:C | --elongation E]\n"
    "               [--map affine|conformal] [--fluid-lattice cubic|shells] [--dihedrals]\n"
    "               --out FILE.data\n"
    "--gap G: the fluid lattice at least G inside the wall (default DX/2), DX/4 <= G < the "
    "smallest\n"
    "            radius (semi-axis), DX the fluid spacing; without fluid (--nfluid 0) 0 <= G.\n"
    "            DX/2 suits the SPH wall boundary (apple.cellsph); the seed's particle model\n"
    "            (apple-seed.cellsph wallfluid) needs its range r0: --gap 11e-6.\n"
    "--wall-mass MW: 0 < MW <= rho0 4/3 pi R^3 (the water filling a cell); --rho0: at most 1e5.\n"
    "--margin F: the box reaches F x R beyond the cells on each side (F > 0, default 0.5);\n"
    "            room to deform: compressing a cell to half its height needs F >= 1.\n"
    "--ellipsoid A:B:C: semi-axes along x, y, z (replaces --radius); --elongation E: prolate along "
    "x,\n"
    "            a/b = E, with the volume of the sphere of --radius; --map: how the sphere mesh\n"
    "            goes onto the ellipsoid (affine x -> (a x, b y, c z), or conformal for "
    "spheroids).\n"
    "--fluid-lattice shells: the cubic lattice's number of fluid particles on concentric spheres,\n"
    "            the outermost at R - G (spherical cells only).\n"
    "--dihedrals: also write one dihedral per wall edge (atom_style molecular), for\n"
    "            dihedral_style cell/bending.\n"
    "All values in SI units. Only 3-D geometries are supported. See tools/cellgen/README.md.\n"
    "A packed tissue of polyhedral cells: cellgen tissue --help.\n";

enum class Mesh { Icosahedral, Spiral };

struct Options {
  double radius = 75e-6;
  long nwall = 1091;
  Mesh mesh = Mesh::Icosahedral;
  long nfluid = 1624;
  std::optional<double> dx, gap, wallMass, spacing;
  double rho0 = 1000.0;
  std::array<long, 3> cells{1, 1, 1};
  double spread = 0.0;
  double margin = 0.5;
  std::uint64_t seed = 1;
  bool dihedrals = false;
  bool shells = false;    // --fluid-lattice shells
  std::string out;
  bool radiusGiven = false;
  std::optional<Vec3> ellipsoid;    // --ellipsoid semi-axes
  std::optional<double> elongation;
  bool conformal = false;       // --map conformal
  Vec3 shape = Vec3::Ones();    // semi-axes of a cell of radius 1 (from the two options above)
  bool sphere() const { return shape == Vec3::Ones(); }
};

// Hands out the command-line words one at a time, converting option values.
class ArgReader {
 public:
  ArgReader(int argc, char **argv) : args_(argv + 1, argv + argc) {}

  bool done() const { return pos_ >= args_.size(); }
  std::string option() { return option_ = args_[pos_++]; }
  std::string word()
  {
    if (done()) throw UsageError(option_ + " needs more values");
    return args_[pos_++];
  }
  double real()
  {
    const double v =
        convert<double>([](const std::string &s, size_t *n) { return std::stod(s, n); });
    if (!std::isfinite(v)) throw UsageError(option_ + ": value must be finite");
    return v;
  }
  long integer()
  {
    return convert<long>([](const std::string &s, size_t *n) { return std::stol(s, n); });
  }

 private:
  template <class T, class F> T convert(F &&parse)
  {
    const std::string s = word();
    size_t used = 0;
    T value{};
    try {
      value = parse(s, &used);
    } catch (const std::logic_error &) {
      used = 0;
    }
    if (used == 0 || used != s.size()) throw UsageError(option_ + ": not a number: '" + s + "'");
    return value;
  }

  std::vector<std::string> args_;
  size_t pos_ = 0;
  std::string option_;
};

// --ellipsoid A:B:C: three positive, finite semi-axes
Vec3 semiAxes(const std::string &word)
{
  Vec3 axes;
  size_t start = 0;
  for (int d = 0; d < 3; ++d) {
    const size_t end = d < 2 ? word.find(':', start) : word.size();
    const std::string part = end == std::string::npos ? "" : word.substr(start, end - start);
    size_t used = 0;
    try {
      axes[d] = std::stod(part, &used);
    } catch (const std::logic_error &) {
      used = 0;
    }
    if (used == 0 || used != part.size() || !std::isfinite(axes[d]) || axes[d] <= 0)
      throw UsageError("--ellipsoid needs three positive semi-axes A:B:C, not '" + word + "'");
    start = end + 1;
  }
  return axes;
}

using Handler = std::function<void(ArgReader &, Options &)>;

const std::map<std::string, Handler> &optionHandlers()
{
  static const std::map<std::string, Handler> handlers = {
      {"--radius",
       [](ArgReader &a, Options &o) {
         o.radius = a.real();
         o.radiusGiven = true;
       }},
      {"--ellipsoid", [](ArgReader &a, Options &o) { o.ellipsoid = semiAxes(a.word()); }},
      {"--elongation", [](ArgReader &a, Options &o) { o.elongation = a.real(); }},
      {"--map",
       [](ArgReader &a, Options &o) {
         const std::string kind = a.word();
         if (kind != "affine" && kind != "conformal")
           throw UsageError("--map must be affine or conformal, not '" + kind + "'");
         o.conformal = kind == "conformal";
       }},
      {"--nwall", [](ArgReader &a, Options &o) { o.nwall = a.integer(); }},
      {"--mesh",
       [](ArgReader &a, Options &o) {
         const std::string kind = a.word();
         if (kind == "icosahedral")
           o.mesh = Mesh::Icosahedral;
         else if (kind == "spiral")
           o.mesh = Mesh::Spiral;
         else
           throw UsageError("--mesh must be icosahedral or spiral, not '" + kind + "'");
       }},
      {"--nfluid", [](ArgReader &a, Options &o) { o.nfluid = a.integer(); }},
      {"--dx", [](ArgReader &a, Options &o) { o.dx = a.real(); }},
      {"--gap", [](ArgReader &a, Options &o) { o.gap = a.real(); }},
      {"--rho0", [](ArgReader &a, Options &o) { o.rho0 = a.real(); }},
      {"--wall-mass", [](ArgReader &a, Options &o) { o.wallMass = a.real(); }},
      {"--spacing", [](ArgReader &a, Options &o) { o.spacing = a.real(); }},
      {"--radius-spread", [](ArgReader &a, Options &o) { o.spread = a.real(); }},
      {"--margin", [](ArgReader &a, Options &o) { o.margin = a.real(); }},
      {"--seed",
       [](ArgReader &a, Options &o) { o.seed = static_cast<std::uint64_t>(a.integer()); }},
      {"--out", [](ArgReader &a, Options &o) { o.out = a.word(); }},
      {"--dihedrals", [](ArgReader &, Options &o) { o.dihedrals = true; }},
      {"--fluid-lattice",
       [](ArgReader &a, Options &o) {
         const std::string kind = a.word();
         if (kind != "cubic" && kind != "shells")
           throw UsageError("--fluid-lattice must be cubic or shells, not '" + kind + "'");
         o.shells = kind == "shells";
       }},
      {"--cells",
       [](ArgReader &a, Options &o) {
         for (long &c : o.cells) c = a.integer();
       }},
      {"--2d",
       [](ArgReader &, Options &) { throw UsageError("2-D geometries are not supported"); }},
  };
  return handlers;
}

void validate(const Options &o)
{
  require(o.radius > 0, "--radius must be positive");
  require(o.nwall >= 4 && o.nwall <= 10000000, "--nwall must be in [4, 1e7]");
  require(o.nfluid >= 0 && o.nfluid <= 100000000, "--nfluid must be in [0, 1e8]");
  require(!o.dx || *o.dx > 0, "--dx must be positive");
  require(o.rho0 > 0 && o.rho0 <= kRho0Max,
          "--rho0 must be in (0, " + show(kRho0Max) + "] kg/m^3, not " + show(o.rho0));
  // a wall particle at most as heavy as the water filling a cell of radius R
  const double cellMass = o.rho0 * 4.0 / 3.0 * kPi * o.radius * o.radius * o.radius;
  require(!o.wallMass || (*o.wallMass > 0 && *o.wallMass <= cellMass),
          "--wall-mass must be in (0, rho0 4/3 pi R^3] = (0, " + show(cellMass) +
              "] kg (the water filling a cell of radius R), not " + show(o.wallMass.value_or(0)));
  require(!o.spacing || *o.spacing > 0, "--spacing must be positive");
  require(o.spread >= 0 && o.spread < 1, "--radius-spread must be in [0, 1)");
  require(o.margin > 0 && o.margin <= 1000,
          "--margin must be in (0, 1000] (box margin as a multiple of R; default 0.5)");
  require(std::all_of(o.cells.begin(), o.cells.end(), [](long c) { return c >= 1 && c <= 1000; }),
          "--cells needs three counts in [1, 1000]");
  require(!o.out.empty(), "--out FILE is required");
}

// true if two of the semi-axes are equal (a spheroid, or a sphere)
bool spheroidAxis(const Vec3 &s)
{
  const auto same = [](double u, double v) { return std::abs(u - v) <= 1e-12 * std::max(u, v); };
  return same(s[0], s[1]) || same(s[1], s[2]) || same(s[0], s[2]);
}

// The cell's shape: --ellipsoid A:B:C gives R = (A B C)^(1/3) (the sphere of equal volume) and
// semi-axes (A, B, C) / R per unit radius; --elongation E the prolate spheroid along x with
// a / b = E of the volume of the sphere of --radius: (E^(2/3), E^(-1/3), E^(-1/3)).
void resolveShape(Options &o)
{
  require(!o.ellipsoid || (!o.radiusGiven && !o.elongation),
          "--ellipsoid gives size and shape: do not combine it with --radius or --elongation");
  if (o.ellipsoid) {
    o.radius = std::cbrt(o.ellipsoid->prod());
    o.shape = *o.ellipsoid / o.radius;
  }
  if (o.elongation) {
    const double e = *o.elongation;
    require(e >= 1 && e <= 100, "--elongation must be in [1, 100]");
    o.shape = Vec3(std::cbrt(e * e), 1 / std::cbrt(e), 1 / std::cbrt(e));
  }
  require(!o.shells || o.sphere(),
          "--fluid-lattice shells needs a spherical cell (no --ellipsoid or --elongation)");
  require(
      !o.conformal || (!o.sphere() && spheroidAxis(o.shape)),
      "--map conformal needs a spheroid: --elongation, or --ellipsoid with two equal semi-axes");
}

FluidSpacing fluidSpacing(const Options &o);

// --gap G: the fluid lattice's outermost points at least G inside the wall, G < the smallest
// cell's smallest semi-axis. With fluid, G >= DX/4: the fluid a point stands for reaches DX/2 from
// it, so that below DX/4 it would reach past the wall by more than DX/4 and the outermost points
// would sit next to the wall particles (at G = 0, on the wall's own surface). README.md, Usage.
void validateGap(const Options &o)
{
  if (!o.gap) return;
  const double rmin = o.radius * o.shape.minCoeff() * (1 - o.spread);
  if (o.nfluid == 0) {
    require(*o.gap >= 0 && *o.gap < rmin,
            "--gap must be in [0, smallest radius) = [0, " + show(rmin) + ") m, not " +
                show(*o.gap));
    return;
  }
  require(*o.gap < rmin,
          "--gap must be in [DX/4, smallest radius), below " + show(rmin) + " m, not " +
              show(*o.gap));
  const double dx = fluidSpacing(o).dx;    // without --dx: DX = (R - G) / rho (chooseSpacing)
  require(*o.gap >= 0.25 * dx,
          "--gap must be in [DX/4, smallest radius) = [" + show(0.25 * dx) + ", " + show(rmin) +
              ") m (DX = " + show(dx) + " m, the fluid spacing), not " + show(*o.gap));
}

Options parseOptions(int argc, char **argv)
{
  Options o;
  ArgReader args(argc, argv);
  while (!args.done()) {
    const std::string opt = args.option();
    const auto h = optionHandlers().find(opt);
    if (h == optionHandlers().end()) throw UsageError("unknown option '" + opt + "'");
    h->second(args, o);
  }
  resolveShape(o);
  validate(o);
  validateGap(o);
  return o;
}

std::string commandLine(int argc, char **argv)
{
  std::string s;
  for (int i = 1; i < argc; ++i) s += std::string(i > 1 ? " " : "") + argv[i];
  return s;
}

// ---- run and summary ---------------------------------------------------------------------

struct Totals {
  size_t cells = 0;
  long fluid = 0, wall = 0;
  long minFluid = 0, maxFluid = 0;
  double sphereVolume = 0, sphereArea = 0, volume = 0, area = 0;
  double minEdge = INFINITY, meanEdge = 0, maxEdge = 0;
};

Totals totals(const System &sys, const std::vector<CellSpec> &cells, const SurfaceStats &unit,
              const Vec3 &shape)
{
  // the exact volume and area of a cell of radius 1: the sphere's, or the ellipsoid's
  const bool sphere = shape == Vec3::Ones();
  const double exactVolume = 4.0 / 3.0 * kPi * shape.prod();
  const double exactArea = sphere ? 4.0 * kPi : ellipsoidArea(shape);
  Totals t;
  t.cells = cells.size();
  std::vector<long> fluidPerCell(cells.size(), 0);
  for (const Particle &p : sys.particles)
    if (p.type == kFluid)
      ++fluidPerCell[p.molecule - 1];
    else
      ++t.wall;
  t.minFluid = *std::min_element(fluidPerCell.begin(), fluidPerCell.end());
  t.maxFluid = *std::max_element(fluidPerCell.begin(), fluidPerCell.end());
  t.fluid = static_cast<long>(sys.particles.size()) - t.wall;
  for (const CellSpec &c : cells) {
    const double r = c.radius;
    t.sphereVolume += exactVolume * r * r * r;
    t.sphereArea += exactArea * r * r;
    t.volume += unit.volume * r * r * r;
    t.area += unit.area * r * r;
    t.minEdge = std::min(t.minEdge, unit.minEdge * r);
    t.maxEdge = std::max(t.maxEdge, unit.maxEdge * r);
    t.meanEdge += unit.meanEdge * r / cells.size();
  }
  return t;
}

// How the wall was meshed, e.g. "icosahedral (h, k) = (7, 5), T = 109" or "spiral".
struct WallMesh {
  Surface unit;
  std::string description;
};

WallMesh wallMesh(const Options &o)
{
  if (o.mesh == Mesh::Spiral)
    return {spiralSurface(static_cast<int>(o.nwall)), "spiral (golden spiral + relaxation)"};
  const GeodesicClass c = chooseGeodesic(o.nwall);
  const char *kind = c.k == 0 ? "I" : (c.k == c.h ? "II" : "III");
  return {icosahedralSurface(c),
          "icosahedral class " + std::string(kind) + ", (h, k) = (" + std::to_string(c.h) + ", " +
              std::to_string(c.k) + "), T = " + std::to_string(c.triangulationNumber())};
}

std::string valenceSummary(const SurfaceStats &st)
{
  std::string s;
  for (size_t z = 0; z < st.valence.size(); ++z)
    if (st.valence[z] > 0)
      s += (s.empty() ? "" : ", ") + std::to_string(st.valence[z]) + " x " + std::to_string(z);
  return s;
}

void printSummary(const Options &o, const FluidSpacing &sp, const System &sys, const Totals &t,
                  const WallMesh &mesh, const SurfaceStats &st, double seconds)
{
  const std::string chosen = o.dx ? "" : " (chosen for " + std::to_string(o.nfluid) + " fluid)";
  std::printf("%s: %zu cell(s), R = %g m (spread %g), DX = %g m%s, gap = %g m\n", kVersion, t.cells,
              o.radius, o.spread, sp.dx, chosen.c_str(), sp.gap);
  const size_t perCell = mesh.unit.points.size();
  std::printf("wall mesh: %s: %zu wall particles per cell (--nwall %ld)\n",
              mesh.description.c_str(), perCell, o.nwall);
  std::printf("particles: %ld fluid (%ld to %ld per cell), %ld wall (%zu per cell); %zu bonds, "
              "%zu triangles%s\n",
              t.fluid, t.minFluid, t.maxFluid, t.wall, perCell, sys.bonds.size(),
              sys.triangles.size(), o.dihedrals ? ", one dihedral per bond" : "");
  std::printf("wall valence (particles x bonds): %s\n", valenceSummary(st).c_str());
  std::printf("wall bond length: min %g, mean %g, max %g m (max/min %.3f)\n", t.minEdge, t.meanEdge,
              t.maxEdge, t.maxEdge / t.minEdge);
  if (o.shells && o.nfluid > 0) {
    // the first cell's shells (cells of another radius have their own)
    const double outer = o.radius - sp.gap;
    const long count = static_cast<long>(fluidLattice(outer, sp.dx).size());
    const double s = shellSpacing(count, outer);
    std::printf("fluid shells: spacing %g m, outermost at %g m, fill radius %g m (R = %g m)\n", s,
                outer, outer + 0.5 * s, o.radius);
  }
  if (!o.sphere())
    std::printf("ellipsoid: semi-axes %g, %g, %g m (x, y, z; elongation %.4f), equal-volume R = %g "
                "m\n",
                o.radius * o.shape[0], o.radius * o.shape[1], o.radius * o.shape[2],
                o.shape.maxCoeff() / o.shape.minCoeff(), o.radius);
  const char *exact = o.sphere() ? "spheres" : "ellipsoids";
  std::printf("enclosed volume %g m^3 = %.5f x %s; area %g m^2 = %.5f x %s\n", t.volume,
              t.volume / t.sphereVolume, exact, t.area, t.area / t.sphereArea, exact);
  std::printf("box [%g, %g] x [%g, %g] x [%g, %g] m; wrote %s in %.2f s\n", sys.lo[0], sys.hi[0],
              sys.lo[1], sys.hi[1], sys.lo[2], sys.hi[2], o.out.c_str(), seconds);
}

FluidSpacing fluidSpacing(const Options &o)
{
  if (o.dx) return {*o.dx, o.gap.value_or(0.5 * *o.dx)};
  if (o.nfluid == 0) return {o.radius, 0.0};    // wall only: the spacing is not used
  return chooseSpacing(o.radius, o.nfluid, o.gap);
}

std::string comment(const Options &o, const std::string &args, const FluidSpacing &sp,
                    const Totals &t)
{
  char buf[256];
  std::snprintf(buf, sizeof buf, " | R=%.15g DX=%.15g gap=%.15g cells=%zu fluid=%ld wall=%ld",
                o.radius, sp.dx, sp.gap, t.cells, t.fluid, t.wall);
  if (!o.sphere())
    std::snprintf(buf + std::strlen(buf), sizeof buf - std::strlen(buf), " axes=%.15g:%.15g:%.15g",
                  o.radius * o.shape[0], o.radius * o.shape[1], o.radius * o.shape[2]);
  return std::string(kVersion) + " | args: " + args + buf;
}

void run(const Options &o, const std::string &args)
{
  const auto start = std::chrono::steady_clock::now();
  const FluidSpacing sp = fluidSpacing(o);
  // default spacing leaves a 5% gap between the largest possible cells
  const double spacing =
      o.spacing.value_or(2.0 * o.radius * (1.0 + o.spread) * 1.05 * o.shape.maxCoeff());
  const std::array<int, 3> counts{static_cast<int>(o.cells[0]), static_cast<int>(o.cells[1]),
                                  static_cast<int>(o.cells[2])};
  const std::vector<CellSpec> cells = cellLattice(counts, spacing, o.radius, o.spread, o.seed);
  checkNoOverlap(cells, o.shape.maxCoeff());
  WallMesh mesh = wallMesh(o);
  if (!o.sphere())
    mesh.unit = o.conformal ? conformalSpheroidSurface(mesh.unit, o.shape)
                            : ellipsoidSurface(mesh.unit, o.shape);
  const Surface &unit = mesh.unit;
  BuildParams params;
  params.spacing = sp;
  params.shape = o.shape;
  params.rho0 = o.rho0;
  params.withFluid = o.nfluid > 0;
  params.shells = o.shells;
  params.seed = o.seed;
  params.wallMass = o.wallMass;
  params.boxMargin = o.margin * o.radius;
  const System sys = buildSystem(unit, cells, params);
  const SurfaceStats stats = surfaceStats(unit);
  const Totals t = totals(sys, cells, stats, o.shape);
  DataExtras extras;
  if (o.dihedrals) extras.dihedrals = wallDihedrals(sys);
  writeData(o.out, sys, comment(o, args, sp, t), extras);
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  printSummary(o, sp, sys, t, mesh, stats, elapsed.count());
}

}    // namespace

int main(int argc, char **argv)
{
  if (argc > 1 && std::string(argv[1]) == "tissue") return cellgen::tissueMain(argc - 1, argv + 1);
  return cellgen::runMain(argc, argv, "cellgen", kUsage,
                          [&] { run(parseOptions(argc, argv), commandLine(argc, argv)); });
}
