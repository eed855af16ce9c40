/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   What the cellsph bond styles share: the damping along the bond (doc/model.md §4.3), the pair of
   equal and opposite forces, and the ghost-velocity requirement of damping.
------------------------------------------------------------------------- */

#ifndef LMP_CELL_BOND_H
#define LMP_CELL_BOND_H

#include "comm.h"
#include "error.h"
#include "lammps.h"

namespace LAMMPS_NS {
namespace CellBond {

  // F^d = -gamma ((v1 - v2) . e) e, as a term of fbond (force on atom 1 = fbond (x1 - x2)): damps
  // stretching, not rigid motion (doc/model.md §4.3)
  inline double damping(const double *v1, const double *v2, double delx, double dely, double delz,
                        double r, double gamma)
  {
    const double vr = (v1[0] - v2[0]) * delx + (v1[1] - v2[1]) * dely + (v1[2] - v2[2]) * delz;
    return -gamma * vr / (r * r);
  }

  // fbond (x1 - x2) on atom 1 and its opposite on atom 2, on the copies this rank owns the force of
  inline void apply(double **f, int i1, int i2, int nlocal, int newton_bond, double fbond,
                    double delx, double dely, double delz)
  {
    if (newton_bond || i1 < nlocal) {
      f[i1][0] += delx * fbond;
      f[i1][1] += dely * fbond;
      f[i1][2] += delz * fbond;
    }
    if (newton_bond || i2 < nlocal) {
      f[i2][0] -= delx * fbond;
      f[i2][1] -= dely * fbond;
      f[i2][2] -= delz * fbond;
    }
  }

  // damping of any bond type (gamma[1..ntypes] > 0) needs the ghosts' velocities
  inline void require_ghost_velocity(LAMMPS *lmp, const char *style, const double *gamma,
                                     int ntypes)
  {
    for (int i = 1; i <= ntypes; i++)
      if (gamma[i] > 0.0 && !lmp->comm->ghost_velocity)
        lmp->error->all(FLERR,
                        "Bond style {} with damping gamma = {} (bond type {}) needs ghost "
                        "velocities: use 'comm_modify vel yes'",
                        style, gamma[i], i);
  }

}    // namespace CellBond
}    // namespace LAMMPS_NS

#endif
