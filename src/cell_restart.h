/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   format versions of the package's restart payloads: since version 2 a payload begins with
   -version; files written before versions (version 1) begin with a value >= 0 of the payload
------------------------------------------------------------------------- */

#ifndef LMP_CELL_RESTART_H
#define LMP_CELL_RESTART_H

#include "error.h"

#include <cmath>
#include <string>

namespace CellRestart {

// the format version of a payload whose first value is first
inline int version(double first)
{
  return first < 0.0 ? static_cast<int>(lround(-first)) : 1;
}

// stop (on all ranks) when the file was written by a newer plugin than this one
inline void refuse_newer(LAMMPS_NS::Error *error, const std::string &file, int line,
                         const std::string &style, int version, int current)
{
  if (version > current)
    error->all(file, line,
               "{}: the restart file has format version {}, newer than this plugin's {}: use a "
               "newer cellsph",
               style, version, current);
}

}    // namespace CellRestart

#endif
