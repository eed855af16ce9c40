/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   pair_style cell/sph: weakly compressible SPH with summation density and per-atom mass.
   One compute() = density pass over the half neighbour list (rho_j accumulated on ghosts too,
   then summed into owners by reverse comm), equation of state on owned atoms, forward comm of
   rho and pressure, force pass. The density pass keeps the pairs inside the kernel support with
   m_i m_j (1/r) dW/dr, so the force pass has no cutoff test, square root or kernel. A half list
   evaluates each pair once; a full list would save the reverse comm but evaluate every pair twice.
------------------------------------------------------------------------- */

#include "pair_cell_sph.h"

#include "atom.h"
#include "cell_compat.h"
#include "cell_limits.h"
#include "cell_params.h"
#include "cell_restart.h"
#include "cell_triangle.h"
#include "cell_wall_triangles.h"
#include "cell_water.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "input.h"
#include "memory.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"
#include "variable.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <vector>

using namespace LAMMPS_NS;

// 2: per type pair, whether it is a wall boundary pair; 3: the smoothing-length mode and eta;
// 4: the temperature of the viscosity (temp, Tref); 5: shift; 6: tensile (eps, n, dp); 7: the
// wall boundary's adhesion W per type pair; 8: grow; 9: background; 10: background auto lag;
// 11: background auto's P_b now; 12: without the removed eos, Tref, shift, tensile, adhesion W,
// grow and lag (read_settings reads them from older files)
static const int RESTART_VERSION = 12;

static const char *const HMODE_NAMES[] = {"fixed", "mass", "adaptive"};
// h adaptive: Newton iterations on h stop when every |dh|/h < HTOL; at most HITER of them
static const double HTOL = 1e-10;
static const int HITER = 50;
// h adaptive with the wall boundary: exact evaluations of the boundary at the first step of a run
// whose h had no value yet (h starts from the pair_coeff value)
static const int HSTART = 4;

/* ---------------------------------------------------------------------- */

PairCellSPH::PairCellSPH(LAMMPS *lmp) :
    Pair(lmp), kernel(CellKernel::WENDLAND), cut_global(0.0), hmode(HFIXED), eta(0.0), hdrift(0.0),
    rho0(nullptr), bulk(nullptr), mu(nullptr), h(nullptr), background(0.0), background_set(0),
    background_auto(0), background_min(0.0), pc(nullptr), wself(nullptr), invrho0(nullptr),
    fluid(nullptr), viscous(0), shared{0.0, 0.0}, irho(-1), ipressure(-1), ih(-1), iomega(-1),
    hcap(nullptr), hscale(nullptr), dsum(nullptr), boundary(nullptr), walls(0), wall(lmp, this),
    commode(COMM_DENSITY), restart_version(0), prho2(nullptr), rhoinv(nullptr), nmax(0),
    pairfirst(nullptr), pairj(nullptr), pairdw(nullptr), pairdwj(nullptr), pairr(nullptr),
    pairmu(nullptr), maxfirst(0), maxpairs(0)
{
  restartinfo = 1;
  temp_set = 0;
  muscale = 1.0;
  temperature = 0.0;
  writedata = 1;
  reinitflag = 0;
  comm_forward = 5;    // rho, pressure (the kernel deficit, h, Omega); with walls: triangle tags
  comm_reverse = 4;    // rho (dS/dh, the kernel deficit, its dh); or the wall load
  // compute pair: the wall boundary's interval between exact evaluations and its last jump, and
  // the background pressure P_b in use
  nextra = 3;
  pvector = new double[nextra];
  pvector[0] = pvector[1] = pvector[2] = 0.0;
}

/* ---------------------------------------------------------------------- */

PairCellSPH::~PairCellSPH()
{
  destroy_peratom();
  delete[] pvector;
  memory->destroy(pairfirst);
  memory->destroy(pairj);
  memory->destroy(pairdw);
  memory->destroy(pairdwj);
  memory->destroy(pairr);
  memory->destroy(pairmu);
  if (allocated) {
    memory->destroy(boundary);
    memory->destroy(setflag);
    memory->destroy(cutsq);
    memory->destroy(rho0);
    memory->destroy(bulk);
    memory->destroy(mu);
    memory->destroy(h);
    memory->destroy(pc);
    memory->destroy(wself);
    memory->destroy(invrho0);
    memory->destroy(fluid);
    memory->destroy(hcap);
  }
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);

  const int peratom = hmode != HFIXED;
  const bool grown = atom->nmax > nmax || (walls && !wall.deficit) || (peratom && !dsum);
  if (grown) grow_peratom();
  if (temp_set) update_viscosity();
  if (background_in.is_variable()) update_background();

  if (walls) wall.start_step(grown);
  // per-atom h; h adaptive starting from the pair_coeff value: the boundary evaluated exactly at
  // the converged h again, so that its linearisation in h starts there
  int passes = 1;
  if (peratom) {
    int fresh = 0, any = 0;
    atom_h(fresh);
    MPI_Allreduce(&fresh, &any, 1, MPI_INT, MPI_MAX, world);
    if (any && walls && hmode == HADAPTIVE) passes = HSTART;
  }
  if (walls && wall.rebuilt) wall.split_list(neighbor->skin);
  for (int pass = 0; pass < passes; pass++) {
    if (walls) wall.start_pass(pass);
    density_pass(1);
    if (hmode == HADAPTIVE) solve_h();
  }
  // compute pair sums pvector over ranks: the global values on rank 0, 0 elsewhere or without walls
  const int reports = walls && comm->me == 0;
  pvector[0] = reports ? wall.every : 0.0;
  pvector[1] = reports ? wall.lastjump : 0.0;
  apply_eos();
  pvector[2] = comm->me == 0 ? background : 0.0;
  forward(COMM_DENSITY);

  const double *rho = atom->dvector[irho];
  const double *pressure = atom->dvector[ipressure];
  const double *omega = peratom ? atom->dvector[iomega] : nullptr;
  const int *type = atom->type;
  const int nall = atom->nlocal + atom->nghost;
  for (int i = atom->nlocal; i < nall; i++)
    if (fluid[type[i]]) {
      rhoinv[i] = 1.0 / rho[i];
      prho2[i] = (pressure[i] + background) * rhoinv[i] * rhoinv[i];
      if (walls) prho2[i] /= std::max(1.0 - wall.deficit[i], wall.GAMMA_MIN);
      if (peratom) prho2[i] /= omega[i];
    }

  typedef void (PairCellSPH::*Loop)();
#define CELLSPH_FORCES(V, E)                                             \
  {                                                                      \
    &PairCellSPH::sum_forces<V, E, 0>, &PairCellSPH::sum_forces<V, E, 1> \
  }
  static const Loop FORCES[2][2][2] = {{CELLSPH_FORCES(0, 0), CELLSPH_FORCES(0, 1)},
                                       {CELLSPH_FORCES(1, 0), CELLSPH_FORCES(1, 1)}};
#undef CELLSPH_FORCES
  (this->*FORCES[viscous][evflag ? 1 : 0][peratom])();
  if (walls) wall.forces(evflag);

  if (vflag_fdotr) virial_fdotr_compute();
}

/* ----------------------------------------------------------------------
   one density pass with the loop compiled for this kernel, with or without wall boundary,
   viscosity and per-atom h; first = 1: the step's first pass (with the wall boundary), 0: a
   Newton iteration of h adaptive (the sums only); then the ghost sums into owners
------------------------------------------------------------------------- */

void PairCellSPH::density_pass(int first)
{
  // per-atom h grown beyond the split's allowance: split again (split_list)
  if (walls && hmode != HFIXED && wall.outgrown()) wall.split_list(2.0 * neighbor->skin);
  typedef void (PairCellSPH::*Loop)(int);
#define CELLSPH_DENSITY(V, W, P)                                 \
  {                                                              \
    &PairCellSPH::sum_density<CellKernel::WENDLAND, V, W, P>,    \
        &PairCellSPH::sum_density<CellKernel::CUBIC, V, W, P>,   \
        &PairCellSPH::sum_density<CellKernel::QUINTIC, V, W, P>, \
        &PairCellSPH::sum_density<CellKernel::LUCY, V, W, P>     \
  }
  static const Loop DENSITY[2][2][2][CellKernel::NTYPES] = {
      {{CELLSPH_DENSITY(0, 0, 0), CELLSPH_DENSITY(0, 0, 1)},
       {CELLSPH_DENSITY(1, 0, 0), CELLSPH_DENSITY(1, 0, 1)}},
      {{CELLSPH_DENSITY(0, 1, 0), CELLSPH_DENSITY(0, 1, 1)},
       {CELLSPH_DENSITY(1, 1, 0), CELLSPH_DENSITY(1, 1, 1)}}};
#undef CELLSPH_DENSITY
  typedef void (PairCellSPH::*Resum)();
#define CELLSPH_RESUM(V)                                     \
  {                                                          \
    &PairCellSPH::resum_density<CellKernel::WENDLAND, V>,    \
        &PairCellSPH::resum_density<CellKernel::CUBIC, V>,   \
        &PairCellSPH::resum_density<CellKernel::QUINTIC, V>, \
        &PairCellSPH::resum_density<CellKernel::LUCY, V>     \
  }
  static const Resum RESUM[2][CellKernel::NTYPES] = {CELLSPH_RESUM(0), CELLSPH_RESUM(1)};
#undef CELLSPH_RESUM
  if (!first && hdrift < HMARGIN) {
    (this->*RESUM[viscous][kernel])();
  } else {
    (this->*DENSITY[walls][viscous][hmode != HFIXED][kernel])(first);
    hdrift = 0.0;
  }
  if (walls && first) wall.after_density();
  reverse(first ? COMM_DENSITY : COMM_SUMS);
}

/* ----------------------------------------------------------------------
   per-atom h of owned and ghost fluid atoms (h adaptive): the last step's h (the start of its
   Newton iteration), the pair_coeff h for an atom without one (fresh = 1 if an owned atom had
   none); then the kernel constants of every atom
------------------------------------------------------------------------- */

void PairCellSPH::atom_h(int &fresh)
{
  double *hv = atom->dvector[ih];
  const int *type = atom->type;
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  fresh = 0;
  for (int i = 0; i < nall; i++) {
    const int t = type[i];
    if (!fluid[t]) continue;
    if (!(hv[i] > 0.0)) {
      hv[i] = h[t][t];
      if (i < nlocal) fresh = 1;
    }
  }
  kernel_scales();
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::kernel_scales()
{
  const double *hv = atom->dvector[ih];
  const int *type = atom->type;
  const int nall = atom->nlocal + atom->nghost;
  const int dim = domain->dimension;
  for (int i = 0; i < nall; i++) {
    if (fluid[type[i]]) {
      const CellKernel::Scale sc = CellKernel::scale(kernel, dim, hv[i]);
      hscale[i][0] = sc.invh;
      hscale[i][1] = sc.w;
      hscale[i][2] = sc.dw;
      const double range = CellKernel::support(kernel) * (1.0 + HMARGIN) * hv[i];
      hscale[i][3] = range * range;
    } else {
      hscale[i][0] = hscale[i][1] = hscale[i][2] = hscale[i][3] = 0.0;
    }
  }
}

/* ----------------------------------------------------------------------
   stop when an atom's h is beyond what the neighbour cutoff allows
------------------------------------------------------------------------- */

void PairCellSPH::too_long(int i) const
{
  const int t = atom->type[i];
  const double hi = atom->dvector[ih][i];
  error->one(FLERR,
             "Pair cell/sph: atom {} (cell {}) needs h = {:.4g} m = {:.3g} x the h of pair_coeff "
             "{} {} on step {}, beyond the {:.4g} m ({:.3g} x) that the neighbour cutoff allows: "
             "split the run (each run measures h again: {} x its largest h) or give pair_style "
             "cell/sph a cutoff of at least {:.4g} m ({} h)",
             atom->tag[i], atom->molecule ? atom->molecule[i] : 0, hi, hi / h[t][t], t, t,
             update->ntimestep, hcap[t], hcap[t] / h[t][t], GROW,
             1.1 * hi * CellKernel::support(kernel), CellKernel::support(kernel));
}

/* ----------------------------------------------------------------------
   h adaptive: Newton iterations on h_i of owned fluid atoms until rho_i h_i^d = eta^d m_i
   (doc/pair_cell_sph.md, smoothing length), each followed by the sums at the new h
------------------------------------------------------------------------- */

void PairCellSPH::solve_h()
{
  for (int iter = 0;; iter++) {
    const double change = newton_h();
    if (change < HTOL) return;
    hdrift += change;
    if (iter == HITER)
      error->all(FLERR,
                 "Pair cell/sph: h adaptive did not converge in {} Newton iterations on step {}",
                 HITER, update->ntimestep);
    forward(COMM_H);
    kernel_scales();
    density_pass(0);
  }
}

/* ----------------------------------------------------------------------
   one Newton step dh = -h (rho - rho_h) / (d rho Omega), rho_h = eta^d m / h^d, for every owned
   fluid atom, applied only if some |dh|/h >= HTOL (on any rank); returns that largest |dh|/h
------------------------------------------------------------------------- */

double PairCellSPH::newton_h()
{
  double *hv = atom->dvector[ih];
  const double *rho = atom->dvector[irho];
  const double *rmass = atom->rmass;
  const int *type = atom->type;
  const int inum = list->inum;
  const int *ilist = list->ilist;
  const int dim = domain->dimension;
  const double etad = dim == 2 ? eta * eta : eta * eta * eta;
  step.resize(inum);
  double largest = 0.0, all = 0.0;
  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    step[ii] = 0.0;
    if (!fluid[type[i]]) continue;
    double gamma = 1.0, dgamma = 0.0;
    if (walls) {
      gamma = 1.0 - wall.deficit[i];
      dgamma = -wall.dhdef[i];
      if (gamma < wall.GAMMA_MIN) gamma = wall.GAMMA_MIN, dgamma = 0.0;
    }
    const double hi = hv[i];
    const double hd = dim == 2 ? hi * hi : hi * hi * hi;
    // rho = S / gamma, drho/dh = S'/gamma - S gamma' / gamma^2 (doc/pair_cell_sph.md)
    const double r = rho[i] / gamma;
    const double dr = dsum[i] / gamma - rho[i] * dgamma / (gamma * gamma);
    // Omega = 1 + h/(d rho) drho/dh; Newton on rho h^d - eta^d m = 0
    const double omega = 1.0 + hi * dr / (dim * r);
    if (!(omega > 0.0)) unsolvable(i, omega);
    double dh = -hi * (r - etad * rmass[i] / hd) / (dim * r * omega);
    dh = std::max(-0.2 * hi, std::min(0.2 * hi, dh));
    step[ii] = dh;
    largest = std::max(largest, fabs(dh) / hi);
  }
  MPI_Allreduce(&largest, &all, 1, MPI_DOUBLE, MPI_MAX, world);
  if (all < HTOL) return all;
  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    if (!fluid[type[i]]) continue;
    hv[i] += step[ii];
    // the deficit at the new h: linear in h between exact evaluations
    if (walls) wall.deficit[i] += wall.dhdef[i] * step[ii];
    if (hv[i] > hcap[type[i]]) too_long(i);
  }
  return all;
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::unsolvable(int i, double omega) const
{
  error->one(FLERR,
             "Pair cell/sph: h adaptive: atom {} (cell {}) at ({:.4g}, {:.4g}, {:.4g}) has Omega "
             "= 1 + h/(3 rho) drho/dh = {:.4g} <= 0 on step {}: its density falls faster than "
             "h^-3 as h grows, and rho h^3 = eta^3 m has no unique solution (too few neighbours "
             "for eta = {})",
             atom->tag[i], atom->molecule ? atom->molecule[i] : 0, atom->x[i][0], atom->x[i][1],
             atom->x[i][2], omega, update->ntimestep, eta);
}

/* ----------------------------------------------------------------------
   per-atom arrays (owned and ghost) at atom->nmax: the force pass's, per-atom h's, and the wall
   boundary's
------------------------------------------------------------------------- */

void PairCellSPH::destroy_peratom()
{
  memory->destroy(prho2);
  memory->destroy(rhoinv);
  memory->destroy(hscale);
  memory->destroy(dsum);
  wall.destroy();
}

void PairCellSPH::grow_peratom()
{
  destroy_peratom();
  nmax = atom->nmax;
  memory->create(prho2, nmax, "pair:prho2");
  memory->create(rhoinv, nmax, "pair:rhoinv");
  if (hmode != HFIXED) {
    memory->create(hscale, nmax, 4, "pair:hscale");
    memory->create(dsum, nmax, "pair:dsum");
  }
  if (walls) wall.grow(nmax, hmode != HFIXED);
}

/* ----------------------------------------------------------------------
   rho_i = sum_j m_j W_ij including j = i, into the custom vector rho of owned (and, with newton,
   ghost) atoms; the pairs inside the support into pairj, pairdw (and pairmu). With per-atom h
   (PERATOM): W_ij = W(r_ij, h_i) in rho_i, dS/dh into dsum, both kernels' gradients kept.
   first = 0: a Newton iteration of h adaptive, the sums only (no wall boundary)
------------------------------------------------------------------------- */

template <int KERNEL, int VISCOUS, int WALLS, int PERATOM> void PairCellSPH::sum_density(int first)
{
  double **x = atom->x;
  double *rho = atom->dvector[irho];
  const double *rmass = atom->rmass;
  const int *type = atom->type;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  const double dim = domain->dimension;
  const double w0 = CellKernel::shape<KERNEL>(0.0);

  const int inum = list->inum;
  const int *ilist = list->ilist;
  const int *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;

  if (inum + 1 > maxfirst) {
    maxfirst = inum + 1;
    memory->destroy(pairfirst);
    memory->create(pairfirst, maxfirst, "pair:pairfirst");
  }

  // self term m_i W(0); per-atom h: d(m W(0, h))/dh = -d m W(0, h) / h
  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    if (PERATOM) {
      rho[i] = rmass[i] * w0 * hscale[i][1];
      dsum[i] = -dim * rho[i] * hscale[i][0];
    } else {
      rho[i] = rmass[i] * wself[type[i]];
    }
  }
  if (newton_pair) {
    const int nall = nlocal + atom->nghost;
    for (int i = nlocal; i < nall; i++) rho[i] = 0.0;
    if (PERATOM)
      for (int i = nlocal; i < nall; i++) dsum[i] = 0.0;
  }
  if (WALLS && first) wall.start_sums(PERATOM);

  int npairs = 0;
  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const double xtmp = x[i][0];
    const double ytmp = x[i][1];
    const double ztmp = x[i][2];
    const double mi = rmass[i];
    const PairConst *pci = pc[type[i]];
    // with the wall boundary, the fluid pairs of the list (split_list() at reneighbouring)
    const int *jlist = WALLS ? &wall.fluidj[wall.fluidfirst[ii]] : firstneigh[i];
    const int jnum = WALLS ? wall.fluidfirst[ii + 1] - wall.fluidfirst[ii] : numneigh[i];
    if (npairs + jnum > maxpairs) grow_pairs(npairs + jnum);
    int *pj = pairj;
    double *pdw = pairdw;
    double *pmu = pairmu;
    pairfirst[ii] = npairs;
    double rhoi = 0.0, dsumi = 0.0;

    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const PairConst &p = pci[type[j]];
      const double delx = xtmp - x[j][0];
      const double dely = ytmp - x[j][1];
      const double delz = ztmp - x[j][2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      if (rsq >= p.cutsq) continue;

      if (PERATOM) {
        // the pairs within (1 + HMARGIN) x the support of h_i or h_j
        if (rsq >= hscale[i][3] && rsq >= hscale[j][3]) continue;
        const double r = sqrt(rsq);
        pairr[npairs] = r;
        pj[npairs] = j;
        peratom_pair<KERNEL, VISCOUS>(i, j, r, p.mu2, npairs, rhoi, dsumi);
        npairs++;
        continue;
      }
      const double r = sqrt(rsq);
      const double mj = rmass[j];
      // rho_i += m_j W_ij, rho_j += m_i W_ij (doc/model.md §3.2); all of the pair's kernel values
      // before the stores, which may alias p
      const double w = CellKernel::W<KERNEL>(p.scale, r);
      const double mmdw = mi * mj * CellKernel::dWr<KERNEL>(p.scale, r);
      const double mu = p.mu2 * mmdw;
      rhoi += mj * w;
      if (newton_pair || j < nlocal) rho[j] += mi * w;
      pj[npairs] = j;
      pdw[npairs] = mmdw;
      if (VISCOUS) pmu[npairs] = mu;
      npairs++;
    }
    rho[i] += rhoi;
    if (PERATOM) dsum[i] += dsumi;
  }
  pairfirst[inum] = npairs;

  if (WALLS && first && wall.refreshing) wall.exact_terms(PERATOM);
}

/* ----------------------------------------------------------------------
   per-atom h: pair k (i, j at distance r) into rho_i (here rhoi, dsumi), rho_j and dS/dh, and the
   pair's kernel gradients at h_i and h_j (zero outside each support)
------------------------------------------------------------------------- */

template <int KERNEL, int VISCOUS>
inline void PairCellSPH::peratom_pair(int i, int j, double r, double mu2, int k, double &rhoi,
                                      double &dsumi)
{
  const double support = CellKernel::support(KERNEL);
  const double dim = domain->dimension;
  const double mi = atom->rmass[i], mj = atom->rmass[j];
  const double qi = r * hscale[i][0], qj = r * hscale[j][0];
  double dwi = 0.0, dwj = 0.0;
  if (qi < support) {
    // rho_i += m_j W(r, h_i); dW/dh = -(d W + r dW/dr) / h (doc/pair_cell_sph.md)
    const double f = CellKernel::shape<KERNEL>(qi), g = CellKernel::slope<KERNEL>(qi);
    rhoi += mj * hscale[i][1] * f;
    dsumi -= mj * hscale[i][1] * hscale[i][0] * (dim * f + qi * qi * g);
    dwi = hscale[i][2] * g;
  }
  if (qj < support) {
    const double f = CellKernel::shape<KERNEL>(qj), g = CellKernel::slope<KERNEL>(qj);
    if (force->newton_pair || j < atom->nlocal) {
      atom->dvector[irho][j] += mi * hscale[j][1] * f;
      dsum[j] -= mi * hscale[j][1] * hscale[j][0] * (dim * f + qj * qj * g);
    }
    dwj = hscale[j][2] * g;
  }
  pairdw[k] = mi * mj * dwi;
  pairdwj[k] = mi * mj * dwj;
  // viscosity with the mean of the two kernels' gradients (doc/pair_cell_sph.md)
  if (VISCOUS) pairmu[k] = 0.5 * mu2 * (pairdw[k] + pairdwj[k]);
}

/* ----------------------------------------------------------------------
   h adaptive, an iteration while every h changed by less than HMARGIN since the last density
   pass: the sums over that pass's pairs, at the new h
------------------------------------------------------------------------- */

template <int KERNEL, int VISCOUS> void PairCellSPH::resum_density()
{
  double *rho = atom->dvector[irho];
  const double *rmass = atom->rmass;
  const int *type = atom->type;
  const int nlocal = atom->nlocal;
  const double dim = domain->dimension;
  const double w0 = CellKernel::shape<KERNEL>(0.0);
  const int inum = list->inum;
  const int *ilist = list->ilist;
  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    rho[i] = rmass[i] * w0 * hscale[i][1];
    dsum[i] = -dim * rho[i] * hscale[i][0];
  }
  if (force->newton_pair)
    for (int i = nlocal; i < nlocal + atom->nghost; i++) rho[i] = dsum[i] = 0.0;
  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const PairConst *pci = pc[type[i]];
    double rhoi = 0.0, dsumi = 0.0;
    for (int k = pairfirst[ii]; k < pairfirst[ii + 1]; k++)
      peratom_pair<KERNEL, VISCOUS>(i, pairj[k], pairr[k], pci[type[pairj[k]]].mu2, k, rhoi, dsumi);
    rho[i] += rhoi;
    dsum[i] += dsumi;
  }
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::grow_pairs(int n)
{
  maxpairs = n + n / 2;
  memory->grow(pairj, maxpairs, "pair:pairj");
  memory->grow(pairdw, maxpairs, "pair:pairdw");
  if (hmode != HFIXED) {
    memory->grow(pairdwj, maxpairs, "pair:pairdwj");
    memory->grow(pairr, maxpairs, "pair:pairr");
  }
  memory->grow(pairmu, maxpairs, "pair:pairmu");
}

/* ----------------------------------------------------------------------
   stop a run whose density left (0, 2 rho0] (a weakly compressible fluid never gets there unless
   the run went unstable), saying where and the likely cause
------------------------------------------------------------------------- */

void PairCellSPH::unstable(int i) const
{
  const int t = atom->type[i];
  const double c = sqrt(bulk[t][t] * invrho0[t]);
  const double rho = atom->dvector[irho][i];
  error->one(FLERR,
             "Pair cell/sph: atom {} (cell {}) at ({:.4g}, {:.4g}, {:.4g}) has density {:.4g} = "
             "{:.3g} rho0 on step {}, outside (0, 2 rho0]: the run went unstable; the acoustic "
             "time step limit is 0.25 h / c = {:.3g} s (c = sqrt(K / rho0) = {:.4g} m/s)",
             atom->tag[i], atom->molecule ? atom->molecule[i] : 0, atom->x[i][0], atom->x[i][1],
             atom->x[i][2], rho, rho * invrho0[t], update->ntimestep,
             0.25 * (hmode == HFIXED ? h[t][t] : atom->dvector[ih][i]) / c, c);
}

/* ----------------------------------------------------------------------
   pressure of owned fluid atoms from their density; P/rho^2 and 1/rho for the force pass;
   the equation-of-state energy m_i e(rho_i), e' = P/rho^2, whose gradient is the pressure force
------------------------------------------------------------------------- */

void PairCellSPH::apply_eos()
{
  double *rho = atom->dvector[irho];
  double *pressure = atom->dvector[ipressure];
  const double *rmass = atom->rmass;
  const int *type = atom->type;
  const int inum = list->inum;
  const int *ilist = list->ilist;
  double volume[2] = {0.0, 0.0};    // this rank's sum m/rho and sum P m/rho over fluid atoms

  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const int t = type[i];
    if (!fluid[t]) continue;
    // rho_i = sum_j m_j W_ij / gamma_i with the wall boundary: the kernel completed by the cell
    const double gamma = walls ? std::max(1.0 - wall.deficit[i], wall.GAMMA_MIN) : 1.0;
    // h adaptive: Omega = 1 + h/(d rho) drho/dh, drho/dh = S'/gamma + S D'/gamma^2 (above the
    // floor); it divides the atom's density gradient (doc/pair_cell_sph.md); 1 at fixed h
    double omega = 1.0;
    if (hmode == HADAPTIVE) {
      const double dgamma = walls && 1.0 - wall.deficit[i] >= wall.GAMMA_MIN ? -wall.dhdef[i] : 0.0;
      const double dr = dsum[i] / gamma - rho[i] * dgamma / (gamma * gamma);
      omega = 1.0 + atom->dvector[ih][i] * dr * gamma / (domain->dimension * rho[i]);
    }
    if (hmode != HFIXED) atom->dvector[iomega][i] = omega;
    rho[i] /= gamma;
    const double x = rho[i] * invrho0[t];
    // P = K (rho/rho0 - 1), e = (K / rho0) [ln(rho/rho0) + rho0/rho - 1]
    const double k = bulk[t][t];
    pressure[i] = k * (x - 1.0);
    const double e = eflag_either ? k * invrho0[t] * (log(x) + 1.0 / x - 1.0) : 0.0;
    if (!(x > 0.0 && x <= 2.0) || !std::isfinite(pressure[i])) unstable(i);
    rhoinv[i] = 1.0 / rho[i];
    // P / (rho^2 gamma Omega): dE/drho d(rho)/d(sum m W) of E = sum m e(rho) (= P / rho^2
    // without walls at fixed h); the background pressure is added below
    prho2[i] = pressure[i] * rhoinv[i] * rhoinv[i] / (gamma * omega);
    volume[0] += rmass[i] * rhoinv[i];
    volume[1] += pressure[i] * rmass[i] * rhoinv[i];
    if (eflag_global) eng_vdwl += rmass[i] * e;
    if (eflag_atom) eatom[i] += rmass[i] * e;
  }
  if (background_auto) {
    // P_b = P_min - the fluid's volume-weighted mean pressure sum P m/rho / sum m/rho (eq. B3)
    double sum[2];
    MPI_Allreduce(volume, sum, 2, MPI_DOUBLE, MPI_SUM, world);
    const double target = background_min - (sum[0] > 0.0 ? sum[1] / sum[0] : 0.0);
    // P_b relaxes to it over the lag time, a step at a time (eq. B4), from the target at the
    // first evaluation; a run's setup keeps a P_b that steps have advanced, so that a run split in
    // two continues as one, and takes the target again while no step has (e.g. after a 'run 0' and
    // a change of the masses)
    const double lag = AUTO_LAG * update->dt;
    if (background_set != BACKGROUND_STEPPED)
      background = target;
    else if (!update->setupflag)
      background += std::min(1.0, update->dt / lag) * (target - background);
    background_set = update->setupflag && background_set != BACKGROUND_STEPPED ? BACKGROUND_SETUP
                                                                               : BACKGROUND_STEPPED;
  }
  if (background == 0.0) return;
  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const int t = type[i];
    if (!fluid[t]) continue;
    const double gamma = walls ? std::max(1.0 - wall.deficit[i], wall.GAMMA_MIN) : 1.0;
    const double omega = hmode == HADAPTIVE ? atom->dvector[iomega][i] : 1.0;
    // P_b + P in the forces; e gains P_b (1/rho0 - 1/rho) (doc/pair_cell_sph.md, eq. B1)
    prho2[i] += background * rhoinv[i] * rhoinv[i] / (gamma * omega);
    if (!eflag_either) continue;
    const double e = rmass[i] * background * (invrho0[t] - rhoinv[i]);
    if (eflag_global) eng_vdwl += e;
    if (eflag_atom) eatom[i] += e;
  }
}

/* ----------------------------------------------------------------------
   pressure and viscous forces over the pairs of sum_density(); the virial is tallied per pair,
   the energy is the equation-of-state energy of apply_eos()
------------------------------------------------------------------------- */

template <int VISCOUS, int EVFLAG, int PERATOM> void PairCellSPH::sum_forces()
{
  double **x = atom->x;
  double **v = atom->v;
  double **f = atom->f;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  const int inum = list->inum;
  const int *ilist = list->ilist;

  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const double xtmp = x[i][0];
    const double ytmp = x[i][1];
    const double ztmp = x[i][2];
    const double vxtmp = v[i][0];
    const double vytmp = v[i][1];
    const double vztmp = v[i][2];
    const double prho2i = prho2[i];
    const double rhoinvi = rhoinv[i];
    double fxi = 0.0, fyi = 0.0, fzi = 0.0;

    for (int k = pairfirst[ii]; k < pairfirst[ii + 1]; k++) {
      const int j = pairj[k];
      const double delx = xtmp - x[j][0];
      const double dely = ytmp - x[j][1];
      const double delz = ztmp - x[j][2];
      // F^p_i = -m_i m_j (P_i/rho_i^2 + P_j/rho_j^2) grad_i W_ij (doc/model.md §3.4); per-atom h:
      // -m_i m_j (P_i/(Omega_i rho_i^2) grad_i W(h_i) + P_j/(Omega_j rho_j^2) grad_i W(h_j))
      const double fpress = PERATOM ? -(pairdw[k] * prho2i + pairdwj[k] * prho2[j])
                                    : -pairdw[k] * (prho2i + prho2[j]);
      double fx = delx * fpress;
      double fy = dely * fpress;
      double fz = delz * fpress;
      if (VISCOUS) {
        // F^v_i = m_i m_j (mu_i + mu_j) v_ij / (rho_i rho_j) (1/r) dW/dr (doc/model.md §3.5)
        const double fvisc = pairmu[k] * rhoinvi * rhoinv[j];
        fx += (vxtmp - v[j][0]) * fvisc;
        fy += (vytmp - v[j][1]) * fvisc;
        fz += (vztmp - v[j][2]) * fvisc;
      }

      fxi += fx;
      fyi += fy;
      fzi += fz;
      if (newton_pair || j < nlocal) {
        f[j][0] -= fx;
        f[j][1] -= fy;
        f[j][2] -= fz;
      }
      if (EVFLAG) ev_tally_xyz(i, j, nlocal, newton_pair, 0.0, 0.0, fx, fy, fz, delx, dely, delz);
    }
    f[i][0] += fxi;
    f[i][1] += fyi;
    f[i][2] += fzi;
  }
}

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
   check the per-atom data, request a half list, select the loops
------------------------------------------------------------------------- */

void PairCellSPH::init_style()
{
  if (!atom->rmass_flag)
    error->all(FLERR,
               "Pair style cell/sph needs per-atom masses (rmass), which atom_style {} does not "
               "have: add 'fix cellatoms all property/atom rmass d2_xref 3 ghost yes' before "
               "read_data",
               atom->atom_style);
  int flag, cols;
  irho = atom->find_custom("rho", flag, cols);
  if (irho < 0 || flag != 1 || cols != 0)
    error->all(FLERR,
               "Pair style cell/sph needs the per-atom vector rho: add 'fix cellsph all "
               "property/atom d_rho d_pressure ghost yes' before read_data");
  ipressure = atom->find_custom("pressure", flag, cols);
  if (ipressure < 0 || flag != 1 || cols != 0)
    error->all(FLERR,
               "Pair style cell/sph needs the per-atom vector pressure: add 'fix cellsph all "
               "property/atom d_rho d_pressure ghost yes' before read_data");

  if (hmode != HFIXED) {
    int hflag, hcols, oflag, ocols;
    ih = atom->find_custom("h", hflag, hcols);
    iomega = atom->find_custom("omega", oflag, ocols);
    if (ih < 0 || hflag != 1 || hcols != 0 || iomega < 0 || oflag != 1 || ocols != 0)
      error->all(FLERR,
                 "Pair style cell/sph: h {} needs the per-atom vectors h and omega: add 'fix "
                 "cellsph all property/atom d_rho d_pressure d_h d_omega ghost yes' before "
                 "read_data",
                 HMODE_NAMES[hmode]);
  }

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

/* ---------------------------------------------------------------------- */

void PairCellSPH::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (setflag[i][j]) {
        fwrite(&boundary[i][j], sizeof(int), 1, fp);
        fwrite(&rho0[i][j], sizeof(double), 1, fp);
        fwrite(&bulk[i][j], sizeof(double), 1, fp);
        fwrite(&mu[i][j], sizeof(double), 1, fp);
        fwrite(&h[i][j], sizeof(double), 1, fp);
      }
    }
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  const int me = comm->me;
  double adhesion = 0.0;    // versions 7-11: the removed wall adhesion W, refused if > 0
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
      if (setflag[i][j]) {
        if (restart_version >= 2) {
          if (me == 0) utils::sfread(FLERR, &boundary[i][j], sizeof(int), 1, fp, nullptr, error);
          MPI_Bcast(&boundary[i][j], 1, MPI_INT, 0, world);
        }
        double values[5] = {0.0, 0.0, 0.0, 0.0, 0.0};
        const int nvalues = restart_version >= 7 && restart_version < 12 ? 5 : 4;
        if (me == 0) utils::sfread(FLERR, values, sizeof(double), nvalues, fp, nullptr, error);
        MPI_Bcast(values, 5, MPI_DOUBLE, 0, world);
        rho0[i][j] = values[0];
        bulk[i][j] = values[1];
        mu[i][j] = values[2];
        h[i][j] = values[3];
        adhesion = std::max(adhesion, values[4]);
      }
    }
  if (adhesion > 0.0)
    error->all(FLERR,
               "Pair cell/sph: the restart file has a wall boundary with adhesion W = {} J/m^2, "
               "which was removed: the wall boundary with 'background auto' (or a background "
               "P_b) holds the fluid on the wall",
               adhesion);
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::write_restart_settings(FILE *fp)
{
  // version 1 (no marker) began with the kernel index >= 0; later versions with -version
  const int marker = -RESTART_VERSION;
  fwrite(&marker, sizeof(int), 1, fp);
  fwrite(&kernel, sizeof(int), 1, fp);
  fwrite(&cut_global, sizeof(double), 1, fp);
  fwrite(&hmode, sizeof(int), 1, fp);
  fwrite(&eta, sizeof(double), 1, fp);
  // temp (flag, number, variable name)
  fwrite(&temp_set, sizeof(int), 1, fp);
  fwrite(&temp.value, sizeof(double), 1, fp);
  const int len = static_cast<int>(temp.name.size());
  fwrite(&len, sizeof(int), 1, fp);
  if (len > 0) fwrite(temp.name.data(), sizeof(char), len, fp);
  // background (number, variable name, auto flag, P_min), auto's P_b now and whether it has one
  fwrite(&background_in.value, sizeof(double), 1, fp);
  const int blen = static_cast<int>(background_in.name.size());
  fwrite(&blen, sizeof(int), 1, fp);
  if (blen > 0) fwrite(background_in.name.data(), sizeof(char), blen, fp);
  fwrite(&background_auto, sizeof(int), 1, fp);
  fwrite(&background_min, sizeof(double), 1, fp);
  fwrite(&background, sizeof(double), 1, fp);
  fwrite(&background_set, sizeof(int), 1, fp);
}

/* ----------------------------------------------------------------------
   the settings of a restart file of any version (on rank 0): those of the removed keywords
   (version < 12: eos, Tref, shift, tensile eps n dp, grow, background auto lag) into old
------------------------------------------------------------------------- */

void PairCellSPH::read_settings(FILE *fp, Removed &old, std::string &name, std::string &bname,
                                double &pb)
{
  const int v = restart_version;
  const auto get = [&](auto *value, int n = 1) {
    utils::sfread(FLERR, value, sizeof(*value), n, fp, nullptr, error);
  };
  const auto text = [&](std::string &str) {
    int n = 0;
    get(&n);
    std::vector<char> chars(n);
    if (n > 0) get(chars.data(), n);
    str.assign(chars.begin(), chars.end());
  };
  if (v < 12) get(&old.eos);
  get(&cut_global);
  if (v >= 3) get(&hmode), get(&eta);
  if (v >= 4) {
    get(&temp_set);
    get(&temp.value);
    if (v < 12) get(&old.tref);
    text(name);
  }
  if (v >= 5 && v < 12) get(&old.shift);
  if (v >= 6 && v < 12) {
    int n = 0;
    double dp = 0.0;
    get(&old.tensile), get(&n), get(&dp);
  }
  if (v >= 8 && v < 12) get(&old.grow);
  if (v >= 9) {
    get(&background_in.value);
    text(bname);
    get(&background_auto);
    get(&background_min);
  }
  if (v >= 10 && v < 12) get(&old.lag);
  if (v >= 11) get(&pb), get(&background_set);
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::read_restart_settings(FILE *fp)
{
  // a file of a version before 12 may hold a removed keyword's setting: refused when it was on
  // (grow, which changed the neighbour range only, is read and ignored)
  Removed old;
  std::string name, bname;
  double pb = 0.0;
  hmode = HFIXED;
  eta = 0.0;
  temp_set = 0;
  temp.value = 0.0;
  background_in = CellQuantity();
  background_auto = background_set = 0;
  background_min = 0.0;
  if (comm->me == 0) {
    int first;
    utils::sfread(FLERR, &first, sizeof(int), 1, fp, nullptr, error);
    restart_version = CellRestart::version(first);
    if (first < 0) utils::sfread(FLERR, &first, sizeof(int), 1, fp, nullptr, error);
    kernel = first;
    read_settings(fp, old, name, bname, pb);
  }
  MPI_Bcast(&restart_version, 1, MPI_INT, 0, world);
  CellRestart::refuse_newer(error, FLERR, "Pair cell/sph", restart_version, RESTART_VERSION);
  double values[8] = {cut_global,     eta, temp.value, background_in.value,
                      background_min, pb,  old.tref,   old.shift};
  MPI_Bcast(values, 8, MPI_DOUBLE, 0, world);
  double olds[2] = {old.tensile, old.lag};
  MPI_Bcast(olds, 2, MPI_DOUBLE, 0, world);
  int flags[6] = {kernel, hmode, temp_set, background_auto, background_set, old.eos};
  MPI_Bcast(flags, 6, MPI_INT, 0, world);
  cut_global = values[0], eta = values[1], temp.value = values[2];
  background_in.value = values[3], background_min = values[4], pb = values[5];
  kernel = flags[0], hmode = flags[1], temp_set = flags[2];
  background_auto = flags[3], background_set = flags[4];
  const char *gone = flags[5] != 0    ? "eos tait"
      : hmode == 1                    ? "h mass"
      : temp_set && values[6] != TREF ? "Tref"
      : values[7] > 0.0               ? "shift"
      : olds[0] > 0.0                 ? "tensile"
      : olds[1] >= 0.0                ? "background auto ... lag"
                                      : nullptr;
  if (gone)
    error->all(FLERR,
               "Pair cell/sph: the restart file (format version {}) uses '{}', which was removed "
               "(doc/pair_cell_sph.md, removed keywords): continue it with an older cellsph",
               restart_version, gone);
  // version 11: a P_b it has is one that steps have advanced
  if (restart_version == 11 && background_set) background_set = BACKGROUND_STEPPED;
  background = background_auto && background_set ? pb : background_in.value;
  for (std::string *str : {&name, &bname}) {
    int n = static_cast<int>(str->size());
    MPI_Bcast(&n, 1, MPI_INT, 0, world);
    str->resize(n);
    if (n > 0) MPI_Bcast(&(*str)[0], n, MPI_CHAR, 0, world);
  }
  temp.name = name;
  background_in.name = bname;
  temp.ivar = -1;
  muscale = 1.0;
}

/* ----------------------------------------------------------------------
   Pair Coeffs: pair I I only; cross pairs are not mixed, so they need 'write_data ... pair ij'
------------------------------------------------------------------------- */

void PairCellSPH::write_data(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++)
    fprintf(fp, "%d %.16g %.16g %.16g %.16g\n", i, rho0[i][i], bulk[i][i], mu[i][i], h[i][i]);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i + 1; j <= atom->ntypes; j++)
      if (setflag[i][j])
        error->warning(FLERR,
                       "Pair cell/sph: the Pair Coeffs section cannot hold pair_coeff {} {} "
                       "(cell/sph does not mix): use 'write_data <file> pair ij'",
                       i, j);
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::write_data_all(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (boundary[i][j])
        fprintf(fp, "%d %d wall\n", i, j);
      else
        fprintf(fp, "%d %d %.16g %.16g %.16g %.16g\n", i, j, rho0[i][j], bulk[i][j], mu[i][j],
                h[i][j]);
}

/* ----------------------------------------------------------------------
   pressure force between atoms i and j from their stored rho and pressure; energy 0: the
   equation-of-state energy is per atom, not per pair
------------------------------------------------------------------------- */

double PairCellSPH::single(int i, int j, int itype, int jtype, double rsq, double /*factor_coul*/,
                           double /*factor_lj*/, double &fforce)
{
  fforce = 0.0;
  const PairConst &p = pc[itype][jtype];
  if (rsq >= p.cutsq) return 0.0;    // also a wall boundary pair (cutsq 0)
  const double *rho = atom->dvector[irho];
  const double *pressure = atom->dvector[ipressure];
  if (hmode != HFIXED) {
    // per-atom h: -m_i m_j (P_i/(Omega_i rho_i^2) dW(h_i) + P_j/(Omega_j rho_j^2) dW(h_j))
    const double *hv = atom->dvector[ih];
    const double *omega = atom->dvector[iomega];
    const double r = sqrt(rsq), support = CellKernel::support(kernel);
    for (int k : {i, j})
      if (r < support * hv[k]) {
        const CellKernel::Scale sk = CellKernel::scale(kernel, domain->dimension, hv[k]);
        const double pk = (pressure[k] + background) / (omega[k] * rho[k] * rho[k]);
        fforce -= atom->rmass[i] * atom->rmass[j] * pk * CellKernel::dWr(kernel, sk, r);
      }
    return 0.0;
  }
  // F^p = -m_i m_j (P_i/rho_i^2 + P_j/rho_j^2) (1/r) dW/dr x_ij (doc/model.md §3.4)
  const double r = sqrt(rsq);
  const double pij = (pressure[i] + background) / (rho[i] * rho[i]) +
      (pressure[j] + background) / (rho[j] * rho[j]);
  fforce = -atom->rmass[i] * atom->rmass[j] * pij * CellKernel::dWr(kernel, p.scale, r);
  return 0.0;
}

/* ----------------------------------------------------------------------
   "rho0" or "K" of the fluid (dim 0) when every type with a pair_coeff I I has the same value,
   e.g. for fix cell/turgor; nullptr if they differ
------------------------------------------------------------------------- */

void *PairCellSPH::extract(const char *str, int &dim)
{
  dim = 0;
  const int which = strcmp(str, "rho0") == 0 ? 0 : strcmp(str, "K") == 0 ? 1 : -1;
  if (which < 0 || !allocated) return nullptr;
  double **values = which == 0 ? rho0 : bulk;
  bool found = false;
  for (int i = 1; i <= atom->ntypes; i++) {
    if (!setflag[i][i]) continue;
    if (found && values[i][i] != shared[which]) return nullptr;
    shared[which] = values[i][i];
    found = true;
  }
  return found ? (void *) &shared[which] : nullptr;
}

/* ---------------------------------------------------------------------- */

int PairCellSPH::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  int m = 0;
  if (commode == COMM_TRIANGLES || commode == COMM_AHEAD)
    return wall.pack_forward(commode, n, list, buf);
  if (commode == COMM_H) {
    const double *hv = atom->dvector[ih];
    for (int k = 0; k < n; k++) buf[m++] = hv[list[k]];
    return m;
  }
  const double *rho = atom->dvector[irho];
  const double *pressure = atom->dvector[ipressure];
  const int peratom = hmode != HFIXED;
  for (int k = 0; k < n; k++) {
    buf[m++] = rho[list[k]];
    buf[m++] = pressure[list[k]];
    if (walls) buf[m++] = wall.deficit[list[k]];
    if (peratom) {
      buf[m++] = atom->dvector[ih][list[k]];
      buf[m++] = atom->dvector[iomega][list[k]];
    }
  }
  return m;
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  if (commode == COMM_TRIANGLES || commode == COMM_AHEAD) {
    wall.unpack_forward(commode, n, first, buf);
    return;
  }
  if (commode == COMM_H) {
    double *hv = atom->dvector[ih];
    for (int i = first; i < first + n; i++) hv[i] = buf[m++];
    return;
  }
  double *rho = atom->dvector[irho];
  double *pressure = atom->dvector[ipressure];
  const int peratom = hmode != HFIXED;
  for (int i = first; i < first + n; i++) {
    rho[i] = buf[m++];
    pressure[i] = buf[m++];
    if (walls) wall.deficit[i] = buf[m++];
    if (peratom) {
      atom->dvector[ih][i] = buf[m++];
      atom->dvector[iomega][i] = buf[m++];
    }
  }
}

/* ----------------------------------------------------------------------
   ghost sums into owners: rho (dS/dh with per-atom h, and the kernel deficit and its dh), the
   sums only (an iteration of h adaptive), or the wall load
------------------------------------------------------------------------- */

int PairCellSPH::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  if (commode == COMM_DENSITY || commode == COMM_SUMS) {
    const double *rho = atom->dvector[irho];
    const int peratom = hmode != HFIXED, deficits = walls && commode == COMM_DENSITY;
    for (int i = first; i < first + n; i++) {
      buf[m++] = rho[i];
      if (peratom) buf[m++] = dsum[i];
      if (deficits) buf[m++] = wall.deficit[i];
      if (deficits && peratom) buf[m++] = wall.dhdef[i];
    }
    return m;
  }
  return wall.pack_reverse(commode, n, first, buf);
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::unpack_reverse_comm(int n, int *list, double *buf)
{
  int m = 0;
  if (commode == COMM_DENSITY || commode == COMM_SUMS) {
    double *rho = atom->dvector[irho];
    const int peratom = hmode != HFIXED, deficits = walls && commode == COMM_DENSITY;
    for (int k = 0; k < n; k++) {
      rho[list[k]] += buf[m++];
      if (peratom) dsum[list[k]] += buf[m++];
      if (deficits) wall.deficit[list[k]] += buf[m++];
      if (deficits && peratom) wall.dhdef[list[k]] += buf[m++];
    }
    return;
  }
  wall.unpack_reverse(commode, n, list, buf);
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

/* ---------------------------------------------------------------------- */

double PairCellSPH::memory_usage()
{
  double bytes = Pair::memory_usage() + 2.0 * nmax * sizeof(double) + maxfirst * sizeof(int) +
      maxpairs * (sizeof(int) + 2.0 * sizeof(double));
  if (hmode != HFIXED)
    bytes +=
        nmax * 4.0 * sizeof(double) + maxpairs * sizeof(double) + step.capacity() * sizeof(double);
  if (walls) bytes += wall.memory_usage(hmode != HFIXED);
  return bytes;
}

/* ----------------------------------------------------------------------
   a forward comm of the kind mode (owned to ghost atoms)
------------------------------------------------------------------------- */

void PairCellSPH::forward(int mode)
{
  commode = static_cast<decltype(commode)>(mode);
  CellCompat::forward_comm(comm, this);
}

/* ----------------------------------------------------------------------
   a reverse comm of the kind mode: the ghost atoms' sums into their owners, with newton pair on
------------------------------------------------------------------------- */

void PairCellSPH::reverse(int mode)
{
  commode = static_cast<decltype(commode)>(mode);
  if (force->newton_pair) CellCompat::reverse_comm(comm, this);
}
