/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   command cell/atoms (cell_atoms.h): defines fix cellatoms, a fix property/atom with rmass, xref
   (3 values) and aref, sent to ghost atoms, unless a fix of that ID with these fields exists
   (doc/cell_atoms.md). A fix property/atom may be defined before read_data; a plugin fix style
   may not, which is why this is a command.
------------------------------------------------------------------------- */

#include "cell_atoms.h"

#include "atom.h"
#include "cell_styles.h"
#include "error.h"
#include "modify.h"

using namespace LAMMPS_NS;

const char *CellAtoms::ID = "cellatoms";
const char *CellAtoms::FIELDS = "rmass d2_xref 3 d_aref ghost yes";

/* ---------------------------------------------------------------------- */

void CellAtoms::command(int narg, char ** /*arg*/)
{
  if (narg != 0) error->all(FLERR, "cell/atoms: takes no arguments, got {}", narg);
  if (modify->find_fix(ID) < 0) {
    modify->add_fix(fmt::format("{} all property/atom {}", ID, FIELDS));
    return;
  }
  // an input that declared the fix itself (fix cellatoms all property/atom ...) keeps it
  int flag, cols, aflag, acols;
  const int ixref = atom->find_custom(CellField::XREF, flag, cols);
  const int iaref = atom->find_custom(CellField::AREF, aflag, acols);
  if (!atom->rmass_flag || ixref < 0 || flag != 1 || cols != 3 || iaref < 0 || aflag != 1 ||
      acols != 0)
    error->all(FLERR,
               "cell/atoms: fix {} exists without the fields rmass, d2_xref 3 and d_aref: "
               "delete it (unfix {}) or give cellsph's fields another fix ID",
               ID, ID);
}
