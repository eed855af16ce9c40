/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   The contracts between cellsph's styles: the names of the per-atom fields they share, the wall
   load that the pair styles tally for the per-cell sums (cell_reduce.h), the wall's stretch that
   a fix hands the wall's bond style, and a typed search for a style among the defined fixes. A
   style that offers or uses one of these includes this header, not the other style's. The styles
   over the same cells find their shared registry and sums by CellSet::join (cell_set.h), through
   their CellReduce.
------------------------------------------------------------------------- */

#ifndef LMP_CELL_STYLES_H
#define LMP_CELL_STYLES_H

#include "fix.h"
#include "force.h"
#include "modify.h"
#include "pair.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

// per-atom fields (fix property/atom names without their d_/d2_ prefix)
namespace CellField {
  constexpr const char *XREF = "xref";            // a wall atom's reference position (3 values)
  constexpr const char *AREF = "aref";            // a wall atom's reference area
  constexpr const char *RHO = "rho";              // a fluid atom's SPH density
  constexpr const char *PRESSURE = "pressure";    // a fluid atom's SPH pressure
  constexpr const char *H = "h";                  // a fluid atom's smoothing length (adaptive h)
  constexpr const char *OMEGA = "omega";          // its grad-h correction
  constexpr const char *FIX = "cellsph";          // the fix property/atom holding rho to omega
  // the wall boundary's linearisation base of each atom (pair_cell_sph_boundary.cpp)
  constexpr const char *XBASE = "xbase";             // its position (3 values)
  constexpr const char *HBASE = "hbase";             // its h (1 on non-fluid atoms)
  constexpr const char *BASEFIX = "cellsph_base";    // the fix property/atom holding them
}    // namespace CellField

// a pair style that tallies the force of each cell's fluid on its wall atoms (doc/model.md §5.3)
class CellWallLoad {
 public:
  virtual ~CellWallLoad() = default;
  // start tallying the load of fluidtype on walltype on every force evaluation until the next
  // init; false if this style carries no wall load (pair cell/sph without a wall boundary,
  // pair cell/wall without wall-fluid terms)
  virtual bool request_wall_load(int fluidtype, int walltype, const std::string &who) = 0;
  // the load on each owned atom at the last evaluation, or nullptr
  virtual double **wall_load() const = 0;
};

// a fix that sets the stress-free in-plane stretch s of each cell's wall (its hygroexpansion,
// doc/model.md §5.15): bond cell/neohookean scales its rest lengths by s and its areas by s^2
class CellWallStretch {
 public:
  virtual ~CellWallStretch() = default;
  // s per owned and ghost atom at this step (1 outside the fix's cells), nullptr while this fix
  // keeps the wall's reference fixed
  virtual const double *wall_stretch() = 0;
};

// the pair styles (also hybrid sub-styles) that carry a wall load, in a fixed order
inline std::vector<CellWallLoad *> cell_wall_loads(Force *force)
{
  std::vector<CellWallLoad *> loads;
  for (const char *style : {"cell/wall", "cell/sph"})
    if (auto *load = dynamic_cast<CellWallLoad *>(force->pair_match(style, 0)))
      loads.push_back(load);
  return loads;
}

// every defined fix of class T, in the order of definition
template <class T> std::vector<T *> cell_fixes(Modify *modify)
{
  std::vector<T *> found;
  for (int i = 0; i < modify->nfix; i++)
    if (auto *fix = dynamic_cast<T *>(modify->fix[i])) found.push_back(fix);
  return found;
}

}    // namespace LAMMPS_NS

#endif
