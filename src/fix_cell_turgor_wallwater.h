/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   fix cell/turgor's wall water (doc/model.md §5.15): the wall's moisture X_w in equilibrium with
   the cell's water potential through a GAB sorption relation of the wall, its water part of the
   cell's water, and the wall's stress-free in-plane stretch s = 1 - beta (X_w0 - X_w) that bond
   cell/neohookean applies to its rest lengths (s) and areas (s^2); the keyword wallwater
------------------------------------------------------------------------- */

#ifndef LMP_FIX_CELL_TURGOR_WALLWATER_H
#define LMP_FIX_CELL_TURGOR_WALLWATER_H

#include "cell_water.h"
#include "pointers.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class CellRegistry;

class TurgorWallWater : protected Pointers {
 public:
  TurgorWallWater(class LAMMPS *, const std::string &command);

  // 'wallwater mass m beta b gab Xm C K' at arg[0] of narg arguments: the arguments it used,
  // else 0
  int parse(int narg, char **arg);
  bool on() const { return enabled; }
  // dry wall mass of a cell of reference wall area A (kg): m_w A
  double dry_mass(double area) const { return mass_area * area; }
  // X_w (kg/kg) at the cell's water potential psi (Pa) and temperature T (K)
  double moisture(double psi, double t) const;
  // the stress-free in-plane stretch s at moisture X_w of a wall first seen at X_w0
  double stretch(double x0, double x) const;

  // per cell (every cell, in cell order): the stretch in effect, and the one after the transfer
  // waiting to be applied; the wall water of all cells, in effect and after it (kg)
  std::vector<double> active, next;
  double water = 0.0, water_next = 0.0;

  // s of each owned and ghost atom from its cell's stretch in effect (1 outside the cells)
  const double *per_atom(const CellRegistry &reg);

 private:
  std::string command;
  bool enabled = false;
  double mass_area = 0.0;    // m_w, dry wall mass per reference wall area (kg m^-2)
  double beta = 0.0;         // in-plane linear hygroexpansion per kg/kg of wall moisture
  CellWater::Gab gab{0.0, 0.0, 0.0};
  std::vector<double> atoms;
};

}    // namespace LAMMPS_NS

#endif
