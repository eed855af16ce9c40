/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   The largest coefficients the styles accept (doc pages, "Ranges"): generous bounds, orders of
   magnitude beyond plant tissue, that keep the constants derived from them finite (K A, G t0,
   G t0^3/3, K/rho0, ...), so that a mistyped 1e300 stops at its coeff line, not as a NaN energy
   or a lost atom some steps later
------------------------------------------------------------------------- */

#ifndef LMP_CELL_LIMITS_H
#define LMP_CELL_LIMITS_H

#include "error.h"

#include <string>

namespace LAMMPS_NS {
namespace CellLimits {

  // the wall (bond cell/neohookean, dihedral cell/bending; keys wall_G, wall_t0, wall_gamma)
  constexpr double WALL_G_MAX = 1e12;     // shear modulus G, Pa (cellulose: about 1e10)
  constexpr double WALL_T0_MAX = 1e-3;    // wall thickness t0, m (plant walls: 0.1-10 um)
  // damping along a bond gamma, N s/m (apple.cellsph: 5e-6)
  constexpr double GAMMA_MAX = 1.0;

  // the middle lamella (bond cell/lamella; keys lamella_K, lamella_sigma, lamella_area)
  // (the strength sigma_c has none: a strength beyond any load is a bond that never breaks)
  constexpr double LAMELLA_K_MAX = 1e20;       // stiffness per area K, Pa/m (apple: 1e13)
  constexpr double LAMELLA_AREA_MAX = 1e-6;    // junction area per bond A, m^2 (apple: 6.45e-11)

  // the cell fluid (pair cell/sph; keys sph_rho0, sph_K, sph_mu, sph_h)
  constexpr double SPH_RHO0_MAX = 1e5;    // reference density rho0, kg/m^3 (water: 1000)
  constexpr double SPH_K_MAX = 1e12;      // bulk modulus K, Pa (apple.cellsph: 20e6)
  constexpr double SPH_MU_MAX = 1e6;      // viscosity mu, Pa s (water: 1e-3)
  constexpr double SPH_H_MAX = 1.0;       // smoothing length h, m (cells: about 1e-5)
  // background pressure |P_b| and background auto P_min, Pa (drying: 3e5)
  constexpr double PRESSURE_MAX = 1e9;

  // the water transfer (fix cell/turgor; keys turgor_LP, turgor_Lcc, turgor_Ea)
  constexpr double CONDUCTANCE_MAX = 1e3;    // L_P and L_cc, m s^-1 Pa^-1 (apple: 1e-13)
  constexpr double EA_MAX = 1e6;             // activation energy of L_P, J/mol (Chara: 16.8e3)
  constexpr double PSI_MAX = 1e9;            // |psi_ext|, Pa (Kelvin at RH 0.01 and 100 C: -7.9e8)
  constexpr double CURVE_MAX = 1e3;          // a curve's X/X0
  constexpr double HM_MAX = 1e3;             // mass-transfer coefficient h_m, m/s (still air: 1e-2)

  // v within [lo, hi] ((lo, hi] with lo_open), else stop: "<what> = <v> <unit> must be in
  // [<lo>, <hi>] <unit>", what naming the command and the coefficient
  inline double within(Error *error, const std::string &what, double v, double lo, double hi,
                       const std::string &unit, bool lo_open)
  {
    if (!(lo_open ? v > lo : v >= lo) || !(v <= hi)) {
      const std::string u = unit.empty() ? "" : " " + unit;
      error->all(FLERR, "{} = {}{} must be in {}{:g}, {:g}]{}", what, v, u, lo_open ? "(" : "[", lo,
                 hi, u);
    }
    return v;
  }
}    // namespace CellLimits
}    // namespace LAMMPS_NS

#endif
