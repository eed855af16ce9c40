// CellWater (src/cell_water.h): the water and air properties of fix cell/turgor and pair cell/sph
// against reference values and their own inverses (doc/model.md §5.7-5.10, §5.14)
#include "cell_water.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace CellWater;

// Kelvin: psi = (R T / V_w) ln a, and activity() its inverse
TEST(Water, KelvinPotentialAndActivityAreInverse)
{
  for (double t : {278.15, 298.15, 343.15})
    for (double a : {0.05, 0.3, 0.75, 0.999, 1.0}) {
      EXPECT_NEAR(activity(kelvin_potential(a, t), t), a, 1e-14);
      // -137.8 MPa at RH 0.37, 25 C: R T / V_w = 137.19 MPa (8.314462618 x 298.15 / 18.07e-6)
      EXPECT_NEAR(kelvin_potential(a, t), GAS_R * t / WATER_V * std::log(a), 1e-9);
    }
  EXPECT_NEAR(kelvin_potential(std::exp(-1.0), 298.15), -137.19e6, 0.01e6);
}

// Wagner & Pruss within 6e-5 of the IAPWS-95 tables: 3.1699 kPa at 25 C, 101.325 kPa at the
// normal boiling point 373.124 K; the vapour density of the ideal gas, 23.04 g/m^3 at 25 C
TEST(Water, SaturationPressureMatchesTheTables)
{
  EXPECT_NEAR(saturation_pressure(298.15), 3169.9, 0.2);
  EXPECT_NEAR(saturation_pressure(373.124), 101325.0, 2.0);
  EXPECT_NEAR(saturation_pressure(CRITICAL_T), 22.064e6, 1.0);
  EXPECT_NEAR(saturation_density(298.15), 23.04e-3, 0.01e-3);
}

// the dew point inverts the saturation density; below the triple point it is the triple point
TEST(Water, DewPointInvertsTheSaturationDensity)
{
  for (double t : {280.0, 300.0, 330.0, 360.0})
    EXPECT_NEAR(dew_point(saturation_density(t), COOLING_TMAX), t, 1e-9 * t);
  EXPECT_EQ(dew_point(1e-9, COOLING_TMAX), TRIPLE_T);
}

// L_P(T)/L_P(Tref) = exp(-(Ea/R)(1/T - 1/Tref)): 1 at Tref, x 2.0 for Ea = 16.8 kJ/mol over
// 298.15 -> 331.3 K (ln 2 R / Ea = 3.43e-4 1/K)
TEST(Water, ArrheniusFactor)
{
  EXPECT_DOUBLE_EQ(arrhenius(16.8e3, 298.15, 298.15), 1.0);
  const double t2 = 1.0 / (1.0 / 298.15 - std::log(2.0) * GAS_R / 16.8e3);
  EXPECT_NEAR(arrhenius(16.8e3, t2, 298.15), 2.0, 1e-12);
  EXPECT_LT(arrhenius(16.8e3, 280.0, 298.15), 1.0);
}

// Vogel: 0.890, 0.651, 0.463, 0.400 mPa s at 25, 40, 60, 70 C (the comment's values)
TEST(Water, ViscosityFollowsVogel)
{
  EXPECT_NEAR(water_viscosity(298.15), 0.890e-3, 0.0015e-3);
  EXPECT_NEAR(water_viscosity(313.15), 0.651e-3, 0.0015e-3);
  EXPECT_NEAR(water_viscosity(333.15), 0.463e-3, 0.0015e-3);
  EXPECT_NEAR(water_viscosity(343.15), 0.400e-3, 0.0015e-3);
}

// air at 1 atm, 300 K: rho = 1.177 kg/m^3, D = 2.56e-5 m^2/s (Bolz & Tuve),
// k = 0.0263 W/(m K); lambda = 2.501 MJ/kg at 0 C, 2.442 at 25 C
TEST(Water, AirPropertiesAndLatentHeat)
{
  EXPECT_NEAR(air_density(300.0), 1.177, 0.002);
  EXPECT_NEAR(vapour_diffusivity(300.0), 2.56e-5, 0.02e-5);
  EXPECT_NEAR(air_conductivity(300.0), 0.0263, 0.0003);
  EXPECT_DOUBLE_EQ(latent_heat(273.15), 2.501e6);
  EXPECT_NEAR(latent_heat(298.15), 2.442e6, 0.001e6);
}

// Le of air about 0.85, so h_c/(h_m rho c_p) = Le^(2/3) about 0.9
TEST(Water, HeatTransfer)
{
  const double t = 300.0;
  const double ratio = heat_transfer(t, 0.02) / (0.02 * air_density(t) * AIR_CP);
  EXPECT_GT(ratio, 0.85);
  EXPECT_LT(ratio, 0.95);
}

// the wall in series with the air film: the flux through both is the same (flux continuity),
// psi_s lies between psi_cell and the air's potential, and the conductance is the series one
TEST(Water, AirFluxIsContinuousThroughWallAndFilm)
{
  const double t = 333.15, rhosat = saturation_density(t);
  for (double rh : {0.2713, 0.5, 0.95})
    for (double gw : {1e-11, 1e-9, 1e-6}) {
      const double psicell = -1e6, hm = 0.02;
      const AirFlux f = air_flux(psicell, t, gw, hm, rhosat, rh * rhosat);
      const double wall = gw * (psicell - f.psi_surface);
      const double film = hm * (rhosat * activity(f.psi_surface, t) - rh * rhosat);
      EXPECT_NEAR(f.flux, wall, 1e-10 * std::fabs(wall) + 1e-300);
      EXPECT_NEAR(f.flux, film, 1e-10 * std::fabs(film) + 1e-300);
      EXPECT_LE(f.psi_surface, std::max(psicell, kelvin_potential(rh, t)) + 1e-6);
      EXPECT_GE(f.psi_surface, std::min(psicell, kelvin_potential(rh, t)) - 1e-6);
      const double gair = hm * rhosat * activity(f.psi_surface, t) * WATER_V / (GAS_R * t);
      EXPECT_NEAR(f.dflux, 1.0 / (1.0 / gw + 1.0 / gair), 1e-12 * f.dflux);
    }
  // no wall and no film: no flux
  EXPECT_EQ(air_flux(-1e6, t, 0.0, 0.0, rhosat, 0.5 * rhosat).flux, 0.0);
}
