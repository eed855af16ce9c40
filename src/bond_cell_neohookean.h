/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   bond_style cell/neohookean: the cell-wall stiffness F^e and damping F^d (doc/model.md §4)
------------------------------------------------------------------------- */

#ifndef LMP_BOND_CELL_NEOHOOKEAN_H
#define LMP_BOND_CELL_NEOHOOKEAN_H

#include "bond.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class CellWallStretch;

class BondCellNeoHookean : public Bond {
 public:
  BondCellNeoHookean(class LAMMPS *);
  ~BondCellNeoHookean() override;
  void compute(int, int) override;
  void coeff(int, char **) override;
  void init_style() override;
  double equilibrium_distance(int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_data(FILE *) override;
  double single(int, double, int, int, double &) override;
  void *extract(const char *, int &) override;

  enum Law { NEOHOOKEAN = 0, LINEAR = 1 };

 protected:
  double *shear, *thickness, *gamma;    // G, t0, damping coefficient per bond type
  int *law;
  double *gt0;      // G t0, precomputed per type
  double *l0max;    // longest rest length per type, for cutoff estimates
  int ixref;        // index of the per-atom reference positions (d2_xref 3)
  int iaref;        // index of the per-atom reference area per bond (d_aref), -1 if absent
  std::vector<CellWallStretch *> stretchers;    // fixes that may set the wall's stretch
  const double *stretch_last = nullptr;         // the stretch of the last compute() ...
  bigint stretch_step = -1;                     // ... and its step, for single()

  void allocate();
  int parse_law(const std::string &);
  double rest_length(int, int) const;
  double bond_area(int, int, double) const;
  const double *wall_stretch() const;
  void reference(int, int, const double *, double &, double &) const;
  double stretch_force(int, double, double, double, double &) const;
};

}    // namespace LAMMPS_NS

#endif
