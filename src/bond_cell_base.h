/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   BondCellBase: what cellsph bond styles with per-bond reference state share (doc/model.md §4.6),
   on the pattern of LAMMPS's BPM bonds: the base class owns the reference-state machinery (an
   internal fix cell/bond/history it creates), each concrete bond style defines its force law.
------------------------------------------------------------------------- */

#ifndef LMP_BOND_CELL_BASE_H
#define LMP_BOND_CELL_BASE_H

#include "bond.h"

#include <string>

namespace LAMMPS_NS {

class FixCellBondHistory;

class BondCellBase : public Bond {
 public:
  BondCellBase(class LAMMPS *, const std::string &name, const std::string &history_id, int ndata);
  ~BondCellBase() override;

 protected:
  std::string name;          // style name, for messages
  std::string history_id;    // ID of the internal fix; its scalar is the broken-bond count
  int ndata;                 // reference values per bond
  FixCellBondHistory *history;

  void init_history();
  // reference values of the bond of type between atoms i and j, from a local atom that stores
  // it; nullptr if none does. Value 0 is FixCellBondHistory::UNSET before the first setup.
  double *reference(int i, int j, int type);
  // store fresh reference values on every local copy of the bond
  void set_reference(int i, int j, int type, const double *fresh);
  void break_bond(int n, int i1, int i2, int type);
};

}    // namespace LAMMPS_NS

#endif
