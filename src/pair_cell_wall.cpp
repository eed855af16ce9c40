/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   pair_style cell/wall: the central short-range forces between a wall particle and a fluid
   particle (repulsion F^rw = -F^rf, adhesion F^a) and between non-bonded wall particles (contact).
   Each term is switched on per type pair; a per-pair bitmask keeps off terms out of the loop.
   With triangles, a wall atom also meets the triangles of the other cells' walls (the distance to
   each triangle's closest point), and a wall atom found behind another cell's face stops the run;
   selftriangles does the same with its own wall's triangles that it is not a vertex of (both in
   pair_cell_wall_triangles.cpp). Bonded wall pairs of one cell are excluded through special_bonds
   (factor_lj; a bonded pair of two cells, a junction, keeps weight 1), fluid-fluid pairs belong to
   pair_style cell/sph (under hybrid/overlay).
------------------------------------------------------------------------- */

#include "pair_cell_wall.h"

#include "atom.h"
#include "cell_compat.h"
#include "cell_params.h"
#include "cell_restart.h"
#include "cell_wall_triangles.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "math_special.h"
#include "memory.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using MathSpecial::cube;
using MathSpecial::powint;

static const char *const TERM_NAMES[] = {"repulsion", "adhesion", "contact", "triangles",
                                         "selftriangles"};
static const int TERM_VALUES[] = {2, 4, 2, 2, 2};    // required numbers after each keyword
static constexpr int NTERMS = 5;
// f0 r0 p1 p2 D alpha ra rc eps sigma teps tsigma seps ssigma; versions 3-5 had the removed
// adhesion smooth flag after sigma (SMOOTH), version 3 ended there, 4 after tsigma
static constexpr int NPARAM = 14;
static constexpr int SMOOTH = 10;
static constexpr double DEFAULT_P1 = 12.0;
static constexpr double DEFAULT_P2 = 4.0;
// a fluid atom that starts a run nearer than START_GAP x the repulsion's range r0 to a wall atom
// of its own cell stops the run: in the seed inflation at 642-3000 wall particles starts up to
// 0.60 r0 blew the cell up, from 0.62 r0 on all ran (doc/pair_cell_wall.md, Restrictions)
static constexpr double START_GAP = 0.62;
// 2: the settings begin with -version (1: none); 3: the adhesion's smooth flag after sigma;
// 4: the triangles' eps and sigma after it; 5: the selftriangles' eps and sigma after those;
// 6: without the smooth flag (smooth removed)
static constexpr int RESTART_VERSION = 6;

static const char *const COEFF_USAGE =
    "expected 'pair_coeff I J [repulsion f0 r0 [p1 p2]] [adhesion D alpha ra rc] "
    "[contact eps sigma] [triangles eps sigma] [selftriangles eps sigma]', 'pair_coeff I J none' "
    "or 'pair_coeff I J file <parameter file> wallfluid|wallwall'";

/* ----------------------------------------------------------------------
   p/2 if p is an even integer, so that (r0/r)^p = powint((r0/r)^2, p/2); else 0
------------------------------------------------------------------------- */

static int even_half(double p)
{
  const double half = 0.5 * p;
  return (half == floor(half) && half >= 1.0 && half <= 64.0) ? (int) half : 0;
}

// (r0/r)^p from s = (r0/r)^2
static inline double ratio_power(double s, double p, int half)
{
  return half ? powint(s, half) : pow(s, 0.5 * p);
}

/* ---------------------------------------------------------------------- */

PairCellWall::PairCellWall(LAMMPS *lmp) :
    Pair(lmp), cut_global(0.0), coeffs(nullptr), restart_version(RESTART_VERSION), load_fluid(0),
    load_wall(0), nmax_load(0), load(nullptr), repulsion(0), triangles(0), trireach(0.0),
    tris(new CellWallTriangles(lmp, "Pair cell/wall", "the triangle contact's neighbour range")),
    nmax_near(0), nearest(nullptr), comm_nearest(0)
{
  writedata = 1;
  comm_reverse = 2 * NEAR;
}

/* ---------------------------------------------------------------------- */

PairCellWall::~PairCellWall()
{
  memory->destroy(load);
  memory->destroy(nearest);
  delete tris;
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    memory->destroy(coeffs);
  }
}

/* ---------------------------------------------------------------------- */

void PairCellWall::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  // the wall triangles on every reneighbouring (the ghosts' by forward comm)
  if (triangles && neighbor->ago == 0) {
    tris->grow(atom->nmax);
    tris->build();
    // a triangle within reach + skin of w at the build has its vertices within reach + skin + 2
    // x its centroid-vertex distance of w (doc/pair_cell_wall.md, Restrictions)
    tris->check_ghost_cutoff("the triangles' reach", trireach, 2, 1);
    CellCompat::forward_comm(comm, this);
  }
  // the pairs at a build, or at a run's setup without one ('run ... pre no'), where the atoms may
  // already be skin/2 from their build positions: then twice the skin
  if (neighbor->ago == 0 || update->setupflag) {
    const double margin = neighbor->ago == 0 ? neighbor->skin : 2.0 * neighbor->skin;
    near_pairs(margin);
    if (triangles) find_touching(margin);
    if (update->setupflag && repulsion) check_start_gap();
  }

  if (load_wall) {
    if (atom->nmax > nmax_load) {
      nmax_load = atom->nmax;
      memory->destroy(load);
      memory->create(load, nmax_load, 3, "pair:load");
    }
    const int nall = atom->nlocal + (force->newton_pair ? atom->nghost : 0);
    if (nall > 0) memset(&load[0][0], 0, sizeof(double) * 3 * nall);
    eval<1>(eflag);
    if (force->newton_pair) CellCompat::reverse_comm(comm, this);
  } else {
    eval<0>(eflag);
  }
  if (triangles) {
    if (evflag)
      triangle_contacts<1>();
    else
      triangle_contacts<0>();
    check_crossing();
  }

  if (vflag_fdotr) virial_fdotr_compute();
}

/* ----------------------------------------------------------------------
   at each neighbour build: the pairs of the list within their own cutoff + margin (with their
   special bits), which are all that can come within the cutoff before the next build. Under
   pair hybrid the list holds every pair within the longest cutoff of its type pair over all
   sub-styles (e.g. the wall boundary's reach of pair cell/sph), most of them far beyond ours.
------------------------------------------------------------------------- */

void PairCellWall::near_pairs(double margin)
{
  double **x = atom->x;
  const int *type = atom->type;
  const int inum = list->inum;
  nearfirst.assign(inum + 1, 0);
  nearj.clear();
  for (int ii = 0; ii < inum; ii++) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    nearfirst[ii] = static_cast<int>(nearj.size());
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double cutsqij = coeffs[type[i]][type[j]].paircutsq;
      if (cutsqij <= 0.0) continue;
      const double reach = sqrt(cutsqij) + margin;
      const double delx = x[i][0] - x[j][0];
      const double dely = x[i][1] - x[j][1];
      const double delz = x[i][2] - x[j][2];
      if (delx * delx + dely * dely + delz * delz < reach * reach) nearj.push_back(jlist[jj]);
    }
  }
  nearfirst[inum] = static_cast<int>(nearj.size());
}

/* ----------------------------------------------------------------------
   at a run's setup: the fluid atom nearest to a wall atom of its own cell (molecule), relative
   to the repulsion's range r0 of their type pair, over all ranks; nearer than START_GAP x r0 is
   an error on every rank. Wall atoms are those of the types whose atoms have bonds, fluid atoms
   those of the other types: a pair of unbonded atoms (the force tests) is never checked.
------------------------------------------------------------------------- */

void PairCellWall::check_start_gap()
{
  if (!atom->molecule_flag || atom->molecular != Atom::MOLECULAR) return;
  double **x = atom->x;
  const int *type = atom->type;
  const tagint *molecule = atom->molecule;
  const tagint *tag = atom->tag;
  const int ntypes = atom->ntypes;
  std::vector<int> bonded(ntypes + 1, 0), wall(ntypes + 1, 0);
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->nspecial[i][0] > 0) bonded[type[i]] = 1;
  MPI_Allreduce(bonded.data(), wall.data(), ntypes + 1, MPI_INT, MPI_MAX, world);

  struct {
    double ratio;
    int rank;
  } mine = {START_GAP, comm->me}, least;
  // distance, r0, fluid atom, wall atom, their types, the cell
  double found[7] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    for (int jj = nearfirst[ii]; jj < nearfirst[ii + 1]; jj++) {
      const int j = nearj[jj] & NEIGHMASK;
      const Coeff &c = coeffs[type[i]][type[j]];
      if (!(c.terms & REPULSION) || molecule[i] != molecule[j] || wall[type[i]] == wall[type[j]])
        continue;
      const double delx = x[i][0] - x[j][0];
      const double dely = x[i][1] - x[j][1];
      const double delz = x[i][2] - x[j][2];
      const double r = sqrt(delx * delx + dely * dely + delz * delz);
      if (r >= mine.ratio * c.r0) continue;
      const int f = wall[type[i]] ? j : i, w = wall[type[i]] ? i : j;
      mine.ratio = r / c.r0;
      found[0] = r;
      found[1] = c.r0;
      found[2] = static_cast<double>(tag[f]);
      found[3] = static_cast<double>(tag[w]);
      found[4] = type[f];
      found[5] = type[w];
      found[6] = static_cast<double>(molecule[f]);
    }
  }
  MPI_Allreduce(&mine, &least, 1, MPI_DOUBLE_INT, MPI_MINLOC, world);
  if (least.ratio >= START_GAP) return;
  MPI_Bcast(found, 7, MPI_DOUBLE, least.rank, world);
  const int ftype = static_cast<int>(found[4]), wtype = static_cast<int>(found[5]);
  error->all(FLERR,
             "Pair cell/wall: fluid atom {} of cell {} starts {:.4g} m from wall atom {} of its "
             "cell, {:.3f} x the range r0 = {:.4g} m of the wall-fluid repulsion (types {} {}); "
             "starts nearer than {} r0 blow the cell up (lost atoms, bond atoms missing): give the "
             "fluid a gap of at least {} r0 = {:.4g} m from the wall (cellgen --gap {:.4g}; r0 "
             "itself is recommended) or hold it with the SPH wall boundary instead ('pair_coeff {} "
             "{} cell/sph wall')",
             static_cast<tagint>(found[2]), static_cast<tagint>(found[6]), found[0],
             static_cast<tagint>(found[3]), least.ratio, found[1], ftype, wtype, START_GAP,
             START_GAP, START_GAP * found[1], START_GAP * found[1], std::min(ftype, wtype),
             std::max(ftype, wtype));
}

/* ----------------------------------------------------------------------
   the pair loop over near_pairs(); with LOAD, also the force of each fluid atom on the wall atoms
   of its own cell
------------------------------------------------------------------------- */

template <int LOAD> void PairCellWall::eval(int eflag)
{
  double **x = atom->x;
  double **f = atom->f;
  const int *type = atom->type;
  const tagint *molecule = atom->molecule;
  const int nlocal = atom->nlocal;
  const double *special_lj = force->special_lj;
  const int newton_pair = force->newton_pair;

  const int inum = list->inum;
  const int *ilist = list->ilist;

  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const double xtmp = x[i][0];
    const double ytmp = x[i][1];
    const double ztmp = x[i][2];
    const int itype = type[i];
    const Coeff *coeffi = coeffs[itype];
    const int *jlist = &nearj[nearfirst[ii]];
    const int jnum = nearfirst[ii + 1] - nearfirst[ii];

    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      // a bonded pair of two cells (a junction) is no wall neighbour pair: full weight
      const double factor_lj =
          molecule && molecule[i] != molecule[j] ? 1.0 : special_lj[sbmask(jlist[jj])];
      if (factor_lj == 0.0) continue;

      const double delx = xtmp - x[j][0];
      const double dely = ytmp - x[j][1];
      const double delz = ztmp - x[j][2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      const int jtype = type[j];
      if (rsq >= coeffi[jtype].paircutsq) continue;

      double fpair;
      const double evdwl = factor_lj * evaluate(coeffi[jtype], rsq, eflag, fpair);
      fpair *= factor_lj;

      f[i][0] += delx * fpair;
      f[i][1] += dely * fpair;
      f[i][2] += delz * fpair;
      if (newton_pair || j < nlocal) {
        f[j][0] -= delx * fpair;
        f[j][1] -= dely * fpair;
        f[j][2] -= delz * fpair;
      }
      if (LOAD && molecule[i] == molecule[j]) {
        if (itype == load_wall && jtype == load_fluid) {
          load[i][0] += delx * fpair;
          load[i][1] += dely * fpair;
          load[i][2] += delz * fpair;
        } else if (itype == load_fluid && jtype == load_wall && (newton_pair || j < nlocal)) {
          load[j][0] -= delx * fpair;
          load[j][1] -= dely * fpair;
          load[j][2] -= delz * fpair;
        }
      }
      if (evflag) ev_tally(i, j, nlocal, newton_pair, evdwl, 0.0, fpair, delx, dely, delz);
    }
  }
}

/* ---------------------------------------------------------------------- */

int PairCellWall::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  return tris->pack(n, list, buf);
}

/* ---------------------------------------------------------------------- */

void PairCellWall::unpack_forward_comm(int n, int first, double *buf)
{
  tris->unpack(n, first, buf);
}

/* ----------------------------------------------------------------------
   tally the fluid-to-wall force of the cell's own fluid on wall atoms from the next force
   evaluation on; one pair of types at a time. False (nothing tallied) without wall-fluid terms
   (repulsion or adhesion) between the two types: the SPH wall boundary then holds the fluid
------------------------------------------------------------------------- */

bool PairCellWall::request_wall_load(int fluidtype, int walltype, const std::string &who)
{
  const int lo = std::min(fluidtype, walltype), hi = std::max(fluidtype, walltype);
  if (!allocated || !setflag[lo][hi] || !(coeffs[lo][hi].terms & (REPULSION | ADHESION)))
    return false;
  if (load_wall && (load_fluid != fluidtype || load_wall != walltype))
    error->all(FLERR,
               "{}: pair cell/wall already tallies the wall load for fluid type {} and wall type "
               "{}, not {} and {}",
               who, load_fluid, load_wall, fluidtype, walltype);
  if (!atom->molecule_flag)
    error->all(FLERR, "{}: the wall load needs molecule (cell) IDs: use atom_style angle", who);
  load_fluid = fluidtype;
  load_wall = walltype;
  return true;
}

/* ---------------------------------------------------------------------- */

int PairCellWall::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  if (comm_nearest) {
    for (int i = first; i < first + n; i++)
      for (int k = 0; k < 2 * NEAR; k++) buf[m++] = nearest[i][k];
    return m;
  }
  for (int i = first; i < first + n; i++) {
    buf[m++] = load[i][0];
    buf[m++] = load[i][1];
    buf[m++] = load[i][2];
  }
  return m;
}

/* ---------------------------------------------------------------------- */

void PairCellWall::unpack_reverse_comm(int n, int *list, double *buf)
{
  int m = 0;
  if (comm_nearest) {
    // the nearer of the two, of other cells and of the own wall
    for (int k = 0; k < n; k++)
      for (int s = 0; s < 2 * NEAR; s += NEAR, m += NEAR) {
        double *near = nearest[list[k]] + s;
        if (buf[m] >= 0.0 && (near[0] < 0.0 || buf[m] < near[0]))
          for (int c = 0; c < NEAR; c++) near[c] = buf[m + c];
      }
    return;
  }
  for (int k = 0; k < n; k++) {
    const int j = list[k];
    load[j][0] += buf[m++];
    load[j][1] += buf[m++];
    load[j][2] += buf[m++];
  }
}

/* ---------------------------------------------------------------------- */

double PairCellWall::memory_usage()
{
  return Pair::memory_usage() + 3.0 * nmax_load * sizeof(double) +
      2 * NEAR * nmax_near * sizeof(double) + tris->memory_usage() +
      touching.capacity() * sizeof(touching[0]);
}

/* ----------------------------------------------------------------------
   all active terms of one pair at squared distance rsq < cutsq: returns the energy (if eflag),
   sets fpair = F/r (positive = repulsive)
------------------------------------------------------------------------- */

inline double PairCellWall::evaluate(const Coeff &c, double rsq, int eflag, double &fpair) const
{
  double u = 0.0;
  fpair = 0.0;

  if ((c.terms & REPULSION) && rsq < c.r0sq) {
    const double s = c.r0sq / rsq;
    const double a = ratio_power(s, c.p1, c.half1);
    const double b = ratio_power(s, c.p2, c.half2);
    // F = f0 [(r0/r)^p1 - (r0/r)^p2] / r for r < r0 (doc/model.md §3.6)
    fpair += c.f0 * (a - b) / rsq;
    // U = f0 [((r0/r)^p1 - 1) / p1 - ((r0/r)^p2 - 1) / p2], so U(r0) = 0
    if (eflag) u += c.f0 * ((a - 1.0) / c.p1 - (b - 1.0) / c.p2);
  }

  if (c.terms & ADHESION) {
    if (rsq < c.rasq) {
      // no force inside ra; U stays at the well bottom U(ra)
      if (eflag) u += c.u_below_ra;
    } else if (rsq < c.rcsq) {
      const double r = sqrt(rsq);
      const double dr = r - c.ra;
      const double e = exp(-c.alpha * dr);
      // F = F_M(r) = 2 alpha D [e^-2alpha(r-ra) - e^-alpha(r-ra)] <= 0 (attractive; doc/model.md
      // §3.7), cut at rc
      fpair += c.two_alpha_d * e * (e - 1.0) / r;
      // U = U_M(r) - u_rc, U_M(r) = D [e^-2alpha(r-ra) - 2 e^-alpha(r-ra)]
      if (eflag) u += c.D * e * (e - 2.0) - c.u_rc;
    }
  }

  if ((c.terms & CONTACT) && rsq < c.contactsq) {
    const double s3 = cube(c.sigsq / rsq);
    // WCA: F = 24 eps [2 (sigma/r)^12 - (sigma/r)^6] / r, r < 2^(1/6) sigma (doc/model.md §4.4)
    fpair += 24.0 * c.eps * s3 * (2.0 * s3 - 1.0) / rsq;
    // U = 4 eps [(sigma/r)^12 - (sigma/r)^6] + eps, zero at the cutoff
    if (eflag) u += 4.0 * c.eps * s3 * (s3 - 1.0) + c.eps;
  }
  return u;
}

/* ---------------------------------------------------------------------- */

void PairCellWall::allocate()
{
  allocated = 1;
  const int n = atom->ntypes + 1;
  memory->create(setflag, n, n, "pair:setflag");
  for (int i = 1; i < n; i++)
    for (int j = i; j < n; j++) setflag[i][j] = 0;
  memory->create(cutsq, n, n, "pair:cutsq");
  memory->create(coeffs, n, n, "pair:coeffs");
}

/* ----------------------------------------------------------------------
   pair_style cell/wall <cutoff>: the longest reach any term may have
------------------------------------------------------------------------- */

void PairCellWall::settings(int narg, char **arg)
{
  if (narg != 1)
    error->all(FLERR,
               "Illegal pair_style cell/wall command: expected 'pair_style cell/wall <cutoff>', "
               "got {} args",
               narg);
  cut_global = utils::numeric(FLERR, arg[0], false, lmp);
  if (!(cut_global > 0.0))
    error->all(FLERR, "Pair_style cell/wall: cutoff = {} must be > 0", cut_global);
}

/* ----------------------------------------------------------------------
   pair_coeff I J [repulsion f0 r0 [p1 p2]] [adhesion D alpha ra rc] [contact eps sigma]
                  [triangles eps sigma] [selftriangles eps sigma]
   pair_coeff I J none
   pair_coeff I J file <parameter file> wallfluid|wallwall
------------------------------------------------------------------------- */

void PairCellWall::coeff(int narg, char **arg)
{
  if (narg < 3) error->all(FLERR, "Incorrect args for pair_coeff cell/wall: {}", COEFF_USAGE);
  if (!allocated) allocate();

  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);

  Coeff c = {};
  std::string from;
  if (strcmp(arg[2], "file") == 0) {
    if (narg != 5)
      error->all(FLERR, "Incorrect args for pair_coeff cell/wall file: {}", COEFF_USAGE);
    read_file(c, arg[3], arg[4]);
    from = fmt::format(" (parameter file {})", arg[3]);
  } else if (strcmp(arg[2], "none") == 0) {
    if (narg != 3)
      error->all(FLERR, "Pair_coeff cell/wall: 'none' takes no other terms; {}", COEFF_USAGE);
  } else {
    for (int iarg = 2; iarg < narg;) {
      int k = 0;
      while (k < NTERMS && strcmp(arg[iarg], TERM_NAMES[k]) != 0) k++;
      if (k == NTERMS)
        error->all(FLERR,
                   "Pair_coeff cell/wall: unknown keyword '{}' (expected repulsion, adhesion, "
                   "contact, triangles, selftriangles, none or file)",
                   arg[iarg]);
      const int term = 1 << k;
      if (c.terms & term) error->all(FLERR, "Pair_coeff cell/wall: {} given twice", TERM_NAMES[k]);
      if (iarg + TERM_VALUES[k] >= narg)
        error->all(FLERR, "Pair_coeff cell/wall: {} needs {} values; {}", TERM_NAMES[k],
                   TERM_VALUES[k], COEFF_USAGE);
      double v[4];
      for (int m = 0; m < TERM_VALUES[k]; m++)
        v[m] = utils::numeric(FLERR, arg[iarg + 1 + m], false, lmp);
      iarg += 1 + TERM_VALUES[k];
      c.terms |= term;
      if (term == REPULSION) {
        c.f0 = v[0];
        c.r0 = v[1];
        c.p1 = DEFAULT_P1;
        c.p2 = DEFAULT_P2;
        // optional exponents: two numbers before the next keyword
        if (iarg < narg && utils::is_double(arg[iarg])) {
          if (iarg + 1 >= narg)
            error->all(FLERR, "Pair_coeff cell/wall: repulsion exponents need two values p1 p2");
          c.p1 = utils::numeric(FLERR, arg[iarg], false, lmp);
          c.p2 = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
          iarg += 2;
        }
      } else if (term == ADHESION) {
        c.D = v[0];
        c.alpha = v[1];
        c.ra = v[2];
        c.rc = v[3];
        if (iarg < narg && strcmp(arg[iarg], "smooth") == 0)
          error->all(FLERR,
                     "Pair_coeff cell/wall: adhesion's 'smooth' was removed: the adhesion force is "
                     "cut at rc (as in the tissue scene)");
      } else if (term == CONTACT) {
        c.eps = v[0];
        c.sigma = v[1];
      } else if (term == TRIANGLES) {
        c.teps = v[0];
        c.tsigma = v[1];
      } else {
        c.seps = v[0];
        c.ssigma = v[1];
      }
    }
  }
  check(c, from);

  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      coeffs[i][j] = c;
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0)
    error->all(FLERR, "Incorrect args for pair_coeff cell/wall: no type pair I <= J in {} {}",
               arg[0], arg[1]);
}

/* ----------------------------------------------------------------------
   the wallfluid (repulsion, adhesion if adhesion_D > 0) or wallwall (contact) keys of a file
------------------------------------------------------------------------- */

void PairCellWall::read_file(Coeff &c, const char *file, const char *which)
{
  const bool wallfluid = strcmp(which, "wallfluid") == 0;
  if (!wallfluid && strcmp(which, "wallwall") != 0)
    error->all(FLERR,
               "Pair_coeff cell/wall: unknown parameter set '{}' for file {} (expected wallfluid "
               "or wallwall)",
               which, file);

  CellParams params(lmp, file, "pair_coeff cell/wall");
  if (wallfluid && !params.has("wallfluid_f0") && !params.has("wallfluid_r0"))
    error->all(FLERR,
               "Pair_coeff cell/wall: parameter file {} has no wallfluid_* keys: it holds the "
               "fluid with the SPH wall boundary (pair_coeff I J cell/sph wall); the wall-fluid "
               "particle model (the seed's) has its keys in apple-seed.cellsph",
               file);
  if (wallfluid) {
    c.terms = REPULSION;
    c.f0 = params.positive("wallfluid_f0");
    c.r0 = params.positive("wallfluid_r0");
    c.p1 = params.has("wallfluid_p1") ? params.positive("wallfluid_p1") : DEFAULT_P1;
    c.p2 = params.has("wallfluid_p2") ? params.positive("wallfluid_p2") : DEFAULT_P2;
    if (params.has("adhesion_D") && params.nonnegative("adhesion_D") > 0.0) {
      c.terms |= ADHESION;
      c.D = params.number("adhesion_D");
      c.alpha = params.positive("adhesion_alpha");
      c.ra = params.nonnegative("adhesion_ra");
      c.rc = params.positive("adhesion_rc");
      if (params.has("adhesion_smooth"))
        error->all(FLERR,
                   "Pair_coeff cell/wall: adhesion_smooth in {} was removed: the adhesion force is "
                   "cut at adhesion_rc",
                   file);
    }
  } else {
    c.terms = CONTACT;
    c.eps = params.positive("wallwall_eps");
    c.sigma = params.positive("wallwall_sigma");
  }
}

/* ---------------------------------------------------------------------- */

void PairCellWall::check(const Coeff &c, const std::string &from)
{
  if (c.terms & REPULSION) {
    if (!(c.f0 > 0.0))
      error->all(FLERR, "Pair_coeff cell/wall: repulsion f0 = {} must be > 0{}", c.f0, from);
    if (!(c.r0 > 0.0))
      error->all(FLERR, "Pair_coeff cell/wall: repulsion r0 = {} must be > 0{}", c.r0, from);
    if (!(c.p2 > 0.0 && c.p1 > c.p2))
      error->all(FLERR,
                 "Pair_coeff cell/wall: repulsion exponents p1 = {}, p2 = {} must satisfy p1 > "
                 "p2 > 0{}",
                 c.p1, c.p2, from);
  }
  if (c.terms & ADHESION) {
    if (!(c.D > 0.0))
      error->all(FLERR, "Pair_coeff cell/wall: adhesion D = {} must be > 0{}", c.D, from);
    if (!(c.alpha > 0.0))
      error->all(FLERR, "Pair_coeff cell/wall: adhesion alpha = {} must be > 0{}", c.alpha, from);
    if (!(c.ra >= 0.0))
      error->all(FLERR, "Pair_coeff cell/wall: adhesion ra = {} must be >= 0{}", c.ra, from);
    if (!(c.rc > c.ra))
      error->all(FLERR, "Pair_coeff cell/wall: adhesion rc = {} must be > ra = {}{}", c.rc, c.ra,
                 from);
  }
  if (c.terms & CONTACT) {
    if (!(c.eps > 0.0))
      error->all(FLERR, "Pair_coeff cell/wall: contact eps = {} must be > 0{}", c.eps, from);
    if (!(c.sigma > 0.0))
      error->all(FLERR, "Pair_coeff cell/wall: contact sigma = {} must be > 0{}", c.sigma, from);
  }
  if (c.terms & TRIANGLES) {
    if (!(c.teps > 0.0))
      error->all(FLERR, "Pair_coeff cell/wall: triangles eps = {} must be > 0{}", c.teps, from);
    if (!(c.tsigma > 0.0))
      error->all(FLERR, "Pair_coeff cell/wall: triangles sigma = {} must be > 0{}", c.tsigma, from);
  }
  if (c.terms & SELFTRIANGLES) {
    if (!(c.seps > 0.0))
      error->all(FLERR, "Pair_coeff cell/wall: selftriangles eps = {} must be > 0{}", c.seps, from);
    if (!(c.ssigma > 0.0))
      error->all(FLERR, "Pair_coeff cell/wall: selftriangles sigma = {} must be > 0{}", c.ssigma,
                 from);
  }
}

/* ----------------------------------------------------------------------
   request a half list, forget wall-load requests (their styles renew them in their init); warn if
   contact would act between bonded (1-2) wall particles, which sit at the contact range (1-3
   pairs, at least sqrt(3) spacings apart on a flat wall, may keep it: doc/pair_cell_wall.md);
   with triangles, measure the wall's edges
------------------------------------------------------------------------- */

void PairCellWall::init_style()
{
  CellCompat::request_list(neighbor, this, 0, CellCompat::REQ_DEFAULT);
  load_fluid = load_wall = 0;

  bool contact = false;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (setflag[i][j] && (coeffs[i][j].terms & CONTACT)) contact = true;
  const double *special_lj = force->special_lj;
  if (contact && atom->molecular && special_lj[1] != 0.0 && comm->me == 0)
    error->warning(FLERR,
                   "Pair cell/wall: contact acts between bonded wall particles (special_bonds lj "
                   "weight 1-2 = {}); use 'special_bonds lj 0 0 1' or 'lj 0 1 1'",
                   special_lj[1]);

  int other = 0;
  triangles = 0;
  repulsion = 0;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (setflag[i][j]) {
        if (coeffs[i][j].terms & REPULSION) repulsion = 1;
        if (coeffs[i][j].terms & TRIANGLES) other = 1;
        if (coeffs[i][j].terms & (TRIANGLES | SELFTRIANGLES)) triangles = 1;
      }
  if (!triangles) return;
  if (!atom->molecule_flag || !atom->num_angle || !force->angle)
    error->all(FLERR,
               "Pair cell/wall: triangles and selftriangles need cell (molecule) IDs and the wall "
               "triangles as angles: use atom_style angle or molecular and an angle style "
               "(angle_style zero)");
  if (!force->newton_pair)
    error->all(FLERR,
               "Pair cell/wall: triangles and selftriangles need newton pair on (the reactions go "
               "to ghost triangle vertices)");
  // LAMMPS drops the pairs whose lj and coul weights are both 0 from the list; a pair of two
  // cells may be a special pair (the two atoms of a junction bond are 1-2); the own wall's
  // dropped partners are taken from the special lists (find_touching)
  const double *special_coul = force->special_coul;
  for (int k = 1; k <= 3; k++)
    if (other && special_lj[k] == 0.0 && special_coul[k] == 0.0)
      error->all(FLERR,
                 "Pair cell/wall: triangles needs every pair of atoms of two cells in the "
                 "neighbour list, and special_bonds lj and coul weights 1-{} = 0 drop the 1-{} "
                 "pairs (a junction bond's atoms are 1-2): give them coul weight 1, e.g. "
                 "'special_bonds lj 0 1 1 coul 1 1 1'",
                 k + 1, k + 1);
  comm_forward = CellWallTriangles::COMM_SIZE;
  tris->start_run();
  trireach = 0.0;    // the longest reach, set by init_one()
}

/* ----------------------------------------------------------------------
   constants of pair i,j; its cutoff is the longest reach of its active terms
------------------------------------------------------------------------- */

double PairCellWall::init_one(int i, int j)
{
  if (setflag[i][j] == 0)
    error->all(FLERR,
               "Pair cell/wall: no pair_coeff for atom types {} {} (cell/wall does not mix; use "
               "'pair_coeff {} {} none' for a pair without interaction)",
               i, j, i, j);

  Coeff &c = coeffs[i][j];
  double cut = 0.0;
  const char *longest = "none";
  if (c.terms & REPULSION) {
    c.r0sq = c.r0 * c.r0;
    c.half1 = even_half(c.p1);
    c.half2 = even_half(c.p2);
    cut = c.r0;
    longest = "repulsion r0";
  }
  if (c.terms & ADHESION) {
    c.rasq = c.ra * c.ra;
    c.rcsq = c.rc * c.rc;
    c.two_alpha_d = 2.0 * c.alpha * c.D;
    const double drc = c.rc - c.ra;
    const double ec = exp(-c.alpha * drc);
    // u_rc = U_M(rc), so U(rc) = 0; inside ra U = U(ra) = -D - u_rc
    c.u_rc = c.D * ec * (ec - 2.0);
    c.u_below_ra = -c.D - c.u_rc;
    if (c.rc > cut) {
      cut = c.rc;
      longest = "adhesion rc";
    }
  }
  if (c.terms & CONTACT) {
    c.sigsq = c.sigma * c.sigma;
    // WCA cutoff 2^(1/6) sigma
    c.contactsq = cbrt(2.0) * c.sigsq;
    if (sqrt(c.contactsq) > cut) {
      cut = sqrt(c.contactsq);
      longest = "contact cutoff 2^(1/6) sigma";
    }
  }
  c.paircutsq = cut * cut;
  double neighbour = cut;
  if (c.terms & TRIANGLES) {
    c.tsigsq = c.tsigma * c.tsigma;
    // WCA reach 2^(1/6) sigma
    c.treach = pow(2.0, 1.0 / 6.0) * c.tsigma;
    if (c.treach > cut) {
      cut = c.treach;
      longest = "triangles reach 2^(1/6) sigma";
    }
    // the neighbour list reaches the keeper b of every triangle within reach: reach + its
    // longest edge b-a, b-c (the run's allowance, which holds the skin)
    neighbour = std::max(neighbour, c.treach + tris->edge_cap());
    trireach = std::max(trireach, c.treach);
  }
  if (c.terms & SELFTRIANGLES) {
    c.ssigsq = c.ssigma * c.ssigma;
    // WCA reach 2^(1/6) sigma
    c.sreach = pow(2.0, 1.0 / 6.0) * c.ssigma;
    if (c.sreach > cut) {
      cut = c.sreach;
      longest = "selftriangles reach 2^(1/6) sigma";
    }
    neighbour = std::max(neighbour, c.sreach + tris->edge_cap());
    trireach = std::max(trireach, c.sreach);
  }
  if (cut > cut_global)
    error->all(FLERR,
               "Pair cell/wall: atom types {} {} reach {} ({}), beyond the pair_style cell/wall "
               "cutoff {}",
               i, j, cut, longest, cut_global);

  coeffs[j][i] = c;
  return neighbour;
}

/* ---------------------------------------------------------------------- */

void PairCellWall::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (setflag[i][j]) {
        const Coeff &c = coeffs[i][j];
        const double v[NPARAM] = {c.f0, c.r0,  c.p1,    c.p2,   c.D,      c.alpha, c.ra,
                                  c.rc, c.eps, c.sigma, c.teps, c.tsigma, c.seps,  c.ssigma};
        fwrite(&c.terms, sizeof(int), 1, fp);
        fwrite(v, sizeof(double), NPARAM, fp);
      }
    }
}

/* ---------------------------------------------------------------------- */

void PairCellWall::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  const int me = comm->me;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
      if (setflag[i][j]) {
        int terms = 0;
        double v[NPARAM + 1] = {};
        // versions 1 and 2 end each pair at sigma, 3 at the smooth flag, 4 at the triangles'
        // sigma; 3-5 have the smooth flag at SMOOTH
        const int flag = restart_version >= 3 && restart_version <= 5;
        const int nparam = restart_version >= 5 ? NPARAM + flag
            : restart_version >= 4              ? NPARAM - 2 + flag
            : restart_version >= 3              ? NPARAM - 4 + flag
                                                : NPARAM - 4;
        if (me == 0) {
          utils::sfread(FLERR, &terms, sizeof(int), 1, fp, nullptr, error);
          utils::sfread(FLERR, v, sizeof(double), nparam, fp, nullptr, error);
        }
        MPI_Bcast(&terms, 1, MPI_INT, 0, world);
        MPI_Bcast(v, nparam, MPI_DOUBLE, 0, world);
        if (flag && v[SMOOTH] != 0.0)
          error->all(FLERR,
                     "Pair cell/wall: the restart file (format version {}) has pair {} {} with "
                     "adhesion 'smooth', which was removed (doc/pair_cell_wall.md): continue it "
                     "with an older cellsph",
                     restart_version, i, j);
        // the values after the smooth flag one place down
        if (flag)
          for (int k = SMOOTH; k < NPARAM; k++) v[k] = v[k + 1];
        Coeff c = {};
        c.terms = terms;
        c.f0 = v[0];
        c.r0 = v[1];
        c.p1 = v[2];
        c.p2 = v[3];
        c.D = v[4];
        c.alpha = v[5];
        c.ra = v[6];
        c.rc = v[7];
        c.eps = v[8];
        c.sigma = v[9];
        c.teps = v[10];
        c.tsigma = v[11];
        c.seps = v[12];
        c.ssigma = v[13];
        coeffs[i][j] = c;
      }
    }
}

/* ---------------------------------------------------------------------- */

void PairCellWall::write_restart_settings(FILE *fp)
{
  // version 1 (no marker) began with the cutoff > 0; later versions with -version
  CellRestart::write_columns(fp, RESTART_VERSION, 1, &cut_global);
}

/* ---------------------------------------------------------------------- */

void PairCellWall::read_restart_settings(FILE *fp)
{
  double first = 0.0;
  restart_version =
      CellRestart::read_version(lmp, fp, FLERR, "Pair cell/wall", RESTART_VERSION, &first);
  // version 1: the value read was the cutoff
  cut_global = first;
  if (restart_version >= 2) CellRestart::read_columns(lmp, fp, 1, &cut_global);
}

/* ----------------------------------------------------------------------
   the terms of one pair in pair_coeff syntax (after the types)
------------------------------------------------------------------------- */

std::string PairCellWall::describe(const Coeff &c) const
{
  std::string s;
  if (c.terms & REPULSION) s += fmt::format(" repulsion {} {} {} {}", c.f0, c.r0, c.p1, c.p2);
  if (c.terms & ADHESION) s += fmt::format(" adhesion {} {} {} {}", c.D, c.alpha, c.ra, c.rc);
  if (c.terms & CONTACT) s += fmt::format(" contact {} {}", c.eps, c.sigma);
  if (c.terms & TRIANGLES) s += fmt::format(" triangles {} {}", c.teps, c.tsigma);
  if (c.terms & SELFTRIANGLES) s += fmt::format(" selftriangles {} {}", c.seps, c.ssigma);
  return s.empty() ? " none" : s;
}

/* ---------------------------------------------------------------------- */

void PairCellWall::write_data(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++) fmt::print(fp, "{}{}\n", i, describe(coeffs[i][i]));
}

/* ---------------------------------------------------------------------- */

void PairCellWall::write_data_all(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      fmt::print(fp, "{} {}{}\n", i, j, describe(coeffs[i][j]));
}

/* ---------------------------------------------------------------------- */

double PairCellWall::single(int i, int j, int itype, int jtype, double rsq, double /*factor_coul*/,
                            double factor_lj, double &fforce)
{
  // as eval(): a bonded pair of two cells has full weight
  if (atom->molecule && atom->molecule[i] != atom->molecule[j]) factor_lj = 1.0;
  double fpair;
  const double u = evaluate(coeffs[itype][jtype], rsq, 1, fpair);
  fforce = factor_lj * fpair;
  return factor_lj * u;
}
