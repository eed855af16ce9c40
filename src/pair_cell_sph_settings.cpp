/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   pair_style cell/sph: the pair_style keywords, the pair_coeff values, the checks and per type
   pair constants of a run's init (init_style, init_one), and the keyword quantities evaluated
   every step (temp T, background P_b)
------------------------------------------------------------------------- */

#include "pair_cell_sph.h"

#include "atom.h"
#include "cell_compat.h"
#include "cell_limits.h"
#include "cell_params.h"
#include "cell_styles.h"
#include "cell_wall_triangles.h"
#include "cell_water.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_cell_continue.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

using namespace LAMMPS_NS;

static const char *const HMODE_NAMES[] = {"fixed", "mass", "adaptive"};

// the range of the Vogel correlation of the viscosity of water
static bool vogel_range(double t)
{
  return t >= CellWater::VOGEL_TMIN && t <= CellWater::VOGEL_TMAX;
}

// keywords of pair_style cell/sph that no scene used, and what replaces each
static const char *const REMOVED[][2] = {
    {"tensile",
     "the wall boundary with 'background auto' (or a background P_b) holds fluid in tension"},
    {"shift", "the wall boundary with 'background auto' makes the fluid at rest uniform"},
    {"Tref", "mu of pair_coeff is the viscosity at 25 C; 'temp T' scales it as water's"},
    {"grow",
     "h may grow 1.5 x its largest value at a run's start; split a longer run or give a cutoff"},
    {"eos", "the equation of state is linear, P = K (rho/rho0 - 1)"}};

/* ---------------------------------------------------------------------- */

void PairCellSPH::allocate()
{
  allocated = 1;
  const int n = atom->ntypes + 1;
  memory->create(setflag, n, n, "pair:setflag");
  memory->create(cutsq, n, n, "pair:cutsq");
  memory->create(rho0, n, n, "pair:rho0");
  memory->create(bulk, n, n, "pair:bulk");
  memory->create(mu, n, n, "pair:mu");
  memory->create(h, n, n, "pair:h");
  memory->create(pc, n, n, "pair:pc");
  memory->create(boundary, n, n, "pair:boundary");
  memory->create(wself, n, "pair:wself");
  memory->create(invrho0, n, "pair:invrho0");
  memory->create(fluid, n, "pair:fluid");
  memory->create(hcap, n, "pair:hcap");
  for (int i = 0; i < n; i++) {
    for (int j = 0; j < n; j++) {
      setflag[i][j] = 0;
      rho0[i][j] = bulk[i][j] = mu[i][j] = h[i][j] = 0.0;
      boundary[i][j] = 0;
      pc[i][j] = PairConst{0.0, {0.0, 0.0, 0.0}, 0.0};
    }
    wself[i] = invrho0[i] = hcap[i] = 0.0;
    fluid[i] = 0;
  }
  wall.allocate(n);
}

/* ----------------------------------------------------------------------
   pair_style cell/sph [cutoff] [kernel wendland|cubic|quintic|lucy] [h fixed|adaptive <eta>]
                       [temp <T>] [background <P_b>|auto <P_min>]
------------------------------------------------------------------------- */

void PairCellSPH::settings(int narg, char **arg)
{
  int iarg = 0;
  cut_global = 0.0;
  kernel = CellKernel::WENDLAND;
  hmode = HFIXED;
  eta = 0.0;
  temp_set = 0;
  temp = CellQuantity();
  muscale = 1.0;
  background_in = CellQuantity();
  background = 0.0;
  background_set = 0;
  background_auto = 0;
  background_min = 0.0;
  // a pair_style command again reuses this instance: the pair arrays regrow for the new settings
  // (h mode)
  maxpairs = 0;
  if (narg > 0 && utils::is_double(arg[0])) {
    cut_global = utils::numeric(FLERR, arg[0], false, lmp);
    if (cut_global <= 0.0)
      error->all(FLERR, "Pair style cell/sph: cutoff = {} must be > 0", cut_global);
    iarg = 1;
  }
  while (iarg < narg) {
    for (const auto &gone : REMOVED)
      if (strcmp(arg[iarg], gone[0]) == 0)
        error->all(FLERR, "Pair style cell/sph: keyword '{}' was removed: {}", gone[0], gone[1]);
    if (iarg + 1 >= narg)
      error->all(FLERR, "Pair style cell/sph: keyword '{}' needs a value", arg[iarg]);
    const std::string value = arg[iarg + 1];
    if (strcmp(arg[iarg], "h") == 0) {
      if (value == HMODE_NAMES[HFIXED]) {
        hmode = HFIXED;
      } else if (value == HMODE_NAMES[HADAPTIVE]) {
        hmode = HADAPTIVE;
        if (iarg + 2 >= narg)
          error->all(FLERR,
                     "Pair style cell/sph: 'h adaptive' needs a value eta (h = eta "
                     "(m/rho)^(1/3))");
        eta = utils::numeric(FLERR, arg[iarg + 2], false, lmp);
        if (eta <= 0.0)
          error->all(FLERR, "Pair style cell/sph: h adaptive eta = {} must be > 0", eta);
        iarg++;
      } else if (value == HMODE_NAMES[1]) {
        error->all(FLERR,
                   "Pair style cell/sph: 'h mass' was removed: 'h adaptive <eta>' (h from each "
                   "atom's mass and density) or h fixed");
      } else {
        error->all(FLERR,
                   "Pair style cell/sph: unknown h mode '{}' (expected fixed or adaptive <eta>)",
                   value);
      }
    } else if (strcmp(arg[iarg], "temp") == 0) {
      temp_set = 1;
      temp = CellQuantity::parse(lmp, arg[iarg + 1], "Pair style cell/sph: temp");
      if (!temp.is_variable()) {
        if (!vogel_range(temp.value))
          error->all(FLERR,
                     "Pair style cell/sph: temperature T = {} K is outside {}-{} K (0-370 C), the "
                     "range of the Vogel correlation of the viscosity of water",
                     temp.value, CellWater::VOGEL_TMIN, CellWater::VOGEL_TMAX);
      }
    } else if (strcmp(arg[iarg], "background") == 0) {
      iarg += parse_background(narg - iarg - 1, &arg[iarg + 1]);
    } else if (strcmp(arg[iarg], "kernel") == 0) {
      kernel = CellKernel::parse(value);
      if (kernel < 0)
        error->all(FLERR,
                   "Pair style cell/sph: unknown kernel '{}' (expected wendland, cubic, quintic "
                   "or lucy)",
                   value);
    } else {
      error->all(FLERR,
                 "Pair style cell/sph: unknown keyword '{}' (expected a cutoff, 'kernel', 'h', "
                 "'temp' or 'background')",
                 arg[iarg]);
    }
    iarg += 2;
  }
  create_fields();
}

/* ----------------------------------------------------------------------
   background <P_b> | auto <P_min> (arg: the values after the keyword, narg >= 1); returns the
   number of values beyond the first
------------------------------------------------------------------------- */

int PairCellSPH::parse_background(int narg, char **arg)
{
  if (strcmp(arg[0], "auto") != 0) {
    background_in = CellQuantity::parse(lmp, arg[0], "Pair style cell/sph: background");
    background = background_in.value;
    if (!std::isfinite(background))
      error->all(FLERR, "Pair style cell/sph: background P_b = {} Pa is not a number", background);
    if (!background_in.is_variable())
      CellLimits::within(error, "Pair style cell/sph: background P_b", background,
                         -CellLimits::PRESSURE_MAX, CellLimits::PRESSURE_MAX, "Pa", false);
    return 0;
  }
  if (narg < 2)
    error->all(FLERR, "Pair style cell/sph: 'background auto' needs a value P_min (Pa)");
  background_auto = 1;
  background_min = utils::numeric(FLERR, arg[1], false, lmp);
  if (!(background_min >= 0.0))
    error->all(FLERR, "Pair style cell/sph: background auto P_min = {} Pa must be >= 0",
               background_min);
  CellLimits::within(error, "Pair style cell/sph: background auto P_min", background_min, 0.0,
                     CellLimits::PRESSURE_MAX, "Pa", false);
  if (narg > 2 && strcmp(arg[2], "lag") == 0)
    error->all(FLERR,
               "Pair style cell/sph: 'background auto ... lag' was removed: P_b follows its "
               "target over {} steps",
               AUTO_LAG);
  return 1;
}

/* ----------------------------------------------------------------------
   pair_coeff I J rho0 K mu h
   pair_coeff I J file <parameter file>    (keys sph_rho0, sph_K, sph_mu, sph_h)
------------------------------------------------------------------------- */

void PairCellSPH::coeff(int narg, char **arg)
{
  if (narg < 2) error->all(FLERR, "Incorrect args for pair_coeff cell/sph");
  if (!allocated) allocate();
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);

  double rho0_one = 0.0, bulk_one = 0.0, mu_one = 0.0, h_one = 0.0;
  const int iswall = narg >= 3 && strcmp(arg[2], "wall") == 0;
  if (iswall) {
    if (ilo <= jhi && jlo <= ihi)
      error->all(FLERR,
                 "Pair_coeff cell/sph: {} {} wall: a type cannot be the wall of itself (give the "
                 "fluid type and the wall type)",
                 arg[0], arg[1]);
    // pair_coeff <fluid> <wall> wall
    if (narg > 3 && strcmp(arg[3], "adhesion") == 0)
      error->all(FLERR,
                 "Pair_coeff cell/sph: 'wall adhesion' was removed: the wall boundary with "
                 "'background auto' (or a background P_b) holds the fluid on the wall");
    if (narg > 3)
      error->all(FLERR,
                 "Pair_coeff cell/sph: expected 'pair_coeff <fluid> <wall> wall', got {} args "
                 "after wall",
                 narg - 3);
  } else if (narg == 4 && strcmp(arg[2], "file") == 0) {
    CellParams params(lmp, arg[3], "pair_coeff cell/sph");
    rho0_one = params.positive("sph_rho0", CellLimits::SPH_RHO0_MAX, "kg/m^3");
    bulk_one = params.positive("sph_K", CellLimits::SPH_K_MAX, "Pa");
    mu_one = params.nonnegative("sph_mu", CellLimits::SPH_MU_MAX, "Pa s");
    h_one = params.positive("sph_h", CellLimits::SPH_H_MAX, "m");
    if (params.has("sph_kernel") && params.word("sph_kernel") != CellKernel::NAMES[kernel])
      error->all(FLERR,
                 "Pair_coeff cell/sph: {} sets sph_kernel = {} but pair_style cell/sph uses "
                 "kernel {} (the kernel is a pair_style keyword)",
                 arg[3], params.word("sph_kernel"), CellKernel::NAMES[kernel]);
  } else {
    if (narg != 6)
      error->all(FLERR,
                 "Incorrect args for pair_coeff cell/sph: expected 'pair_coeff <I> <J> <rho0> "
                 "<K> <mu> <h>', 'pair_coeff <I> <J> file <parameter file>' or 'pair_coeff "
                 "<fluid> <wall> wall', got {} args",
                 narg);
    rho0_one = utils::numeric(FLERR, arg[2], false, lmp);
    bulk_one = utils::numeric(FLERR, arg[3], false, lmp);
    mu_one = utils::numeric(FLERR, arg[4], false, lmp);
    h_one = utils::numeric(FLERR, arg[5], false, lmp);
    if (rho0_one <= 0.0)
      error->all(FLERR, "Pair_coeff cell/sph: reference density rho0 = {} must be > 0", rho0_one);
    if (bulk_one <= 0.0)
      error->all(FLERR, "Pair_coeff cell/sph: bulk modulus K = {} must be > 0", bulk_one);
    if (mu_one < 0.0)
      error->all(FLERR, "Pair_coeff cell/sph: viscosity mu = {} must be >= 0", mu_one);
    if (h_one <= 0.0)
      error->all(FLERR, "Pair_coeff cell/sph: smoothing length h = {} must be > 0", h_one);
    const std::string c = "Pair_coeff cell/sph: ";
    CellLimits::within(error, c + "reference density rho0", rho0_one, 0.0, CellLimits::SPH_RHO0_MAX,
                       "kg/m^3", true);
    CellLimits::within(error, c + "bulk modulus K", bulk_one, 0.0, CellLimits::SPH_K_MAX, "Pa",
                       true);
    CellLimits::within(error, c + "viscosity mu", mu_one, 0.0, CellLimits::SPH_MU_MAX, "Pa s",
                       false);
    CellLimits::within(error, c + "smoothing length h", h_one, 0.0, CellLimits::SPH_H_MAX, "m",
                       true);
  }

  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = std::max(jlo, i); j <= jhi; j++) {
      rho0[i][j] = rho0_one;
      bulk[i][j] = bulk_one;
      mu[i][j] = mu_one;
      h[i][j] = h_one;
      boundary[i][j] = iswall;
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0)
    error->all(FLERR, "Incorrect args for pair_coeff cell/sph: no type pair in {} {}", arg[0],
               arg[1]);
}

/* ----------------------------------------------------------------------
   the per-atom vectors of cell/sph (cell_styles.h) as fix cellsph (property/atom, with ghosts) when
   an input has declared none of them, at pair_style and, after read_restart, at the first run (where
   the fix takes its values from the restart file); an input's own 'fix cellsph all property/atom
   d_rho d_pressure ...' before read_data keeps working
------------------------------------------------------------------------- */

void PairCellSPH::create_fields()
{
  int flag, cols;
  for (const char *name : {CellField::RHO, CellField::PRESSURE, CellField::H, CellField::OMEGA})
    if (atom->find_custom(name, flag, cols) >= 0) return;
  if (modify->find_fix(CellField::FIX) >= 0) return;
  modify->add_fix(fmt::format("{} all property/atom d_{} d_{} d_{} d_{} ghost yes", CellField::FIX,
                              CellField::RHO, CellField::PRESSURE, CellField::H, CellField::OMEGA));
}

/* ----------------------------------------------------------------------
   the per-atom data pair cell/sph needs: rmass, the custom vectors rho and pressure (and h and
   omega with per-atom h)
------------------------------------------------------------------------- */

void PairCellSPH::find_fields()
{
  create_fields();
  if (!atom->rmass_flag)
    error->all(FLERR,
               "Pair style cell/sph needs per-atom masses (rmass), which atom_style {} does not "
               "have: add 'fix cellatoms all property/atom rmass d2_xref 3 ghost yes' (or "
               "'cell/atoms') before read_data",
               atom->atom_style);
  int flag, cols;
  irho = atom->find_custom(CellField::RHO, flag, cols);
  if (irho < 0 || flag != 1 || cols != 0)
    error->all(FLERR,
               "Pair style cell/sph needs the per-atom vector rho: add 'fix cellsph all "
               "property/atom d_rho d_pressure ghost yes' before read_data");
  ipressure = atom->find_custom(CellField::PRESSURE, flag, cols);
  if (ipressure < 0 || flag != 1 || cols != 0)
    error->all(FLERR,
               "Pair style cell/sph needs the per-atom vector pressure: add 'fix cellsph all "
               "property/atom d_rho d_pressure ghost yes' before read_data");

  if (hmode != HFIXED) {
    int hflag, hcols, oflag, ocols;
    ih = atom->find_custom(CellField::H, hflag, hcols);
    iomega = atom->find_custom(CellField::OMEGA, oflag, ocols);
    if (ih < 0 || hflag != 1 || hcols != 0 || iomega < 0 || oflag != 1 || ocols != 0)
      error->all(FLERR,
                 "Pair style cell/sph: h {} needs the per-atom vectors h and omega: add 'fix "
                 "cellsph all property/atom d_rho d_pressure d_h d_omega ghost yes' before "
                 "read_data",
                 HMODE_NAMES[hmode]);
  }
}

/* ----------------------------------------------------------------------
   stop on a fluid atom without a positive per-atom mass (the lowest ID of all ranks)
------------------------------------------------------------------------- */

void PairCellSPH::check_masses()
{
  tagint massless = MAXTAGINT, first;
  for (int i = 0; i < atom->nlocal; i++)
    if (fluid[atom->type[i]] && !(atom->rmass[i] > 0.0))
      massless = std::min(massless, atom->tag[i]);
  MPI_Allreduce(&massless, &first, 1, MPI_LMP_TAGINT, MPI_MIN, world);
  if (first != MAXTAGINT)
    error->all(FLERR,
               "Pair style cell/sph: fluid atom {} has per-atom mass rmass <= 0: set the masses "
               "(e.g. 'set type <I> mass <m>')",
               first);
}

/* ----------------------------------------------------------------------
   check the per-atom data, request a half list, select the loops
------------------------------------------------------------------------- */

void PairCellSPH::init_style()
{
  find_fields();
  if (temp_set && !temp.name.empty()) { temp.resolve(lmp, "Pair style cell/sph: temp variable"); }
  muscale = 1.0;

  const int n = atom->ntypes;
  viscous = 0;
  bool all_set = true;
  for (int i = 1; i <= n; i++) {
    fluid[i] = setflag[i][i];
    for (int j = i; j <= n; j++) {
      if (setflag[i][j] && mu[i][j] > 0.0) viscous = 1;
      all_set = all_set && setflag[i][j];
    }
  }
  // per-atom h: the largest h of each fluid type that the neighbour cutoff allows
  for (int i = 1; i <= n; i++)
    hcap[i] = cut_global > 0.0 ? cut_global / CellKernel::support(kernel) : run_hcap(i);
  walls = has_wall_boundary() ? 1 : 0;
  if (background_in.is_variable())
    background_in.resolve(lmp, "Pair style cell/sph: background variable");
  if ((background != 0.0 || background_in.is_variable() || background_auto) && !walls) {
    const std::string pb = background_auto ? fmt::format("auto {} Pa", background_min)
        : background_in.is_variable()      ? "v_" + background_in.name
                                           : fmt::format("{} Pa", background);
    error->all(FLERR,
               "Pair cell/sph: background P_b = {} needs the wall boundary (pair_coeff I J wall), "
               "whose triangles carry P_b from outside",
               pb);
  }
  if (walls) {
    wall.init();
    comm_forward = std::max(3, CellWallTriangles::COMM_SIZE);
  }
  writedata = all_set ? 1 : 0;
  if (viscous && !comm->ghost_velocity)
    error->all(FLERR,
               "Pair style cell/sph with viscosity mu > 0 needs ghost velocities: use "
               "'comm_modify vel yes'");

  check_masses();
  // a run's setup that continues the last step: its velocities for the viscous forces
  FixCellContinue::ensure(lmp);
  CellCompat::request_list(neighbor, this, instance_me, CellCompat::REQ_DEFAULT);
}

/* ----------------------------------------------------------------------
   the largest h of fluid type t that the default cutoff allows in this run: GROW x the largest
   per-atom h of the type over all ranks (h adaptive, atoms that have one), so that the neighbour
   list follows a cell that dries or takes up water; from the pair_coeff h before any atom has one
------------------------------------------------------------------------- */

double PairCellSPH::run_hcap(int t) const
{
  double hmax = 0.0, all = 0.0;
  if (hmode != HFIXED) {
    const double *hv = atom->dvector[ih];
    for (int i = 0; i < atom->nlocal; i++)
      if (atom->type[i] == t) hmax = std::max(hmax, hv[i]);
  }
  MPI_Allreduce(&hmax, &all, 1, MPI_DOUBLE, MPI_MAX, world);
  return GROW * (all > 0.0 ? all : h[t][t]);
}

/* ----------------------------------------------------------------------
   kernel constants, viscosity and cutoff of one type pair; the equation of state of type i
------------------------------------------------------------------------- */

double PairCellSPH::init_one(int i, int j)
{
  if (!setflag[i][j]) {
    pc[i][j] = pc[j][i] = PairConst{0.0, {0.0, 0.0, 0.0}, 0.0};
    return 0.0;
  }
  if (boundary[i][j]) {
    // the wall boundary's own constants; no SPH sums over the pair
    pc[i][j] = pc[j][i] = PairConst{0.0, {0.0, 0.0, 0.0}, 0.0};
    const double range = wall.init_pair(i, j);
    return cut_global > 0.0 ? std::max(cut_global, range) : range;
  }
  for (int t : {i, j}) {
    if (!setflag[t][t])
      error->all(FLERR,
                 "Pair cell/sph: pair_coeff {} {} is set but pair_coeff {} {} is not (type {} "
                 "takes its equation of state from pair_coeff {} {})",
                 i, j, t, t, t, t, t);
    if (rho0[i][j] != rho0[t][t] || bulk[i][j] != bulk[t][t])
      error->all(FLERR,
                 "Pair cell/sph: pair_coeff {} {} has rho0 = {}, K = {} but pair_coeff {} {} has "
                 "rho0 = {}, K = {}: interacting types must share the equation of state",
                 i, j, rho0[i][j], bulk[i][j], t, t, rho0[t][t], bulk[t][t]);
  }

  const int dim = domain->dimension;
  const double support = CellKernel::support(kernel) * h[i][j];
  if (cut_global > 0.0 && cut_global < support)
    error->all(FLERR,
               "Pair style cell/sph: cutoff = {} is shorter than the support {} of the {} kernel "
               "for pair {} {} ({} h, h = {})",
               cut_global, support, CellKernel::NAMES[kernel], i, j, CellKernel::support(kernel),
               h[i][j]);

  // per-atom h: every pair within the support of the largest h allowed
  const double reach =
      hmode == HFIXED ? support : CellKernel::support(kernel) * std::max(hcap[i], hcap[j]);
  pc[i][j].cutsq = reach * reach;
  pc[i][j].scale = CellKernel::scale(kernel, dim, h[i][j]);
  pc[i][j].mu2 = 2.0 * mu[i][j];
  pc[j][i] = pc[i][j];

  if (i == j) {
    wself[i] = CellKernel::W(kernel, pc[i][i].scale, 0.0);
    invrho0[i] = 1.0 / rho0[i][i];
  }
  return cut_global > 0.0 ? cut_global : reach;
}

/* ----------------------------------------------------------------------
   temp T: mu(T) = mu mu_w(T)/mu_w(25 C) of every pair (mu of pair_coeff at 25 C), mu_w from the
   Vogel equation of liquid water (doc/model.md §5.9); T evaluated once per step (a variable may
   change it)
------------------------------------------------------------------------- */

void PairCellSPH::update_viscosity()
{
  const double t = temp.get(lmp);
  if (!vogel_range(t))
    error->all(FLERR,
               "Pair style cell/sph: temperature T = {} K (variable {}) on step {} is outside "
               "{}-{} K (0-370 C), the range of the Vogel correlation of the viscosity of water",
               t, temp.name.empty() ? "-" : temp.name, update->ntimestep, CellWater::VOGEL_TMIN,
               CellWater::VOGEL_TMAX);
  temperature = t;
  // mu(T) / mu(25 C) = mu_w(T) / mu_w(25 C) (doc/model.md §5.9)
  const double scale = CellWater::water_viscosity(t) / CellWater::water_viscosity(TREF);
  if (scale == muscale) return;
  muscale = scale;
  const int n = atom->ntypes;
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++)
      if (setflag[i][j] && !boundary[i][j]) pc[i][j].mu2 = pc[j][i].mu2 = 2.0 * mu[i][j] * muscale;
}

/* ----------------------------------------------------------------------
   background P_b from its equal-style variable, evaluated once per step (doc/pair_cell_sph.md,
   background pressure)
------------------------------------------------------------------------- */

void PairCellSPH::update_background()
{
  background = background_in.get(lmp);
  if (!std::isfinite(background))
    error->all(FLERR,
               "Pair style cell/sph: background P_b = {} Pa (variable {}) on step {} is not a "
               "number",
               background, background_in.name, update->ntimestep);
  if (std::fabs(background) > CellLimits::PRESSURE_MAX)
    error->all(FLERR,
               "Pair style cell/sph: background P_b = {} Pa (variable {}) on step {} must be in "
               "[{:g}, {:g}] Pa",
               background, background_in.name, update->ntimestep, -CellLimits::PRESSURE_MAX,
               CellLimits::PRESSURE_MAX);
}

/* ----------------------------------------------------------------------
   whether a type pair is a wall boundary pair (before init_style, which sets walls)
------------------------------------------------------------------------- */

bool PairCellSPH::has_wall_boundary() const
{
  for (int i = 1; allocated && i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (setflag[i][j] && boundary[i][j]) return true;
  return false;
}
