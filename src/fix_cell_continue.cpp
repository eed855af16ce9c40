/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   fix cell/continue: the velocities of the last step's forces at a run's setup that continues it
   (fix_cell_continue.h)
------------------------------------------------------------------------- */

#include "fix_cell_continue.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "modify.h"
#include "update.h"

#include <utility>

using namespace LAMMPS_NS;
using namespace FixConst;

// the fix's ID, and that of the fix property/atom of its per-atom fields
static const char *ID = "cellsph_continue";
static const char *FIELDS = "cellsph_last";
static const char *XFORCE = "xforce";    // x at the last force evaluation
static const char *VFORCE = "vforce";    // v at the last force evaluation (the half step)
static const char *VEND = "vend";        // v at the end of the last step

/* ---------------------------------------------------------------------- */

FixCellContinue::FixCellContinue(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), ixforce(-1), ivforce(-1), ivend(-1), swapped(0)
{
  if (narg != 3) error->all(FLERR, "Fix cell/continue: no arguments (it is made by pair cell/sph)");
}

/* ---------------------------------------------------------------------- */

int FixCellContinue::setmask()
{
  return PRE_FORCE | POST_FORCE | END_OF_STEP;
}

/* ---------------------------------------------------------------------- */

void FixCellContinue::ensure(LAMMPS *lmp)
{
  Modify *modify = lmp->modify;
  if (modify->find_fix(FIELDS) < 0)
    modify->add_fix(
        fmt::format("{} all property/atom d2_{} 3 d2_{} 3 d2_{} 3", FIELDS, XFORCE, VFORCE, VEND));
  if (modify->find_fix(ID) < 0) modify->add_fix(fmt::format("{} all cell/continue", ID));
  // internal: no section in data files (an input reading them does not define the fix)
  lmp->modify->fix[modify->find_fix(FIELDS)]->wd_section = 0;
}

/* ---------------------------------------------------------------------- */

bool FixCellContinue::setup_continues(LAMMPS *lmp)
{
  const int ifix = lmp->modify->find_fix(ID);
  const auto *fix = ifix < 0 ? nullptr : dynamic_cast<FixCellContinue *>(lmp->modify->fix[ifix]);
  return fix && fix->swapped;
}

/* ---------------------------------------------------------------------- */

void FixCellContinue::init()
{
  int flag, cols;
  int *index[3] = {&ixforce, &ivforce, &ivend};
  const char *names[3] = {XFORCE, VFORCE, VEND};
  for (int k = 0; k < 3; k++) {
    *index[k] = atom->find_custom(names[k], flag, cols);
    if (*index[k] < 0 || flag != 1 || cols != 3)
      error->all(FLERR, "Fix cell/continue: needs the per-atom array {} (3 values) of fix {}",
                 names[k], FIELDS);
  }
}

/* ----------------------------------------------------------------------
   true on every rank if every atom is where the last force evaluation saw it and as fast as
   the last step left it: a run's setup continuing the last step (no command between changed
   positions or velocities)
------------------------------------------------------------------------- */

bool FixCellContinue::continues() const
{
  double **x = atom->x, **v = atom->v;
  double **xforce = atom->darray[ixforce], **vend = atom->darray[ivend];
  int same = 1, all = 0;
  for (int i = 0; i < atom->nlocal && same; i++)
    for (int d = 0; d < 3; d++) same = same && x[i][d] == xforce[i][d] && v[i][d] == vend[i][d];
  MPI_Allreduce(&same, &all, 1, MPI_INT, MPI_MIN, world);
  return all == 1 && atom->natoms > 0;
}

/* ----------------------------------------------------------------------
   a run's setup that continues the last step: its forces with the velocities the last step's
   forces saw (each atom's v and the stored vforce exchanged, ghost atoms' v sent again)
------------------------------------------------------------------------- */

void FixCellContinue::setup_pre_force(int /*vflag*/)
{
  swapped = update->whichflag == 1 && continues();
  if (swapped) exchange_velocities();
}

/* ----------------------------------------------------------------------
   after the setup's forces (the fixes defined before this one have added theirs): the step-end
   velocities back
------------------------------------------------------------------------- */

void FixCellContinue::setup(int /*vflag*/)
{
  if (swapped) exchange_velocities();
  swapped = 0;
}

/* ---------------------------------------------------------------------- */

void FixCellContinue::exchange_velocities()
{
  double **v = atom->v, **vforce = atom->darray[ivforce];
  for (int i = 0; i < atom->nlocal; i++)
    for (int d = 0; d < 3; d++) std::swap(v[i][d], vforce[i][d]);
  if (comm->ghost_velocity) comm->forward_comm();
}

/* ----------------------------------------------------------------------
   each step: x and v that its forces saw, and v at its end
------------------------------------------------------------------------- */

void FixCellContinue::post_force(int /*vflag*/)
{
  double **x = atom->x, **v = atom->v;
  double **xforce = atom->darray[ixforce], **vforce = atom->darray[ivforce];
  for (int i = 0; i < atom->nlocal; i++)
    for (int d = 0; d < 3; d++) {
      xforce[i][d] = x[i][d];
      vforce[i][d] = v[i][d];
    }
}

void FixCellContinue::end_of_step()
{
  double **v = atom->v, **vend = atom->darray[ivend];
  for (int i = 0; i < atom->nlocal; i++)
    for (int d = 0; d < 3; d++) vend[i][d] = v[i][d];
}
