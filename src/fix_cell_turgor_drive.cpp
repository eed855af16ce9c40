/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   fix cell/turgor's external drive: psi_ext, air (T, RH, h_m) or a drying curve, and
   the cell temperature, given or (cooling) that of the exposed surface's heat balance
   (doc/model.md §5.1, §5.7-5.10, §5.14)
------------------------------------------------------------------------- */

#include "fix_cell_turgor_drive.h"

#include "cell_args.h"
#include "cell_limits.h"
#include "error.h"
#include "group.h"
#include "update.h"

#include <algorithm>
#include <cstring>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

TurgorDrive::TurgorDrive(LAMMPS *lmp, const std::string &command) :
    Pointers(lmp), kind(PSI), cooling(0), surface_group(-1), temperature(0.0), mass_transfer(0.0),
    psi_ext(0.0), target(0.0), air_temperature(0.0),
    command(command), psi{0.0, "", -1}, temp{0.0, "", -1}, air_t{0.0, "", -1}, air_rh{0.0, "", -1},
    air_hm{0.0, "", -1}, curve{0.0, "", -1}, temp_set(0), area_fraction(1.0), hm(0.0), rho_sat(0.0),
    rho_air(0.0)
{
}

/* ----------------------------------------------------------------------
   psi value, air T RH hm [area f] [surface group-ID], curve v_name, temp T,
   cooling yes|no
------------------------------------------------------------------------- */

int TurgorDrive::parse(int narg, char **arg, double tref)
{
  const std::string key = arg[0];
  if (key != "psi" && key != "air" && key != "curve" && key != "temp" && key != "cooling") return 0;
  const char *value = CellArgs::values(error, command, narg, arg, 1)[0];
  if (key == "cooling") {
    if (strcmp(value, "yes") != 0 && strcmp(value, "no") != 0)
      error->all(FLERR, "{}: cooling = {} must be yes or no", command, value);
    cooling = strcmp(value, "yes") == 0;
    return 2;
  }
  if (key == "temp") {
    temp = CellQuantity::parse(lmp, value, command + ": temp");
    if (temp.name.empty()) check_temperature(temp.value, "");
    temp_set = 1;
    return 2;
  }
  drives += " " + key;
  if (key == "psi") {
    psi = CellQuantity::parse(lmp, value, command + ": psi");
    if (psi.name.empty()) check_psi(psi.value, command, "");
    return 2;
  }
  if (key == "curve") {
    curve = CellQuantity::parse(lmp, value, command + ": curve");
    if (curve.name.empty())
      error->all(FLERR, "{}: curve = {} must be an equal-style variable v_name", command, value);
    kind = CURVE;
    return 2;
  }
  char **v = CellArgs::values(error, command, narg, arg, 3);
  air_t = CellQuantity::parse(lmp, v[0], command + ": air T");
  air_rh = CellQuantity::parse(lmp, v[1], command + ": air RH");
  int used = 4;
  if (strcmp(v[2], "flow") == 0)
    error->all(FLERR,
               "{}: air's 'flow U L' was removed: give the mass-transfer coefficient h_m (m/s; "
               "2 cm/s for air at 0.5-2 m/s over a slab, doc/model.md §10.2)",
               command);
  air_hm = CellQuantity::parse(lmp, v[2], command + ": air hm");
  // numbers are checked now, variables at every transfer (placeholders pass the check)
  const double t0 = air_t.name.empty() ? air_t.value : tref;
  const double rh0 = air_rh.name.empty() ? air_rh.value : 1.0;
  check_air(t0, rh0, air_hm.name.empty() ? air_hm.value : 0.0, "");
  // optional 'area f' and 'surface group-ID', in either order
  while (used + 1 < narg) {
    const char *word = arg[used], *next = arg[used + 1];
    if (strcmp(word, "area") == 0) {
      area_fraction = utils::numeric(FLERR, next, false, lmp);
      if (!(area_fraction > 0.0 && area_fraction <= 1.0))
        error->all(FLERR, "{}: air area fraction = {} must be in (0, 1]", command, area_fraction);
    } else if (strcmp(word, "surface") == 0) {
      surface_group = group->find(next);
      if (surface_group < 0)
        error->all(FLERR, "{}: air surface group {} does not exist", command, next);
    } else
      break;
    used += 2;
  }
  kind = AIR;
  return used;
}

/* ---------------------------------------------------------------------- */

void TurgorDrive::check(double tref)
{
  if (drives.find(' ', 1) != std::string::npos)
    error->all(FLERR, "{}: give one drive of psi, air and curve, not{}", command, drives);
  if (cooling && kind != AIR)
    error->all(FLERR, "{}: cooling needs the air drive (this fix has {})", command,
               kind == PSI ? "psi" : "curve");
  if (cooling && temp_set)
    error->all(FLERR,
               "{}: cooling sets the temperature of the cells to that of their surface: give "
               "cooling or temp, not both",
               command);
  if (cooling && !air_t.is_variable()) check_cooling(air_t.value);
  // the cell is at the air's temperature unless 'temp' says otherwise; without either at Tref
  if (!temp_set) temp = kind == AIR ? air_t : CellQuantity{tref, "", -1};
}

/* ---------------------------------------------------------------------- */

void TurgorDrive::init()
{
  for (CellQuantity *in : {&psi, &temp, &air_t, &air_rh, &air_hm, &curve})
    in->resolve(lmp, command + ": variable");
}

/* ---------------------------------------------------------------------- */

void TurgorDrive::modify_psi(const char *arg)
{
  if (kind != PSI)
    error->all(FLERR, "Fix_modify cell/turgor: psi needs the psi drive (this fix has {})",
               kind == AIR ? "air" : "curve");
  psi = CellQuantity::parse(lmp, arg, "Fix_modify cell/turgor: psi");
  if (psi.name.empty()) check_psi(psi.value, "Fix_modify cell/turgor", "");
  psi.resolve(lmp, command + ": variable");
}

/* ---------------------------------------------------------------------- */

void TurgorDrive::evaluate(double &time, double advance)
{
  const std::string step = fmt::format(" (step {})", update->ntimestep);
  const double t = temp.get(lmp);
  check_temperature(t, step);
  temperature = t;
  psi_ext = hm = rho_sat = rho_air = target = air_temperature = 0.0;
  if (kind == PSI) {
    psi_ext = psi.get(lmp);
    check_psi(psi_ext, command, step);
  } else if (kind == AIR) {
    const double tair = air_t.get(lmp), rh = air_rh.get(lmp);
    hm = air_hm.get(lmp);
    mass_transfer = hm;
    check_air(tair, rh, hm, step);
    if (cooling) check_cooling(tair);
    air_temperature = tair;
    rho_air = rh * CellWater::saturation_density(tair);
    surface(t);
  } else {
    time += advance;
    target = curve.get(lmp);
    // the cell's water relative to its first: finite, and masses M0 X/X0 too
    if (!(target > 0.0 && target <= CellLimits::CURVE_MAX))
      error->all(FLERR, "{}: curve X/X0 = {} must be > 0 and <= 1e3 (physical time {} s, step {})",
                 command, target, time, update->ntimestep);
  }
}

/* ----------------------------------------------------------------------
   the cells and their surface at T: rho_v,sat(T) and the air's water potential there
------------------------------------------------------------------------- */

void TurgorDrive::surface(double t)
{
  temperature = t;
  rho_sat = CellWater::saturation_density(t);
  // the water potential of the air at the surface temperature: (R T / V_w) ln(rho_air/rho_sat)
  psi_ext = CellWater::kelvin_potential(rho_air / rho_sat, t);
}

/* ----------------------------------------------------------------------
   cooling: the surface temperature T_s of the quasi-steady heat balance of the exposed surface,
   b(T) = h_c (T_air - T) - lambda(T) J(T) = 0, convection from the air supplying the latent heat
   of the vapour flux (doc/model.md §5.14). b falls with T (J rises with rho_v,sat); the root lies
   in [dew point, T_air] when the cells dry (b(T_air) <= 0; at the dew point J <= 0 for a_s <= 1),
   else in [T_air, T_air + lambda h_m rho_air / h_c] (J >= -h_m rho_air). Illinois false position,
   from the same bracket at every evaluation (no state carried between transfers)
------------------------------------------------------------------------- */

void TurgorDrive::cool(const std::function<double()> &mean_flux)
{
  const double tair = air_temperature;
  const double hc = CellWater::heat_transfer(tair, hm);
  // b(T) = h_c (T_air - T) - lambda(T) J(T) with the drive at T (doc/model.md §5.14)
  auto balance = [&](double t) {
    surface(t);
    return hc * (tair - t) - CellWater::latent_heat(t) * mean_flux();
  };
  double lo = tair, hi = tair, blo = balance(tair), bhi = blo;
  if (blo == 0.0) return;
  if (bhi < 0.0) {
    lo = CellWater::dew_point(rho_air, tair);
    blo = balance(lo);
    // a cell above full hydration (a_s > 1) still evaporates at the dew point: go lower
    while (blo < 0.0 && lo > CellWater::TRIPLE_T) {
      lo = std::max(CellWater::TRIPLE_T, lo - (tair - lo) - 1.0);
      blo = balance(lo);
    }
  } else {
    hi = std::min(tair + CellWater::latent_heat(tair) * hm * rho_air / hc,
                  0.99 * CellWater::CRITICAL_T);
    bhi = balance(hi);
  }
  if (!(blo >= 0.0 && bhi <= 0.0))
    error->all(FLERR,
               "{}: cooling finds no surface temperature between {} and {} K that balances the "
               "heat of the vapour flux (air at T = {} K, h_c = {} W/m^2/K; step {})",
               command, lo, hi, tair, hc, update->ntimestep);
  double t = hi, bt = bhi;
  int side = 0;
  for (int iter = 0; iter < 200 && bt != 0.0 && hi - lo > 1e-12 * tair; iter++) {
    t = hi - bhi * (hi - lo) / (bhi - blo);
    if (!(t > lo && t < hi)) t = 0.5 * (lo + hi);
    bt = balance(t);
    // Illinois: halve the value at the end that stays twice in a row
    if (bt > 0.0) {
      lo = t;
      blo = bt;
      if (side > 0) bhi *= 0.5;
      side = 1;
    } else {
      hi = t;
      bhi = bt;
      if (side < 0) blo *= 0.5;
      side = -1;
    }
  }
  if (temperature != t) surface(t);
}

/* ----------------------------------------------------------------------
   cooling: the air temperature within the range of the heat balance's properties
------------------------------------------------------------------------- */

void TurgorDrive::check_cooling(double t) const
{
  if (!(t > CellWater::TRIPLE_T && t < CellWater::COOLING_TMAX))
    error->all(FLERR,
               "{}: air temperature T = {} K is outside {}-{} K, the range of cooling (liquid "
               "water, the vapour diffusivity in air behind h_c)",
               command, t, CellWater::TRIPLE_T, CellWater::COOLING_TMAX);
}

/* ----------------------------------------------------------------------
   air temperature T > 0 K (and below the critical point), 0 < RH <= 1, 0 <= h_m <=
   CellLimits::HM_MAX; 'when' ends the message
------------------------------------------------------------------------- */

void TurgorDrive::check_air(double t, double rh, double hm, const std::string &when) const
{
  if (!(t > 0.0)) error->all(FLERR, "{}: air temperature T = {} K must be > 0{}", command, t, when);
  if (!(t < CellWater::CRITICAL_T))
    error->all(FLERR,
               "{}: air temperature T = {} K must be below the critical point of water, {} K{}",
               command, t, CellWater::CRITICAL_T, when);
  if (!(rh > 0.0 && rh <= 1.0))
    error->all(FLERR, "{}: relative humidity RH = {} must be in (0, 1]{}", command, rh, when);
  if (!(hm >= 0.0 && hm <= CellLimits::HM_MAX))
    error->all(FLERR, "{}: mass-transfer coefficient hm = {} m/s must be >= 0 and <= 1e3 m/s{}",
               command, hm, when);
}

/* ----------------------------------------------------------------------
   the cells' temperature: 0 < T < the critical point of water; 'when' ends the message
------------------------------------------------------------------------- */

void TurgorDrive::check_temperature(double t, const std::string &when) const
{
  if (!(t > 0.0)) error->all(FLERR, "{}: temperature T = {} K must be > 0{}", command, t, when);
  if (!(t < CellWater::CRITICAL_T))
    error->all(FLERR, "{}: temperature T = {} K must be below the critical point of water, {} K{}",
               command, t, CellWater::CRITICAL_T, when);
}

/* ----------------------------------------------------------------------
   psi_ext finite and |psi_ext| <= CellLimits::PSI_MAX, above Kelvin's potential of any drying air
   (doc/fix_cell_turgor.md); 'who' begins the message, 'when' ends it
------------------------------------------------------------------------- */

void TurgorDrive::check_psi(double value, const std::string &who, const std::string &when) const
{
  if (!(value >= -CellLimits::PSI_MAX && value <= CellLimits::PSI_MAX))
    error->all(FLERR, "{}: water potential psi = {} Pa must be in [-1e9, 1e9] Pa{}", who, value,
               when);
}
