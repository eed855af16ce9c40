/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   compute cell/shape: one row per cell of the 2-D descriptors of a section through it, as image
   analysis reports them, and of the wall's wrinkling (doc/compute_cell_shape.md, doc/model.md §5.11)
------------------------------------------------------------------------- */

#ifndef LMP_COMPUTE_CELL_SHAPE_H
#define LMP_COMPUTE_CELL_SHAPE_H

#include "compute.h"

#include <memory>
#include <vector>

namespace LAMMPS_NS {

class CellReduce;
class CellTriangles;

class ComputeCellShape : public Compute {
 public:
  ComputeCellShape(class LAMMPS *, int, char **);
  ~ComputeCellShape() override;
  void init() override;
  void compute_array() override;
  void compute_vector() override;

  // columns of the global array
  enum {
    ID,
    AREA,
    PERIMETER,
    FERET,
    MINFERET,
    MAJOR,
    MINOR,
    CIRCULARITY,
    ROUNDNESS,
    ASPECT,
    SOLIDITY,
    COMPACTNESS,
    LOOPS,
    HULLAREA,
    WRINKLING,
    HULLFILL,
    HULLPERIMETER,
    NCOLUMN
  };

 private:
  enum { PLANE_X, PLANE_Y, PLANE_Z, PLANE_PRINCIPAL, PLANE_NORMAL };
  std::unique_ptr<CellReduce> cells;
  const CellTriangles *walls = nullptr;    // the wall triangles of this rank's home cells
  int plane;
  double normal[3] = {0.0, 0.0, 1.0};    // plane normal: the unit normal
  double offset;
  std::vector<double> rows, all;    // home cells' rows, every row
  double held[3];       // the vector (held yes): wall triangles held (CellSet::held_triangles)
  int held_flag = 0;    // held yes: the vector is on

  void measure(int h, double *row);
};

}    // namespace LAMMPS_NS

#endif
