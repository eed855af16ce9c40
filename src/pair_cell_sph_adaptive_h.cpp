/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   pair_style cell/sph h adaptive: the per-atom smoothing length h = eta (m/rho)^(1/3), found by
   Newton iterations on rho h^3 = eta^3 m, with the kernel constants of every atom
   (doc/pair_cell_sph.md, smoothing length)
------------------------------------------------------------------------- */

#include "pair_cell_sph.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "neigh_list.h"
#include "update.h"

#include <algorithm>
#include <cmath>

using namespace LAMMPS_NS;

// h adaptive: Newton iterations on h stop when every |dh|/h < HTOL; at most HITER of them
static const double HTOL = 1e-10;
static const int HITER = 50;
// a Newton step with every |dh|/h < HTAYLOR updates S, dS/dh by their Taylor series in dh instead
// of summing them again: the remainders are O((d dh/h)^3) and O((d dh/h)^2) relative
// (doc/pair_cell_sph.md; on the seed cell, steps of 1e-6: h, rho, Omega as summed again to 4e-16,
// 1e-15, 2e-13, doc/notes/2026-12-07-speed-against-error.md)
static const double HTAYLOR = 1e-5;

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
   (doc/pair_cell_sph.md, smoothing length), each followed by the sums at the new h: summed again
   (the ghosts' h first, density_pass), or their Taylor series for small steps (the ghosts' h
   then follow with the density's forward comm)
------------------------------------------------------------------------- */

void PairCellSPH::solve_h()
{
  for (int iter = 0;; iter++) {
    int taylor = 0;
    const double change = newton_h(taylor);
    if (change < HTOL) return;
    hdrift += change;
    hstale = 1;
    if (iter == HITER)
      error->all(FLERR,
                 "Pair cell/sph: h adaptive did not converge in {} Newton iterations on step {}",
                 HITER, update->ntimestep);
    if (!taylor) density_pass(0);
  }
}

/* ----------------------------------------------------------------------
   one Newton step dh = -h (rho - rho_h) / (d rho Omega), rho_h = eta^d m / h^d, for every owned
   fluid atom, applied only if some |dh|/h >= HTOL (on any rank); returns that largest |dh|/h.
   taylor = 1: the step was small enough that S and dS/dh followed it by their Taylor series
------------------------------------------------------------------------- */

double PairCellSPH::newton_h(int &taylor)
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
  // the pairs of the last density pass hold while every h changed by less than HMARGIN
  taylor = all < HTAYLOR && hdrift + all < HMARGIN;
  double *sum = atom->dvector[irho];
  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    if (!fluid[type[i]]) continue;
    const double dh = step[ii];
    hv[i] += dh;
    // S(h + dh) = S + S' dh + S'' dh^2 / 2, S'(h + dh) = S' + S'' dh
    if (taylor) {
      sum[i] += (dsum[i] + 0.5 * d2sum[i] * dh) * dh;
      dsum[i] += d2sum[i] * dh;
    }
    // the deficit at the new h: linear in h between exact evaluations
    if (walls) wall.deficit[i] += wall.dhdef[i] * dh;
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
