/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   fix cell/turgor: every N steps each cell (molecule ID) gains or loses water at the rate
   dM/dt = rho_w L_P A (psi_ext - (P_T - pi)), or through the wall and an air film in series, or
   along a prescribed X/X0(t) (doc/model.md §5.7-5.10), integrated with an exponential Euler step
   in the cell's pressure response so that it is stable for any L_P, and spread over its fluid.
------------------------------------------------------------------------- */

#include "fix_cell_turgor.h"

#include "atom.h"
#include "bond.h"
#include "cell_args.h"
#include "cell_compat.h"
#include "cell_limits.h"
#include "cell_params.h"
#include "cell_reduce.h"
#include "cell_restart.h"
#include "cell_water.h"
#include "comm.h"
#include "error.h"
#include "fix_cell_turgor_junctions.h"
#include "force.h"
#include "group.h"
#include "input.h"
#include "math_const.h"
#include "memory.h"
#include "pair.h"
#include "update.h"
#include "variable.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;
using MathConst::MY_PI;

// 7: + the wall edges of accel; 6: + the water and time of the transfer waiting to be applied (per
// atom: its mass change); 5: + water exchanged between cells; 4: + accel auto state; 3: + solids
// per cell; 2: begins with -version; 1: none
static const int RESTART_VERSION = 7;

// the largest conductance L_P or L_cc (m s^-1 Pa^-1) and activation energy Ea (J/mol) accepted, far
// above any membrane's (doc/fix_cell_turgor.md); the messages give them as 1e3 and 1e6

// global restart values after the number of cells: physical time, water moved (1-3), adapted
// accel (0: not auto), open and sealed samples, lag estimate and its error (4), water exchanged
// between cells (5), water and physical time of the waiting transfer, the step of the last
// transfer's evaluation (6), the shortest and the last longest wall edge, its growth (7)
static int restart_globals(int version)
{
  return version >= 7 ? 14 : version >= 6 ? 11 : version >= 5 ? 8 : (version >= 4 ? 7 : 2);
}

/* ---------------------------------------------------------------------- */

FixCellTurgor::FixCellTurgor(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), lp(0.0), pi0(0.0), rhow(1000.0), accel(lmp), ea(0.0),
    osmotic_model(lmp, "Fix cell/turgor"), drive(lmp, "Fix cell/turgor"), tau(0.0), bulk(0.0),
    kfluid(0.0), limit(LIMIT_ERROR), limit_set(0), fluidtype(1), walltype(2), state(lmp),
    physical_time(0.0), water_moved(0.0), max_imbalance(0.0), max_stiffness(0.0), busiest(0.0),
    exposed_flux(0.0), exposed_area(0.0), lcc{0.0, "", -1}, water_exchanged(0.0), exchange_net(0.0),
    exchange_stiffness(0.0), crossing(0)
{
  if (narg < 4)
    error->all(FLERR,
               "Illegal fix cell/turgor command: expected 'fix ID group cell/turgor N keyword "
               "value ...'");
  every = utils::inumeric(FLERR, arg[3], false, lmp);
  if (every <= 0) error->all(FLERR, "Fix cell/turgor: N = {} must be > 0", every);

  bool lp_set = false, pi0_set = false;
  int bondtype = 0;           // 'exchange ... bondtype N'
  bool exchanging = false;    // 'exchange' given
  std::string areas;          // 'exchange ... areas FILE'
  bool lcc_file = false;      // 'exchange file ...': L_cc from the parameter file's turgor_Lcc
  double file_lcc = -1.0;     // turgor_Lcc of the last 'file', -1 if none
  std::string measure = "wall";
  int iarg = 4;
  // the values after keyword key: n of them, or stop
  auto values = [&](const std::string &key, int n) {
    if (iarg + n >= narg)
      error->all(FLERR, "Fix cell/turgor: missing value after '{}' (expected {})", key, n);
    return &arg[iarg + 1];
  };
  while (iarg < narg) {
    const std::string key = arg[iarg];
    const char *value = values(key, 1)[0];
    int used = 2;
    if (key == "LP") {
      lp = utils::numeric(FLERR, value, false, lmp);
      lp_set = true;
    } else if (key == "pi0") {
      pi0 = utils::numeric(FLERR, value, false, lmp);
      pi0_set = true;
    } else if (int n = drive.parse(narg - iarg, &arg[iarg], osmotic_model.tref)) {
      used = n;
    } else if (key == "Ea") {
      ea = utils::numeric(FLERR, value, false, lmp);
      if (!(ea >= 0.0 && ea <= CellLimits::EA_MAX))
        error->all(FLERR,
                   "Fix cell/turgor: activation energy Ea = {} must be >= 0 and <= 1e6 J/mol", ea);
    } else if (key == "rhow") {
      rhow = utils::numeric(FLERR, value, false, lmp);
      if (rhow <= 0.0)
        error->all(FLERR, "Fix cell/turgor: water density rhow = {} must be > 0", rhow);
    } else if (key == "exchange") {
      char **v = values(key, 3);
      if (strcmp(v[1], "bondtype") != 0)
        error->all(FLERR,
                   "Fix cell/turgor: expected 'exchange L_cc bondtype N', not 'exchange {} {}'",
                   v[0], v[1]);
      lcc_file = strcmp(v[0], "file") == 0;
      if (!lcc_file) lcc = CellQuantity::parse(lmp, v[0], "Fix cell/turgor: exchange L_cc");
      if (!lcc_file && !lcc.is_variable()) check_lcc(lcc.value, "");
      bondtype = utils::inumeric(FLERR, v[2], false, lmp);
      exchanging = true;
      used = 4;
      if (iarg + 5 < narg && strcmp(arg[iarg + 4], "areas") == 0) {
        areas = arg[iarg + 5];
        used = 6;
      }
    } else if (key == "accel") {
      used = 1 + accel.parse(narg - iarg - 1, &arg[iarg + 1], "Fix cell/turgor");
    } else if (key == "bulk") {
      bulk = utils::numeric(FLERR, value, false, lmp);
      if (bulk <= 0.0) error->all(FLERR, "Fix cell/turgor: bulk modulus K = {} must be > 0", bulk);
    } else if (key == "limit") {
      if (strcmp(value, "error") == 0)
        limit = LIMIT_ERROR;
      else if (strcmp(value, "warn") == 0)
        limit = LIMIT_WARN;
      else
        error->all(FLERR, "Fix cell/turgor: unknown limit action '{}' (expected error or warn)",
                   value);
      limit_set = 1;
    } else if (int n = osmotic_model.parse(narg - iarg, &arg[iarg])) {
      used = n;
    } else if (key == "file") {
      CellParams params(lmp, value, "Fix cell/turgor");
      lp = params.nonnegative("turgor_LP", CellLimits::CONDUCTANCE_MAX, "m s^-1 Pa^-1");
      pi0 = params.nonnegative("turgor_pi0");
      lp_set = pi0_set = true;
      // optional drying keys (doc/fix_cell_turgor.md)
      if (params.has("turgor_Ea"))
        ea = params.nonnegative("turgor_Ea", CellLimits::EA_MAX, "J/mol");
      if (params.has("turgor_Lcc"))
        file_lcc = params.nonnegative("turgor_Lcc", CellLimits::CONDUCTANCE_MAX, "m s^-1 Pa^-1");
      osmotic_model.read(params, value);
    } else if (key == "turgor") {
      measure = value;
    } else if (key == "tau") {
      tau = utils::numeric(FLERR, value, false, lmp);
      if (tau <= 0.0) error->all(FLERR, "Fix cell/turgor: offset time tau = {} must be > 0", tau);
    } else if (key == "fluid") {
      fluidtype = utils::inumeric(FLERR, value, false, lmp);
    } else if (key == "wall") {
      walltype = utils::inumeric(FLERR, value, false, lmp);
    } else {
      error->all(FLERR, "Fix cell/turgor: unknown keyword '{}'", key);
    }
    iarg += used;
  }
  if (!lp_set) error->all(FLERR, "Fix cell/turgor: wall permeability not set: give 'LP value'");
  check_lp(lp, "Fix cell/turgor");
  if (!pi0_set) error->all(FLERR, "Fix cell/turgor: osmotic pressure not set: give 'pi0 value'");
  if (pi0 < 0.0) error->all(FLERR, "Fix cell/turgor: osmotic pressure pi0 = {} must be >= 0", pi0);
  drive.check(osmotic_model.tref);
  osmotic_model.check();
  if (accel.automatic && drive.kind == TurgorDrive::CURVE)
    error->all(FLERR,
               "Fix cell/turgor: accel auto needs the psi or air drive (a prescribed curve has no "
               "flux that the mechanics could delay)");

  if (lcc_file) {
    if (file_lcc < 0.0)
      error->all(FLERR,
                 "Fix cell/turgor: 'exchange file' takes L_cc from the key turgor_Lcc of a "
                 "parameter file: give 'file name' with that key");
    lcc = CellQuantity{file_lcc, "", -1};
  }
  if (exchanging && drive.kind == TurgorDrive::CURVE)
    error->all(FLERR,
               "Fix cell/turgor: exchange needs the psi or air drive (a prescribed curve sets each "
               "cell's water)");

  cells = std::make_unique<CellReduce>(lmp, "Fix cell/turgor", igroup, fluidtype, walltype);
  cells->set_turgor(measure);
  if (drive.surface_group >= 0) cells->set_surface(group->bitmask[drive.surface_group]);
  if (exchanging) {
    // bond type 0 too is out of range there
    junctions = std::make_unique<TurgorJunctions>(lmp, "Fix cell/turgor", bondtype, areas);
    network = std::make_unique<TurgorNetwork>(world);
  }

  vector_flag = 1;
  size_vector = 19;
  global_freq = 1;
  extvector = 0;
  restart_global = 1;
  restart_peratom = 1;
  create_attribute = 1;
  comm_forward = 1;
  grow_arrays(atom->nmax);
  for (int i = 0; i < atom->nlocal; i++) pending[i] = 0.0;
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
}

/* ----------------------------------------------------------------------
   a transfer still waiting (evaluated at the last step of the fix's last run) is applied
------------------------------------------------------------------------- */

FixCellTurgor::~FixCellTurgor()
{
  if (atom->rmass)
    for (int i = 0; i < atom->nlocal; i++) atom->rmass[i] *= 1.0 + pending[i];
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(pending);
}

/* ---------------------------------------------------------------------- */

int FixCellTurgor::setmask()
{
  return END_OF_STEP | PRE_FORCE;
}

/* ----------------------------------------------------------------------
   cells of the group, per-cell state for new cells, fluid bulk modulus, wall G t0 per bond type
------------------------------------------------------------------------- */

void FixCellTurgor::init()
{
  // every cell's state from where it was (the last run's home ranks, or the restart file on every
  // rank) to the cell's home rank of this run; cells no longer in the group stay on rank 0
  std::vector<double> list, before;
  state.gather(true, list);
  // the state before the transfer evaluated at this step too, for setup to evaluate it again
  const bool again = saved == update->ntimestep;
  if (again) {
    state.swap_saved();
    state.gather(true, before);
    state.swap_saved();
  }
  cells->find_cells();
  cells->init();
  state.keep_home(list, cells->registry(), pi0);
  if (again) {
    state.swap_saved();
    state.keep_home(before, cells->registry(), pi0);
    state.swap_saved();
  }
  drive.init();
  lcc.resolve(lmp, "Fix cell/turgor: variable");
  if (junctions) junctions->init();
  network_stale = true;
  kfluid = bulk > 0.0 ? bulk : pair_bulk_modulus();

  gt0.clear();
  int dim;
  const double *shear = force->bond ? (double *) force->bond->extract("G", dim) : nullptr;
  const double *thickness = force->bond ? (double *) force->bond->extract("t0", dim) : nullptr;
  if (shear && thickness)
    for (int t = 0; t <= atom->nbondtypes; t++)
      gt0.push_back(t > 0 ? shear[t] * thickness[t] : 0.0);
  else if (limit_set && comm->me == 0)
    error->warning(FLERR,
                   "Fix cell/turgor: no limit-point check: the bond style does not provide the "
                   "wall's G and t0 (bond_style cell/neohookean does)");
}

/* ----------------------------------------------------------------------
   K of the fluid's equation of state, from pair cell/sph
------------------------------------------------------------------------- */

double FixCellTurgor::pair_bulk_modulus()
{
  Pair *pair = force->pair_match("cell/sph", 1);
  int dim = -1;
  const double *k = pair ? (double *) pair->extract("K", dim) : nullptr;
  if (!k || dim != 0)
    error->all(FLERR,
               "Fix cell/turgor: the fluid's bulk modulus is unknown: give 'bulk K' or use "
               "pair_style cell/sph");
  return *k;
}

/* ---------------------------------------------------------------------- */

void FixCellTurgor::setup(int)
{
  // a transfer waiting from the last run or the restart file (its per-atom changes)
  int mine = 0, any = 0;
  for (int i = 0; i < atom->nlocal && !mine; i++) mine = pending[i] != 0.0;
  MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, world);
  any_pending = any != 0 || moved_pending != 0.0 || time_pending != 0.0;
  // the transfer of the run's first step: evaluated again from the state as it is now when the
  // last run's end evaluated it (the same, unless set or fix_modify changed something between
  // the runs), kept as read from a restart file, else evaluated here
  const bigint step = update->ntimestep;
  if (saved == step) {
    state.restore();
    accel.restore(accel_saved);
    water_exchanged = exchanged_saved;
    transfer();
  } else if ((step + 1) % every == 0 && evaluated != step) {
    transfer();
  } else {
    evaluate(false);
  }
}

/* ----------------------------------------------------------------------
   evaluate the transfer of the next step; on a run's last step (the only one whose transfer a
   setup evaluates again) keep the state from before it
------------------------------------------------------------------------- */

void FixCellTurgor::transfer()
{
  saved = update->ntimestep == update->laststep ? update->ntimestep : -1;
  if (saved >= 0) {
    state.save();
    accel_saved = accel.save();
    exchanged_saved = water_exchanged;
  }
  evaluate(true);
}

/* ----------------------------------------------------------------------
   the transfer of the last step's end, before this step's forces (after its neighbour build)
------------------------------------------------------------------------- */

void FixCellTurgor::pre_force(int)
{
  if (any_pending) apply_pending();
}

/* ----------------------------------------------------------------------
   m_i <- m_i (1 + dM/M) on the fluid atoms of the cells, owned then ghosts
------------------------------------------------------------------------- */

void FixCellTurgor::apply_pending()
{
  double *rmass = atom->rmass;
  for (int i = 0; i < atom->nlocal; i++) {
    rmass[i] *= 1.0 + pending[i];
    pending[i] = 0.0;
  }
  CellCompat::forward_comm(comm, this);
  water_moved += moved_pending;
  physical_time += time_pending;
  moved_pending = time_pending = 0.0;
  any_pending = false;
}

/* ---------------------------------------------------------------------- */

void FixCellTurgor::end_of_step()
{
  // evaluated at the end of step j N - 1, applied before the forces of step j N
  if ((update->ntimestep + 1) % every == 0) transfer();
}

/* ----------------------------------------------------------------------
   per-cell turgor, osmotic pressure and water flux; with transfer, advance each cell's fluid mass
   over dtw = accel N dt of physical time and spread it over the cell's fluid atoms
------------------------------------------------------------------------- */

void FixCellTurgor::evaluate(bool transfer)
{
  cells->reduce(gt0.empty() ? nullptr : gt0.data());
  // the per-cell logic runs on each cell's home rank, for its home cells
  const std::vector<int> &home = cells->home_cells();
  // accel auto: transfer j (at step j N; the next one when not transferring) is at position
  // (j - 1) % (every + hold) of its cycle: open for every transfers, then sealed (no water, no
  // physical time) for hold; the second half of each is sampled (doc/model.md §5.12)
  const bigint next = update->ntimestep + 1;
  const TurgorAccel::Cycle cycle =
      accel.cycle(next / every + (transfer ? 0 : 1), transfer, offset_time(), every * update->dt);
  const double dtw = cycle.sealed ? 0.0 : accel.value * every * update->dt;
  std::vector<double> scale(home.size(), 0.0);
  double moved = 0.0, first_accel = HUGE_VAL;
  // exchange: per home cell psi, dpsi/dM, rate and z for the network, and M
  const size_t nnet = junctions ? home.size() : 0;
  TurgorNetwork::Cells net{std::vector<double>(nnet), std::vector<double>(nnet),
                           std::vector<double>(nnet), std::vector<double>(nnet)};
  std::vector<double> net_mass(nnet);
  max_imbalance = max_stiffness = 0.0;
  failure = Failure{cells->ncell(), ""};
  warnings.clear();

  // T and the drive's inputs at the physical time of the start of the transfer (f_ID[2]); a curve
  // X/X0(t) at its end
  // (the curve's variable reads f_ID[2] at the transfer's end; the fix's clock moves there when
  // the transfer is applied)
  const double start = physical_time;
  drive.evaluate(physical_time, drive.kind == TurgorDrive::CURVE && transfer ? dtw : 0.0);
  physical_time = start;

  // each home cell's flux turgor and conductance, the cell checked and its M0 and S set
  std::vector<double> turgors(home.size()), conductances(home.size());
  for (int h = 0; h < (int) home.size(); h++) {
    const int c = home[h];
    const tagint id = cells->id(c);
    const double mass = cells->mass(c);
    const double volume = cells->volume(c);
    TurgorState::Cell &s = state[id];
    const double turgor = turgors[h] = flux_turgor(c, s, transfer);
    if (cells->get(c, CellReduce::NFLUID) == 0.0) {
      failure = Failure{c,
                        fmt::format("Fix cell/turgor: cell {} has no fluid atoms of type {} in "
                                    "group {}",
                                    id, fluidtype, group->names[igroup])};
      break;
    }
    if (!std::isfinite(turgor) || !std::isfinite(mass) || !(mass > 0.0) || !std::isfinite(volume) ||
        !(volume > 0.0)) {
      failure = Failure{c,
                        fmt::format("Fix cell/turgor: cell {} is not physical at step {}: "
                                    "turgor P_T = {} Pa, volume V = {} m^3, fluid mass M = {} kg",
                                    id, update->ntimestep, turgor, volume, mass)};
      break;
    }
    if (s.mass0 == 0.0) s.mass0 = mass;
    // dry solids S = M0 w_s / (1 - w_s): the fluid the fix first sees is the fresh cell's water
    if (s.solids == 0.0) s.solids = osmotic_model.solids(s.mass0);
  }
  if (drive.cooling) {
    // the surface temperature from every cell's flux at its current state (doc/model.md §5.14)
    cells->registry().settle(failure.cell, failure.message, warnings);
    drive.cool([&]() {
      const double t = drive.temperature;
      // rho_w L_P(T), as in the loop below
      const double gw = rhow * (lp * arrhenius_factor(t));
      double sums[2] = {0.0, 0.0}, all[2];
      for (int h = 0; h < (int) home.size(); h++) {
        const int c = home[h];
        const TurgorState::Cell &s = state[cells->id(c)];
        const double mass = cells->mass(c);
        const double pi = osmotic_model.pressure(s.pi0, s.mass0, s.solids, mass, t, nullptr);
        const double area = cells->area(c), surface = cells->surface_area(c);
        // the exposed flux f A J = -dM/dt of the air drive (doc/model.md §5.8)
        sums[0] -= drive.flux(turgors[h] - pi, gw, area, surface, mass, s.mass0, 0.0).rate;
        sums[1] += drive.exposed_area(area, surface);
      }
      MPI_Allreduce(sums, all, 2, MPI_DOUBLE, MPI_SUM, world);
      // J = sum f A J / sum f A over the exposed cells
      return all[1] > 0.0 ? all[0] / all[1] : 0.0;
    });
  }
  const double t = drive.temperature, psi_ext = drive.psi_ext;
  // L_P(T) = L_P exp(-(Ea/R)(1/T - 1/Tref)), the same factor on L_cc (doc/model.md §5.9, §5.13)
  const double arrhenius = arrhenius_factor(t);
  const double lpt = lp * arrhenius;
  double air_sums[2] = {0.0, 0.0};    // the exposed cells' vapour flux and area

  for (int h = 0; h < (int) home.size() && failure.cell == cells->ncell(); h++) {
    const int c = home[h];
    const tagint id = cells->id(c);
    const double mass = cells->mass(c);
    const double area = cells->area(c);
    TurgorState::Cell &s = state[id];
    const double turgor = turgors[h];
    double slope;
    const double pi = osmotic_model.pressure(s.pi0, s.mass0, s.solids, mass, t, &slope);
    // psi_cell = P_T - pi (doc/model.md §5.1)
    const double psi_cell = turgor - pi;
    const TurgorDrive::Flux flux =
        drive.flux(psi_cell, rhow * lpt, area, cells->surface_area(c), mass, s.mass0, dtw);
    const double conductance = flux.conductance, rate = flux.rate;
    s.psi_surface = flux.psi_surface;
    s.rate = rate;
    if (drive.kind == TurgorDrive::AIR) {
      air_sums[0] -= rate;
      air_sums[1] += drive.exposed_area(area, cells->surface_area(c));
    }
    // k = G d(P_T - pi)/dM, dP_T/dM = (K + P_SPH)/M (summation density), -dpi/dM = slope
    const double stiffness = (kfluid + cells->sph_turgor(c)) / mass + slope;
    const double relax = conductance * std::max(0.0, stiffness);
    const double z = dtw * relax;
    if (drive.kind != TurgorDrive::CURVE)
      max_imbalance = std::max(max_imbalance, fabs(psi_ext - psi_cell));
    max_stiffness = std::max(max_stiffness, z);
    if (drive.kind != TurgorDrive::CURVE && !check_limit(c, s, turgor, pi, pi + psi_ext)) break;
    if (accel.pending)
      first_accel =
          std::min(first_accel,
                   accel.first(conductance, slope,
                               TurgorAccel::modulus(kfluid + cells->sph_turgor(c),
                                                    gt0.empty() ? 0.0 : cells->mean_gt0(c),
                                                    cells->ref_area(c), cells->area(c)),
                               mass, offset_time()));
    conductances[h] = conductance;
    if (junctions) {
      // advanced with the network below (doc/model.md §5.13), which needs psi to rise with M
      if (!(stiffness > 0.0)) {
        failure = Failure{c,
                          fmt::format("Fix cell/turgor: cell {} cannot exchange water: its water "
                                      "potential does not rise with its water, dpsi/dM = {} Pa/kg "
                                      "(K + P_SPH = {} Pa)",
                                      id, stiffness, kfluid + cells->sph_turgor(c))};
        break;
      }
      net.psi[h] = psi_cell;
      net.s[h] = stiffness;
      net.rate[h] = rate;
      net.z[h] = z;
      net_mass[h] = mass;
      continue;
    }
    if (!transfer) continue;

    // exponential Euler: dM = dtw r (1 - exp(-z)) / z, z = dtw k (exact when linear); the curve sets
    // M = M0 X/X0(t + dtw)
    const double dmass = drive.kind == TurgorDrive::CURVE
        ? drive.target * s.mass0 - mass
        : dtw * rate * (z > 0.0 ? -expm1(-z) / z : 1.0);
    if (!(mass + dmass > 0.0)) {
      failure = Failure{c,
                        fmt::format("Fix cell/turgor: cell {} would lose all its water at step "
                                    "{}: fluid mass M = {} kg, change {} kg (psi_ext = {} Pa, "
                                    "turgor P_T = {} Pa, pi = {} Pa)",
                                    id, update->ntimestep, mass, dmass, psi_ext, turgor, pi)};
      break;
    }
    scale[h] = dmass / mass;
    moved += dmass;
  }
  // the home ranks' problems stop or warn every rank; maxima over all cells, the busiest rank
  cells->registry().settle(failure.cell, failure.message, warnings);
  double most[4] = {max_imbalance, max_stiffness, -first_accel,
                    (double) cells->registry().touched().size()};
  double all_most[4];
  MPI_Allreduce(most, all_most, 4, MPI_DOUBLE, MPI_MAX, world);
  max_imbalance = all_most[0];
  max_stiffness = all_most[1];
  first_accel = -all_most[2];
  busiest = all_most[3];
  exposed_flux = exposed_area = 0.0;
  if (drive.kind == TurgorDrive::AIR) {
    double all_air[2];
    MPI_Allreduce(air_sums, all_air, 2, MPI_DOUBLE, MPI_SUM, world);
    exposed_area = all_air[1];
    // the mean vapour flux over the exposed area, sum f A J / sum f A
    exposed_flux = exposed_area > 0.0 ? all_air[0] / exposed_area : 0.0;
  }
  const bool starting = accel.pending;
  if (accel.pending) max_stiffness *= accel.begin(first_accel);
  if (junctions) {
    // the network on the home ranks: each solves its home cells' rows (doc/model.md §5.2)
    std::vector<double> dmass;
    exchange(net, transfer, dtw, arrhenius, dmass);
    for (int h = 0; h < (int) dmass.size(); h++) {
      const int c = home[h];
      if (!(net_mass[h] + dmass[h] > 0.0) && failure.cell == cells->ncell())
        failure = Failure{c,
                          fmt::format("Fix cell/turgor: cell {} would lose all its water at step "
                                      "{}: fluid mass M = {} kg, change {} kg with its neighbours "
                                      "(psi_cell = {} Pa, psi_ext = {} Pa)",
                                      cells->id(c), update->ntimestep, net_mass[h], dmass[h],
                                      net.psi[h], psi_ext)};
      scale[h] = dmass[h] / net_mass[h];
      moved += dmass[h];
    }
    if (transfer) cells->registry().settle(failure.cell, failure.message, {});
  }
  control(cycle, transfer || starting, transfer, turgors, conductances);
  if (!transfer) return;

  // dM/M of each cell from its home rank to its fluid atoms, applied before the next step's forces
  // (pre_force: m_i <- m_i (1 + dM/M))
  const CellRegistry &reg = cells->registry();
  std::vector<double> factor;
  reg.scatter(1, scale, factor);
  const int *type = atom->type;
  const std::vector<int> &cellof = cells->cell_of_atom();
  for (int i = 0; i < atom->nlocal; i++)
    if (cellof[i] >= 0 && type[i] == fluidtype) pending[i] = factor[reg.slot(cellof[i])];
  any_pending = true;

  double all_moved;
  MPI_Allreduce(&moved, &all_moved, 1, MPI_DOUBLE, MPI_SUM, world);
  moved_pending = all_moved;
  time_pending = dtw;
  evaluated = update->ntimestep;
}

/* ----------------------------------------------------------------------
   accel after an evaluation (doc/model.md §5.12): the home cells' probes, turgor, water, rate
   and conductance (with the exchange's) for accel auto; the wall edges measured
------------------------------------------------------------------------- */

void FixCellTurgor::control(const TurgorAccel::Cycle &cycle, bool limit, bool transfer,
                            const std::vector<double> &turgors,
                            const std::vector<double> &conductances)
{
  const std::vector<int> &home = cells->home_cells();
  TurgorAccel::Home in{{}, turgors, {}, {}, conductances};
  std::vector<double> between;
  if (junctions) network->conductances(between);
  for (int h = 0; h < (int) home.size() && accel.automatic; h++) {
    TurgorState::Cell &s = state[cells->id(home[h])];
    in.probe.push_back(s.probe);
    in.mass.push_back(cells->mass(home[h]));
    in.rate.push_back(s.rate);
    if (junctions) in.conductance[h] += between[h];
  }
  accel.after(cycle, limit, transfer, in, every * update->dt, cells->ncell() > 0);
}

/* ----------------------------------------------------------------------
   exchange: the cells' own transfer and the water between them through their junctions, one
   implicit step of the network over dtw (doc/model.md §5.13); dmass per cell with transfer, else
   only the start-of-step rates and the stiffness. g_ij = rho_w L_cc A_ij, A_ij = its bonds x the
   area per bond (the bond type's A, or the pair's from a junction areas file).
------------------------------------------------------------------------- */

void FixCellTurgor::exchange(const TurgorNetwork::Cells &in, bool transfer, double dtw,
                             double factor, std::vector<double> &dmass)
{
  CellRegistry &registry = cells->registry();
  const std::vector<int> &home = registry.home_cells();
  const bool counted = junctions->gather(registry, !transfer);
  const double l = lcc.get(lmp);
  check_lcc(l, fmt::format(" (step {})", update->ntimestep));
  // the junctions set up again when they were counted again or the home ranks changed (init)
  if (counted || network_stale) {
    std::vector<TurgorNetwork::Edge> edges;
    for (const auto &j : junctions->junctions()) edges.push_back({j.i, j.j, rhow * j.area});
    network->set_edges(home, edges, [&](int c) { return registry.home(c); });
    const int mine = network->crossing();
    MPI_Allreduce(&mine, &crossing, 1, MPI_INT, MPI_SUM, world);
    network_stale = false;
  }
  // g_ij = rho_w L_cc(T) A_ij (doc/model.md §5.13): rho_w A_ij on the edges, L_cc(T) here
  network->set_scale(l * factor);
  network->set_cells(in);
  exchange_stiffness = network->stiffness(dtw);
  std::vector<double> rate;
  network->rates(rate);
  for (int h = 0; h < (int) home.size(); h++) state[cells->id(home[h])].rate += rate[h];
  if (!transfer) return;

  TurgorNetwork::Change change;
  if (!network->step(dtw, change))
    error->all(
        FLERR,
        "Fix cell/turgor: the water network's solver did not converge at step {} ({} iterations)",
        update->ntimestep, network->iterations());
  dmass.resize(home.size());
  for (int h = 0; h < (int) home.size(); h++) dmass[h] = change.own[h] + change.exchange[h];
  exchange_net = change.net;
  water_exchanged += change.gross;
}

/* ----------------------------------------------------------------------
   MD time of the running mean of the offset D: tau, default 100 N dt
------------------------------------------------------------------------- */

double FixCellTurgor::offset_time() const
{
  return tau > 0.0 ? tau : 100.0 * every * update->dt;
}

/* ----------------------------------------------------------------------
   the turgor that drives the flux. turgor sph: the mean SPH pressure. turgor wall: the mean SPH
   pressure minus its running mean offset from the wall load, so that the steady state is the wall
   load P_W = pi + psi_ext while each transfer sees the fluid's instantaneous, smooth response (the
   wall load alone carries the wall's ringing into the mass at large dtw k); the mean advances on
   transfer steps only, so a run split in two continues as one
------------------------------------------------------------------------- */

double FixCellTurgor::flux_turgor(int c, TurgorState::Cell &s, bool advance)
{
  const double psph = cells->sph_turgor(c);
  s.turgor = psph;
  if (!cells->wall_measure()) return psph;
  const double gap = psph - cells->wall_turgor(c);
  const double window = offset_time();
  // offset <- offset + (N dt / tau) (P_SPH - P_W - offset), from 0: an exponential running mean
  if (advance) s.offset += std::min(1.0, every * update->dt / window) * (gap - s.offset);
  s.turgor = psph - s.offset;
  return s.turgor;
}

/* ----------------------------------------------------------------------
   stop (false, with the failure set) or warn when the cell's thin Neo-Hookean wall cannot hold the
   turgor (doc/model.md §6)
------------------------------------------------------------------------- */

bool FixCellTurgor::check_limit(int c, TurgorState::Cell &s, double turgor, double pi,
                                double demand)
{
  const double gt = cells->mean_gt0(c);
  const double area0 = cells->ref_area(c);
  if (gt0.empty() || gt <= 0.0 || area0 <= 0.0) return true;

  const double r0 = sqrt(area0 / (4.0 * MY_PI));
  // P_max = (2 G t0 / R0) (6/7) 7^(-1/6) = 0.6197 (2 G t0 / R0) at stretch 7^(1/6)
  const double pmax = 2.0 * gt / r0 * (6.0 / 7.0) * pow(7.0, -1.0 / 6.0);
  const double stretch = sqrt(cells->area(c) / area0);

  std::string why;
  if (!osmotic_model.vanthoff() && demand > pmax)
    why = "its demanded turgor pi + psi_ext exceeds the wall's limit-point pressure";
  else if (stretch > pow(7.0, 1.0 / 6.0) && turgor < demand)
    why = fmt::format("its wall passed the limit-point stretch 7^(1/6) = 1.383 (stretch {:.4g}) "
                      "with turgor below pi + psi_ext",
                      stretch);
  else
    return true;

  const std::string message = fmt::format(
      "Fix cell/turgor: cell {} cannot hold its turgor: {}: turgor P_T = {:.6g} Pa, pi = {:.6g} "
      "Pa, psi_ext = {:.6g} Pa, limit-point pressure P_max = 0.6197 (2 G t0 / R0) = {:.6g} Pa "
      "(G t0 = {:.4g} N/m, R0 = {:.4g} m)",
      cells->id(c), why, turgor, pi, demand - pi, pmax, gt, r0);
  if (limit == LIMIT_ERROR) {
    failure = Failure{c, message};
    return false;
  }
  if (!s.warned) warnings.push_back(message);
  s.warned = 1;
  return true;
}

/* ----------------------------------------------------------------------
   turgor P_T of a cell at the last evaluation (what drives its flux); false if this fix does not
   act on the cell
------------------------------------------------------------------------- */

bool FixCellTurgor::turgor(tagint cell, double &pt) const
{
  const TurgorState::Cell *s = state.find(cell);
  if (!s) return false;
  pt = s->turgor;
  return true;
}

/* ----------------------------------------------------------------------
   osmotic pressure pi of a cell at fluid mass M and the last evaluation's temperature; false if
   this fix does not act on the cell
------------------------------------------------------------------------- */

bool FixCellTurgor::osmotic(tagint cell, double mass, double &pi) const
{
  const TurgorState::Cell *s = state.find(cell);
  if (!s) return false;
  pi = osmotic_model.pressure(s->pi0, s->mass0, s->solids, mass,
                              drive.temperature > 0.0 ? drive.temperature : osmotic_model.tref,
                              nullptr);
  return true;
}

/* ----------------------------------------------------------------------
   moisture content X = M/S, X/X0 = M/M0, temperature, surface water potential and water flux of
   a cell at fluid mass M; false if this fix does not act on the cell
------------------------------------------------------------------------- */

bool FixCellTurgor::water(tagint cell, double mass, Water &w) const
{
  const TurgorState::Cell *s = state.find(cell);
  if (!s) return false;
  w.moisture = s->solids > 0.0 ? mass / s->solids : 0.0;
  w.relative = s->mass0 > 0.0 ? mass / s->mass0 : 0.0;
  w.temperature = drive.temperature > 0.0 ? drive.temperature : osmotic_model.tref;
  w.psi_surface = s->psi_surface;
  w.rate = s->rate;
  return true;
}

/* ----------------------------------------------------------------------
   1 water moved into the cells (kg), 2 physical time (s), 3 cells, 4 max |psi_ext - psi_cell| (Pa),
   5 max dtw k: an explicit update would be unstable above 2, 6 temperature T (K), 7 h_m (m/s),
   8 accel, 9 lag e of the last accel auto window (max over cells), 10 its standard error,
   11 water moved between cells (kg), 12 the exchange's net mass change at the last transfer (kg,
   0 to round-off), 13 max dt_w g_ij (s_i + s_j) over junctions, 14 the most cells one rank
   summed at the last evaluation, 15 the surface temperature of the air drive (K), 16 the mean
   vapour flux over the exposed area (kg m^-2 s^-1), 17 the exposed area (m^2), 18 junctions
   between cells of different home ranks, 19 the longest wall edge over the shortest longest one
   since the start (0 before the first transfer)
------------------------------------------------------------------------- */

double FixCellTurgor::compute_vector(int n)
{
  const double values[] = {water_moved,
                           physical_time,
                           (double) cells->ncell(),
                           max_imbalance,
                           max_stiffness,
                           drive.temperature,
                           drive.mass_transfer,
                           accel.value,
                           accel.lag_estimate,
                           accel.lag_error,
                           water_exchanged,
                           exchange_net,
                           exchange_stiffness,
                           busiest,
                           drive.kind == TurgorDrive::AIR ? drive.temperature : 0.0,
                           exposed_flux,
                           exposed_area,
                           (double) crossing,
                           accel.edge};
  return values[n];
}

/* ----------------------------------------------------------------------
   fix_modify ID LP|psi|accel value: change the water transfer between runs; the per-cell state
   (M0, pi0, the running offset D, warnings) and the outputs carry on
------------------------------------------------------------------------- */

int FixCellTurgor::modify_param(int narg, char **arg)
{
  const std::string key = arg[0];
  if (key != "LP" && key != "psi" && key != "accel")
    error->all(FLERR,
               "Fix_modify cell/turgor: unknown keyword '{}' (expected LP, psi or accel, or a "
               "keyword of every fix)",
               key);
  if (narg < 2) error->all(FLERR, "Fix_modify cell/turgor: missing value after '{}'", key);
  if (key == "accel") {
    const int used = 1 + accel.parse(narg - 1, &arg[1], "Fix_modify cell/turgor");
    if (accel.automatic && drive.kind == TurgorDrive::CURVE)
      error->all(FLERR, "Fix_modify cell/turgor: accel auto needs the psi or air drive");
    // a transfer evaluated again at setup (setup) keeps the new accel
    accel_saved = accel.save();
    return used;
  }
  const double value = key == "psi" ? 0.0 : utils::numeric(FLERR, arg[1], false, lmp);
  if (key == "LP") {
    check_lp(value, "Fix_modify cell/turgor");
    lp = value;
  } else if (key == "psi") {
    drive.modify_psi(arg[1]);
  }
  return 2;
}

/* ---------------------------------------------------------------------- */

void FixCellTurgor::write_restart(FILE *fp)
{
  std::vector<double> cellstate;
  const int ncell = state.gather_restart(RESTART_VERSION, cellstate);
  if (comm->me != 0) return;
  // version 1 (no marker) began with the number of cells >= 0; later versions with -version
  std::vector<double> list = {(double) -RESTART_VERSION, (double) ncell, physical_time,
                              water_moved};
  accel.write(list);
  list.push_back(water_exchanged);
  list.push_back(moved_pending);
  list.push_back(time_pending);
  list.push_back((double) evaluated);
  accel.write_edges(list);
  list.insert(list.end(), cellstate.begin(), cellstate.end());
  const int size = (int) (list.size() * sizeof(double));
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(list.data(), sizeof(double), list.size(), fp);
}

/* ---------------------------------------------------------------------- */

void FixCellTurgor::restart(char *buf)
{
  const double *list = (double *) buf;
  const int version = CellRestart::version(list[0]);
  CellRestart::refuse_newer(error, FLERR, "Fix cell/turgor", version, RESTART_VERSION);
  if (version >= 2) list++;
  const double count = list[0];
  if (!(count >= 0.0 && count == floor(count)))
    error->all(FLERR,
               "Fix cell/turgor: the restart file's state (format version {}) is not valid: "
               "number of cells = {}",
               version, count);
  const int n = (int) count;
  physical_time = list[1];
  water_moved = list[2];
  // accel auto continues from the adapted accel and its window when the file has them (4)
  const bool adapted = version >= 4 && accel.read(&list[3]);
  if (version >= 5) water_exchanged = list[8];
  if (version >= 6) moved_pending = list[9], time_pending = list[10], evaluated = (bigint) list[11];
  if (version >= 7) accel.read_edges(&list[12]);
  state.clear();
  bool other_pi0 = false, other_solids = false;
  const int nvalues = TurgorState::restart_values(version);
  for (int k = 0; k < n; k++) {
    const double *v = &list[1 + restart_globals(version) + nvalues * k];
    // version 1 files written before the offset was stored had 4 values per cell: caught here
    if (!(v[0] >= 1.0 && v[0] == floor(v[0]) && (v[3] == 0.0 || v[3] == 1.0)))
      error->all(FLERR,
                 "Fix cell/turgor: the restart file's state (format version {}) is not valid at "
                 "cell {} of {}: ID = {}, warned = {}",
                 version, k + 1, n, v[0], v[3]);
    // solids from version 3 on; older files: from 'solids' and M0 at the first evaluation
    const double solids = version >= 3 ? v[5] : 0.0;
    TurgorState::Cell cell{v[1], v[2], (int) v[3], v[4], solids, 0.0, 0.0, 0.0, {}};
    if (adapted) std::copy(v + 6, v + 6 + TurgorAccel::NPROBE, cell.probe);
    // every rank holds every cell until init() keeps its home cells
    state[(tagint) v[0]] = cell;
    other_pi0 = other_pi0 || v[2] != pi0;
    other_solids = other_solids ||
        (solids > 0.0 && osmotic_model.solids_fraction > 0.0 &&
         fabs(solids - osmotic_model.solids(v[1])) > 1e-12 * solids);
  }
  if (other_pi0 && comm->me == 0)
    error->warning(FLERR,
                   "Fix cell/turgor: cells continue with the osmotic pressure pi0 stored in the "
                   "restart file, not pi0 = {}",
                   pi0);
  if (other_solids && comm->me == 0)
    error->warning(
        FLERR,
        "Fix cell/turgor: cells continue with the dry solids stored in the restart file, "
        "not those of solids = {}",
        osmotic_model.solids_fraction);
}

/* ---------------------------------------------------------------------- */

int FixCellTurgor::pack_forward_comm(int n, int *list, double *buf, int, int *)
{
  for (int k = 0; k < n; k++) buf[k] = atom->rmass[list[k]];
  return n;
}

/* ---------------------------------------------------------------------- */

void FixCellTurgor::unpack_forward_comm(int n, int first, double *buf)
{
  for (int k = 0; k < n; k++) atom->rmass[first + k] = buf[k];
}

/* ----------------------------------------------------------------------
   per atom: the waiting transfer's relative mass change (0 for atoms that get none)
------------------------------------------------------------------------- */

void FixCellTurgor::grow_arrays(int nmax)
{
  memory->grow(pending, nmax, "cell/turgor:pending");
}

void FixCellTurgor::copy_arrays(int i, int j, int)
{
  pending[j] = pending[i];
}

void FixCellTurgor::set_arrays(int i)
{
  pending[i] = 0.0;
}

int FixCellTurgor::pack_exchange(int i, double *buf)
{
  buf[0] = pending[i];
  return 1;
}

int FixCellTurgor::unpack_exchange(int nlocal, double *buf)
{
  pending[nlocal] = buf[0];
  return 1;
}

/* ----------------------------------------------------------------------
   restart: the count of values (2) first, as every fix with per-atom restart data
------------------------------------------------------------------------- */

int FixCellTurgor::pack_restart(int i, double *buf)
{
  buf[0] = 2;
  buf[1] = pending[i];
  return 2;
}

void FixCellTurgor::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  pending[nlocal] = extra[nlocal][m + 1];
}

int FixCellTurgor::size_restart(int)
{
  return 2;
}

int FixCellTurgor::maxsize_restart()
{
  return 2;
}

double FixCellTurgor::memory_usage()
{
  return (double) atom->nmax * sizeof(double);
}

/* ---------------------------------------------------------------------- */

const CellRegistry &FixCellTurgor::registry() const
{
  return cells->registry();
}

/* ----------------------------------------------------------------------
   L_P(T)/L_P = exp(-(Ea/R)(1/T - 1/Tref)), 1 without Ea; the same factor on L_cc
   (doc/model.md §5.9, §5.13)
------------------------------------------------------------------------- */

double FixCellTurgor::arrhenius_factor(double t) const
{
  return ea > 0.0 ? CellWater::arrhenius(ea, t, osmotic_model.tref) : 1.0;
}

/* ----------------------------------------------------------------------
   0 <= L_P <= CellLimits::CONDUCTANCE_MAX; 'who' begins the message
------------------------------------------------------------------------- */

void FixCellTurgor::check_lp(double value, const std::string &who) const
{
  if (!(value >= 0.0 && value <= CellLimits::CONDUCTANCE_MAX))
    error->all(FLERR, "{}: wall permeability LP = {} must be >= 0 and <= 1e3 m s^-1 Pa^-1", who,
               value);
}

/* ----------------------------------------------------------------------
   0 <= L_cc <= CellLimits::CONDUCTANCE_MAX; 'when' ends the message
------------------------------------------------------------------------- */

void FixCellTurgor::check_lcc(double value, const std::string &when) const
{
  if (!(value >= 0.0 && value <= CellLimits::CONDUCTANCE_MAX))
    error->all(FLERR,
               "Fix cell/turgor: cell-to-cell conductance L_cc = {} must be >= 0 and <= 1e3 m "
               "s^-1 Pa^-1{}",
               value, when);
}
