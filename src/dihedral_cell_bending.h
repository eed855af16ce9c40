/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   dihedral_style cell/bending: bending stiffness of the triangulated cell wall (doc/model.md §4.2)
------------------------------------------------------------------------- */

#ifndef LMP_DIHEDRAL_CELL_BENDING_H
#define LMP_DIHEDRAL_CELL_BENDING_H

#include "dihedral.h"

#include <string>

namespace LAMMPS_NS {

class DihedralCellBending : public Dihedral {
 public:
  DihedralCellBending(class LAMMPS *);
  ~DihedralCellBending() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_data(FILE *) override;

  enum Reference { XREF = 0, FLAT = 1 };
  enum Form { COS = 0, TAN = 1 };    // k (1 - cos(theta - theta0)) or 2k tan^2((theta - theta0)/2)

 protected:
  double *shear, *thickness;    // G, t0 per dihedral type
  int *reference;               // rest angle from xref, or 0 (flat)
  int *form;                    // energy law of the bend theta - theta0 (Form)
  double *kappa;                // bending rigidity G t0^3 / 3, precomputed per type
  int ixref;                    // index of the per-atom reference positions (d2_xref 3)

  void allocate();
  int parse_reference(const std::string &);
  int parse_form(const std::string &);
};

}    // namespace LAMMPS_NS

#endif
