/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   Reading a style's keywords, shared by the style and the helper classes that take some of them
   (fix cell/turgor: TurgorDrive, TurgorOsmotic): the values after a keyword
------------------------------------------------------------------------- */

#ifndef LMP_CELL_ARGS_H
#define LMP_CELL_ARGS_H

#include "error.h"

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
}    // namespace CellArgs
}    // namespace LAMMPS_NS

#endif
