/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
------------------------------------------------------------------------- */

#include "cell_hull.h"

#include <libqhull_r/qhull_ra.h>

#include <cstdio>

namespace CellHull {

std::string area_volume(std::vector<double> points, double &area, double &volume)
{
  area = volume = 0.0;
  qhT context;
  qhT *qh = &context;
  char options[] = "qhull";    // default precision handling: merged facets, area unchanged
  qh_zero(qh, stderr);
  const int exitcode =
      qh_new_qhull(qh, 3, (int) points.size() / 3, points.data(), False, options, nullptr, stderr);
  if (exitcode == 0) {
    // total facet area and enclosed volume (Qhull option FA)
    qh_getarea(qh, qh->facet_list);
    area = qh->totarea;
    volume = qh->totvol;
  }
  qh_freeqhull(qh, !qh_ALL);
  int curlong, totlong;
  qh_memfreeshort(qh, &curlong, &totlong);
  return exitcode == 0 ? std::string() : "Qhull exit code " + std::to_string(exitcode);
}

}    // namespace CellHull
