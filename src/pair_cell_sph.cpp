/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   pair_style cell/sph: weakly compressible SPH with summation density and per-atom mass.
   One compute() = density pass over the half neighbour list (rho_j accumulated on ghosts too,
   then summed into owners by reverse comm), equation of state on owned atoms, forward comm of
   rho and pressure, force pass. The density pass keeps the pairs inside the kernel support with
   m_i m_j (1/r) dW/dr, so the force pass has no cutoff test, square root or kernel (h adaptive:
   with r_ij and m_i m_j, the force pass taking the gradients at the converged h). A half list
   evaluates each pair once; a full list would save the reverse comm but evaluate every pair twice.
------------------------------------------------------------------------- */

#include "pair_cell_sph.h"

#include "atom.h"
#include "cell_compat.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

// h adaptive with the wall boundary: exact evaluations of the boundary at the first step of a run
// whose h had no value yet (h starts from the pair_coeff value)
static const int HSTART = 4;

/* ---------------------------------------------------------------------- */

PairCellSPH::PairCellSPH(LAMMPS *lmp) :
    Pair(lmp), kernel(CellKernel::WENDLAND), cut_global(0.0), hmode(HFIXED), eta(0.0), hdrift(0.0),
    rho0(nullptr), bulk(nullptr), mu(nullptr), h(nullptr), background(0.0), background_set(0),
    background_auto(0), background_min(0.0), pc(nullptr), wself(nullptr), invrho0(nullptr),
    fluid(nullptr), viscous(0), shared{0.0, 0.0}, irho(-1), ipressure(-1), ih(-1), iomega(-1),
    hcap(nullptr), hscale(nullptr), dsum(nullptr), d2sum(nullptr), hsum(nullptr), hstale(0),
    boundary(nullptr), walls(0), wall(lmp, this), commode(COMM_DENSITY), restart_version(0),
    prho2(nullptr), rhoinv(nullptr), nmax(0), pairfirst(nullptr), pairj(nullptr), pairdw(nullptr),
    pairr(nullptr), pairmu(nullptr), maxfirst(0), maxpairs(0)
{
  restartinfo = 1;
  temp_set = 0;
  muscale = 1.0;
  temperature = 0.0;
  writedata = 1;
  reinitflag = 0;
  comm_forward = 5;    // rho, pressure (the kernel deficit, h, Omega); with walls: triangle tags
  comm_reverse = 5;    // rho (dS/dh, d2S/dh2, the kernel deficit, its dh); or the wall load
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
  if (walls && wall.rebuilt) {
    wall.split_list(neighbor->skin);
    wall.search_contacts();
    wall.rebase(peratom);
  }
  for (int pass = 0; pass < passes; pass++) {
    // a new base of the wall boundary takes the ghosts' h (store_base): theirs at the last
    // iteration's h
    ghost_h();
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

  forces(peratom);
  if (walls) wall.forces(evflag);

  if (vflag_fdotr) virial_fdotr_compute();
}

/* ----------------------------------------------------------------------
   h adaptive: the ghosts' h and every atom's kernel constants at the h of the last iteration
------------------------------------------------------------------------- */

void PairCellSPH::ghost_h()
{
  if (!hstale) return;
  forward(COMM_H);
  kernel_scales();
  hstale = 0;
}

/* ----------------------------------------------------------------------
   one density pass with the loop compiled for this kernel, with or without wall boundary,
   viscosity and per-atom h; first = 1: the step's first pass (with the wall boundary), 0: a
   Newton iteration of h adaptive (the sums only); then the ghost sums into owners
------------------------------------------------------------------------- */

void PairCellSPH::density_pass(int first)
{
  ghost_h();
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
  static const Resum RESUM[CellKernel::NTYPES] = {&PairCellSPH::resum_density<CellKernel::WENDLAND>,
                                                  &PairCellSPH::resum_density<CellKernel::CUBIC>,
                                                  &PairCellSPH::resum_density<CellKernel::QUINTIC>,
                                                  &PairCellSPH::resum_density<CellKernel::LUCY>};
  if (!first && hdrift < HMARGIN) {
    (this->*RESUM[kernel])();
  } else {
    (this->*DENSITY[walls][viscous][hmode != HFIXED][kernel])(first);
    hdrift = 0.0;
  }
  if (walls && first) wall.after_density();
  reverse(first ? COMM_DENSITY : COMM_SUMS);
  if (hmode != HFIXED) scale_sums();
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
  memory->destroy(d2sum);
  memory->destroy(hsum);
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
    memory->create(d2sum, nmax, "pair:d2sum");
    memory->create(hsum, nmax, 3, "pair:hsum");
  }
  if (walls) wall.grow(nmax, hmode != HFIXED);
}

/* ----------------------------------------------------------------------
   the density sums' start: the self term m_i W(0) of the list's atoms, zero on ghost atoms (with
   newton, they gather the pairs' other halves); per-atom h: the sums of hsum likewise
------------------------------------------------------------------------- */

template <int KERNEL, int PERATOM> void PairCellSPH::self_density()
{
  double *rho = atom->dvector[irho];
  const double *rmass = atom->rmass;
  const int *type = atom->type;
  const int nlocal = atom->nlocal;
  const double w0 = CellKernel::shape<KERNEL>(0.0);
  const int inum = list->inum;
  const int *ilist = list->ilist;
  // self term m_i W(0); per-atom h: m_i f(0) (q = 0: no q^2 f'/q, q^2 f'')
  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    if (PERATOM) {
      hsum[i][0] = rmass[i] * w0;
      hsum[i][1] = hsum[i][2] = 0.0;
    } else {
      rho[i] = rmass[i] * wself[type[i]];
    }
  }
  if (force->newton_pair) {
    const int nall = nlocal + atom->nghost;
    for (int i = nlocal; i < nall; i++)
      if (PERATOM)
        hsum[i][0] = hsum[i][1] = hsum[i][2] = 0.0;
      else
        rho[i] = 0.0;
  }
}

/* ----------------------------------------------------------------------
   rho_i = sum_j m_j W_ij including j = i, into the custom vector rho of owned (and, with newton,
   ghost) atoms; the pairs inside the support into pairj, pairdw (and pairmu). With per-atom h
   (PERATOM): W_ij = W(r_ij, h_i) in rho_i, the sums of scale_sums() into hsum, the pairs' r_ij
   and masses kept (the force pass takes the gradients at the converged h).
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

  const int inum = list->inum;
  const int *ilist = list->ilist;
  const int *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;

  if (inum + 1 > maxfirst) {
    maxfirst = inum + 1;
    memory->destroy(pairfirst);
    memory->create(pairfirst, maxfirst, "pair:pairfirst");
  }
  self_density<KERNEL, PERATOM>();
  if (WALLS && first) wall.start_sums(PERATOM);
  // per-atom h: rows of hscale (4 values) and hsum (3) as flat arrays (memory->create: contiguous)
  const double *hs = PERATOM ? hscale[0] : nullptr;
  double *hsm = PERATOM ? hsum[0] : nullptr;

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
    double sums[3] = {0.0, 0.0, 0.0};    // per-atom h: S_i, dS_i/dh_i, d2S_i/dh_i2
    double rhoi = 0.0;

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
        if (rsq >= hs[4 * i + 3] && rsq >= hs[4 * j + 3]) continue;
        const double r = sqrt(rsq);
        pairr[npairs] = r;
        pj[npairs] = j;
        pdw[npairs] = mi * rmass[j];
        if (VISCOUS) pmu[npairs] = 0.5 * p.mu2 * pdw[npairs];
        peratom_pair<KERNEL>(r * hs[4 * i], r * hs[4 * j], mi, rmass[j], sums,
                             newton_pair || j < nlocal ? hsm + 3 * j : nullptr);
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
    if (PERATOM)
      for (int d = 0; d < 3; d++) hsum[i][d] += sums[d];
    else
      rho[i] += rhoi;
  }
  pairfirst[inum] = npairs;

  if (WALLS && first && wall.refreshing) wall.exact_terms(PERATOM);
}

/* ----------------------------------------------------------------------
   per-atom h: pair (i, j at q_i = r/h_i, q_j = r/h_j; masses m_i, m_j) into the sums of i (sums)
   and of j (sumj, null if j's sums are not kept here): m f(q), m q^2 f'(q)/q, m q^2 f''(q) at each
   atom's q (zero outside its support)
------------------------------------------------------------------------- */

template <int KERNEL>
inline void PairCellSPH::peratom_pair(double qi, double qj, double mi, double mj, double *sums,
                                      double *sumj)
{
  const double support = CellKernel::support(KERNEL);
  if (qi < support) {
    const double q2 = qi * qi;
    sums[0] += mj * CellKernel::shape<KERNEL>(qi);
    sums[1] += mj * q2 * CellKernel::slope<KERNEL>(qi);
    sums[2] += mj * q2 * CellKernel::curve<KERNEL>(qi);
  }
  if (qj < support && sumj) {
    const double q2 = qj * qj;
    sumj[0] += mi * CellKernel::shape<KERNEL>(qj);
    sumj[1] += mi * q2 * CellKernel::slope<KERNEL>(qj);
    sumj[2] += mi * q2 * CellKernel::curve<KERNEL>(qj);
  }
}

/* ----------------------------------------------------------------------
   per-atom h, after the ghosts' sums reached their owners: S = sum_j m_j W(r_ij, h_i) and its
   derivatives of the owned atoms from their sums A = sum m f, B = sum m q^2 f'/q,
   C = sum m q^2 f'' (W = sigma/h^d f(q), q = r/h): S = sigma/h^d A, dS/dh = -sigma/h^(d+1)
   (d A + B), d2S/dh2 = sigma/h^(d+2) (d (d+1) A + 2 (d+1) B + C) (doc/pair_cell_sph.md)
------------------------------------------------------------------------- */

void PairCellSPH::scale_sums()
{
  double *rho = atom->dvector[irho];
  const double dim = domain->dimension;
  const int inum = list->inum;
  const int *ilist = list->ilist;
  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const double w = hscale[i][1], invh = hscale[i][0];
    const double a = hsum[i][0], b = hsum[i][1], c = hsum[i][2];
    rho[i] = w * a;
    dsum[i] = -(dim * rho[i] + w * b) * invh;
    d2sum[i] = (dim * (dim + 1.0) * rho[i] + w * (2.0 * (dim + 1.0) * b + c)) * invh * invh;
  }
}

/* ----------------------------------------------------------------------
   h adaptive, an iteration while every h changed by less than HMARGIN since the last density
   pass: the sums over that pass's pairs, at the new h
------------------------------------------------------------------------- */

template <int KERNEL> void PairCellSPH::resum_density()
{
  const int inum = list->inum;
  const int *ilist = list->ilist;
  const double *rmass = atom->rmass;
  const double *hs = hscale[0];
  double *hsm = hsum[0];
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  self_density<KERNEL, 1>();
  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    double sums[3] = {0.0, 0.0, 0.0};
    for (int k = pairfirst[ii]; k < pairfirst[ii + 1]; k++) {
      const int j = pairj[k];
      peratom_pair<KERNEL>(pairr[k] * hs[4 * i], pairr[k] * hs[4 * j], rmass[i], rmass[j], sums,
                           newton_pair || j < nlocal ? hsm + 3 * j : nullptr);
    }
    for (int d = 0; d < 3; d++) hsum[i][d] += sums[d];
  }
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::grow_pairs(int n)
{
  maxpairs = n + n / 2;
  memory->grow(pairj, maxpairs, "pair:pairj");
  memory->grow(pairdw, maxpairs, "pair:pairdw");
  if (hmode != HFIXED) memory->grow(pairr, maxpairs, "pair:pairr");
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
   the energy is the equation-of-state energy of apply_eos(). KERNEL = FIXED_H: one h per type
   pair, the gradients stored with the pairs; a kernel: each atom's own h (pair_cell_sph_adaptive_h.cpp)
------------------------------------------------------------------------- */

template <int KERNEL, int VISCOUS, int EVFLAG> void PairCellSPH::sum_forces()
{
  constexpr bool PERATOM = KERNEL != FIXED_H;
  double **x = atom->x;
  double **v = atom->v;
  double **f = atom->f;
  const double support = PERATOM ? CellKernel::support(KERNEL) : 0.0;
  const double *hs = PERATOM ? hscale[0] : nullptr;    // rows of 4, contiguous
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  const int inum = list->inum;
  const int *ilist = list->ilist;

  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const double xtmp = x[i][0], ytmp = x[i][1], ztmp = x[i][2];
    const double vxtmp = v[i][0], vytmp = v[i][1], vztmp = v[i][2];
    const double prho2i = prho2[i], rhoinvi = rhoinv[i];
    const double invhi = PERATOM ? hs[4 * i] : 0.0, dwi = PERATOM ? hs[4 * i + 2] : 0.0;
    double fxi = 0.0, fyi = 0.0, fzi = 0.0;

    for (int k = pairfirst[ii]; k < pairfirst[ii + 1]; k++) {
      const int j = pairj[k];
      const double delx = xtmp - x[j][0];
      const double dely = ytmp - x[j][1];
      const double delz = ztmp - x[j][2];
      double fpress, gsum = 1.0;
      if constexpr (PERATOM) {
        // (1/r) dW/dr at h_i and at h_j, zero outside each support
        const double qi = pairr[k] * invhi, qj = pairr[k] * hs[4 * j];
        const double gi = qi < support ? dwi * CellKernel::slope<KERNEL>(qi) : 0.0;
        const double gj = qj < support ? hs[4 * j + 2] * CellKernel::slope<KERNEL>(qj) : 0.0;
        // F^p_i = -m_i m_j (P_i/(Omega_i rho_i^2) grad_i W(h_i) + P_j/(Omega_j rho_j^2) grad_i
        // W(h_j)) (doc/pair_cell_sph.md, smoothing length)
        fpress = -pairdw[k] * (gi * prho2i + gj * prho2[j]);
        gsum = gi + gj;
      } else {
        // F^p_i = -m_i m_j (P_i/rho_i^2 + P_j/rho_j^2) grad_i W_ij (doc/model.md §3.4)
        fpress = -pairdw[k] * (prho2i + prho2[j]);
      }
      double fx = delx * fpress;
      double fy = dely * fpress;
      double fz = delz * fpress;
      if (VISCOUS) {
        // F^v_i = m_i m_j (mu_i + mu_j) v_ij / (rho_i rho_j) (1/r) dW/dr (doc/model.md §3.5), per-atom
        // h with the mean of the two kernels' gradients (gsum = 1 at fixed h: exact)
        const double fvisc = pairmu[k] * gsum * rhoinvi * rhoinv[j];
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

/* ----------------------------------------------------------------------
   the force pass: per-atom h with the kernel constants of every atom at the converged h first
------------------------------------------------------------------------- */

void PairCellSPH::forces(int peratom)
{
  if (peratom) {
    if (hstale) kernel_scales();
    hstale = 0;
  }
  typedef void (PairCellSPH::*Loop)();
#define CELLSPH_FORCES(K)                                                   \
  {                                                                         \
    {&PairCellSPH::sum_forces<K, 0, 0>, &PairCellSPH::sum_forces<K, 0, 1>}, \
    {                                                                       \
      &PairCellSPH::sum_forces<K, 1, 0>, &PairCellSPH::sum_forces<K, 1, 1>  \
    }                                                                       \
  }
  static const Loop FORCES[CellKernel::NTYPES + 1][2][2] = {
      CELLSPH_FORCES(FIXED_H), CELLSPH_FORCES(CellKernel::WENDLAND),
      CELLSPH_FORCES(CellKernel::CUBIC), CELLSPH_FORCES(CellKernel::QUINTIC),
      CELLSPH_FORCES(CellKernel::LUCY)};
#undef CELLSPH_FORCES
  (this->*FORCES[peratom ? kernel + 1 : 0][viscous][evflag ? 1 : 0])();
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
  if (commode == COMM_TRIANGLES || commode == COMM_AHEAD || commode == COMM_BASE)
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
  if (commode == COMM_TRIANGLES || commode == COMM_AHEAD || commode == COMM_BASE) {
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
   ghost sums into owners: rho (dS/dh and d2S/dh2 with per-atom h, and the kernel deficit and its dh), the
   sums only (an iteration of h adaptive), or the wall load
------------------------------------------------------------------------- */

int PairCellSPH::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  if (commode == COMM_DENSITY || commode == COMM_SUMS) {
    const double *rho = atom->dvector[irho];
    const int peratom = hmode != HFIXED, deficits = walls && commode == COMM_DENSITY;
    for (int i = first; i < first + n; i++) {
      if (peratom)
        for (int d = 0; d < 3; d++) buf[m++] = hsum[i][d];
      else
        buf[m++] = rho[i];
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
      if (peratom)
        for (int d = 0; d < 3; d++) hsum[list[k]][d] += buf[m++];
      else
        rho[list[k]] += buf[m++];
      if (deficits) wall.deficit[list[k]] += buf[m++];
      if (deficits && peratom) wall.dhdef[list[k]] += buf[m++];
    }
    return;
  }
  wall.unpack_reverse(commode, n, list, buf);
}

/* ---------------------------------------------------------------------- */

double PairCellSPH::memory_usage()
{
  double bytes = Pair::memory_usage() + 2.0 * nmax * sizeof(double) + maxfirst * sizeof(int) +
      maxpairs * (sizeof(int) + 2.0 * sizeof(double));
  if (hmode != HFIXED)
    bytes +=
        nmax * 9.0 * sizeof(double) + maxpairs * sizeof(double) + step.capacity() * sizeof(double);
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
