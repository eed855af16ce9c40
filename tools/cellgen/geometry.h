// Geometry for cellgen: sphere point sets, their triangulation, the fluid fill and the lattice of
// cells that together make a cellsph initial configuration.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <optional>
#include <random>
#include <vector>

namespace cellgen {

using Vec3 = Eigen::Vector3d;
using Tri = std::array<int, 3>;
using Edge = std::array<int, 2>;

// Near-uniform points on the unit sphere: golden-spiral start, then tangential relaxation.
std::vector<Vec3> fibonacciSphere(int n);
void relaxOnSphere(std::vector<Vec3> &points, int iterations);

// Goldberg-Coxeter class of a geodesic icosahedral mesh: every icosahedron face is covered by the
// triangular lattice so that its vertices sit at lattice vectors (h, k) apart; T = h^2 + hk + k^2
// lattice triangles per face and 10 T + 2 vertices. Class I: k = 0; II: h = k; III: otherwise.
struct GeodesicClass {
  int h = 1, k = 0;
  long triangulationNumber() const
  {
    return static_cast<long>(h) * h + static_cast<long>(h) * k + static_cast<long>(k) * k;
  }
  long points() const { return 10 * triangulationNumber() + 2; }
};

// The (h, k), h >= k >= 0, whose 10 T + 2 is closest to n; ties go to class I (k = 0), then to
// the smaller k, then to the smaller T.
GeodesicClass chooseGeodesic(long n);

// Vertices of the (h, k) geodesic subdivision of the icosahedron, projected onto the unit sphere:
// the 12 icosahedron vertices, then the points inside its edges, then those inside its faces.
std::vector<Vec3> geodesicSphere(const GeodesicClass &c);

// Convex hull of points in strictly convex position (e.g. on a sphere), every triangle oriented
// outward. Orientation tests are exact (integer arithmetic on coordinates snapped to 2^-39).
std::vector<Tri> convexHull(const std::vector<Vec3> &points);

// Unique undirected edges (i < j) of a triangulation, sorted.
std::vector<Edge> uniqueEdges(const std::vector<Tri> &triangles);

// A closed triangulated unit sphere: wall points, outward triangles and their edges.
struct Surface {
  std::vector<Vec3> points;
  std::vector<Tri> triangles;
  std::vector<Edge> edges;
};

// Triangulates points on the unit sphere (convex hull = spherical Delaunay triangulation) and
// checks the result is a closed, outward, genus-0 manifold on all of them.
Surface sphereSurface(std::vector<Vec3> points);

// The wall of n golden-spiral points relaxed by 40 repulsion steps (--mesh spiral).
Surface spiralSurface(int n);

// The wall of the (h, k) geodesic icosahedron, 10 T + 2 points (--mesh icosahedral).
Surface icosahedralSurface(const GeodesicClass &c);

struct SurfaceStats {
  double minEdge = 0, meanEdge = 0, maxEdge = 0;
  double area = 0, volume = 0;
  std::vector<long> valence;    // valence[z] = number of points with z bonds
};
SurfaceStats surfaceStats(const Surface &surface);

// Fluid spacing DX and the gap G between the fluid fill and the wall.
struct FluidSpacing {
  double dx = 0;
  double gap = 0;
};

// Picks DX so that the simple cubic fill of the sphere of radius R - G holds as close to `target`
// points as possible. G is `gap` if given, else 0.5 * DX.
FluidSpacing chooseSpacing(double radius, long target, std::optional<double> gap);

// Simple cubic lattice points of spacing dx, centred on the origin, with |x| <= radius.
std::vector<Vec3> fluidLattice(double radius, double dx);

// `count` points on concentric spheres centred on the origin (--fluid-lattice shells), the
// outermost of radius `outer`, the others spacing apart inwards down to the centre (a point at
// the origin when outer / spacing is an integer). Shell k holds its share of `count` in
// proportion to the volume of its slab, [r_k - spacing/2, r_k + spacing/2] (the centre point
// [0, spacing/2]), so the number density is uniform over the ball of radius outer + spacing/2.
// The spacing is the one nearest to (4/3 pi (outer + spacing/2)^3 / count)^(1/3) that makes
// outer / spacing a multiple of 1/2. Each shell is a golden spiral relaxed on its sphere
// (relaxOnSphere, 40 steps) and turned by a uniform random rotation drawn from rng.
struct FluidShells {
  std::vector<Vec3> points;
  double spacing = 0;    // between shells
  int shells = 0;        // the centre point not counted
};
FluidShells fluidShells(long count, double outer, std::mt19937_64 &rng);
double shellSpacing(long count, double outer);    // the spacing of fluidShells

// ---- ellipsoidal cells (--ellipsoid, --elongation) ----------------------------------------

// The unit sphere mesh mapped onto the ellipsoid of semi-axes `axes` by x -> (a x, b y, c z). The
// map is affine, so the triangles stay the outward convex hull of the points and keep their
// topology (12 five-fold particles for a geodesic mesh); bonds along an axis stretch by its factor.
Surface ellipsoidSurface(const Surface &unitSphere, const Vec3 &axes);

// The unit sphere mesh's points mapped onto the spheroid of semi-axes `axes` (two equal) by a
// conformal map: a point at angle theta from the axis of revolution goes to the point of the
// spheroid at isothermal latitude equal to the sphere's, ln tan(theta/2) = ln tan(phi/2) + G(phi),
// G(phi) = int_{pi/2}^{phi} (sqrt(a^2 sin^2 t + b^2 cos^2 t) - b) / (b sin t) dt (a along the
// axis, b around it), keeping the azimuth and the sphere's triangles (topology). Small triangles
// keep their angles, their size varies along the axis; the wall is not always exactly the convex
// hull of its points. Throws unless two semi-axes are equal, or if a triangle turns inward.
Surface conformalSpheroidSurface(const Surface &unitSphere, const Vec3 &axes);

// Simple cubic lattice points of spacing dx, centred on the origin, inside the ellipsoid of
// semi-axes `axes` scaled by 1 - gap / (smallest semi-axis): at least `gap` from its surface.
std::vector<Vec3> fluidEllipsoid(const Vec3 &axes, double gap, double dx);

// Exact area of the ellipsoid of semi-axes `axes` (Legendre's incomplete elliptic integrals).
double ellipsoidArea(const Vec3 &axes);

struct CellSpec {
  Vec3 centre;
  double radius;
};

// NX x NY x NZ cells on a simple cubic lattice of spacing `spacing` centred on the origin; radius
// R (1 + spread u), u uniform in [-1, 1] from a 64-bit Mersenne twister seeded with `seed`.
std::vector<CellSpec> cellLattice(const std::array<int, 3> &counts, double spacing, double radius,
                                  double spread, std::uint64_t seed);

// Throws if two cells intersect; a cell reaches `extent` times its radius from its centre.
void checkNoOverlap(const std::vector<CellSpec> &cells, double extent = 1.0);

enum ParticleType { kFluid = 1, kWall = 2 };

struct Particle {
  int molecule;
  ParticleType type;
  Vec3 x;
  double mass;
};

struct BuildParams {
  FluidSpacing spacing;
  Vec3 shape = Vec3::Ones();    // semi-axes of a cell of radius 1: the unit mesh's ellipsoid
  double rho0 = 1000;
  bool withFluid = true;     // false: walls only (--nfluid 0)
  bool shells = false;       // --fluid-lattice shells: the cubic lattice's count on shells
  std::uint64_t seed = 1;    // of the shells' rotations
  std::optional<double> wallMass;
  double wallThickness = 1e-6;
  double boxMargin = 0;
};

// Particles, bonds and wall triangles (0-based particle indices) of all cells, and the box.
struct System {
  std::vector<Particle> particles;
  std::vector<Edge> bonds;
  std::vector<Tri> triangles;
  Vec3 lo, hi;
};

System buildSystem(const Surface &unit, const std::vector<CellSpec> &cells,
                   const BuildParams &params);

// Per particle: its share of wall area per bond, a_i / z_i, with a_i a third of the area of its
// triangles and z_i its number of bonds (0 for fluid). A bond's reference area a_i/z_i + a_j/z_j
// sums to the wall area over all bonds; bond_style cell/neohookean weights each bond by it.
std::vector<double> bondAreaShares(const System &sys);

// Wall dihedrals (--dihedrals): one per wall edge b-c, as (a, b, c, d) with (a, b, c) and (d, c, b)
// the two outward wall triangles sharing it (0-based indices), in the order of sys.bonds; b < c.
// Throws unless every edge lies in exactly one triangle in each direction (a closed wall).
using Quad = std::array<int, 4>;
std::vector<Quad> wallDihedrals(const System &sys);

}    // namespace cellgen
