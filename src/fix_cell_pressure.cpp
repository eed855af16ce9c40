/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   fix cell/pressure: a uniform pressure P inside closed walls, applied to the wall triangles
   (stored as angles, outward oriented). The force on the vertices is P dV/dx, so the wall does
   work P dV exactly: the equilibrium of a wall under an imposed turgor.
------------------------------------------------------------------------- */

#include "fix_cell_pressure.h"

#include "atom.h"
#include "atom_vec.h"
#include "error.h"
#include "force.h"
#include "input.h"
#include "neighbor.h"
#include "update.h"
#include "variable.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

/* ---------------------------------------------------------------------- */

FixCellPressure::FixCellPressure(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), pressure(0.0), angle_type(1), work_local(0.0)
{
  if (narg != 4 && narg != 6)
    error->all(FLERR,
               "Illegal fix cell/pressure command: expected 'fix ID group cell/pressure "
               "<P or v_name> [angletype N]'");
  if (!atom->molecular || !atom->avec->angles_allow)
    error->all(FLERR,
               "Fix cell/pressure needs wall triangles stored as angles (atom_style angle, "
               "molecular or full)");
  source = CellQuantity::parse(lmp, arg[3], "Fix cell/pressure: P");
  pressure = source.value;
  if (narg == 6) {
    if (strcmp(arg[4], "angletype") != 0)
      error->all(FLERR, "Fix cell/pressure: unknown keyword '{}' (expected angletype)", arg[4]);
    angle_type = utils::inumeric(FLERR, arg[5], false, lmp);
    if (angle_type < 1 || angle_type > atom->nangletypes)
      error->all(FLERR, "Fix cell/pressure: angletype {} is not in 1..{}", angle_type,
                 atom->nangletypes);
  }
  scalar_flag = 1;
  global_freq = 1;
  extscalar = 1;
  energy_global_flag = 1;
  virial_global_flag = 1;    // the load's virial enters compute pressure and the barostats
  thermo_virial = 1;
}

/* ---------------------------------------------------------------------- */

int FixCellPressure::setmask()
{
  return PRE_REVERSE | MIN_PRE_REVERSE;
}

/* ---------------------------------------------------------------------- */

void FixCellPressure::init()
{
  source.resolve(lmp, "Fix cell/pressure: variable");
}

/* ---------------------------------------------------------------------- */

void FixCellPressure::setup_pre_reverse(int eflag, int vflag)
{
  pre_reverse(eflag, vflag);
}

/* ---------------------------------------------------------------------- */

void FixCellPressure::min_pre_reverse(int eflag, int vflag)
{
  pre_reverse(eflag, vflag);
}

/* ----------------------------------------------------------------------
   before forces on ghosts are summed into their owners: like a bond style, each triangle is
   listed once with newton_bond on (forces on ghosts are communicated) and on every rank that owns
   one of its atoms with newton_bond off (only owned atoms get forces)
------------------------------------------------------------------------- */

void FixCellPressure::pre_reverse(int, int vflag)
{
  if (source.is_variable()) pressure = source.get(lmp);
  v_init(vflag);

  double **x = atom->x;
  double **f = atom->f;
  int *mask = atom->mask;
  int **anglelist = neighbor->anglelist;
  const int nanglelist = neighbor->nanglelist;
  const int nlocal = atom->nlocal;
  const int newton_bond = force->newton_bond;
  const double p6 = pressure / 6.0;
  work_local = 0.0;

  for (int n = 0; n < nanglelist; n++) {
    if (anglelist[n][3] != angle_type) continue;
    const int i[3] = {anglelist[n][0], anglelist[n][1], anglelist[n][2]};
    if (!(mask[i[0]] & groupbit)) continue;
    const double *a = x[i[0]], *b = x[i[1]], *c = x[i[2]];
    const double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double ac[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    // (P/6)(x_b - x_a) x (x_c - x_a) = P (area vector of the triangle) / 3: dV/dx_k per vertex
    const double fn[3] = {p6 * (ab[1] * ac[2] - ab[2] * ac[1]),
                          p6 * (ab[2] * ac[0] - ab[0] * ac[2]),
                          p6 * (ab[0] * ac[1] - ab[1] * ac[0])};
    int owned = 0;
    for (int k = 0; k < 3; k++)
      if (newton_bond || i[k] < nlocal) {
        f[i[k]][0] += fn[0];
        f[i[k]][1] += fn[1];
        f[i[k]][2] += fn[2];
        owned++;
      }
    if (vflag_global) {
      // virial sum_k x_k F = (x_a + x_b + x_c) F, P V I over a closed wall (doc/model.md §4.5);
      // with newton_bond off each rank tallies the share of the vertices it owns (global only)
      const double share = owned / 3.0;
      const double s[3] = {share * (a[0] + b[0] + c[0]), share * (a[1] + b[1] + c[1]),
                           share * (a[2] + b[2] + c[2])};
      virial[0] += s[0] * fn[0];
      virial[1] += s[1] * fn[1];
      virial[2] += s[2] * fn[2];
      virial[3] += s[0] * fn[1];
      virial[4] += s[0] * fn[2];
      virial[5] += s[1] * fn[2];
    }
    // P V, V = (1/6) sum x_a . (x_b x x_c): divergence theorem over the closed wall
    if (newton_bond || i[0] < nlocal)
      work_local += p6 *
          (a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
           a[2] * (b[0] * c[1] - b[1] * c[0]));
  }
}

/* ----------------------------------------------------------------------
   potential energy of the load, -P V (enters pe with fix_modify energy yes)
------------------------------------------------------------------------- */

double FixCellPressure::compute_scalar()
{
  double work = 0.0;
  MPI_Allreduce(&work_local, &work, 1, MPI_DOUBLE, MPI_SUM, world);
  return -work;
}
