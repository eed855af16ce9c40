/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   compute cell/props: one row per cell of mass, geometry, turgor and shape (doc/model.md §5.2)
------------------------------------------------------------------------- */

#ifndef LMP_COMPUTE_CELL_PROPS_H
#define LMP_COMPUTE_CELL_PROPS_H

#include "compute.h"

#include <memory>
#include <vector>

namespace LAMMPS_NS {

class CellReduce;
class CellTriangles;
class FixCellTurgor;

class ComputeCellProps : public Compute {
 public:
  ComputeCellProps(class LAMMPS *, int, char **);
  ~ComputeCellProps() override;
  void init() override;
  void compute_array() override;
  void compute_vector() override;

  // columns of the global array
  enum {
    ID,
    MASS,
    VOLUME,
    AREA,
    TURGOR,
    OSMOTIC,
    PSI,
    DIAMETER,
    LENGTH1,
    LENGTH2,
    LENGTH3,
    ELONGATION,
    FLUIDVOL,
    SPHTURGOR,
    WALLTURGOR,
    OUTSIDE,
    GAPVOL,
    MOISTURE,
    MOISTURE_RELATIVE,
    ACTIVITY,
    PSI_SURFACE,
    WATER_RATE,
    NCOLUMN
  };

 private:
  std::unique_ptr<CellReduce> cells;
  const CellTriangles *walls = nullptr;    // the wall triangles of this rank's home cells
  std::vector<FixCellTurgor *> turgor;
  int fluidtype;
  std::vector<double> centre;           // per home cell ball tests
  std::vector<double> away, got;        // fluid positions sent to, received from the homes
  std::vector<double> outside, rows;    // per home cell: fluid atoms outside, rows of the array
  std::vector<double> all;              // every cell's row
  double held[3];                       // the vector (held yes): wall triangles held
  int held_flag = 0;                    // held yes: the vector is on

  bool homes_checked;    // the fixes cell/turgor give each cell the same home rank

  void count_outside();
  bool is_outside(int h, const double *x) const;
  void check_homes();
};

}    // namespace LAMMPS_NS

#endif
