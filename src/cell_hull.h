/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   area and volume of the convex hull of 3-D points, by Qhull (Debian libqhull-dev, reentrant
   libqhull_r): the wrinkling measure of compute cell/shape (doc/compute_cell_shape.md). Apart from
   the styles so that Qhull's macros (True, False, ...) never meet LAMMPS headers.
------------------------------------------------------------------------- */

#ifndef LMP_CELL_HULL_H
#define LMP_CELL_HULL_H

#include <string>
#include <vector>

namespace CellHull {

// points: x y z triples (at least 4, not all in one plane). Returns an empty string and sets area
// and volume, or Qhull's exit code as a message.
std::string area_volume(std::vector<double> points, double &area, double &volume);

}    // namespace CellHull

#endif
