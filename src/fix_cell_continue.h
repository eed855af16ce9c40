/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   fix cell/continue (internal, made by pair cell/sph): a run's setup that continues the last
   step (every atom where it was and as fast as the step left it) computes the velocity-dependent
   forces (SPH viscosity, wall damping, ...) with the velocities the last step's forces saw, v at
   the half step, instead of the step-end ones, so that a run split in two continues as one
   (doc/notes/2026-12-07-run-split.md). Per atom, in fix property/atom FIELDS (it migrates, sorts
   and goes into restart files): x and v at the last force evaluation, and v at the step's end.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_CELL_CONTINUE_H
#define LMP_FIX_CELL_CONTINUE_H

#include "fix.h"

#include <vector>

namespace LAMMPS_NS {

class FixCellContinue : public Fix {
 public:
  FixCellContinue(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup_pre_force(int) override;
  void setup(int) override;
  void post_force(int) override;
  void end_of_step() override;

  // define the fix (ID, style cell/continue) and its fields, unless they exist
  static void ensure(class LAMMPS *);
  // true during a run's setup that continues the last step (between setup_pre_force and setup)
  static bool setup_continues(class LAMMPS *);

 private:
  int ixforce, ivforce, ivend;    // the per-atom arrays of fix FIELDS
  int swapped;                    // 1 from setup_pre_force to setup: v is the last force's
  bool continues() const;
  void exchange_velocities();
};

}    // namespace LAMMPS_NS

#endif
