// Geometry for cellgen: sphere point sets, their triangulation, the fluid fill and the lattice of
// cells that together make a cellsph initial configuration.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace cellgen {

using Vec3 = Eigen::Vector3d;
using Tri = std::array<int, 3>;
using Edge = std::array<int, 2>;

// Near-uniform points on the unit sphere: golden-spiral start, then tangential relaxation.
std::vector<Vec3> fibonacciSphere(int n);
void relaxOnSphere(std::vector<Vec3> &points, int iterations);

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

// Builds the unit-sphere wall of n points and checks it is a closed, outward, genus-0 manifold.
Surface unitSphereSurface(int n);

struct SurfaceStats {
  double minEdge = 0, meanEdge = 0, maxEdge = 0;
  double area = 0, volume = 0;
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

struct CellSpec {
  Vec3 centre;
  double radius;
};

// NX x NY x NZ cells on a simple cubic lattice of spacing `spacing` centred on the origin; radius
// R (1 + spread u), u uniform in [-1, 1] from a 64-bit Mersenne twister seeded with `seed`.
std::vector<CellSpec> cellLattice(const std::array<int, 3> &counts, double spacing, double radius,
                                  double spread, std::uint64_t seed);

// Throws if two cells intersect.
void checkNoOverlap(const std::vector<CellSpec> &cells);

enum ParticleType { kFluid = 1, kWall = 2 };

struct Particle {
  int molecule;
  ParticleType type;
  Vec3 x;
  double mass;
};

struct BuildParams {
  FluidSpacing spacing;
  double rho0 = 1000;
  bool withFluid = true;    // false: walls only (--nfluid 0)
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

}    // namespace cellgen
