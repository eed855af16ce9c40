/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   fix cell/turgor's wall water (doc/model.md §5.15): the keyword, the wall's sorption and
   hygroexpansion (TurgorWallWater), and the fix's steps that move water between each cell's sap
   and its wall and hand the wall's stretch to bond cell/neohookean (FixCellTurgor members)
------------------------------------------------------------------------- */

#include "fix_cell_turgor_wallwater.h"

#include "atom.h"
#include "cell_args.h"
#include "cell_reduce.h"
#include "cell_registry.h"
#include "error.h"
#include "fix_cell_turgor.h"
#include "update.h"

#include <algorithm>
#include <cmath>

using namespace LAMMPS_NS;

// the least stress-free stretch a wall may reach, 1 - beta X_w(a = 1): a wall that shrinks to half
// its length on drying is beyond any measured (wood across the grain: 0.92; doc/model.md §5.15)
static constexpr double MIN_STRETCH = 0.5;
// the largest dry wall mass per area, kg m^-2 (1 mm of dry wall at 1000 kg m^-3; apple: 1e-4)
static constexpr double MASS_AREA_MAX = 1.0;

/* ---------------------------------------------------------------------- */

TurgorWallWater::TurgorWallWater(LAMMPS *lmp, const std::string &command) :
    Pointers(lmp), command(command)
{
}

/* ----------------------------------------------------------------------
   wallwater mass m beta b gab Xm C K
------------------------------------------------------------------------- */

int TurgorWallWater::parse(int narg, char **arg)
{
  if (std::string(arg[0]) != "wallwater") return 0;
  char **v = CellArgs::values(error, command, narg, arg, 8);
  if (std::string(v[0]) != "mass" || std::string(v[2]) != "beta" || std::string(v[4]) != "gab")
    error->all(FLERR,
               "{}: expected 'wallwater mass m beta b gab Xm C K', not 'wallwater {} {} {} "
               "{} {}'",
               command, v[0], v[1], v[2], v[3], v[4]);
  mass_area = utils::numeric(FLERR, v[1], false, lmp);
  beta = utils::numeric(FLERR, v[3], false, lmp);
  gab = CellWater::Gab{utils::numeric(FLERR, v[5], false, lmp),
                       utils::numeric(FLERR, v[6], false, lmp),
                       utils::numeric(FLERR, v[7], false, lmp)};
  if (!(mass_area > 0.0 && mass_area <= MASS_AREA_MAX))
    error->all(FLERR, "{}: wallwater mass = {} must be > 0 and <= 1 kg m^-2 (dry wall per area)",
               command, mass_area);
  if (!(beta >= 0.0))
    error->all(FLERR, "{}: wallwater beta = {} must be >= 0 (a wall shrinks as it dries)", command,
               beta);
  // the wall holds finite water at a = 1 only with K < 1 (doc/model.md §5.15)
  if (!(gab.xm > 0.0 && gab.c > 0.0 && gab.k > 0.0 && gab.k < 1.0))
    error->all(FLERR,
               "{}: wallwater gab Xm = {}, C = {}, K = {} is impossible for a wall: needs Xm > 0, "
               "C > 0 and 0 < K < 1 (finite water at a = 1)",
               command, gab.xm, gab.c, gab.k);
  // the most a wall can shrink: from X_w(a = 1) to dry, s = 1 - beta X_w(1)
  const double least = 1.0 - beta * gab.moisture(1.0);
  if (!(least >= MIN_STRETCH))
    error->all(
        FLERR,
        "{}: wallwater beta = {} would shrink a drying wall to s = 1 - beta X_w(a=1) = {:.4g} "
        "(X_w(1) = {:.4g} kg/kg), beyond what a wall can do (s >= 0.5)",
        command, beta, least, gab.moisture(1.0));
  enabled = true;
  return 9;
}

/* ----------------------------------------------------------------------
   X_w = GAB(a), a = min(1, exp(psi V_w / (R T))): the wall's water at the activity of the cell's
   water potential, saturated at a = 1 (doc/model.md §5.15)
------------------------------------------------------------------------- */

double TurgorWallWater::moisture(double psi, double t) const
{
  return gab.moisture(std::min(1.0, CellWater::activity(psi, t)));
}

/* ----------------------------------------------------------------------
   s = 1 - beta (X_w0 - X_w) (doc/model.md §5.15)
------------------------------------------------------------------------- */

double TurgorWallWater::stretch(double x0, double x) const
{
  return 1.0 - beta * (x0 - x);
}

/* ---------------------------------------------------------------------- */

const double *TurgorWallWater::per_atom(const CellRegistry &reg)
{
  const int n = atom->nlocal + atom->nghost;
  if ((int) atoms.size() < n) atoms.resize(n);
  const tagint *molecule = atom->molecule;
  const int ncell = (int) active.size();
  for (int i = 0; i < n; i++) {
    const int c = molecule[i] > 0 ? reg.index(molecule[i]) : -1;
    atoms[i] = c >= 0 && c < ncell ? active[c] : 1.0;
  }
  return atoms.data();
}

/* ----------------------------------------------------------------------
   the contract of cell_styles.h: each atom's wall stretch s, nullptr without wallwater
------------------------------------------------------------------------- */

const double *FixCellTurgor::wall_stretch()
{
  return wallwater.on() ? wallwater.per_atom(cells->registry()) : nullptr;
}

/* ----------------------------------------------------------------------
   after an evaluation's transfers: each home cell's wall moisture X_w at its psi_cell = P_T - pi;
   a cell first seen starts its wall at X_w0 = X_w (s = 1), its wall water m_w A_ref X_w0 beside
   its sap. With a transfer that moves water, the wall takes dW = m_dry (X_w - X_w,last) from the
   sap (flux drives: dM_sap = dM - dW, the cell's water changes by dM) or from outside (curve: the
   sap follows the curve, the cell's water changes by dM + dW). The stretch after it is shared
------------------------------------------------------------------------- */

void FixCellTurgor::wall_water(Evaluation &e, bool transfer)
{
  const double t = drive.temperature > 0.0 ? drive.temperature : osmotic_model.tref;
  const bool moves = transfer && (e.dtw > 0.0 || drive.kind == TurgorDrive::CURVE);
  std::vector<double> stretch(e.home.size(), 1.0);
  double water = 0.0;
  for (int pos = 0; pos < (int) e.home.size(); pos++) {
    const int c = e.home[pos];
    TurgorState::Cell &s = state[cells->id(c)];
    const double mass = cells->mass(c);
    const double pi = osmotic_model.pressure(s.pi0, s.mass0, s.solids, mass, t, nullptr);
    const double x = wallwater.moisture(e.turgor[pos] - pi, t);
    if (s.wall_dry == 0.0) {
      const double area0 = cells->ref_area(c) > 0.0 ? cells->ref_area(c) : cells->area(c);
      s.wall_dry = wallwater.dry_mass(area0);
      s.wall_x0 = s.wall_x = x;
    } else if (moves) {
      s.wall_dx = x - s.wall_x;
      // dW = m_dry dX_w, the wall's water change (doc/model.md §5.15)
      const double dw = s.wall_dry * s.wall_dx;
      if (drive.kind == TurgorDrive::CURVE)
        e.moved += dw;
      else
        e.scale[pos] -= dw / mass;
      if (!(1.0 + e.scale[pos] > 0.0) && failure.cell == cells->ncell())
        failure = Failure{c,
                          fmt::format("Fix cell/turgor: cell {} would lose all its sap to its "
                                      "wall at step {}: fluid mass M = {} kg, wall water change "
                                      "{} kg",
                                      cells->id(c), update->ntimestep, mass, dw)};
    }
    stretch[pos] = wallwater.stretch(s.wall_x0, s.wall_x + s.wall_dx);
    water += s.wall_dry * (s.wall_x + s.wall_dx);
  }
  if (transfer) cells->registry().settle(failure.cell, failure.message, {});
  cells->registry().allgather(1, stretch, wallwater.next);
  MPI_Allreduce(&water, &wallwater.water_next, 1, MPI_DOUBLE, MPI_SUM, world);
  // a cell first seen at an evaluation without transfer: its stretch and water are in effect
  if (!transfer && !any_pending) apply_wall_water();
}

/* ----------------------------------------------------------------------
   the waiting transfer's wall water and stretch take effect (with its masses, pre_force)
------------------------------------------------------------------------- */

void FixCellTurgor::apply_wall_water()
{
  for (int c : cells->home_cells()) {
    TurgorState::Cell &s = state[cells->id(c)];
    s.wall_x += s.wall_dx;
    s.wall_dx = 0.0;
  }
  wallwater.active = wallwater.next;
  wallwater.water = wallwater.water_next;
}

/* ----------------------------------------------------------------------
   init: the stretch and wall water in effect and after the waiting transfer, from the home
   cells' state (after a restart or between runs)
------------------------------------------------------------------------- */

void FixCellTurgor::share_wall_water()
{
  const std::vector<int> &home = cells->home_cells();
  std::vector<double> now(home.size(), 1.0), after(home.size(), 1.0);
  double water[2] = {0.0, 0.0}, all[2];
  for (int pos = 0; pos < (int) home.size(); pos++) {
    const TurgorState::Cell &s = state[cells->id(home[pos])];
    if (s.wall_dry == 0.0) continue;
    now[pos] = wallwater.stretch(s.wall_x0, s.wall_x);
    after[pos] = wallwater.stretch(s.wall_x0, s.wall_x + s.wall_dx);
    water[0] += s.wall_dry * s.wall_x;
    water[1] += s.wall_dry * (s.wall_x + s.wall_dx);
  }
  cells->registry().allgather(1, now, wallwater.active);
  cells->registry().allgather(1, after, wallwater.next);
  MPI_Allreduce(water, all, 2, MPI_DOUBLE, MPI_SUM, world);
  wallwater.water = all[0];
  wallwater.water_next = all[1];
}
