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
#include "cell_params.h"
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

static const char *const EOS_NAMES[] = {"linear", "tait"};

/* ---------------------------------------------------------------------- */

PairCellSPH::PairCellSPH(LAMMPS *lmp) :
    Pair(lmp), kernel(CellKernel::WENDLAND), eos(LINEAR), cut_global(0.0), rho0(nullptr),
    bulk(nullptr), mu(nullptr), h(nullptr), pc(nullptr), wself(nullptr), invrho0(nullptr),
    eosk(nullptr), fluid(nullptr), viscous(0), shared{0.0, 0.0}, irho(-1), ipressure(-1),
    prho2(nullptr), rhoinv(nullptr), nmax(0), pairfirst(nullptr), pairj(nullptr), pairdw(nullptr),
    pairmu(nullptr), maxfirst(0), maxpairs(0)
{
  restartinfo = 1;
  writedata = 1;
  reinitflag = 0;
  comm_forward = 2;    // rho, pressure
  comm_reverse = 1;    // rho
}

/* ---------------------------------------------------------------------- */

PairCellSPH::~PairCellSPH()
{
  memory->destroy(prho2);
  memory->destroy(rhoinv);
  memory->destroy(pairfirst);
  memory->destroy(pairj);
  memory->destroy(pairdw);
  memory->destroy(pairmu);
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    memory->destroy(rho0);
    memory->destroy(bulk);
    memory->destroy(mu);
    memory->destroy(h);
    memory->destroy(pc);
    memory->destroy(wself);
    memory->destroy(invrho0);
    memory->destroy(eosk);
    memory->destroy(fluid);
  }
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);

  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(prho2);
    memory->destroy(rhoinv);
    memory->create(prho2, nmax, "pair:prho2");
    memory->create(rhoinv, nmax, "pair:rhoinv");
  }

  // the loops compiled for this kernel, with or without viscosity and tallies
  typedef void (PairCellSPH::*Loop)();
  static const Loop DENSITY[2][CellKernel::NTYPES] = {
      {&PairCellSPH::sum_density<CellKernel::WENDLAND, 0>,
       &PairCellSPH::sum_density<CellKernel::CUBIC, 0>,
       &PairCellSPH::sum_density<CellKernel::QUINTIC, 0>,
       &PairCellSPH::sum_density<CellKernel::LUCY, 0>},
      {&PairCellSPH::sum_density<CellKernel::WENDLAND, 1>,
       &PairCellSPH::sum_density<CellKernel::CUBIC, 1>,
       &PairCellSPH::sum_density<CellKernel::QUINTIC, 1>,
       &PairCellSPH::sum_density<CellKernel::LUCY, 1>}};
  static const Loop FORCES[2][2] = {
      {&PairCellSPH::sum_forces<0, 0>, &PairCellSPH::sum_forces<0, 1>},
      {&PairCellSPH::sum_forces<1, 0>, &PairCellSPH::sum_forces<1, 1>}};

  (this->*DENSITY[viscous][kernel])();
  if (force->newton_pair) CellCompat::reverse_comm(comm, this);
  apply_eos();
  CellCompat::forward_comm(comm, this);

  const double *rho = atom->dvector[irho];
  const double *pressure = atom->dvector[ipressure];
  const int *type = atom->type;
  const int nall = atom->nlocal + atom->nghost;
  for (int i = atom->nlocal; i < nall; i++)
    if (fluid[type[i]]) {
      rhoinv[i] = 1.0 / rho[i];
      prho2[i] = pressure[i] * rhoinv[i] * rhoinv[i];
    }

  (this->*FORCES[viscous][evflag ? 1 : 0])();

  if (vflag_fdotr) virial_fdotr_compute();
}

/* ----------------------------------------------------------------------
   rho_i = sum_j m_j W_ij including j = i, into the custom vector rho of owned (and, with newton,
   ghost) atoms; the pairs inside the support into pairj, pairdw (and pairmu)
------------------------------------------------------------------------- */

template <int KERNEL, int VISCOUS> void PairCellSPH::sum_density()
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

  // self term m_i W(0)
  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    rho[i] = rmass[i] * wself[type[i]];
  }
  if (newton_pair) {
    const int nall = nlocal + atom->nghost;
    for (int i = nlocal; i < nall; i++) rho[i] = 0.0;
  }

  int npairs = 0;
  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const double xtmp = x[i][0];
    const double ytmp = x[i][1];
    const double ztmp = x[i][2];
    const double mi = rmass[i];
    const PairConst *pci = pc[type[i]];
    const int *jlist = firstneigh[i];
    const int jnum = numneigh[i];
    if (npairs + jnum > maxpairs) grow_pairs(npairs + jnum);
    int *pj = pairj;
    double *pdw = pairdw;
    double *pmu = pairmu;
    pairfirst[ii] = npairs;
    double rhoi = 0.0;

    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double delx = xtmp - x[j][0];
      const double dely = ytmp - x[j][1];
      const double delz = ztmp - x[j][2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      const PairConst &p = pci[type[j]];
      if (rsq >= p.cutsq) continue;

      const double r = sqrt(rsq);
      const double mj = rmass[j];
      // rho_i += m_j W_ij, rho_j += m_i W_ij (doc/model.md §3.2)
      const double w = CellKernel::W<KERNEL>(p.scale, r);
      rhoi += mj * w;
      if (newton_pair || j < nlocal) rho[j] += mi * w;

      const double mmdw = mi * mj * CellKernel::dWr<KERNEL>(p.scale, r);
      pj[npairs] = j;
      pdw[npairs] = mmdw;
      if (VISCOUS) pmu[npairs] = p.mu2 * mmdw;
      npairs++;
    }
    rho[i] += rhoi;
  }
  pairfirst[inum] = npairs;
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::grow_pairs(int n)
{
  maxpairs = n + n / 2;
  memory->grow(pairj, maxpairs, "pair:pairj");
  memory->grow(pairdw, maxpairs, "pair:pairdw");
  memory->grow(pairmu, maxpairs, "pair:pairmu");
}

/* ----------------------------------------------------------------------
   pressure of owned fluid atoms from their density; P/rho^2 and 1/rho for the force pass;
   the equation-of-state energy m_i e(rho_i), e' = P/rho^2, whose gradient is the pressure force
------------------------------------------------------------------------- */

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
             atom->x[i][2], rho, rho * invrho0[t], update->ntimestep, 0.25 * h[t][t] / c, c);
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::apply_eos()
{
  const double *rho = atom->dvector[irho];
  double *pressure = atom->dvector[ipressure];
  const double *rmass = atom->rmass;
  const int *type = atom->type;
  const int inum = list->inum;
  const int *ilist = list->ilist;

  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const int t = type[i];
    const double x = rho[i] * invrho0[t];
    double e = 0.0;
    if (eos == TAIT) {
      const double x2 = x * x;
      const double x6 = x2 * x2 * x2;
      // P = (K/7) [(rho/rho0)^7 - 1], e = (K / 7 rho0) [((rho/rho0)^6 - 1)/6 + rho0/rho - 1]
      pressure[i] = eosk[t] * (x6 * x - 1.0);
      if (eflag_either) e = eosk[t] * invrho0[t] * ((x6 - 1.0) / 6.0 + 1.0 / x - 1.0);
    } else {
      // P = K (rho/rho0 - 1), e = (K / rho0) [ln(rho/rho0) + rho0/rho - 1]
      pressure[i] = eosk[t] * (x - 1.0);
      if (eflag_either) e = eosk[t] * invrho0[t] * (log(x) + 1.0 / x - 1.0);
    }
    if (!(x > 0.0 && x <= 2.0) || !std::isfinite(pressure[i])) unstable(i);
    rhoinv[i] = 1.0 / rho[i];
    prho2[i] = pressure[i] * rhoinv[i] * rhoinv[i];
    if (eflag_global) eng_vdwl += rmass[i] * e;
    if (eflag_atom) eatom[i] += rmass[i] * e;
  }
}

/* ----------------------------------------------------------------------
   pressure and viscous forces over the pairs of sum_density(); the virial is tallied per pair,
   the energy is the equation-of-state energy of apply_eos()
------------------------------------------------------------------------- */

template <int VISCOUS, int EVFLAG> void PairCellSPH::sum_forces()
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
      // F^p_i = -m_i m_j (P_i/rho_i^2 + P_j/rho_j^2) grad_i W_ij (doc/model.md §3.4)
      const double fpress = -pairdw[k] * (prho2i + prho2[j]);
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
  memory->create(wself, n, "pair:wself");
  memory->create(invrho0, n, "pair:invrho0");
  memory->create(eosk, n, "pair:eosk");
  memory->create(fluid, n, "pair:fluid");
  for (int i = 0; i < n; i++) {
    for (int j = 0; j < n; j++) {
      setflag[i][j] = 0;
      rho0[i][j] = bulk[i][j] = mu[i][j] = h[i][j] = 0.0;
      pc[i][j] = PairConst{0.0, {0.0, 0.0, 0.0}, 0.0};
    }
    wself[i] = invrho0[i] = eosk[i] = 0.0;
    fluid[i] = 0;
  }
}

/* ----------------------------------------------------------------------
   pair_style cell/sph [cutoff] [kernel wendland|cubic|quintic|lucy] [eos linear|tait]
------------------------------------------------------------------------- */

void PairCellSPH::settings(int narg, char **arg)
{
  int iarg = 0;
  cut_global = 0.0;
  kernel = CellKernel::WENDLAND;
  eos = LINEAR;
  if (narg > 0 && utils::is_double(arg[0])) {
    cut_global = utils::numeric(FLERR, arg[0], false, lmp);
    if (cut_global <= 0.0)
      error->all(FLERR, "Pair style cell/sph: cutoff = {} must be > 0", cut_global);
    iarg = 1;
  }
  while (iarg < narg) {
    if (iarg + 1 >= narg)
      error->all(FLERR, "Pair style cell/sph: keyword '{}' needs a value", arg[iarg]);
    const std::string value = arg[iarg + 1];
    if (strcmp(arg[iarg], "kernel") == 0) {
      kernel = CellKernel::parse(value);
      if (kernel < 0)
        error->all(FLERR,
                   "Pair style cell/sph: unknown kernel '{}' (expected wendland, cubic, quintic "
                   "or lucy)",
                   value);
    } else if (strcmp(arg[iarg], "eos") == 0) {
      if (value == EOS_NAMES[LINEAR])
        eos = LINEAR;
      else if (value == EOS_NAMES[TAIT])
        eos = TAIT;
      else
        error->all(FLERR, "Pair style cell/sph: unknown eos '{}' (expected linear or tait)", value);
    } else {
      error->all(FLERR,
                 "Pair style cell/sph: unknown keyword '{}' (expected a cutoff, 'kernel' or "
                 "'eos')",
                 arg[iarg]);
    }
    iarg += 2;
  }
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

  double rho0_one, bulk_one, mu_one, h_one;
  if (narg == 4 && strcmp(arg[2], "file") == 0) {
    CellParams params(lmp, arg[3], "pair_coeff cell/sph");
    rho0_one = params.positive("sph_rho0");
    bulk_one = params.positive("sph_K");
    mu_one = params.nonnegative("sph_mu");
    h_one = params.positive("sph_h");
    if (params.has("sph_kernel") && params.word("sph_kernel") != CellKernel::NAMES[kernel])
      error->all(FLERR,
                 "Pair_coeff cell/sph: {} sets sph_kernel = {} but pair_style cell/sph uses "
                 "kernel {} (the kernel is a pair_style keyword)",
                 arg[3], params.word("sph_kernel"), CellKernel::NAMES[kernel]);
  } else {
    if (narg != 6)
      error->all(FLERR,
                 "Incorrect args for pair_coeff cell/sph: expected 'pair_coeff <I> <J> <rho0> "
                 "<K> <mu> <h>' or 'pair_coeff <I> <J> file <parameter file>', got {} args",
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
  }

  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = std::max(jlo, i); j <= jhi; j++) {
      rho0[i][j] = rho0_one;
      bulk[i][j] = bulk_one;
      mu[i][j] = mu_one;
      h[i][j] = h_one;
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
   kernel constants, viscosity and cutoff of one type pair; the equation of state of type i
------------------------------------------------------------------------- */

double PairCellSPH::init_one(int i, int j)
{
  if (!setflag[i][j]) {
    pc[i][j] = pc[j][i] = PairConst{0.0, {0.0, 0.0, 0.0}, 0.0};
    return 0.0;
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

  pc[i][j].cutsq = support * support;
  pc[i][j].scale = CellKernel::scale(kernel, dim, h[i][j]);
  pc[i][j].mu2 = 2.0 * mu[i][j];
  pc[j][i] = pc[i][j];

  if (i == j) {
    wself[i] = CellKernel::W(kernel, pc[i][i].scale, 0.0);
    invrho0[i] = 1.0 / rho0[i][i];
    eosk[i] = eos == TAIT ? bulk[i][i] / 7.0 : bulk[i][i];
  }
  return cut_global > 0.0 ? cut_global : support;
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (setflag[i][j]) {
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
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
      if (setflag[i][j]) {
        double values[4];
        if (me == 0) utils::sfread(FLERR, values, sizeof(double), 4, fp, nullptr, error);
        MPI_Bcast(values, 4, MPI_DOUBLE, 0, world);
        rho0[i][j] = values[0];
        bulk[i][j] = values[1];
        mu[i][j] = values[2];
        h[i][j] = values[3];
      }
    }
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::write_restart_settings(FILE *fp)
{
  fwrite(&kernel, sizeof(int), 1, fp);
  fwrite(&eos, sizeof(int), 1, fp);
  fwrite(&cut_global, sizeof(double), 1, fp);
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::read_restart_settings(FILE *fp)
{
  if (comm->me == 0) {
    utils::sfread(FLERR, &kernel, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &eos, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &cut_global, sizeof(double), 1, fp, nullptr, error);
  }
  MPI_Bcast(&kernel, 1, MPI_INT, 0, world);
  MPI_Bcast(&eos, 1, MPI_INT, 0, world);
  MPI_Bcast(&cut_global, 1, MPI_DOUBLE, 0, world);
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
      fprintf(fp, "%d %d %.16g %.16g %.16g %.16g\n", i, j, rho0[i][j], bulk[i][j], mu[i][j],
              h[i][j]);
}

/* ----------------------------------------------------------------------
   conservative pressure force between atoms i and j from their stored rho and pressure;
   energy 0: the equation-of-state energy is per atom, not per pair
------------------------------------------------------------------------- */

double PairCellSPH::single(int i, int j, int itype, int jtype, double rsq, double /*factor_coul*/,
                           double /*factor_lj*/, double &fforce)
{
  fforce = 0.0;
  const PairConst &p = pc[itype][jtype];
  if (rsq >= p.cutsq) return 0.0;
  const double *rho = atom->dvector[irho];
  const double *pressure = atom->dvector[ipressure];
  // F^p = -m_i m_j (P_i/rho_i^2 + P_j/rho_j^2) (1/r) dW/dr x_ij (doc/model.md §3.4)
  fforce = -atom->rmass[i] * atom->rmass[j] *
      (pressure[i] / (rho[i] * rho[i]) + pressure[j] / (rho[j] * rho[j])) *
      CellKernel::dWr(kernel, p.scale, sqrt(rsq));
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
  const double *rho = atom->dvector[irho];
  const double *pressure = atom->dvector[ipressure];
  int m = 0;
  for (int k = 0; k < n; k++) {
    buf[m++] = rho[list[k]];
    buf[m++] = pressure[list[k]];
  }
  return m;
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::unpack_forward_comm(int n, int first, double *buf)
{
  double *rho = atom->dvector[irho];
  double *pressure = atom->dvector[ipressure];
  int m = 0;
  for (int i = first; i < first + n; i++) {
    rho[i] = buf[m++];
    pressure[i] = buf[m++];
  }
}

/* ---------------------------------------------------------------------- */

int PairCellSPH::pack_reverse_comm(int n, int first, double *buf)
{
  const double *rho = atom->dvector[irho];
  for (int k = 0; k < n; k++) buf[k] = rho[first + k];
  return n;
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::unpack_reverse_comm(int n, int *list, double *buf)
{
  double *rho = atom->dvector[irho];
  for (int k = 0; k < n; k++) rho[list[k]] += buf[k];
}

/* ---------------------------------------------------------------------- */

double PairCellSPH::memory_usage()
{
  return Pair::memory_usage() + 2.0 * nmax * sizeof(double) + maxfirst * sizeof(int) +
      maxpairs * (sizeof(int) + 2.0 * sizeof(double));
}
