/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   fix cell/turgor's external drive (doc/model.md §5.1, §5.7-5.10): the cell temperature T and one
   of a water potential psi_ext, air of temperature, humidity and h_m on
   the exposed wall, or a prescribed drying curve X/X0(t); the keywords psi, air, curve, temp and
   cooling. evaluate() takes the inputs of one evaluation, flux() gives one cell's water flux from
   them; with cooling, cool() sets T to the surface temperature of the heat balance (§5.14).
------------------------------------------------------------------------- */

#ifndef LMP_FIX_CELL_TURGOR_DRIVE_H
#define LMP_FIX_CELL_TURGOR_DRIVE_H

#include "cell_quantity.h"
#include "cell_water.h"
#include "pointers.h"

#include <functional>
#include <string>

namespace LAMMPS_NS {

class TurgorDrive : protected Pointers {
 public:
  enum Kind { PSI = 0, AIR = 1, CURVE = 2 };
  TurgorDrive(class LAMMPS *, const std::string &command);

  // the keyword arg[0] of narg arguments if it is one of this class's: the arguments it used
  // (keyword and values), else 0; tref: the reference temperature so far (the check of air)
  int parse(int narg, char **arg, double tref);
  // after all keywords: one drive; T is the air's without 'temp', else Tref
  void check(double tref);
  // the variables, looked up at init
  void init();
  // fix_modify psi value
  void modify_psi(const char *arg);

  // T and the drive's inputs at the physical time 'time' (the fix's f_ID[2]) of the start of a
  // transfer; the curve's X/X0 at its end: time advances by 'advance' after T, before X/X0
  void evaluate(double &time, double advance);
  // cooling (after evaluate): T = T_s, the root of h_c (T_air - T_s) = lambda(T_s) J(T_s) in
  // [dew point, T_air] (above T_air where the cells take water up), J(T) = mean_flux() the exposed
  // cells' mean vapour flux with the drive at T; collective when mean_flux is (doc/model.md §5.14)
  void cool(const std::function<double()> &mean_flux);

  // a cell's water uptake: conductance G = d(dM/dt)/d(-psi_cell), rate dM/dt and the water
  // potential just outside the wall
  struct Flux {
    double conductance, rate, psi_surface;
  };
  // of a cell at psi_cell with rho_lp = rho_w L_P(T) of its wall, wall area A, area of its
  // surface group's triangles, fluid mass M and M0, over a transfer of dtw
  Flux flux(double psi_cell, double rho_lp, double area, double surface_area, double mass,
            double mass0, double dtw) const
  {
    if (kind == AIR) {
      // wall and air film in series on the exposed area (doc/model.md §5.8)
      const double exposed = exposed_area(area, surface_area);
      const auto air = CellWater::air_flux(psi_cell, temperature, rho_lp, hm, rho_sat, rho_air);
      return {exposed * air.dflux, -exposed * air.flux, air.psi_surface};
    }
    if (kind == PSI) {
      // dM/dt = rho_w L_P A (psi_ext - psi_cell) (doc/model.md §5.1)
      const double conductance = rho_lp * area;
      return {conductance, conductance * (psi_ext - psi_cell), psi_ext};
    }
    // the curve: M0 X/X0(t + dtw) at the end of the transfer (doc/model.md §5.10)
    return {0.0, (target * mass0 - mass) / dtw, psi_cell};
  }

  // the area of a cell that faces the air: f A, or f A_surface with 'surface' (doc/model.md §5.8)
  double exposed_area(double area, double surface_area) const
  {
    return area_fraction * (surface_group >= 0 ? surface_area : area);
  }

  // the largest |psi_ext| (Pa), X/X0 of the curve and h_m (m/s) accepted (doc/fix_cell_turgor.md)

  int kind;
  int cooling;             // 'cooling yes': T is the surface temperature of the heat balance
  int surface_group;       // 'surface': air only on the triangles of this group's atoms, or -1
  double temperature;      // cell temperature T of the last evaluation (K), 0 before
  double mass_transfer;    // h_m of the last evaluation (m/s)
  double psi_ext;          // of the last evaluation: the drive's water potential (Pa), 0 for curve
  double target;           // of the last evaluation: the curve's X/X0
  double air_temperature;    // T_air of the last evaluation (K), 0 without air

 private:
  std::string command;
  std::string drives;    // the drive keywords given, for the check
  CellQuantity psi, temp, air_t, air_rh, air_hm, curve;
  int temp_set;
  double area_fraction;           // share of the wall area in contact with the air
  double hm, rho_sat, rho_air;    // h_m, rho_v,sat(T) and RH rho_v,sat(T_air) of the evaluation

  void check_air(double t, double rh, double hm, const std::string &when) const;
  void check_psi(double value, const std::string &who, const std::string &when) const;
  void check_temperature(double t, const std::string &when) const;
  void check_cooling(double t) const;
  void surface(double t);
};

}    // namespace LAMMPS_NS

#endif
