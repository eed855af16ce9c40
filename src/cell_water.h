/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   Water outside and inside a drying cell (doc/model.md §5.7-5.10), as pure functions used by
   fix cell/turgor: Kelvin's relation, the saturation vapour density of water, the Arrhenius law
   of L_P, the GAB sorption isotherm, and the exact surface water potential of the wall in series
   with an air film; the latent heat and the air film's heat transfer of evaporative cooling; the
   viscosity of liquid water (pair cell/sph).
------------------------------------------------------------------------- */

#ifndef LMP_CELL_WATER_H
#define LMP_CELL_WATER_H

#include <algorithm>
#include <cmath>

namespace CellWater {

constexpr double GAS_R = 8.314462618;     // molar gas constant R (J mol^-1 K^-1), CODATA 2018
constexpr double WATER_V = 18.07e-6;      // molar volume of liquid water V_w (m^3 mol^-1), 25 C
constexpr double WATER_M = 18.015e-3;     // molar mass of water M_w (kg mol^-1)
constexpr double CRITICAL_T = 647.096;    // critical temperature of water (K), Wagner & Pruss

// water potential psi (Pa) of water at activity a and temperature T: Kelvin, psi = (R T / V_w) ln a
inline double kelvin_potential(double a, double t)
{
  return GAS_R * t / WATER_V * log(a);
}

// water activity a at water potential psi (Pa): a = exp(psi V_w / (R T)), not linearised
inline double activity(double psi, double t)
{
  return exp(psi * WATER_V / (GAS_R * t));
}

// saturation vapour pressure over liquid water (Pa), 273.16 K < T < 647.096 K:
// ln(p/pc) = (Tc/T)(a1 v + a2 v^1.5 + a3 v^3 + a4 v^3.5 + a5 v^4 + a6 v^7.5), v = 1 - T/Tc
// (Wagner & Pruss 1993, J. Phys. Chem. Ref. Data 22, 783; doc/model.md §5.8)
inline double saturation_pressure(double t)
{
  const double v = 1.0 - t / CRITICAL_T;
  const double sum = -7.85951783 * v + 1.84408259 * pow(v, 1.5) - 11.7866497 * pow(v, 3.0) +
      22.6807411 * pow(v, 3.5) - 15.9618719 * pow(v, 4.0) + 1.80122502 * pow(v, 7.5);
  return 22.064e6 * exp(CRITICAL_T / t * sum);
}

// saturation vapour density (kg m^-3), ideal gas: rho_v,sat = p_sat M_w / (R T)
inline double saturation_density(double t)
{
  return saturation_pressure(t) * WATER_M / (GAS_R * t);
}

// Arrhenius factor of L_P: L_P(T) / L_P(Tref) = exp(-(Ea/R)(1/T - 1/Tref))
inline double arrhenius(double ea, double t, double tref)
{
  return exp(-ea / GAS_R * (1.0 / t - 1.0 / tref));
}

// dry air at 1 atm: density (ideal gas, M_air = 28.965e-3 kg/mol) and the diffusivity of water
// vapour in air (Bolz & Tuve 1976, 250-450 K): D = -2.775e-6 + 4.479e-8 T + 1.656e-10 T^2 m^2/s
// (doc/model.md §5.8)
inline double air_density(double t)
{
  return 101325.0 * 28.965e-3 / (GAS_R * t);
}
inline double vapour_diffusivity(double t)
{
  return -2.775e-6 + 4.479e-8 * t + 1.656e-10 * t * t;
}
// evaporative cooling of the exposed surface (doc/model.md §5.14)
constexpr double TRIPLE_T = 273.16;       // triple point of water (K): Wagner & Pruss's lower end
constexpr double COOLING_TMAX = 450.0;    // upper end of the vapour diffusivity behind h_c (K)
constexpr double AIR_CP = 1007.0;         // c_p of dry air (J kg^-1 K^-1), 1006-1009 at 250-350 K

// latent heat of vaporisation of water (J/kg): lambda = 2.501e6 - 2361 (T - 273.15)
// (Harrison 1963; Allen et al. 1998, FAO-56, eq. 3-1 of annex 3)
inline double latent_heat(double t)
{
  return 2.501e6 - 2361.0 * (t - 273.15);
}
// thermal conductivity of dry air (W m^-1 K^-1), Sutherland's law k = 0.0241 (T/273)^1.5
// (273 + 194)/(T + 194) (White, Viscous Fluid Flow, table 1-3)
inline double air_conductivity(double t)
{
  return 0.0241 * pow(t / 273.0, 1.5) * (273.0 + 194.0) / (t + 194.0);
}
// heat-transfer coefficient of the air film from its mass-transfer coefficient h_m at the air's
// T, Chilton-Colburn: h_c = h_m rho_a c_p,a Le^(2/3), Le = k_a / (rho_a c_p,a D)
inline double heat_transfer(double t, double hm)
{
  const double rhocp = air_density(t) * AIR_CP;
  return hm * rhocp * pow(air_conductivity(t) / (rhocp * vapour_diffusivity(t)), 2.0 / 3.0);
}
// the temperature in [TRIPLE_T, tmax] at which rho_v,sat(T) = rho (bisection; rho_v,sat rises
// with T): below it a surface of activity a_s <= 1 takes water up from air of vapour density rho
inline double dew_point(double rho, double tmax)
{
  double lo = TRIPLE_T, hi = tmax;
  if (!(saturation_density(lo) < rho)) return lo;
  while (hi - lo > 1e-12 * hi) {
    const double mid = 0.5 * (lo + hi);
    (saturation_density(mid) < rho ? lo : hi) = mid;
  }
  return hi;
}

// viscosity of liquid water (Pa s), Vogel equation mu_w = A 10^(B / (T - C)), A = 2.414e-5 Pa s,
// B = 247.8 K, C = 140 K: 0.890, 0.651, 0.463, 0.400 mPa s at 25, 40, 60, 70 C (measured: 0.890,
// 0.653, 0.466, 0.404), within about 2 % of tabulated values from 0 to 100 C (-2.2 % at 0 C)
// (Al-Shemmeri, Engineering Fluid Mechanics, 2012; CRC Handbook of Chemistry and Physics); used by
// pair cell/sph (doc/model.md §5.9)
constexpr double VOGEL_TMIN = 273.15;    // range of the correlation (K), 0-370 C
constexpr double VOGEL_TMAX = 643.15;
inline double water_viscosity(double t)
{
  return 2.414e-5 * pow(10.0, 247.8 / (t - 140.0));
}

// GAB sorption isotherm X(a) = Xm C K a / ((1 - K a)(1 - K a + C K a)), X dry basis (kg/kg)
struct Gab {
  double xm, c, k;

  double moisture(double a) const
  {
    const double y = k * a;
    return xm * c * y / ((1.0 - y) * (1.0 - y + c * y));
  }
  // inverse: y = K a is the root in (0, 1) of X (C - 1) y^2 + (Xm C - X (C - 2)) y - X = 0,
  // written without cancellation as y = 2 X / (b + sqrt(b^2 + 4 X^2 (C - 1))), b = Xm C - X (C - 2)
  double activity(double x) const
  {
    const double b = xm * c - x * (c - 2.0);
    return 2.0 * x / (b + sqrt(b * b + 4.0 * x * x * (c - 1.0))) / k;
  }
  // da/dX = 1 / (dX/da), dX/da = K X (1/y - D'/D), D = (1 - y)(1 + (C - 1) y)
  double activity_slope(double x) const
  {
    const double y = k * activity(x);
    const double d = (1.0 - y) * (1.0 + (c - 1.0) * y);
    const double dd = (c - 2.0) - 2.0 * (c - 1.0) * y;
    return 1.0 / (k * x * (1.0 / y - dd / d));
  }
};

// The wall (rho_lp = rho_w L_P, kg m^-2 s^-1 Pa^-1) in series with an air film (h_m, m/s): the
// flux continuity rho_lp (psi_cell - psi_s) = h_m (rho_sat a(psi_s) - rho_air) for the surface
// water potential psi_s, solved exactly (doc/model.md §5.8)
struct AirFlux {
  double psi_surface;    // psi_s (Pa)
  double flux;           // J, out of the cell (kg m^-2 s^-1)
  // dJ/dpsi_cell = 1 / (1/rho_lp + 1/g_air) per area (kg m^-2 s^-1 Pa^-1), the air film's
  // g_air = h_m rho_sat a V_w/(R T)
  double dflux;
};

// rho_sat = rho_v,sat(T_s) of the surface, rho_air = RH rho_v,sat(T_air) > 0 of the air
inline AirFlux air_flux(double psi_cell, double t, double rho_lp, double hm, double rho_sat,
                        double rho_air)
{
  const double rt = GAS_R * t / WATER_V;
  // (rho_lp == 0.0 && hm == 0.0) return {psi_cell, 0.0, 0.0}; f(u) = rho_lp (psi_cell - rt u) - h_m
  // (rho_sat e^u - rho_air), u = ln a_s: decreasing and concave, root between u_cell = psi_cell /
  // rt and u_air = ln(rho_air / rho_sat); Newton from the larger
  // (where f <= 0) converges monotonically to it without leaving the bracket
  const double ucell = psi_cell / rt, uair = log(rho_air / rho_sat);
  const double lo = std::min(ucell, uair);
  double u = std::max(ucell, uair);
  for (int iter = 0; iter < 100; iter++) {
    const double vap = hm * rho_sat * exp(u);
    const double residual = rho_lp * (psi_cell - rt * u) - (vap - hm * rho_air);
    const double step = residual / (rho_lp * rt + vap);
    u = std::max(lo, u + step);
    if (fabs(step) <= 1e-15 * (1.0 + fabs(u))) break;
  }
  const double vap = hm * rho_sat * exp(u);
  const double gair = vap / rt;
  const double dflux = (rho_lp > 0.0 && gair > 0.0) ? rho_lp * gair / (rho_lp + gair) : 0.0;
  // J = h_m (rho_sat a_s - rho_air) (doc/model.md §5.8)
  return {rt * u, vap - hm * rho_air, dflux};
}

}    // namespace CellWater

#endif
