/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   fix cell/turgor's osmotic pressure: solutes (fixed or van 't Hoff) and the GAB sorption
   isotherm of the dry solids (doc/model.md §5.5, §5.10)
------------------------------------------------------------------------- */

#include "fix_cell_turgor_osmotic.h"

#include "cell_args.h"
#include "cell_params.h"
#include "cell_water.h"
#include "error.h"

#include <cstring>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

TurgorOsmotic::TurgorOsmotic(LAMMPS *lmp, const std::string &command) :
    Pointers(lmp), tref(298.15), solids_fraction(0.0), command(command), law(FIXED), isotherm(0),
    gab_xm(0.0), gab_c(0.0), gab_k(0.0)
{
}

/* ----------------------------------------------------------------------
   solids w_s, isotherm gab Xm C K | none, osmotic fixed | vanthoff
------------------------------------------------------------------------- */

int TurgorOsmotic::parse(int narg, char **arg)
{
  const std::string key = arg[0];
  if (key != "solids" && key != "isotherm" && key != "osmotic") return 0;
  const char *value = CellArgs::values(error, command, narg, arg, 1)[0];
  if (key == "solids") {
    solids_fraction = utils::numeric(FLERR, value, false, lmp);
    if (!(solids_fraction > 0.0 && solids_fraction < 1.0))
      error->all(FLERR, "{}: solids = {} must be in (0, 1) (wet-basis mass fraction)", command,
                 solids_fraction);
  } else if (key == "isotherm") {
    if (strcmp(value, "none") == 0) {
      isotherm = 0;
    } else if (strcmp(value, "gab") == 0) {
      char **v = CellArgs::values(error, command, narg, arg, 4);
      gab_xm = utils::numeric(FLERR, v[1], false, lmp);
      gab_c = utils::numeric(FLERR, v[2], false, lmp);
      gab_k = utils::numeric(FLERR, v[3], false, lmp);
      isotherm = 1;
      return 5;
    } else {
      error->all(FLERR, "{}: unknown isotherm '{}' (expected gab or none)", command, value);
    }
  } else {
    if (strcmp(value, "fixed") == 0)
      law = FIXED;
    else if (strcmp(value, "vanthoff") == 0)
      law = VANTHOFF;
    else
      error->all(FLERR, "{}: unknown osmotic law '{}' (expected fixed or vanthoff)", command,
                 value);
  }
  return 2;
}

/* ---------------------------------------------------------------------- */

void TurgorOsmotic::read(const CellParams &params, const std::string &file)
{
  if (params.has("turgor_solids")) solids_fraction = params.positive("turgor_solids");
  if (params.has("turgor_gab_Xm") || params.has("turgor_gab_C") || params.has("turgor_gab_K")) {
    gab_xm = params.number("turgor_gab_Xm");
    gab_c = params.number("turgor_gab_C");
    gab_k = params.number("turgor_gab_K");
    isotherm = 1;
  }
  if (!(solids_fraction < 1.0))
    error->all(FLERR, "{}: {}: turgor_solids = {} must be in (0, 1) (wet-basis mass fraction)",
               command, file, solids_fraction);
}

/* ---------------------------------------------------------------------- */

void TurgorOsmotic::check() const
{
  if (isotherm && solids_fraction == 0.0)
    error->all(FLERR,
               "{}: the sorption isotherm needs the moisture content X: give the dry solids with "
               "'solids w_s'",
               command);
  if (isotherm && !(gab_xm > 0.0 && gab_c > 0.0 && gab_k > 0.0 && gab_k <= 1.0))
    error->all(FLERR,
               "{}: GAB isotherm Xm = {}, C = {}, K = {} is impossible: needs Xm > 0, C > 0 and "
               "0 < K <= 1 (K > 1 diverges below a_w = 1)",
               command, gab_xm, gab_c, gab_k);
}

/* ---------------------------------------------------------------------- */

double TurgorOsmotic::solids(double mass0) const
{
  // S = M0 w_s / (1 - w_s): the fluid the fix first sees is the fresh cell's water (§5.10)
  return solids_fraction > 0.0 ? mass0 * solids_fraction / (1.0 - solids_fraction) : 0.0;
}

/* ----------------------------------------------------------------------
   solutes pi0 (T/Tref) [M0/M with van 't Hoff]; with the GAB isotherm, where it is larger, the
   sorption pressure -(R T/V_w) ln a_GAB(X), X = M/S (doc/model.md §5.5, §5.10)
------------------------------------------------------------------------- */

double TurgorOsmotic::pressure(double pi0, double mass0, double solids, double mass, double t,
                               double *slope) const
{
  const bool vanthoff = law == VANTHOFF && mass0 > 0.0;
  // pi = pi0 (T/Tref) M0/M (van 't Hoff, non-permeating solutes)
  double pi = pi0 * (t / tref) * (vanthoff ? mass0 / mass : 1.0);
  if (slope) *slope = vanthoff ? pi / mass : 0.0;
  if (!isotherm || solids <= 0.0) return pi;
  const CellWater::Gab gab{gab_xm, gab_c, gab_k};
  const double x = mass / solids;
  const double a = gab.activity(x);
  if (!(a < 1.0)) return pi;
  // pi_sorption = -(R T / V_w) ln a_GAB(X), -dpi/dM = (R T / V_w) (da/dX) / (a S)
  const double sorption = -CellWater::kelvin_potential(a, t);
  if (sorption <= pi) return pi;
  if (slope)
    *slope = CellWater::GAS_R * t / CellWater::WATER_V * gab.activity_slope(x) / (a * solids);
  return sorption;
}
