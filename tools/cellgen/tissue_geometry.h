// Tissue geometry for cellgen: a Voronoi tessellation of seeds (Voro++), each cell's wall as the
// surface of its polyhedron shrunk and rounded, and the flat facets where neighbouring walls face
// each other (doc/model.md §10.6, tools/cellgen/README.md "Tissue mode").
#pragma once

#include "geometry.h"

#include <array>
#include <cstdint>
#include <vector>

namespace cellgen {

// One face of a Voronoi polyhedron: the plane n . (x - seed) = offset, its polygon (absolute
// coordinates, counter-clockwise seen from outside) and the cell across it.
struct VoronoiFace {
  Vec3 normal;
  double offset = 0;
  std::vector<Vec3> polygon;
  int neighbour = -1;                   // 0-based cell index, -1 for a free (box) face
  std::array<int, 3> image{0, 0, 0};    // the neighbour across it is its seed + image * box length
};

struct VoronoiCell {
  Vec3 seed;
  double volume = 0;
  Vec3 centroid;
  std::vector<VoronoiFace> faces;
};

struct Box {
  Vec3 lo, hi;
  std::array<bool, 3> periodic{true, true, true};
  Vec3 length() const { return hi - lo; }
};

// Voronoi cells of the seeds in the box (Voro++, Rycroft 2009); periodic axes wrap.
std::vector<VoronoiCell> tessellate(const std::vector<Vec3> &seeds, const Box &box);

// Coefficient of variation (std / mean) of the cell volumes.
double volumeCV(const std::vector<VoronoiCell> &cells);

// Seeds for n cells: uniform random (Poisson) in the box from a 64-bit Mersenne twister, then
// Lloyd steps (each seed to its cell's centroid) until the volume CV is at most `targetCV` or
// `maxSteps` steps have been made. Returns the number of steps taken in `steps`.
std::vector<Vec3> relaxedSeeds(int n, const Box &box, double targetCV, std::uint64_t seed,
                               int maxSteps, int &steps);

// A convex polytope: vertices, faces as vertex loops (outward), and per face the index of the
// Voronoi face it lies on.
struct Polytope {
  std::vector<Vec3> vertices;
  std::vector<std::vector<int>> faces;
  std::vector<Vec3> normals;
  std::vector<int> faceId;
  std::vector<Edge> edges;
  double volume = 0, area = 0;
  double meanCurvature = 0;    // M = sum over edges of length * exterior angle / 2
};

// Centre and radius of the largest ball inside the polyhedron (its Chebyshev centre).
struct InBall {
  Vec3 centre;
  double radius = 0;
};
InBall largestInscribedBall(const VoronoiCell &cell);

// The cell's wall body B = (P shrunk by rho) + ball(r), r = rho - eps: its flat faces lie eps
// inside the Voronoi planes and its edges and corners are rounded with radius r. The cell's outer
// surface (half the junction gap outside the wall) is (P shrunk by rho) + ball(rho).
class RoundedCell {
 public:
  RoundedCell(const VoronoiCell &cell, const InBall &ball, double rho, double eps);

  const Vec3 &centre() const { return centre_; }
  double rounding() const { return r_; }

  // Steiner's formula for a convex body Q + ball(t): V = V_Q + t S_Q + t^2 M_Q + 4/3 pi t^3.
  double parallelVolume(double t) const;
  // Its area, the derivative: S = S_Q + 2 t M_Q + 4 pi t^2.
  double parallelArea(double t) const;

  // Distance from the centre along the unit direction u to the wall surface (exact).
  double rayExit(const Vec3 &u) const;
  // Distance from a point inside the wall body to its surface (negative outside).
  double depth(const Vec3 &x) const;
  // The flat facet of Voronoi face f on the wall surface (absolute coordinates; empty if the
  // rounding has consumed it).
  std::vector<Vec3> facet(int f) const;

 private:
  Vec3 centre_;
  double r_;
  Polytope core_;                      // Q, relative to the centre
  std::vector<double> planeOffset_;    // of each core face, relative to the centre
};

// Volume and area of a closed triangulated surface, and its outer parallel volume at distance t
// (Steiner's formula on the mesh: V + t A + t^2/2 sum L psi + 4/3 pi t^3, psi the signed exterior
// dihedral angle of each edge).
struct MeshMeasure {
  double volume = 0, area = 0, parallel = 0;
};
MeshMeasure meshMeasure(const std::vector<Vec3> &x, const std::vector<Tri> &tri,
                        const std::vector<Edge> &edges, double t);

// Maps the unit sphere mesh radially from the centre onto the wall surface, then relaxes it
// `iterations` times (tension-only springs of the mean edge length along the mesh edges, each point
// projected back radially); points of a triangle a step would fold keep their old positions.
std::vector<Vec3> wallOnCell(const Surface &unit, const RoundedCell &cell, int iterations);

// Fluid lattice points (spacing dx, centred on the cell's centre) at least `gap` inside the wall
// mesh (exact distance to its triangles; the mesh is star-shaped from the centre).
std::vector<Vec3> fluidInWall(const RoundedCell &cell, const std::vector<Vec3> &wall,
                              const std::vector<Tri> &tri, double dx, double gap);

// Area of the intersection of two convex polygons lying in the plane with normal n.
double overlapArea(const std::vector<Vec3> &a, const std::vector<Vec3> &b, const Vec3 &n);

}    // namespace cellgen
