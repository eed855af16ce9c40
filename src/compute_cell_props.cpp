/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   compute cell/props: per-cell state from the shared per-cell sums (cell_reduce.h), one row per
   cell in ascending cell ID, usable as c_ID[i][j] in thermo and by fix ave/time mode vector.
------------------------------------------------------------------------- */

#include "compute_cell_props.h"

#include "cell_reduce.h"
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

/* ---------------------------------------------------------------------- */

ComputeCellProps::ComputeCellProps(LAMMPS *lmp, int narg, char **arg) : Compute(lmp, narg, arg)
{
  int fluidtype = 1, walltype = 2;
  std::string measure = "wall";
  for (int iarg = 3; iarg < narg; iarg += 2) {
    if (iarg + 1 >= narg)
      error->all(FLERR, "Compute cell/props: missing value after '{}'", arg[iarg]);
    if (strcmp(arg[iarg], "fluid") == 0)
      fluidtype = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
    else if (strcmp(arg[iarg], "wall") == 0)
      walltype = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
    else if (strcmp(arg[iarg], "turgor") == 0)
      measure = arg[iarg + 1];
    else
      error->all(FLERR, "Compute cell/props: unknown keyword '{}' (expected fluid, wall or turgor)",
                 arg[iarg]);
  }
  cells = std::make_unique<CellReduce>(lmp, "Compute cell/props", igroup, fluidtype, walltype);
  cells->set_turgor(measure);
  cells->find_cells();

  array_flag = 1;
  size_array_rows = cells->ncell();
  size_array_cols = NCOLUMN;
  extarray = 0;
  memory->create(array, size_array_rows, size_array_cols, "cell/props:array");
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
  turgor.clear();
  for (int i = 0; i < modify->nfix; i++)
    if (strcmp(modify->fix[i]->style, "cell/turgor") == 0)
      turgor.push_back(dynamic_cast<FixCellTurgor *>(modify->fix[i]));
}

/* ---------------------------------------------------------------------- */

void ComputeCellProps::compute_array()
{
  invoked_array = update->ntimestep;
  cells->reduce();

  for (int c = 0; c < size_array_rows; c++) {
    double *row = array[c];
    row[ID] = cells->id(c);
    row[MASS] = cells->mass(c);
    row[VOLUME] = cells->volume(c);
    row[AREA] = cells->area(c);
    // P_T and pi from the first fix cell/turgor acting on the cell, else this compute's measure and 0
    row[TURGOR] = cells->turgor(c);
    row[OSMOTIC] = 0.0;
    for (auto *fix : turgor)
      if (fix->osmotic(cells->id(c), row[MASS], row[OSMOTIC])) {
        fix->turgor(cells->id(c), row[TURGOR]);
        break;
      }
    // psi_cell = P_T - pi
    row[PSI] = row[TURGOR] - row[OSMOTIC];
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
  }
}
