/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   fix cell/bond/history: per-bond reference state of a cellsph bond style (doc/model.md §4.6),
   created by the bond style (BondCellBase). Per atom, ndata values for each of its bond slots,
   aligned with atom->bond_atom[i][k]; they migrate with the atom, and go into restart files;
   a broken bond (type 0) keeps its slot.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_CELL_BOND_HISTORY_H
#define LMP_FIX_CELL_BOND_HISTORY_H

#include "fix.h"

namespace LAMMPS_NS {

class FixCellBondHistory : public Fix {
 public:
  FixCellBondHistory(class LAMMPS *, int, char **);
  ~FixCellBondHistory() override;
  int setmask() override;
  void setup_post_neighbor() override;
  void post_neighbor() override;
  void min_post_neighbor() override;
  double compute_scalar() override;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  double memory_usage() override;

  static constexpr double UNSET = -1.0;    // value 0 of a bond before its first setup

  int ndata;    // values per bond
  // value k of the bond in slot m of local atom i
  double &value(int i, int m, int k) { return values[i][m * ndata + k]; }
  // slot of the bond of local atom i to the atom with tag j and bond type type, -1 if none
  int slot(int i, tagint j, int type) const;

 protected:
  double **values;    // nmax x (bond_per_atom * ndata)
  int width;          // bond_per_atom * ndata
};

}    // namespace LAMMPS_NS

#endif
