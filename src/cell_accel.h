/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   fix cell/turgor's time-scale bridging (doc/model.md §5.12): accel, the physical time per MD time
   of the water transfer, fixed or 'accel auto': a cycle of open transfers and sealed ones (no
   water, no physical time) whose turgor samples give each cell's lag behind the quasi-static
   response, and accel adapted to keep the largest lag within the tolerance. The per-cell sums
   (Probe) live in the fix's per-cell state; this class owns the global state and the formulas.
------------------------------------------------------------------------- */

#ifndef LMP_CELL_ACCEL_H
#define LMP_CELL_ACCEL_H

#include "pointers.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class CellAccel : protected Pointers {
 public:
  // per cell: P_T shifted by its first sample, sums over the open window's samples (t = position,
  // y = P_T), the rate and conductance of its last transfer, sums over the sealed window's samples
  enum Probe { Y0, ST, SY, STT, STY, SYY, RATE, COND, SY2, SYY2, NPROBE };
  // global restart values: accel if auto (else 0), open and sealed samples, lag and its error
  static constexpr int RESTART_VALUES = 5;
  // the largest accel accepted: also of accel auto min, max (default) and start
  // (doc/fix_cell_turgor.md)
  static constexpr double MAX = 1e15;

  CellAccel(class LAMMPS *);

  // the values after 'accel': a number, or auto tol [min a] [max a] [start a] [every n] [hold n];
  // returns how many it used
  int parse(int narg, char **arg, const std::string &command);

  // a transfer's place in its cycle: open transfers, sealed ones, its position; sampled or not
  struct Cycle {
    bigint every, hold, position;
    bool sealed, sample;
  };
  // transfer j (with transfer, else the next one), offset time tau and MD time N dt per transfer;
  // counts the sample
  Cycle cycle(bigint j, bool transfer, double offset, double step);
  // a cell's sample at a transfer of the cycle
  void sample(double *probe, const Cycle &at, double turgor, double rate, double conductance) const;
  // a cell's first accel from its conductance G, -dpi/dM, modulus eps and fluid mass M
  double first(double conductance, double slope, double eps, double mass, double offset) const;
  // accel of the first evaluation: 'start' or the smallest first accel of the cells (HUGE_VAL:
  // none); returns new accel / old accel
  double begin(double first);
  // at the end of a cycle of 'every' open transfers, from the probes of this rank's home cells;
  // cells: whether there are any
  void adapt(bigint every, const std::vector<const double *> &probes, bool cells);

  // the restart values, and back (false: not continued, e.g. not auto now)
  void write(std::vector<double> &list) const;
  bool read(const double *v);

  // what an evaluation changes, to evaluate a transfer again from the state before it
  struct Saved {
    double value, lag_estimate, lag_error;
    int pending, open_samples, sealed_samples;
  };
  Saved save() const
  {
    return {value, lag_estimate, lag_error, pending, open_samples, sealed_samples};
  }
  void restore(const Saved &s)
  {
    value = s.value, lag_estimate = s.lag_estimate, lag_error = s.lag_error;
    pending = s.pending, open_samples = s.open_samples, sealed_samples = s.sealed_samples;
  }

  double value;              // accel in use
  int automatic, pending;    // auto; pending: set from the cells' state at the next evaluation
  double lag_estimate, lag_error;    // of the last adaptation window

 private:
  int every, hold;                     // transfers per open and sealed window, 0: from tau
  int open_samples, sealed_samples;    // of the current cycle
  double tol, lo, hi, start;    // tolerance, floor, ceiling, start (0: from the cells' state)

  bool lag(const double *probe, bigint every, double &e, double &se) const;
};

}    // namespace LAMMPS_NS

#endif
