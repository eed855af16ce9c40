/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   compute cell/shape: per cell, the section through its centre by a plane and that section's
   shape descriptors as image analysis (ImageJ) defines them, and the wall's wrinkling, wall area
   over the area of its convex hull. Each cell's wall triangles go to its home rank only
   (CellReduce::home_triangles), which measures the cell; every rank then gathers the rows
   (CellRegistry::allgather, O(cells)).
------------------------------------------------------------------------- */

#include "compute_cell_shape.h"

#include "cell_compat.h"
#include "cell_hull.h"
#include "cell_reduce.h"
#include "cell_section.h"
#include "error.h"
#include "math_const.h"
#include "memory.h"
#include "update.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using MathConst::MY_PI;

// principal lengths closer than this fraction of the largest count as equal (plane principal)
static constexpr double DEGENERATE = 1e-9;

namespace {

// the section plane through the principal axes of a volume with central second moments central:
// normal along the shortest axis, e1 along the longest; where the two shortest are equal to
// round-off (a spheroid, a sphere) the normal is the part of the z axis (y if z lies along e1)
// normal to e1, so that every rank and run picks the same plane
void principal_plane(const Eigen::Matrix3d &central, Eigen::Vector3d &n, Eigen::Vector3d &e1,
                     Eigen::Vector3d &e2)
{
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(central);
  const Eigen::Vector3d &lambda = eig.eigenvalues();
  e1 = eig.eigenvectors().col(2);
  if (lambda[1] - lambda[0] > DEGENERATE * lambda[2])
    n = eig.eigenvectors().col(0);
  else {
    if (lambda[2] - lambda[0] <= DEGENERATE * lambda[2]) e1 = Eigen::Vector3d::UnitX();
    const Eigen::Vector3d axis =
        std::abs(e1[2]) < 0.9 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitY();
    n = (axis - axis.dot(e1) * e1).normalized();
  }
  int big = 0;
  n.cwiseAbs().maxCoeff(&big);
  if (n[big] < 0.0) n = -n;
  e2 = n.cross(e1);
}

}    // namespace

/* ---------------------------------------------------------------------- */

ComputeCellShape::ComputeCellShape(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), plane(PLANE_Z), offset(0.0), held{}
{
  int walltype = 2;
  for (int iarg = 3; iarg < narg; iarg += 2) {
    if (iarg + 1 >= narg)
      error->all(FLERR, "Compute cell/shape: missing value after '{}'", arg[iarg]);
    const std::string value = arg[iarg + 1];
    if (strcmp(arg[iarg], "plane") == 0) {
      if (value == "x")
        plane = PLANE_X;
      else if (value == "y")
        plane = PLANE_Y;
      else if (value == "z")
        plane = PLANE_Z;
      else if (value == "principal")
        plane = PLANE_PRINCIPAL;
      else if (value == "normal") {
        if (iarg + 4 >= narg)
          error->all(FLERR, "Compute cell/shape: plane normal needs three components nx ny nz");
        plane = PLANE_NORMAL;
        for (int d = 0; d < 3; d++)
          normal[d] = utils::numeric(FLERR, arg[iarg + 2 + d], false, lmp);
        const double len =
            sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
        if (!(len > 0.0) || !std::isfinite(len))
          error->all(FLERR, "Compute cell/shape: plane normal {} {} {} has no direction",
                     arg[iarg + 2], arg[iarg + 3], arg[iarg + 4]);
        for (double &c : normal) c /= len;
        iarg += 3;
      } else
        error->all(FLERR,
                   "Compute cell/shape: plane = {} is not a section plane (expected x, y, z, "
                   "principal or normal nx ny nz)",
                   value);
    } else if (strcmp(arg[iarg], "offset") == 0)
      offset = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
    else if (strcmp(arg[iarg], "wall") == 0)
      walltype = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
    else if (strcmp(arg[iarg], "held") == 0) {
      held_flag = CellCompat::logical(arg[iarg + 1]);
      if (held_flag < 0)
        error->all(FLERR, "Compute cell/shape: held = {} (expected yes or no)", value);
    } else
      error->all(FLERR,
                 "Compute cell/shape: unknown keyword '{}' (expected plane, offset, wall or held)",
                 arg[iarg]);
  }
  cells = std::make_unique<CellReduce>(lmp, "Compute cell/shape", igroup, 0, walltype, false);
  cells->find_cells();

  array_flag = 1;
  size_array_rows = cells->ncell();
  size_array_cols = NCOLUMN;
  extarray = 0;
  memory->create(array, size_array_rows, size_array_cols, "cell/shape:array");
  // with held yes: the wall triangles held at the last evaluation (doc/compute_cell_shape.md);
  // off by default, since a global vector beside the array changes what c_ID[j] means in a
  // vector-style variable in 29 Sep 2021 (the vector's element) but not in later releases
  vector_flag = held_flag;
  size_vector = 3;
  extvector = 0;
  vector = held;
}

/* ---------------------------------------------------------------------- */

ComputeCellShape::~ComputeCellShape()
{
  memory->destroy(array);
}

/* ---------------------------------------------------------------------- */

void ComputeCellShape::init()
{
  cells->find_cells();
  if (cells->ncell() != size_array_rows)
    error->all(FLERR,
               "Compute cell/shape: the number of cells changed from {} to {}: define the compute "
               "again",
               size_array_rows, cells->ncell());
  cells->init();
}

/* ---------------------------------------------------------------------- */

void ComputeCellShape::compute_array()
{
  invoked_array = update->ntimestep;
  cells->reduce(nullptr, true);
  walls = &cells->home_triangles();

  const std::vector<int> &home = cells->home_cells();
  rows.assign(home.size() * NCOLUMN, 0.0);
  for (int h = 0; h < (int) home.size(); h++) {
    rows[(size_t) h * NCOLUMN + ID] = cells->id(home[h]);
    measure(h, &rows[(size_t) h * NCOLUMN]);
  }
  cells->registry().allgather(NCOLUMN, rows, all);
  std::copy(all.begin(), all.end(), &array[0][0]);

  for (int c = 0; c < size_array_rows; c++) {
    if (array[c][LOOPS] == -2.0)
      error->all(FLERR,
                 "Compute cell/shape: cell {} encloses no volume: its wall triangles are not a "
                 "closed, outward surface",
                 cells->id(c));
    if (array[c][LOOPS] < 0.0)
      error->all(FLERR,
                 "Compute cell/shape: the section of cell {} does not close: its wall triangles "
                 "are not a closed surface",
                 cells->id(c));
    if (array[c][HULLAREA] < 0.0)
      error->all(FLERR, "Compute cell/shape: Qhull found no convex hull of the wall of cell {}",
                 cells->id(c));
  }
}

/* ---------------------------------------------------------------------- */

void ComputeCellShape::compute_vector()
{
  invoked_vector = update->ntimestep;
  if (invoked_array != update->ntimestep) compute_array();
  cells->held_triangles(held);
}

/* ----------------------------------------------------------------------
   the row of home cell h (doc/compute_cell_shape.md); LOOPS -2 if the wall encloses no volume,
   LOOPS or HULLAREA -1 if the section or the hull failed
------------------------------------------------------------------------- */

void ComputeCellShape::measure(int h, double *row)
{
  const double *tri = walls->xyz(h);
  const tagint *ids = walls->ids(h);
  const int nt = walls->ntri(h);

  // volume, centroid and second moments of the enclosed volume from the tetrahedra (0, a, b, c):
  // V_t = a . (b x c) / 6, int x dV = V_t (a + b + c) / 4,
  // int x x^T dV = V_t / 20 (a a^T + b b^T + c c^T + s s^T), s = a + b + c (divergence theorem)
  double volume = 0.0, wallarea = 0.0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (int t = 0; t < nt; t++) {
    const Eigen::Vector3d a(tri + 9 * t), b(tri + 9 * t + 3), cc(tri + 9 * t + 6);
    const double v = a.dot(b.cross(cc)) / 6.0;
    const Eigen::Vector3d s = a + b + cc;
    volume += v;
    first += v * s / 4.0;
    second += v / 20.0 *
        (a * a.transpose() + b * b.transpose() + cc * cc.transpose() + s * s.transpose());
    // wall area A = 1/2 sum |(b - a) x (c - a)|
    wallarea += 0.5 * (b - a).cross(cc - a).norm();
  }
  if (!(volume > 0.0)) {
    row[LOOPS] = -2.0;
    return;
  }
  const Eigen::Vector3d centre = first / volume;

  // the plane: normal n, in-plane axes e1, e2 with e1 x e2 = n
  Eigen::Vector3d n, e1, e2;
  if (plane == PLANE_PRINCIPAL) {
    principal_plane(second - volume * centre * centre.transpose(), n, e1, e2);
  } else if (plane == PLANE_NORMAL) {
    // e1 along the part of the coordinate axis least aligned with n that is normal to n
    n = Eigen::Vector3d(normal[0], normal[1], normal[2]);
    int least = 0;
    n.cwiseAbs().minCoeff(&least);
    const Eigen::Vector3d axis = Eigen::Vector3d::Unit(least);
    e1 = (axis - axis.dot(n) * n).normalized();
    e2 = n.cross(e1);
  } else {
    const int k = plane - PLANE_X;
    n = Eigen::Vector3d::Unit(k);
    e1 = Eigen::Vector3d::Unit((k + 1) % 3);
    e2 = Eigen::Vector3d::Unit((k + 2) % 3);
  }
  const Eigen::Vector3d p = centre + offset * n;

  CellSection::Shape s;
  if (!CellSection::measure(tri, ids, nt, p.data(), n.data(), e1.data(), e2.data(), s)) {
    row[LOOPS] = -1.0;
    return;
  }
  row[AREA] = s.area;
  row[PERIMETER] = s.perimeter;
  row[FERET] = s.feret;
  row[MINFERET] = s.minferet;
  row[MAJOR] = s.major;
  row[MINOR] = s.minor;
  // ImageJ: Circ. = 4 pi A / P^2, Round = 4 A / (pi major^2), AR = major / minor,
  // Solidity = A / convex area; compactness sqrt(4 A / pi) / Feret (Russ)
  row[CIRCULARITY] = s.perimeter > 0.0 ? 4.0 * MY_PI * s.area / (s.perimeter * s.perimeter) : 0.0;
  row[ROUNDNESS] = s.major > 0.0 ? 4.0 * s.area / (MY_PI * s.major * s.major) : 0.0;
  row[ASPECT] = s.minor > 0.0 ? s.major / s.minor : 0.0;
  row[SOLIDITY] = s.convex_area > 0.0 ? s.area / s.convex_area : 0.0;
  row[COMPACTNESS] = s.feret > 0.0 ? sqrt(4.0 * s.area / MY_PI) / s.feret : 0.0;
  row[LOOPS] = s.loops;
  row[HULLPERIMETER] = s.convex_perimeter;

  // wrinkling: wall area over the area of the convex hull of the wall atoms (each once)
  std::vector<std::pair<tagint, int>> vertex(3 * (size_t) nt);
  for (int k = 0; k < 3 * nt; k++) vertex[k] = {ids[k], k};
  std::sort(vertex.begin(), vertex.end());
  vertex.erase(std::unique(vertex.begin(), vertex.end(),
                           [](const std::pair<tagint, int> &a, const std::pair<tagint, int> &b) {
                             return a.first == b.first;
                           }),
               vertex.end());
  std::vector<double> points;
  points.reserve(3 * vertex.size());
  for (const auto &v : vertex)
    points.insert(points.end(), tri + 3 * v.second, tri + 3 * v.second + 3);
  double hullarea, hullvolume;
  if (!CellHull::area_volume(points, hullarea, hullvolume).empty() || !(hullarea > 0.0)) {
    row[HULLAREA] = -1.0;
    return;
  }
  row[HULLAREA] = hullarea;
  row[WRINKLING] = wallarea / hullarea;
  row[HULLFILL] = volume / hullvolume;
}
