/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   fix cell/pressure: an imposed turgor pressure on the wall triangles of closed cells
------------------------------------------------------------------------- */

#ifndef LMP_FIX_CELL_PRESSURE_H
#define LMP_FIX_CELL_PRESSURE_H

#include "cell_quantity.h"
#include "fix.h"

#include <string>

namespace LAMMPS_NS {

class FixCellPressure : public Fix {
 public:
  FixCellPressure(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup_pre_reverse(int, int) override;
  void pre_reverse(int, int) override;
  void min_pre_reverse(int, int) override;
  double compute_scalar() override;

 protected:
  double pressure;        // Pa, or from an equal-style variable
  CellQuantity source;    // P: a number or an equal-style variable
  int angle_type;         // angle type of the wall triangles
  double work_local;      // P V of the triangles this rank summed at the last force evaluation
};

}    // namespace LAMMPS_NS

#endif
