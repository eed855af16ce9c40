/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   BondCellBase: per-bond reference state for bonds that do not exist in the reference geometry
   (cell-cell junctions), kept by an internal fix cell/bond/history (doc/model.md §4.6)
------------------------------------------------------------------------- */

#include "bond_cell_base.h"

#include "atom.h"
#include "error.h"
#include "fix_cell_bond_history.h"
#include "modify.h"
#include "neighbor.h"

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

BondCellBase::BondCellBase(LAMMPS *lmp, const std::string &style, const std::string &id, int n) :
    Bond(lmp), name(style), history_id(id), ndata(n), history(nullptr)
{
}

/* ----------------------------------------------------------------------
   the fix goes with the style; during 'clear' the plugin may have removed it already
------------------------------------------------------------------------- */

BondCellBase::~BondCellBase()
{
  if (modify && modify->find_fix(history_id) >= 0) modify->delete_fix(history_id);
}

/* ----------------------------------------------------------------------
   find or create the history fix, from coeff() and init_style(). Created after read_restart (at
   bond_coeff, or at init before the fixes are initialised), a fix with the ID and style of one in
   the restart file gets its per-atom values back.
------------------------------------------------------------------------- */

void BondCellBase::init_history()
{
  int ifix = modify->find_fix(history_id);
  if (ifix < 0) {
    modify->add_fix(fmt::format("{} all cell/bond/history {}", history_id, ndata));
    ifix = modify->find_fix(history_id);
  }
  history = dynamic_cast<FixCellBondHistory *>(modify->fix[ifix]);
  if (!history || history->ndata != ndata)
    error->all(FLERR,
               "Bond style {}: fix {} must be a fix cell/bond/history with {} values per bond",
               name, history_id, ndata);
}

/* ---------------------------------------------------------------------- */

double *BondCellBase::reference(int i, int j, int type)
{
  for (int e = 0; e < 2; e++) {
    const int a = e ? j : i, b = e ? i : j;
    if (a >= atom->nlocal) continue;    // ghosts carry no reference state
    const int m = history->slot(a, atom->tag[b], type);
    if (m >= 0) return &history->value(a, m, 0);
  }
  return nullptr;
}

/* ----------------------------------------------------------------------
   two local copies with newton_bond off; a copy on another rank gets the same values there
------------------------------------------------------------------------- */

void BondCellBase::set_reference(int i1, int i2, int type, const double *fresh)
{
  for (int e = 0; e < 2; e++) {
    const int i = e ? i2 : i1, j = e ? i1 : i2;
    if (i >= atom->nlocal) continue;
    const int m = history->slot(i, atom->tag[j], type);
    if (m < 0) continue;
    for (int k = 0; k < ndata; k++) history->value(i, m, k) = fresh[k];
  }
}

/* ----------------------------------------------------------------------
   break bond n of the bond list for good: type 0 on every local copy and in the list. Its
   reference values stay in their slot. With newton_bond off the rank holding the other atom
   breaks its copy by the same test on the same coordinates.
------------------------------------------------------------------------- */

void BondCellBase::break_bond(int n, int i1, int i2, int type)
{
  for (int e = 0; e < 2; e++) {
    const int i = e ? i2 : i1, j = e ? i1 : i2;
    if (i >= atom->nlocal) continue;
    const int m = history->slot(i, atom->tag[j], type);
    if (m >= 0) atom->bond_type[i][m] = 0;
  }
  neighbor->bondlist[n][2] = 0;
}
