/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   fix cell/turgor's per-cell state, kept on each cell's home rank (doc/model.md §5.2): one Cell
   per cell ID, moved to the home ranks of a run at init, gathered in ascending ID for the restart
   file, and the per-cell layout of each restart format version
------------------------------------------------------------------------- */

#ifndef LMP_FIX_CELL_TURGOR_STATE_H
#define LMP_FIX_CELL_TURGOR_STATE_H

#include "fix_cell_turgor_accel.h"
#include "pointers.h"

#include <map>
#include <vector>

namespace LAMMPS_NS {

class CellRegistry;

class TurgorState : protected Pointers {
 public:
  struct Cell {
    double mass0;                // fluid mass when the fix first saw the cell (kg)
    double pi0;                  // osmotic pressure at mass0 and Tref (Pa)
    int warned;                  // 1 once the limit-point warning was printed
    double offset;               // running mean of (mean SPH pressure - wall turgor) (Pa), from 0
    double solids;               // dry solids S (kg), 0 without 'solids'
    double psi_surface, rate;    // of the last evaluation (Pa, kg/s)
    double probe[TurgorAccel::NPROBE];    // accel auto: the cycle's sums
    // wallwater (0 without): dry wall mass (kg), the wall's moisture when first seen, in effect,
    // and its change by the transfer waiting to be applied (kg/kg)
    double wall_dry = 0.0, wall_x0 = 0.0, wall_x = 0.0, wall_dx = 0.0;
  };

  TurgorState(class LAMMPS *);

  // restart values per cell of format version: ID, mass0, pi0, warned, offset (versions 1, 2),
  // solids (3), the accel auto cycle's sums (4: TurgorAccel::NPROBE = 10 values), the wall's
  // water: wall_dry, wall_x0, wall_x, wall_dx (8)
  static int restart_values(int version);

  Cell &operator[](tagint id) { return cells[id]; }
  // the cell's state on this rank, nullptr if it has none
  const Cell *find(tagint id) const;
  void clear() { cells.clear(); }
  // the state before a transfer's evaluation, to evaluate it again (fix cell/turgor setup)
  void save() { saved = cells; }
  void restore() { cells = saved; }
  void swap_saved() { cells.swap(saved); }

  // every rank's cell states: with everywhere, their restart values and the last evaluation's
  // psi_surface and rate on every rank (before the cells are found again at init)
  void gather(bool everywhere, std::vector<double> &list) const;
  // keep the gathered cells whose home rank this is (rank 0: also cells no longer in the group);
  // home cells without a state begin one with osmotic pressure pi0
  void keep_home(const std::vector<double> &list, const CellRegistry &reg, double pi0);
  // on rank 0: every cell's restart values of format version (the fix's current one) from its
  // home rank, in ascending ID (a cell's copies on every rank when no run followed read_restart:
  // the first); returns the number of cells
  int gather_restart(int version, std::vector<double> &list) const;

 private:
  std::map<tagint, Cell> cells;    // the home cells' (and on rank 0 unknown cells') state
  std::map<tagint, Cell> saved;    // as it was before the last transfer's evaluation

  void pack(std::vector<double> &list, bool full) const;
};

}    // namespace LAMMPS_NS

#endif
