/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   fix cell/turgor's accel and accel auto: the lag probe of each cell and the adaptation of accel
   (doc/model.md §5.12)
------------------------------------------------------------------------- */

#include "fix_cell_turgor_accel.h"

#include "cell_wall_triangles.h"

#include "comm.h"
#include "error.h"
#include "math_const.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

TurgorAccel::TurgorAccel(LAMMPS *lmp) :
    Pointers(lmp), value(1.0), automatic(0), pending(0), lag_estimate(0.0), lag_error(0.0),
    edge(0.0), every(0), hold(0), open_samples(0), sealed_samples(0), tol(0.0), lo(1.0), hi(MAX),
    start(0.0), change(CHANGE), least(0.0), last(0.0), growth(0.0)
{
}

/* ---------------------------------------------------------------------- */

int TurgorAccel::parse(int narg, char **arg, const std::string &command)
{
  if (narg < 1) error->all(FLERR, "{}: missing value after 'accel'", command);
  if (strcmp(arg[0], "auto") != 0) {
    const double a = utils::numeric(FLERR, arg[0], false, lmp);
    if (!(a > 0.0 && a <= MAX))
      error->all(FLERR, "{}: accel = {} must be > 0 and <= 1e15", command, a);
    value = a;
    automatic = pending = 0;
    return 1;
  }
  if (narg < 2) error->all(FLERR, "{}: missing tolerance after 'accel auto'", command);
  const double t = utils::numeric(FLERR, arg[1], false, lmp);
  if (!(t > 0.0 && t < 1.0))
    error->all(FLERR, "{}: accel auto tolerance = {} must be in (0, 1)", command, t);
  double min = 1.0, max = MAX, first = 0.0, most = CHANGE;
  int open = 0, sealed = 0, used = 2;
  while (used + 1 < narg) {
    const std::string key = arg[used];
    if (key != "min" && key != "max" && key != "start" && key != "every" && key != "hold" &&
        key != "change")
      break;
    if (key == "change") {
      most = utils::numeric(FLERR, arg[used + 1], false, lmp);
      if (!(most > 0.0 && most <= 0.1))
        error->all(FLERR, "{}: accel auto change = {} must be > 0 and <= 0.1", command, most);
    } else if (key == "every" || key == "hold") {
      const int n = utils::inumeric(FLERR, arg[used + 1], false, lmp);
      if (n < 4)
        error->all(FLERR, "{}: accel auto {} = {} must be >= 4 transfers", command, key, n);
      (key == "every" ? open : sealed) = n;
    } else {
      const double a = utils::numeric(FLERR, arg[used + 1], false, lmp);
      if (!(a > 0.0 && a <= MAX))
        error->all(FLERR, "{}: accel auto {} = {} must be > 0 and <= 1e15", command, key, a);
      (key == "min" ? min : key == "max" ? max : first) = a;
    }
    used += 2;
  }
  if (min > max)
    error->all(FLERR, "{}: accel auto min = {} must be <= max = {}", command, min, max);
  if (first > 0.0 && (first < min || first > max))
    error->all(FLERR, "{}: accel auto start = {} must be in [min, max] = [{}, {}]", command, first,
               min, max);
  automatic = pending = 1;
  tol = t;
  lo = min;
  hi = max;
  start = first;
  every = open;
  hold = sealed;
  change = most;
  return used;
}

/* ----------------------------------------------------------------------
   transfer j is at position (j - 1) % (every + hold) of its cycle: open for every transfers
   (default 20 offset times tau, in [8, 200]), then sealed for hold (default 5 tau, in [4, 50]):
   a cycle ends within 250 transfers; the second half of each is sampled (doc/model.md §5.12)
------------------------------------------------------------------------- */

TurgorAccel::Cycle TurgorAccel::cycle(bigint j, bool transfer, double offset, double step)
{
  Cycle at;
  const double taus = offset / step;
  at.every = every > 0 ? every : std::min((bigint) 200, std::max((bigint) 8, lround(20.0 * taus)));
  at.hold = hold > 0 ? hold : std::min((bigint) 50, std::max((bigint) 4, lround(5.0 * taus)));
  at.position = automatic ? (j - 1) % (at.every + at.hold) : 0;
  at.sealed = automatic && at.position >= at.every;
  at.sample = automatic && transfer &&
      2 * (at.sealed ? at.position - at.every : at.position) >= (at.sealed ? at.hold : at.every);
  if (at.sample) (at.sealed ? sealed_samples : open_samples)++;
  return at;
}

/* ----------------------------------------------------------------------
   a sample of the cell's turgor at a transfer of the second half of the open window (with the
   rate and conductance; the last one is kept) or of the sealed window
------------------------------------------------------------------------- */

void TurgorAccel::sample(double *p, const Cycle &at, double turgor, double rate,
                         double conductance) const
{
  if (!at.sealed && open_samples == 1) {
    for (int k = 0; k < NPROBE; k++) p[k] = 0.0;
    p[Y0] = turgor;
  }
  const double y = turgor - p[Y0];
  if (at.sealed) {
    p[SY2] += y;
    p[SYY2] += y * y;
    return;
  }
  const double t = (double) at.position;
  p[ST] += t;
  p[SY] += y;
  p[STT] += t * t;
  p[STY] += t * y;
  p[SYY] += y * y;
  p[RATE] = rate;
  p[COND] = conductance;
}

/* ----------------------------------------------------------------------
   the cell's lag e = G (P_T - P_qs) / (dM/dt) at the end of the open window and its standard
   error se, |dM/dt| raised to the largest of the cells' (flux: a cell whose flux is small moves
   little water, its shortfall counts against the largest): P_T from the least-squares line
   through the open window's samples at the seal, P_qs the mean of the sealed window's second half
   (doc/model.md §5.12); false without enough samples or flux
------------------------------------------------------------------------- */

bool TurgorAccel::lag(const double *p, bigint open, double flux, double &e, double &se) const
{
  const double n = open_samples, m = sealed_samples;
  if (n < 3 || m < 2 || p[RATE] == 0.0) return false;
  const double dtt = p[STT] - p[ST] * p[ST] / n;
  const double dty = p[STY] - p[ST] * p[SY] / n;
  const double dyy = p[SYY] - p[SY] * p[SY] / n;
  if (!(dtt > 0.0)) return false;
  const double slope = dty / dtt, tbar = p[ST] / n, at = (double) open - tbar;
  // P_T at the seal (t = every) on the line, variance s^2 (1/n + (t - tbar)^2 / Stt)
  const double popen = p[SY] / n + slope * at;
  const double vopen = std::max(0.0, dyy - slope * dty) / (n - 2.0) * (1.0 / n + at * at / dtt);
  // P_qs = the sealed mean, variance s^2 / m
  const double psealed = p[SY2] / m;
  const double vsealed = std::max(0.0, p[SYY2] - p[SY2] * p[SY2] / m) / ((m - 1.0) * m);
  // e = G (P_T - P_qs) / (dM/dt): the flux's shortfall from its quasi-static value, relative to
  // the largest flux of the cells (flux) where that is larger
  const double scale = std::max(fabs(p[RATE]), flux);
  e = p[COND] * (popen - psealed) / scale * (p[RATE] > 0.0 ? 1.0 : -1.0);
  se = p[COND] * sqrt(vopen + vsealed) / scale;
  return std::isfinite(e) && std::isfinite(se);
}

/* ----------------------------------------------------------------------
   the first accel of a cell: a = tol tau_w / tau_m with the water relaxation time
   tau_w = 1 / (G (eps/M + slope)) (Boyle-van 't Hoff, doc/model.md §9.3) and, for tau_m, the
   offset time tau, the one mechanical time known before the run; the window then measures the lag
------------------------------------------------------------------------- */

double TurgorAccel::first(double conductance, double slope, double eps, double mass,
                          double offset) const
{
  // 1/tau_w = G (eps/M + slope), dP/dM = eps/M for a cell full of fluid
  const double relax = conductance * (eps / mass + slope);
  return relax > 0.0 ? tol / (relax * offset) : HUGE_VAL;
}

/* ----------------------------------------------------------------------
   the cell's elastic modulus eps = V dP/dV: the fluid's K + P_SPH, in series with the thin
   Neo-Hookean wall when the bond style gives G t0 (doc/model.md §6, §9.3)
------------------------------------------------------------------------- */

double TurgorAccel::modulus(double fluid, double gt, double area0, double area)
{
  if (!(gt > 0.0 && area0 > 0.0)) return fluid;
  const double r0 = sqrt(area0 / (4.0 * MathConst::MY_PI));
  const double lam = sqrt(area / area0);
  // eps = V dP/dV = (2 G t0 / 3 R0)(7 lam^-7 - lam^-1) of the thin Neo-Hookean sphere (§6)
  const double wall = std::max(0.0, 2.0 * gt / (3.0 * r0) * (7.0 * pow(lam, -7.0) - 1.0 / lam));
  // in series with the fluid: 1/eps = 1/eps_wall + 1/(K + P)
  return wall * fluid / (wall + fluid);
}

/* ---------------------------------------------------------------------- */

double TurgorAccel::begin(double smallest)
{
  // the first accel of auto: from the cells' state, or 'start' (doc/model.md §5.12)
  const double a0 = start > 0.0 ? start : smallest;
  const double a = std::isfinite(a0) ? std::min(hi, std::max(lo, a0)) : lo;
  const double ratio = a / value;
  value = a;
  pending = 0;
  // the current cycle's samples were made at another accel
  open_samples = sealed_samples = 0;
  return ratio;
}

/* ----------------------------------------------------------------------
   accel changes only when a cell's lag e is outside the tolerance by more than twice its standard
   error (e - 2 se > tol: down to tol/e; e + 2 se < tol: up to tol/(e + 2 se)), by at most x2 or
   /2, the most restrictive cell deciding, within [min, max] (doc/model.md §5.12)
------------------------------------------------------------------------- */

void TurgorAccel::adapt(bigint open, const std::vector<const double *> &probes, bool cells)
{
  double factor = cells ? 2.0 : 1.0;
  bool none = true;
  double largest = 0.0, largest_se = 0.0, flux = 0.0, all_flux;
  // the largest |dM/dt| of the cells' last open transfer
  for (const double *p : probes) flux = std::max(flux, fabs(p[RATE]));
  MPI_Allreduce(&flux, &all_flux, 1, MPI_DOUBLE, MPI_MAX, world);
  for (const double *p : probes) {
    double e, se, f = 1.0;
    if (lag(p, open, all_flux, e, se)) {
      if (e - 2.0 * se > tol)
        f = std::max(0.5, tol / e);
      else if (e + 2.0 * se < tol)
        f = e + 2.0 * se > 0.0 ? std::min(2.0, tol / (e + 2.0 * se)) : 2.0;
      if (none || e > largest) {
        largest = e;
        largest_se = se;
        none = false;
      }
    }
    factor = std::min(factor, f);
  }
  // over all ranks: the most restrictive factor, the largest lag (the lowest rank's of equals)
  double all_factor;
  MPI_Allreduce(&factor, &all_factor, 1, MPI_DOUBLE, MPI_MIN, world);
  factor = all_factor;
  const double mine[3] = {none ? 0.0 : 1.0, largest, largest_se};
  std::vector<double> lags(3 * comm->nprocs);
  MPI_Allgather(mine, 3, MPI_DOUBLE, lags.data(), 3, MPI_DOUBLE, world);
  none = true;
  for (int p = 0; p < comm->nprocs; p++)
    if (lags[3 * p] > 0.0 && (none || lags[3 * p + 1] > lag_estimate)) {
      lag_estimate = lags[3 * p + 1];
      lag_error = lags[3 * p + 2];
      none = false;
    }
  value = std::min(hi, std::max(lo, value * factor));
  open_samples = sealed_samples = 0;
}

/* ---------------------------------------------------------------------- */

void TurgorAccel::after(const Cycle &at, bool bound, bool transfer, const Home &home, double step,
                        bool cells)
{
  if (!automatic) {
    if (transfer) limit({}, {}, step, true);
    return;
  }
  if (at.sample)
    for (size_t pos = 0; pos < home.probe.size(); pos++)
      sample(home.probe[pos], at, home.turgor[pos], home.rate[pos], home.conductance[pos]);
  if (transfer && at.position == at.every + at.hold - 1)
    adapt(at.every, std::vector<const double *>(home.probe.begin(), home.probe.end()), cells);
  if (bound) limit(home.mass, home.rate, step, transfer);
}

/* ----------------------------------------------------------------------
   the ceiling of accel for the next transfers (doc/fix_cell_turgor.md, Safe bridging): each cell's
   water changes by at most 'change' of itself per transfer, and in the last half of its allowance
   (1.5 x the shortest longest edge since the start; pair cell/sph stops a run at 1.5 x the longest
   at the run's start) the longest wall edge grows by at most 'change' x the room left: at most
   halved per transfer; never below 'min'
------------------------------------------------------------------------- */

void TurgorAccel::limit(const std::vector<double> &mass, const std::vector<double> &rate,
                        double step, bool transfer)
{
  double ceiling = HUGE_VAL, all;
  // |dM|/M = a N dt |dM/dt| / M <= change
  for (size_t pos = 0; pos < mass.size(); pos++)
    if (rate[pos] != 0.0)
      ceiling = std::min(ceiling, change * mass[pos] / (step * fabs(rate[pos])));
  MPI_Allreduce(&ceiling, &all, 1, MPI_DOUBLE, MPI_MIN, world);
  double a = std::min(value, all);
  // the longest wall edge as pair cell/sph's guard measures it
  const double l = transfer ? CellWallTriangles::longest_edge(lmp) : 0.0;
  if (l > 0.0) {
    least = least > 0.0 ? std::min(least, l) : l;
    // room in [0, 1]: 1 at the shortest, 0 at the allowance
    const double room = std::min(1.0, std::max(0.0, (ALLOWANCE - l / least) / (ALLOWANCE - 1.0)));
    // growth per transfer, a running mean over SMOOTH transfers (the wall's ringing averages out):
    // g <- g + ((l - l_last)/l_last - g)/SMOOTH; in the last ZONE of the allowance, above
    // change x room: a x max(1/2, allowed/g)
    if (last > 0.0) growth += ((l - last) / last - growth) / SMOOTH;
    if (room < ZONE && growth > change * room)
      a = std::min(a, value * std::max(0.5, change * room / growth));
    last = l;
    edge = l / least;
  }
  // a fixed accel: the edges are only measured (output)
  if (automatic) value = std::max(lo, std::min(hi, a));
}

/* ---------------------------------------------------------------------- */

void TurgorAccel::write(std::vector<double> &list) const
{
  list.insert(list.end(),
              {automatic ? value : 0.0, (double) open_samples, (double) sealed_samples,
               lag_estimate, lag_error});
}

/* ----------------------------------------------------------------------
   accel auto continues from the adapted accel and its window when the file has them
------------------------------------------------------------------------- */

bool TurgorAccel::read(const double *v)
{
  if (!(v[0] > 0.0 && automatic)) return false;
  value = std::min(hi, std::max(lo, v[0]));
  pending = 0;
  open_samples = (int) v[1];
  sealed_samples = (int) v[2];
  lag_estimate = v[3];
  lag_error = v[4];
  return true;
}
