/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   fix cell/turgor: water transfer through the cell wall driven by turgor, osmotic pressure and the
   external water potential (doc/model.md §5)
------------------------------------------------------------------------- */

#ifndef LMP_FIX_CELL_TURGOR_H
#define LMP_FIX_CELL_TURGOR_H

#include "fix.h"

#include <map>
#include <memory>
#include <vector>

namespace LAMMPS_NS {

class CellReduce;

class FixCellTurgor : public Fix {
 public:
  FixCellTurgor(class LAMMPS *, int, char **);
  ~FixCellTurgor() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void end_of_step() override;
  double compute_vector(int) override;
  int modify_param(int, char **) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;

  bool osmotic(tagint cell, double mass, double &pi) const;
  bool turgor(tagint cell, double &pt) const;

 protected:
  enum Osmotic { FIXED = 0, VANTHOFF = 1 };
  enum Limit { LIMIT_ERROR = 0, LIMIT_WARN = 1 };
  struct CellState {
    double mass0;     // fluid mass when the fix first saw the cell (kg)
    double pi0;       // osmotic pressure at mass0 (Pa)
    int warned;       // 1 once the limit-point warning was printed
    double offset;    // running mean of (mean SPH pressure - wall turgor) (Pa), from 0
    double turgor;    // turgor P_T of the last evaluation (Pa), set again by setup()
  };

  double lp, pi0, psi, rhow, accel;
  double tau;       // MD time of the running mean of the offset (s), 0 = 100 N dt
  double bulk;      // fluid bulk modulus K from the 'bulk' keyword, 0 = from pair cell/sph
  double kfluid;    // K in use
  int osmotic_law, limit, limit_set, fluidtype, walltype;
  std::unique_ptr<CellReduce> cells;
  std::map<tagint, CellState> state;
  std::vector<double> gt0;    // G t0 per bond type from the bond style, empty without it

  double physical_time, water_moved, max_imbalance, max_stiffness;

  void evaluate(bool transfer);
  void check_limit(int c, CellState &s, double turgor, double pi);
  double flux_turgor(int c, CellState &s, bool advance);
  double pair_bulk_modulus();
};

}    // namespace LAMMPS_NS

#endif
