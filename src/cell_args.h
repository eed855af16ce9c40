/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   Reading a style's keywords, shared by the style and the helper classes that take some of them
   (fix cell/turgor: CellDrive, CellOsmotic): the values after a keyword, a number or v_name
------------------------------------------------------------------------- */

#ifndef LMP_CELL_ARGS_H
#define LMP_CELL_ARGS_H

#include "cell_quantity.h"
#include "error.h"
#include "utils.h"

#include <cstring>
#include <string>

namespace LAMMPS_NS {
namespace CellArgs {

  // the n values after the keyword arg[0] of the narg arguments arg, or stop naming the command
  inline char **values(Error *error, const std::string &command, int narg, char **arg, int n)
  {
    if (n >= narg)
      error->all(FLERR, "{}: missing value after '{}' (expected {})", command, arg[0], n);
    return &arg[1];
  }

  // a number or v_name; variables are looked up in init() (they may be defined after the command)
  inline CellQuantity quantity(LAMMPS *lmp, const char *arg)
  {
    if (strncmp(arg, "v_", 2) == 0) return CellQuantity{0.0, arg + 2, -1};
    return CellQuantity{utils::numeric(FLERR, arg, false, lmp), "", -1};
  }

}    // namespace CellArgs
}    // namespace LAMMPS_NS

#endif
