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

/* ---------------------------------------------------------------------- */

FixCellTurgor::FixCellTurgor(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), lp(0.0), pi0(0.0), rhow(1000.0), accel(lmp), ea(0.0),
    osmotic_model(lmp, "Fix cell/turgor"), drive(lmp, "Fix cell/turgor"), tau(0.0), bulk(0.0),
    kfluid(0.0), limit(LIMIT_ERROR), limit_set(0), fluidtype(1), walltype(2), state(lmp),
    wallwater(lmp, "Fix cell/turgor"), physical_time(0.0), water_moved(0.0), max_imbalance(0.0),
    max_stiffness(0.0), busiest(0.0), exposed_flux(0.0), exposed_area(0.0), lcc{0.0, "", -1},
    water_exchanged(0.0), exchange_net(0.0), exchange_stiffness(0.0), crossing(0)
{
  if (narg < 4)
    error->all(FLERR,
               "Illegal fix cell/turgor command: expected 'fix ID group cell/turgor N keyword "
               "value ...'");
  every = utils::inumeric(FLERR, arg[3], false, lmp);
  if (every <= 0) error->all(FLERR, "Fix cell/turgor: N = {} must be > 0", every);

  Keywords given;
  for (int iarg = 4; iarg < narg;) iarg += parse_keyword(narg - iarg, &arg[iarg], given);
  check_keywords(given);

  cells = std::make_unique<CellReduce>(lmp, "Fix cell/turgor", igroup, fluidtype, walltype);
  if (drive.surface_group >= 0) cells->set_surface(group->bitmask[drive.surface_group]);
  if (given.exchanging) {
    // bond type 0 too is out of range there
    junctions =
        std::make_unique<TurgorJunctions>(lmp, "Fix cell/turgor", given.bondtype, given.areas);
    network = std::make_unique<TurgorNetwork>(world);
  }
  vector_flag = 1;
  size_vector = 20;
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
   the keyword arg[0] of the narg arguments left and its values: returns how many it used. The
   drive's (psi, air, curve, temp, cooling) and the osmotic model's keywords go to their classes
------------------------------------------------------------------------- */

int FixCellTurgor::parse_keyword(int narg, char **arg, Keywords &given)
{
  const std::string key = arg[0];
  const char *value = CellArgs::values(error, "Fix cell/turgor", narg, arg, 1)[0];
  removed_keyword(key, value);
  if (key == "LP") {
    lp = utils::numeric(FLERR, value, false, lmp);
    given.lp_set = true;
  } else if (key == "pi0") {
    pi0 = utils::numeric(FLERR, value, false, lmp);
    given.pi0_set = true;
  } else if (int n = drive.parse(narg, arg, osmotic_model.tref)) {
    return n;
  } else if (key == "Ea") {
    ea = utils::numeric(FLERR, value, false, lmp);
    if (!(ea >= 0.0 && ea <= CellLimits::EA_MAX))
      error->all(FLERR, "Fix cell/turgor: activation energy Ea = {} must be >= 0 and <= 1e6 J/mol",
                 ea);
  } else if (key == "exchange") {
    return parse_exchange(narg, arg, given);
  } else if (key == "accel") {
    return 1 + accel.parse(narg - 1, &arg[1], "Fix cell/turgor");
  } else if (key == "bulk") {
    bulk = utils::numeric(FLERR, value, false, lmp);
    if (bulk <= 0.0) error->all(FLERR, "Fix cell/turgor: bulk modulus K = {} must be > 0", bulk);
  } else if (key == "limit") {
    parse_limit(value);
  } else if (int n = osmotic_model.parse(narg, arg)) {
    return n;
  } else if (int n = wallwater.parse(narg, arg)) {
    return n;
  } else if (key == "file") {
    read_file(value, given);
  } else if (key == "tau") {
    tau = utils::numeric(FLERR, value, false, lmp);
    if (tau <= 0.0) error->all(FLERR, "Fix cell/turgor: offset time tau = {} must be > 0", tau);
  } else {
    error->all(FLERR, "Fix cell/turgor: unknown keyword '{}'", key);
  }
  return 2;
}

/* ----------------------------------------------------------------------
   exchange L_cc|file bondtype N [areas FILE]: returns how many arguments it used
------------------------------------------------------------------------- */

int FixCellTurgor::parse_exchange(int narg, char **arg, Keywords &given)
{
  char **v = CellArgs::values(error, "Fix cell/turgor", narg, arg, 3);
  if (strcmp(v[1], "bondtype") != 0)
    error->all(FLERR, "Fix cell/turgor: expected 'exchange L_cc bondtype N', not 'exchange {} {}'",
               v[0], v[1]);
  given.lcc_file = strcmp(v[0], "file") == 0;
  if (!given.lcc_file) lcc = CellQuantity::parse(lmp, v[0], "Fix cell/turgor: exchange L_cc");
  if (!given.lcc_file && !lcc.is_variable()) check_lcc(lcc.value, "");
  given.bondtype = utils::inumeric(FLERR, v[2], false, lmp);
  given.exchanging = true;
  if (5 < narg && strcmp(arg[4], "areas") == 0) {
    given.areas = arg[5];
    return 6;
  }
  return 4;
}

/* ---------------------------------------------------------------------- */

void FixCellTurgor::parse_limit(const char *value)
{
  if (strcmp(value, "error") == 0)
    limit = LIMIT_ERROR;
  else if (strcmp(value, "warn") == 0)
    limit = LIMIT_WARN;
  else
    error->all(FLERR, "Fix cell/turgor: unknown limit action '{}' (expected error or warn)", value);
  limit_set = 1;
}

/* ----------------------------------------------------------------------
   keywords no scene used, removed (doc/notes/2026-12-07-keywords.md): stop naming what replaces them
------------------------------------------------------------------------- */

void FixCellTurgor::removed_keyword(const std::string &key, const char *value)
{
  std::string instead;
  if (key == "turgor")
    instead = "P_T follows the wall-fluid model (the mean SPH pressure under the wall boundary of "
              "pair cell/sph; less the running offset D from the wall load under pair cell/wall's "
              "wall-fluid terms); compute cell/props columns 14 and 15 give the mean SPH pressure "
              "and the wall load";
  else if (key == "rhow")
    instead = "the water crossing the wall has the density 1000 kg/m^3";
  else if (key == "Tref")
    instead = "L_P, L_cc and pi0 are given at 298.15 K (25 C), as in apple.cellsph";
  else if (key == "fluid" || key == "wall")
    instead = "the cell fluid is atom type 1 and the wall type 2, as tools/cellgen writes them";
  else
    return;
  error->all(FLERR, "Fix cell/turgor: keyword '{} {}' was removed: {}", key, value, instead);
}

/* ----------------------------------------------------------------------
   file NAME: L_P (turgor_LP) and pi0, optionally Ea, L_cc and the osmotic model's keys
------------------------------------------------------------------------- */

void FixCellTurgor::read_file(const char *file, Keywords &given)
{
  CellParams params(lmp, file, "Fix cell/turgor");
  lp = params.nonnegative("turgor_LP", CellLimits::CONDUCTANCE_MAX, "m s^-1 Pa^-1");
  pi0 = params.nonnegative("turgor_pi0");
  given.lp_set = given.pi0_set = true;
  // optional drying keys (doc/fix_cell_turgor.md)
  if (params.has("turgor_Ea")) ea = params.nonnegative("turgor_Ea", CellLimits::EA_MAX, "J/mol");
  if (params.has("turgor_Lcc"))
    given.file_lcc = params.nonnegative("turgor_Lcc", CellLimits::CONDUCTANCE_MAX, "m s^-1 Pa^-1");
  osmotic_model.read(params, file);
}

/* ----------------------------------------------------------------------
   after all keywords: L_P and pi0 given, one drive, and accel auto and exchange with a drive
   that has a flux
------------------------------------------------------------------------- */

void FixCellTurgor::check_keywords(const Keywords &given)
{
  if (!given.lp_set)
    error->all(FLERR, "Fix cell/turgor: wall permeability not set: give 'LP value'");
  check_lp(lp, "Fix cell/turgor");
  if (!given.pi0_set)
    error->all(FLERR, "Fix cell/turgor: osmotic pressure not set: give 'pi0 value'");
  if (pi0 < 0.0) error->all(FLERR, "Fix cell/turgor: osmotic pressure pi0 = {} must be >= 0", pi0);
  drive.check(osmotic_model.tref);
  osmotic_model.check();
  if (accel.automatic && drive.kind == TurgorDrive::CURVE)
    error->all(FLERR,
               "Fix cell/turgor: accel auto needs the psi or air drive (a prescribed curve has no "
               "flux that the mechanics could delay)");

  if (given.lcc_file) {
    if (given.file_lcc < 0.0)
      error->all(FLERR,
                 "Fix cell/turgor: 'exchange file' takes L_cc from the key turgor_Lcc of a "
                 "parameter file: give 'file name' with that key");
    lcc = CellQuantity{given.file_lcc, "", -1};
  }
  if (given.exchanging && drive.kind == TurgorDrive::CURVE)
    error->all(FLERR,
               "Fix cell/turgor: exchange needs the psi or air drive (a prescribed curve sets each "
               "cell's water)");
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
  if (wallwater.on()) share_wall_water();
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
  if (wallwater.on()) apply_wall_water();
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
  Evaluation e = begin_evaluation(transfer);
  check_cells(e, transfer);
  if (drive.cooling) cool_surface(e);
  e.arrhenius = arrhenius_factor(drive.temperature);
  e.rho_lp = rho_lp(drive.temperature);
  for (int pos = 0; pos < (int) e.home.size() && failure.cell == cells->ncell(); pos++)
    if (!cell_flux(e, pos, transfer)) break;
  gather_maxima(e);
  const bool starting = accel.pending;
  if (accel.pending) max_stiffness *= accel.begin(e.first_accel);
  if (junctions) network_transfer(e, transfer);
  if (wallwater.on()) wall_water(e, transfer);
  control(e.cycle, transfer || starting, transfer, e.turgor, e.conductance);
  if (transfer) spread(e);
}

/* ----------------------------------------------------------------------
   the start of an evaluation: the transfer's place in the accel cycle and its physical time dtw,
   the maxima and problems cleared, the drive's inputs
------------------------------------------------------------------------- */

FixCellTurgor::Evaluation FixCellTurgor::begin_evaluation(bool transfer)
{
  // the per-cell logic runs on each cell's home rank, for its home cells
  const std::vector<int> &home = cells->home_cells();
  // accel auto: transfer j (at step j N; the next one when not transferring) is at position
  // (j - 1) % (every + hold) of its cycle: open for every transfers, then sealed (no water, no
  // physical time) for hold; the second half of each is sampled (doc/model.md §5.12)
  const bigint next = update->ntimestep + 1;
  const TurgorAccel::Cycle cycle =
      accel.cycle(next / every + (transfer ? 0 : 1), transfer, offset_time(), every * update->dt);
  const double dtw = cycle.sealed ? 0.0 : accel.value * every * update->dt;
  const size_t nnet = junctions ? home.size() : 0;
  Evaluation e{home,
               cycle,
               dtw,
               std::vector<double>(home.size()),
               std::vector<double>(home.size()),
               std::vector<double>(home.size(), 0.0),
               0.0,
               HUGE_VAL,
               {std::vector<double>(nnet), std::vector<double>(nnet), std::vector<double>(nnet),
                std::vector<double>(nnet)},
               std::vector<double>(nnet),
               {0.0, 0.0},
               1.0,
               0.0};
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
  return e;
}

/* ----------------------------------------------------------------------
   each home cell's flux turgor, the cell checked and its M0 and S set
------------------------------------------------------------------------- */

void FixCellTurgor::check_cells(Evaluation &e, bool transfer)
{
  for (int pos = 0; pos < (int) e.home.size(); pos++) {
    const int c = e.home[pos];
    const tagint id = cells->id(c);
    const double mass = cells->mass(c);
    const double volume = cells->volume(c);
    TurgorState::Cell &s = state[id];
    const double turgor = e.turgor[pos] = flux_turgor(c, s, transfer);
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
}

/* ----------------------------------------------------------------------
   cooling: the surface temperature from every cell's flux at its current state (doc/model.md
   §5.14)
------------------------------------------------------------------------- */

void FixCellTurgor::cool_surface(const Evaluation &e)
{
  cells->registry().settle(failure.cell, failure.message, warnings);
  drive.cool([&]() {
    const double t = drive.temperature;
    const double rho_lp_t = rho_lp(t);
    double sums[2] = {0.0, 0.0}, all[2];
    for (int pos = 0; pos < (int) e.home.size(); pos++) {
      const int c = e.home[pos];
      const TurgorState::Cell &s = state[cells->id(c)];
      const double mass = cells->mass(c);
      const double pi = osmotic_model.pressure(s.pi0, s.mass0, s.solids, mass, t, nullptr);
      const double area = cells->area(c), surface = cells->surface_area(c);
      // the exposed flux f A J = -dM/dt of the air drive (doc/model.md §5.8)
      sums[0] -= drive.flux(e.turgor[pos] - pi, rho_lp_t, area, surface, mass, s.mass0, 0.0).rate;
      sums[1] += drive.exposed_area(area, surface);
    }
    MPI_Allreduce(sums, all, 2, MPI_DOUBLE, MPI_SUM, world);
    // J = sum f A J / sum f A over the exposed cells
    return all[1] > 0.0 ? all[0] / all[1] : 0.0;
  });
}

/* ----------------------------------------------------------------------
   home cell e.home[pos]: its osmotic pressure, flux, conductance G and stiffness, its limit
   point checked; its mass change (own transfer) or its row of the network (exchange). False
   (with the failure set) stops the evaluation's loop over the cells
------------------------------------------------------------------------- */

bool FixCellTurgor::cell_flux(Evaluation &e, int pos, bool transfer)
{
  const int c = e.home[pos];
  const double mass = cells->mass(c);
  const double area = cells->area(c);
  TurgorState::Cell &s = state[cells->id(c)];
  const double turgor = e.turgor[pos], psi_ext = drive.psi_ext;
  double slope;
  const double pi =
      osmotic_model.pressure(s.pi0, s.mass0, s.solids, mass, drive.temperature, &slope);
  // psi_cell = P_T - pi (doc/model.md §5.1)
  const double psi_cell = turgor - pi;
  const TurgorDrive::Flux flux =
      drive.flux(psi_cell, e.rho_lp, area, cells->surface_area(c), mass, s.mass0, e.dtw);
  const double conductance = flux.conductance, rate = flux.rate;
  s.psi_surface = flux.psi_surface;
  s.rate = rate;
  if (drive.kind == TurgorDrive::AIR) {
    e.air[0] -= rate;
    e.air[1] += drive.exposed_area(area, cells->surface_area(c));
  }
  // k = G d(P_T - pi)/dM, dP_T/dM = (K + P_SPH)/M (summation density), -dpi/dM = slope
  const double stiffness = (kfluid + cells->sph_turgor(c)) / mass + slope;
  const double relax = conductance * std::max(0.0, stiffness);
  const double z = e.dtw * relax;
  if (drive.kind != TurgorDrive::CURVE)
    max_imbalance = std::max(max_imbalance, fabs(psi_ext - psi_cell));
  max_stiffness = std::max(max_stiffness, z);
  if (drive.kind != TurgorDrive::CURVE && !check_limit(c, s, turgor, pi, pi + psi_ext))
    return false;
  if (accel.pending)
    e.first_accel =
        std::min(e.first_accel,
                 accel.first(conductance, slope,
                             TurgorAccel::modulus(kfluid + cells->sph_turgor(c),
                                                  gt0.empty() ? 0.0 : cells->mean_gt0(c),
                                                  cells->ref_area(c), cells->area(c)),
                             mass, offset_time()));
  e.conductance[pos] = conductance;
  if (junctions) {
    // advanced with the network below (doc/model.md §5.13), which needs psi to rise with M
    if (!(stiffness > 0.0)) {
      failure = Failure{c,
                        fmt::format("Fix cell/turgor: cell {} cannot exchange water: its water "
                                    "potential does not rise with its water, dpsi/dM = {} Pa/kg "
                                    "(K + P_SPH = {} Pa)",
                                    cells->id(c), stiffness, kfluid + cells->sph_turgor(c))};
      return false;
    }
    e.net.psi[pos] = psi_cell;
    e.net.s[pos] = stiffness;
    e.net.rate[pos] = rate;
    e.net.z[pos] = z;
    e.net_mass[pos] = mass;
    return true;
  }
  return !transfer || own_transfer(e, pos, mass, rate, z, turgor, pi);
}

/* ----------------------------------------------------------------------
   the mass change of home cell e.home[pos] of fluid mass M on its own (no exchange): exponential
   Euler, or the curve's M0 X/X0(t + dtw); false (with the failure set) if it empties the cell
------------------------------------------------------------------------- */

bool FixCellTurgor::own_transfer(Evaluation &e, int pos, double mass, double rate, double z,
                                 double turgor, double pi)
{
  const int c = e.home[pos];
  const TurgorState::Cell &s = state[cells->id(c)];
  // exponential Euler: dM = dtw r (1 - exp(-z)) / z, z = dtw k (exact when linear); the curve sets
  // M = M0 X/X0(t + dtw)
  const double dmass = drive.kind == TurgorDrive::CURVE
      ? drive.target * s.mass0 - mass
      : e.dtw * rate * (z > 0.0 ? -expm1(-z) / z : 1.0);
  if (!(mass + dmass > 0.0)) {
    failure = Failure{c,
                      fmt::format("Fix cell/turgor: cell {} would lose all its water at step "
                                  "{}: fluid mass M = {} kg, change {} kg (psi_ext = {} Pa, "
                                  "turgor P_T = {} Pa, pi = {} Pa)",
                                  cells->id(c), update->ntimestep, mass, dmass, drive.psi_ext,
                                  turgor, pi)};
    return false;
  }
  e.scale[pos] = dmass / mass;
  e.moved += dmass;
  return true;
}

/* ----------------------------------------------------------------------
   the home ranks' problems stop or warn every rank; maxima over all cells, the busiest rank; the
   air's mean vapour flux over the exposed area
------------------------------------------------------------------------- */

void FixCellTurgor::gather_maxima(Evaluation &e)
{
  cells->registry().settle(failure.cell, failure.message, warnings);
  double most[4] = {max_imbalance, max_stiffness, -e.first_accel,
                    (double) cells->registry().touched().size()};
  double all_most[4];
  MPI_Allreduce(most, all_most, 4, MPI_DOUBLE, MPI_MAX, world);
  max_imbalance = all_most[0];
  max_stiffness = all_most[1];
  e.first_accel = -all_most[2];
  busiest = all_most[3];
  exposed_flux = exposed_area = 0.0;
  if (drive.kind == TurgorDrive::AIR) {
    double all_air[2];
    MPI_Allreduce(e.air, all_air, 2, MPI_DOUBLE, MPI_SUM, world);
    exposed_area = all_air[1];
    // the mean vapour flux over the exposed area, sum f A J / sum f A
    exposed_flux = exposed_area > 0.0 ? all_air[0] / exposed_area : 0.0;
  }
}

/* ----------------------------------------------------------------------
   exchange: the network on the home ranks, each solving its home cells' rows (doc/model.md
   §5.2); each cell's mass change with its neighbours, checked
------------------------------------------------------------------------- */

void FixCellTurgor::network_transfer(Evaluation &e, bool transfer)
{
  std::vector<double> dmass;
  exchange(e.net, transfer, e.dtw, e.arrhenius, dmass);
  for (int pos = 0; pos < (int) dmass.size(); pos++) {
    const int c = e.home[pos];
    if (!(e.net_mass[pos] + dmass[pos] > 0.0) && failure.cell == cells->ncell())
      failure = Failure{c,
                        fmt::format("Fix cell/turgor: cell {} would lose all its water at step "
                                    "{}: fluid mass M = {} kg, change {} kg with its neighbours "
                                    "(psi_cell = {} Pa, psi_ext = {} Pa)",
                                    cells->id(c), update->ntimestep, e.net_mass[pos], dmass[pos],
                                    e.net.psi[pos], drive.psi_ext)};
    e.scale[pos] = dmass[pos] / e.net_mass[pos];
    e.moved += dmass[pos];
  }
  if (transfer) cells->registry().settle(failure.cell, failure.message, {});
}

/* ----------------------------------------------------------------------
   dM/M of each cell from its home rank to its fluid atoms, applied before the next step's forces
   (pre_force: m_i <- m_i (1 + dM/M)); the water moved and its physical time wait with it
------------------------------------------------------------------------- */

void FixCellTurgor::spread(const Evaluation &e)
{
  const CellRegistry &reg = cells->registry();
  std::vector<double> factor;
  reg.scatter(1, e.scale, factor);
  const int *type = atom->type;
  const std::vector<int> &cellof = cells->cell_of_atom();
  for (int i = 0; i < atom->nlocal; i++)
    if (cellof[i] >= 0 && type[i] == fluidtype) pending[i] = factor[reg.slot(cellof[i])];
  any_pending = true;

  double all_moved;
  MPI_Allreduce(&e.moved, &all_moved, 1, MPI_DOUBLE, MPI_SUM, world);
  moved_pending = all_moved;
  time_pending = e.dtw;
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
  for (int pos = 0; pos < (int) home.size() && accel.automatic; pos++) {
    TurgorState::Cell &s = state[cells->id(home[pos])];
    in.probe.push_back(s.probe);
    in.mass.push_back(cells->mass(home[pos]));
    in.rate.push_back(s.rate);
    if (junctions) in.conductance[pos] += between[pos];
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
  const double lcc_value = lcc.get(lmp);
  check_lcc(lcc_value, fmt::format(" (step {})", update->ntimestep));
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
  network->set_scale(lcc_value * factor);
  network->set_cells(in);
  exchange_stiffness = network->stiffness(dtw);
  std::vector<double> rate;
  network->rates(rate);
  for (int pos = 0; pos < (int) home.size(); pos++) state[cells->id(home[pos])].rate += rate[pos];
  if (!transfer) return;

  TurgorNetwork::Change change;
  if (!network->step(dtw, change))
    error->all(
        FLERR,
        "Fix cell/turgor: the water network's solver did not converge at step {} ({} iterations)",
        update->ntimestep, network->iterations());
  dmass.resize(home.size());
  for (int pos = 0; pos < (int) home.size(); pos++)
    dmass[pos] = change.own[pos] + change.exchange[pos];
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
   the turgor that drives the flux (doc/model.md §1.4): the mean SPH pressure, which under the wall
   boundary equals the wall load within 0.2 %. Under the seed's particle wall-fluid model (P_SPH ~21 %
   above the wall load) the mean SPH pressure minus its running mean offset D from the wall load, so
   that the steady state is the wall load P_W = pi + psi_ext while each transfer sees the fluid's
   instantaneous, smooth response; D advances on transfer steps only, so a split run continues as one
------------------------------------------------------------------------- */

double FixCellTurgor::flux_turgor(int c, TurgorState::Cell &s, bool advance)
{
  const double psph = cells->sph_turgor(c);
  if (!cells->wall_measure()) return psph;
  const double gap = psph - cells->wall_turgor(c);
  const double window = offset_time();
  // offset <- offset + (N dt / tau) (P_SPH - P_W - offset), from 0: an exponential running mean
  if (advance) s.offset += std::min(1.0, every * update->dt / window) * (gap - s.offset);
  // P_T = P_SPH - D (doc/model.md §5.3)
  return psph - s.offset;
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
   turgor P_T of a cell at the state whose mean SPH pressure is psph (compute cell/props: the state
   at its step, the masses of the last transfer applied): psph under the wall boundary, psph less
   the offset D of the last evaluation under the particle model; false if this fix does not act on
   the cell
------------------------------------------------------------------------- */

bool FixCellTurgor::turgor(tagint cell, double psph, double &pt) const
{
  const TurgorState::Cell *s = state.find(cell);
  if (!s) return false;
  // P_T = P_SPH (wall boundary), P_SPH - D (particle model) (doc/model.md §5.3)
  pt = cells->wall_measure() ? psph - s->offset : psph;
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
   since the start (0 before the first transfer), 20 the water of the cells' walls (kg)
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
                           accel.edge,
                           wallwater.water};
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
   rho_w L_P(T), the wall's water mass flux per area per water potential difference
   (kg m^-2 s^-1 Pa^-1) that the drive turns into a cell's conductance G (doc/model.md §5.1, §5.9)
------------------------------------------------------------------------- */

double FixCellTurgor::rho_lp(double t) const
{
  return rhow * (lp * arrhenius_factor(t));
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
