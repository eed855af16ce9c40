/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   fix cell/turgor's time-scale bridging (doc/model.md §5.12): accel, the physical time per MD time
   of the water transfer, fixed or 'accel auto': a cycle of open transfers and sealed ones (no
   water, no physical time) whose turgor samples give each cell's lag behind the quasi-static
   response, and accel adapted to keep the largest lag within the tolerance; a ceiling on accel
   keeps each cell's water and the longest wall edge from changing by more than a limit per
   transfer, the edge's limit vanishing at its allowance. The per-cell sums (Probe) live in the
   fix's per-cell state; this class owns the global state and the formulas.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_CELL_TURGOR_ACCEL_H
#define LMP_FIX_CELL_TURGOR_ACCEL_H

#include "pointers.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class TurgorAccel : protected Pointers {
 public:
  // per cell: P_T shifted by its first sample, sums over the open window's samples (t = position,
  // y = P_T), the rate and conductance of its last transfer, sums over the sealed window's samples
  enum Probe { Y0, ST, SY, STT, STY, SYY, RATE, COND, SY2, SYY2, NPROBE };
  // global restart values: accel if auto (else 0), open and sealed samples, lag and its error;
  // then (format 7) the shortest and the last longest wall edge, its mean growth per transfer
  static constexpr int RESTART_VALUES = 5, EDGE_VALUES = 3;
  // a wall edge may grow to 1.5 x the longest at a run's start (pair cell/sph's guard)
  static constexpr double ALLOWANCE = 1.5;
  // transfers of the running mean of the longest wall edge's growth
  static constexpr double SMOOTH = 8.0;
  // the part of the allowance (room left below it) in which the edge's growth lowers accel
  static constexpr double ZONE = 0.5;
  // the largest accel accepted: also of accel auto min, max (default) and start
  // (doc/fix_cell_turgor.md)
  static constexpr double MAX = 1e15;
  // default 'change': the largest relative change per transfer of a cell's water, and of the
  // longest wall edge's growth far from its allowance
  static constexpr double CHANGE = 1e-3;

  TurgorAccel(class LAMMPS *);

  // the values after 'accel': a number, or auto tol [min a] [max a] [start a] [every n] [hold n]
  // [change c]; returns how many it used
  int parse(int narg, char **arg, const std::string &command);

  // a transfer's place in its cycle: open transfers, sealed ones, its position; sampled or not
  struct Cycle {
    bigint every, hold, position;
    bool sealed, sample;
  };
  // transfer j (with transfer, else the next one), offset time tau and MD time N dt per transfer;
  // counts the sample
  Cycle cycle(bigint j, bool transfer, double offset, double step);
  // a cell's sample at a transfer of the cycle (rate and conductance with the exchange's)
  void sample(double *probe, const Cycle &at, double turgor, double rate, double conductance) const;
  // a cell's elastic modulus eps = V dP/dV from the fluid's K + P_SPH, in series with the thin
  // Neo-Hookean wall of G t0 (0: none), reference area A0 and area A
  static double modulus(double fluid, double gt, double area0, double area);
  // a cell's first accel from its conductance G, -dpi/dM, modulus eps and fluid mass M
  double first(double conductance, double slope, double eps, double mass, double offset) const;
  // accel of the first evaluation: 'start' or the smallest first accel of the cells (HUGE_VAL:
  // none); returns new accel / old accel
  double begin(double first);
  // at the end of a cycle of 'every' open transfers, from the probes of this rank's home cells;
  // cells: whether there are any
  void adapt(bigint every, const std::vector<const double *> &probes, bool cells);

  // per home cell after an evaluation: its probe, turgor, fluid mass, rate and conductance
  struct Home {
    std::vector<double *> probe;
    std::vector<double> turgor, mass, rate, conductance;
  };
  // after an evaluation: accel auto's samples, its adaptation at the end of a cycle (cells: there
  // are any) and, with bound, the ceiling (below); a fixed accel: the wall edges measured
  void after(const Cycle &at, bool bound, bool transfer, const Home &home, double step, bool cells);
  // after a transfer's evaluation (transfer; a run's setup only sets the first accel): the
  // longest wall edge measured, and for accel auto the ceiling of the next transfers from each
  // home cell's fluid mass and rate (with the exchange) and the edge; step = N dt
  void limit(const std::vector<double> &mass, const std::vector<double> &rate, double step,
             bool transfer);

  // the restart values, and back (false: not continued, e.g. not auto now)
  void write(std::vector<double> &list) const;
  bool read(const double *v);
  void write_edges(std::vector<double> &list) const
  {
    list.insert(list.end(), {least, last, growth});
  }
  void read_edges(const double *v) { least = v[0], last = v[1], growth = v[2]; }

  // what an evaluation changes, to evaluate a transfer again from the state before it
  struct Saved {
    double value, lag_estimate, lag_error, least, last, growth;
    int pending, open_samples, sealed_samples;
  };
  Saved save() const
  {
    return {value,  lag_estimate, lag_error,    least,         last,
            growth, pending,      open_samples, sealed_samples};
  }
  void restore(const Saved &s)
  {
    value = s.value, lag_estimate = s.lag_estimate, lag_error = s.lag_error;
    least = s.least, last = s.last, growth = s.growth;
    pending = s.pending, open_samples = s.open_samples, sealed_samples = s.sealed_samples;
  }

  double value;              // accel in use
  int automatic, pending;    // auto; pending: set from the cells' state at the next evaluation
  double lag_estimate, lag_error;    // of the last adaptation window
  double edge;                       // longest wall edge / the shortest longest one (output)

 private:
  int every, hold;                     // transfers per open and sealed window, 0: from tau
  int open_samples, sealed_samples;    // of the current cycle
  double tol, lo, hi, start;    // tolerance, floor, ceiling, start (0: from the cells' state)
  double change;                // the largest change of a cell's water or wall edge per transfer
  double least, last;    // the shortest longest wall edge since the start, the last one (0: none)
  double growth;         // the running mean of the longest edge's growth per transfer

  bool lag(const double *probe, bigint every, double flux, double &e, double &se) const;
};

}    // namespace LAMMPS_NS

#endif
