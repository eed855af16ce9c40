/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   command cell/atoms: declares the per-atom fields that a cellsph data file carries (each atom's
   mass, a wall atom's reference position and reference area) under the names of cell_styles.h
------------------------------------------------------------------------- */

#ifdef COMMAND_CLASS
// clang-format off
CommandStyle(cell/atoms,CellAtoms);
// clang-format on
#else

#ifndef LMP_CELL_ATOMS_H
#define LMP_CELL_ATOMS_H

#include "command.h"

namespace LAMMPS_NS {

class CellAtoms : public Command {
 public:
  CellAtoms(class LAMMPS *lmp) : Command(lmp) {}
  void command(int, char **) override;
  static const char *ID;        // the ID of the fix property/atom it defines
  static const char *FIELDS;    // its fields, as fix property/atom arguments
};

}    // namespace LAMMPS_NS

#endif
#endif
