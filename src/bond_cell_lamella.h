/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   bond_style cell/lamella: the middle lamella, a breakable junction between the walls of two
   neighbouring cells (doc/model.md §4.6)
------------------------------------------------------------------------- */

#ifndef LMP_BOND_CELL_LAMELLA_H
#define LMP_BOND_CELL_LAMELLA_H

#include "bond_cell_base.h"

namespace LAMMPS_NS {

class BondCellLamella : public BondCellBase {
 public:
  BondCellLamella(class LAMMPS *);
  ~BondCellLamella() override;
  void compute(int, int) override;
  void coeff(int, char **) override;
  void init_style() override;
  double equilibrium_distance(int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_data(FILE *) override;
  double single(int, double, int, int, double &) override;
  void *extract(const char *, int &) override;

 protected:
  double *stiffness, *strength, *area, *gamma;    // K (Pa/m), sigma_c (Pa), A (m^2), gamma per type
  double *kbond;    // K A, spring constant of one bond (N/m), precomputed
  double *dcrit;    // sigma_c / K, opening at which the bond breaks (m), precomputed
  double r0max;     // longest rest length set, for cutoff estimates

  void allocate();
};

}    // namespace LAMMPS_NS

#endif
