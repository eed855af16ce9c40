/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   fix cell/turgor's osmotic pressure of a cell (doc/model.md §5.5, §5.10): the solutes' pi0 at
   Tref, fixed or van 't Hoff in the cell's water, and with dry solids the GAB sorption isotherm;
   the keywords osmotic, solids and isotherm and the parameter file's turgor_solids and
   turgor_gab_*. pressure() is a pure function of the cell's state.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_CELL_TURGOR_OSMOTIC_H
#define LMP_FIX_CELL_TURGOR_OSMOTIC_H

#include "pointers.h"

#include <string>

namespace LAMMPS_NS {

class CellParams;

class TurgorOsmotic : protected Pointers {
 public:
  TurgorOsmotic(class LAMMPS *, const std::string &command);

  // the keyword arg[0] of narg arguments if it is one of this class's: the arguments it used
  // (keyword and values), else 0
  int parse(int narg, char **arg);
  // turgor_solids and turgor_gab_Xm, _C, _K of the parameter file 'file'
  void read(const CellParams &params, const std::string &file);
  // after all keywords: the isotherm's solids and constants
  void check() const;

  // dry solids S = M0 w_s / (1 - w_s) of a cell first seen with fluid mass M0, 0 without solids
  double solids(double mass0) const;
  // pi of a cell (pi0 at Tref, first fluid mass M0, dry solids S) at fluid mass M and temperature
  // T, and slope = -dpi/dM unless nullptr
  double pressure(double pi0, double mass0, double solids, double mass, double t,
                  double *slope) const;
  // pi0 is diluted by the cell's water (van 't Hoff), not fixed
  bool vanthoff() const { return law == VANTHOFF; }

  double tref;               // reference temperature of pi0 and L_P (K): 298.15
  double solids_fraction;    // wet-basis solids fraction w_s, 0 = none

 private:
  enum Law { FIXED = 0, VANTHOFF = 1 };
  std::string command;
  int law;
  int isotherm;    // 1: GAB isotherm below
  double gab_xm, gab_c, gab_k;
};

}    // namespace LAMMPS_NS

#endif
