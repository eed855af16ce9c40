/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   compute cell/props: per-cell state from the shared per-cell sums (cell_reduce.h), one row per
   cell in ascending cell ID, usable as c_ID[i][j] in thermo and by fix ave/time mode vector. Each
   row is made on the cell's home rank (where fix cell/turgor keeps the cell's water), then every
   rank gathers all rows. The leak count runs there too: the cell's wall triangles and the
   positions of its fluid atoms owned elsewhere go to the home rank only.
------------------------------------------------------------------------- */

#include "compute_cell_props.h"

#include "atom.h"
#include "cell_compat.h"
#include "cell_reduce.h"
#include "cell_styles.h"
#include "cell_water.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_cell_turgor.h"
#include "math_const.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using MathConst::MY_PI;

// winding number of the closed surface of ntri triangles (9 numbers each: corners a b c, outward)
// about p: sum of the solid angles / 4 pi, tan(Omega/2) = a.(b x c) / (|a||b||c| + (a.b)|c| +
// (a.c)|b| + (b.c)|a|) with corners relative to p (Van Oosterom & Strackee 1983); 1 inside, 0 out
static double winding_number(const double *tri, int ntri, const double *p)
{
  double sum = 0.0;
  for (int t = 0; t < ntri; t++, tri += 9) {
    const double ax = tri[0] - p[0], ay = tri[1] - p[1], az = tri[2] - p[2];
    const double bx = tri[3] - p[0], by = tri[4] - p[1], bz = tri[5] - p[2];
    const double cx = tri[6] - p[0], cy = tri[7] - p[1], cz = tri[8] - p[2];
    const double la = sqrt(ax * ax + ay * ay + az * az);
    const double lb = sqrt(bx * bx + by * by + bz * bz);
    const double lc = sqrt(cx * cx + cy * cy + cz * cz);
    const double num =
        ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx);
    const double den = la * lb * lc + (ax * bx + ay * by + az * bz) * lc +
        (ax * cx + ay * cy + az * cz) * lb + (bx * cx + by * cy + bz * cz) * la;
    sum += atan2(num, den);
  }
  // Omega = 2 atan2(num, den); w = sum Omega / 4 pi
  return sum / (2.0 * MY_PI);
}

// the same winding number by the triangles that the ray from p along +z crosses: w = sum of
// sign(n_z) over them (doc/compute_cell_props.md, leak count). A ray within round-off of an edge or
// a vertex, or p within round-off of a triangle it crosses, has no clean count: then the solid
// angles decide
static double ray_winding_number(const double *tri, int ntri, const double *p)
{
  static const double TINY = 1e-9;
  int w = 0;
  const double *t = tri;
  for (int k = 0; k < ntri; k++, t += 9) {
    const double ax = t[0] - p[0], ay = t[1] - p[1];
    const double bx = t[3] - p[0], by = t[4] - p[1];
    const double cx = t[6] - p[0], cy = t[7] - p[1];
    if ((ax > 0.0 && bx > 0.0 && cx > 0.0) || (ax < 0.0 && bx < 0.0 && cx < 0.0) ||
        (ay > 0.0 && by > 0.0 && cy > 0.0) || (ay < 0.0 && by < 0.0 && cy < 0.0))
      continue;
    // edge functions of the projection on z = 0 about the ray: twice the areas of p b c, p c a,
    // p a b, whose sum is twice the projected area, signed as n_z
    const double ea = bx * cy - by * cx, eb = cx * ay - cy * ax, ec = ax * by - ay * bx;
    const double area = ea + eb + ec;
    const double tol = TINY * (fabs(ea) + fabs(eb) + fabs(ec));
    if (fabs(ea) <= tol || fabs(eb) <= tol || fabs(ec) <= tol) {
      if (fabs(area) <= tol) continue;    // a triangle seen edge-on from the ray: not crossed
      return winding_number(tri, ntri, p);
    }
    if ((ea > 0.0) != (area > 0.0) || (eb > 0.0) != (area > 0.0) || (ec > 0.0) != (area > 0.0))
      continue;
    // height of the crossing above p: barycentric (ea, eb, ec) / area of the corners' z
    const double az = t[2] - p[2], bz = t[5] - p[2], cz = t[8] - p[2];
    const double z = (ea * az + eb * bz + ec * cz) / area;
    if (fabs(z) <= TINY * (fabs(az) + fabs(bz) + fabs(cz))) return winding_number(tri, ntri, p);
    if (z > 0.0) w += area > 0.0 ? 1 : -1;
  }
  return w;
}

/* ---------------------------------------------------------------------- */

ComputeCellProps::ComputeCellProps(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), held{}, homes_checked(false)
{
  int walltype = 2;
  fluidtype = 1;
  for (int iarg = 3; iarg < narg; iarg += 2) {
    if (iarg + 1 >= narg)
      error->all(FLERR, "Compute cell/props: missing value after '{}'", arg[iarg]);
    if (strcmp(arg[iarg], "fluid") == 0)
      fluidtype = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
    else if (strcmp(arg[iarg], "wall") == 0)
      walltype = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
    else if (strcmp(arg[iarg], "turgor") == 0)
      error->all(FLERR,
                 "Compute cell/props: keyword 'turgor {}' was removed: column 5 follows the "
                 "wall-fluid model (the mean SPH pressure under the wall boundary of pair "
                 "cell/sph, the wall load under pair cell/wall's wall-fluid terms); columns 14 and "
                 "15 give the mean SPH pressure and the wall load",
                 arg[iarg + 1]);
    else if (strcmp(arg[iarg], "held") == 0) {
      held_flag = CellCompat::logical(arg[iarg + 1]);
      if (held_flag < 0)
        error->all(FLERR, "Compute cell/props: held = {} (expected yes or no)", arg[iarg + 1]);
    } else
      error->all(FLERR, "Compute cell/props: unknown keyword '{}' (expected fluid, wall or held)",
                 arg[iarg]);
  }
  cells = std::make_unique<CellReduce>(lmp, "Compute cell/props", igroup, fluidtype, walltype);
  cells->find_cells();

  array_flag = 1;
  size_array_rows = cells->ncell();
  size_array_cols = NCOLUMN;
  extarray = 0;
  memory->create(array, size_array_rows, size_array_cols, "cell/props:array");
  // with held yes: the wall triangles held at the last evaluation (doc/compute_cell_props.md);
  // off by default, since a global vector beside the array changes what c_ID[j] means in a
  // vector-style variable in 29 Sep 2021 (the vector's element) but not in later releases
  vector_flag = held_flag;
  size_vector = 3;
  extvector = 0;
  vector = held;
}

/* ---------------------------------------------------------------------- */

ComputeCellProps::~ComputeCellProps()
{
  memory->destroy(array);
}

/* ---------------------------------------------------------------------- */

void ComputeCellProps::init()
{
  cells->find_cells();
  if (cells->ncell() != size_array_rows)
    error->all(FLERR,
               "Compute cell/props: the number of cells changed from {} to {}: define the compute "
               "again",
               size_array_rows, cells->ncell());
  cells->init();
  turgor = cell_fixes<FixCellTurgor>(modify);
  homes_checked = false;
}

/* ---------------------------------------------------------------------- */

void ComputeCellProps::compute_array()
{
  invoked_array = update->ntimestep;
  cells->reduce(nullptr, true);
  count_outside();
  if (!homes_checked) check_homes();

  const std::vector<int> &home = cells->home_cells();
  rows.assign(NCOLUMN * home.size(), 0.0);
  for (int h = 0; h < (int) home.size(); h++) {
    const int c = home[h];
    double *row = &rows[NCOLUMN * h];
    row[ID] = cells->id(c);
    row[MASS] = cells->mass(c);
    row[VOLUME] = cells->volume(c);
    row[AREA] = cells->area(c);
    // P_T of this step's state and pi from the first fix cell/turgor acting on the cell, else P_T
    // measured as the fix would (the wall load under pair cell/wall's particle model, no offset)
    // and pi = 0
    row[TURGOR] = cells->turgor(c);
    row[OSMOTIC] = 0.0;
    FixCellTurgor::Water water{0.0, 0.0, 0.0, 0.0, 0.0};
    for (auto *fix : turgor)
      if (fix->osmotic(cells->id(c), row[MASS], row[OSMOTIC])) {
        fix->turgor(cells->id(c), cells->sph_turgor(c), row[TURGOR]);
        fix->water(cells->id(c), row[MASS], water);
        break;
      }
    // psi_cell = P_T - pi
    row[PSI] = row[TURGOR] - row[OSMOTIC];
    row[MOISTURE] = water.moisture;
    row[MOISTURE_RELATIVE] = water.relative;
    // a_w = exp(psi V_w / (R T)) (Kelvin, doc/model.md §5.7); 0 without a fix cell/turgor
    row[ACTIVITY] =
        water.temperature > 0.0 ? CellWater::activity(row[PSI], water.temperature) : 0.0;
    row[PSI_SURFACE] = water.psi_surface;
    row[WATER_RATE] = water.rate;
    // D_eq = (6 V / pi)^(1/3)
    row[DIAMETER] = cbrt(6.0 * row[VOLUME] / MY_PI);

    // principal lengths: square roots of the gyration tensor's eigenvalues, largest first
    double s[6];
    cells->gyration(c, s);
    Eigen::Matrix3d gyr;
    gyr << s[0], s[3], s[4], s[3], s[1], s[5], s[4], s[5], s[2];
    const Eigen::Vector3d eig =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(gyr, Eigen::EigenvaluesOnly).eigenvalues();
    for (int k = 0; k < 3; k++) row[LENGTH1 + k] = sqrt(std::max(0.0, eig[2 - k]));
    row[ELONGATION] = row[LENGTH3] > 0.0 ? row[LENGTH1] / row[LENGTH3] : 0.0;
    row[FLUIDVOL] = cells->fluid_volume(c);
    row[SPHTURGOR] = cells->sph_turgor(c);
    row[WALLTURGOR] = cells->has_wall_load() ? cells->wall_turgor(c) : 0.0;
    row[OUTSIDE] = outside[h];
    // fluid-free volume between fluid and wall: V - sum m/rho
    row[GAPVOL] = row[VOLUME] - row[FLUIDVOL];
  }
  cells->registry().allgather(NCOLUMN, rows, all);
  std::copy(all.begin(), all.end(), &array[0][0]);
}

/* ---------------------------------------------------------------------- */

void ComputeCellProps::compute_vector()
{
  invoked_vector = update->ntimestep;
  if (invoked_array != update->ntimestep) compute_array();
  cells->held_triangles(held);
}

/* ----------------------------------------------------------------------
   a cell's row is made where the fixes cell/turgor keep its water: they must give it the same
   home rank (once per run, after the fixes' init)
------------------------------------------------------------------------- */

void ComputeCellProps::check_homes()
{
  tagint other = 0;
  for (auto *fix : turgor) {
    const CellRegistry &theirs = fix->registry();
    if (!theirs.has_homes()) continue;
    for (int c : cells->home_cells()) {
      const int k = theirs.index(cells->id(c));
      if (k >= 0 && theirs.home(k) != comm->me) other = cells->id(c);
    }
  }
  tagint any;
  MPI_Allreduce(&other, &any, 1, MPI_LMP_TAGINT, MPI_MAX, world);
  if (any > 0)
    error->all(FLERR,
               "Compute cell/props: cell {} has another home rank in a fix cell/turgor: give the "
               "compute and the fix groups that hold the same atoms of each cell",
               any);
  homes_checked = true;
}

/* ----------------------------------------------------------------------
   the number of each home cell's fluid atoms outside its wall: winding number < 1/2 about the atom
   (unwrapped as the wall triangles) of the cell's triangles, on the cell's home rank. The
   triangles go there (home_triangles) and so do the positions of the cell's fluid atoms owned by
   other ranks: 4 numbers per such atom against 10 per triangle to every rank touching the cell.
   Exact shortcuts: outside the ball around the corners' centroid o that holds every corner the
   winding number is 0; inside the ball around o that touches no triangle plane it is that of o.
------------------------------------------------------------------------- */

void ComputeCellProps::count_outside()
{
  walls = &cells->home_triangles();
  const CellRegistry &registry = cells->registry();
  const int nhome = (int) cells->home_cells().size();

  // per home cell: o, squared radius of the ball holding every corner, of the ball touching no
  // triangle plane, winding number at o
  centre.assign(6 * (size_t) nhome, 0.0);
  for (int h = 0; h < nhome; h++) {
    double *o = &centre[6 * h];
    const double *ct = walls->xyz(h);
    const int nt = walls->ntri(h);
    for (int k = 0; k < 9 * nt; k++) o[k % 3] += ct[k] / (3.0 * nt);
    double rout2 = 0.0, rin2 = INFINITY;
    for (int t = 0; t < nt; t++) {
      const double *a = ct + 9 * t, *b = a + 3, *cc = a + 6;
      for (const double *v : {a, b, cc}) {
        const double dx = v[0] - o[0], dy = v[1] - o[1], dz = v[2] - o[2];
        rout2 = std::max(rout2, dx * dx + dy * dy + dz * dz);
      }
      const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
      const double w[3] = {cc[0] - a[0], cc[1] - a[1], cc[2] - a[2]};
      const double nx = u[1] * w[2] - u[2] * w[1], ny = u[2] * w[0] - u[0] * w[2],
                   nz = u[0] * w[1] - u[1] * w[0];
      const double nn = nx * nx + ny * ny + nz * nz;
      // squared distance of o from the triangle's plane: (n . (a - o))^2 / |n|^2
      const double h2 = nx * (a[0] - o[0]) + ny * (a[1] - o[1]) + nz * (a[2] - o[2]);
      if (nn > 0.0) rin2 = std::min(rin2, h2 * h2 / nn);
    }
    o[3] = rout2;
    o[4] = rin2;
    o[5] = nt > 0 ? winding_number(ct, nt, o) : 0.0;
  }

  // fluid atoms of home cells are tested here, the others' positions (relative to the cell's
  // reference point, unwrapped) go to their cell's home
  outside.assign(nhome, 0.0);
  away.clear();
  const std::vector<int> &cellof = cells->cell_of_atom();
  double xu[3];
  for (int i = 0; i < atom->nlocal; i++) {
    const int c = cellof[i];
    if (c < 0 || atom->type[i] != fluidtype) continue;
    const double *ref = cells->reference(c);
    domain->unmap(atom->x[i], atom->image[i], xu);
    for (int d = 0; d < 3; d++) xu[d] -= ref[d];
    const int h = registry.home_slot(c);
    if (h >= 0)
      outside[h] += is_outside(h, xu) ? 1.0 : 0.0;
    else
      away.insert(away.end(), {(double) c, xu[0], xu[1], xu[2]});
  }
  registry.send_home(4, away, got);
  for (size_t r = 0; r < got.size(); r += 4) {
    const int h = registry.home_slot((int) got[r]);
    if (h < 0)
      error->one(FLERR, "Compute cell/props: rank {} got a fluid atom of another rank's cell",
                 comm->me);
    outside[h] += is_outside(h, &got[r + 1]) ? 1.0 : 0.0;
  }
}

/* ----------------------------------------------------------------------
   is x (relative to the reference point of home cell h) outside the cell's wall
------------------------------------------------------------------------- */

bool ComputeCellProps::is_outside(int h, const double *x) const
{
  const double *o = &centre[6 * h];
  const double dx = x[0] - o[0], dy = x[1] - o[1], dz = x[2] - o[2];
  const double r2 = dx * dx + dy * dy + dz * dz;
  double w = 0.0;
  if (r2 < o[4])
    w = o[5];
  else if (r2 <= o[3])
    w = ray_winding_number(walls->xyz(h), walls->ntri(h), x);
  return w < 0.5;
}
