/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   the wall boundary of pair_style cell/sph, owned by PairCellSPH (pair_cell_sph_boundary.h). The
   kernel completion 1 - gamma of every fluid atom is evaluated exactly every REFRESH to
   REFRESH_MAX steps (or when an atom moved half the skin from its base), from base positions half
   an interval ahead, and linearised in the displacements in between (doc/pair_cell_sph.md, cost
   control). The base goes with each atom (pair_cell_sph_boundary_base.cpp), so that a neighbour
   build, a run's setup and a restart evaluate the same linearisation again at it: the state does
   not depend on how the runs are split.
------------------------------------------------------------------------- */

#include "pair_cell_sph_boundary.h"

#include "atom.h"
#include "cell_triangle.h"
#include "cell_wall_triangles.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_cell_continue.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair_cell_sph.h"
#include "update.h"

#include <algorithm>
#include <cmath>

using namespace LAMMPS_NS;

// contact with the wall surface: range delta = h / CONTACT_H, force F_c = K delta^2 at contact
static const double CONTACT_H = 2.5;
// kernel completion evaluated exactly every REFRESH to REFRESH_MAX steps (next_interval),
// linearised in between in the displacements from a base half an interval ahead (base_positions)
static const int REFRESH = 20;
static const int REFRESH_MAX = 320;
// and as soon as an atom is half the skin from its base (pair_cell_sph_boundary_base.cpp)
// the largest jump of 1 - gamma of a fluid atom at an exact evaluation that lets the interval grow
// (doc/pair_cell_sph.md, cost control: 1e-6 is 20 Pa of pressure at K = 20 MPa)
static const double JUMP_TOL = 1e-6;
// contacts: the near candidates lie within reach + NEAR x skin of the wall (wall_forces)
static const double NEAR = 0.25;
// per-atom h: the fluid pairs kept at a split of the list allow each h to grow by HGROW before
// the list is split again (split_list)
static const double HGROW = 0.05;

/* ---------------------------------------------------------------------- */

PairCellSPHBoundary::PairCellSPHBoundary(LAMMPS *lmp, PairCellSPH *owner) :
    Pointers(lmp), deficit(nullptr), dhdef(nullptr), wallload(nullptr), refreshing(1), rebuilt(1),
    every(REFRESH), lastjump(0.0), sph(owner), pairs(nullptr), wallsupport(0.0), phidq(0.0),
    tris(new CellWallTriangles(lmp, "Pair cell/sph", "the wall boundary's neighbour range")),
    deficit0(nullptr), dhdef0(nullptr), hbase(nullptr), xbase(nullptr), ixfield(-1), ihfield(-1),
    gradsum(nullptr), disp(nullptr), jump(nullptr), xnear(nullptr), slot(nullptr), predicted(0),
    measuring(0), rebasing(0), reached(0), pending(REFRESH), refreshed(-1), nmax(0)
{
}

/* ---------------------------------------------------------------------- */

PairCellSPHBoundary::~PairCellSPHBoundary()
{
  destroy();
  delete tris;
  memory->destroy(pairs);
}

/* ----------------------------------------------------------------------
   per fluid-wall type pair constants, zero until init_pair()
------------------------------------------------------------------------- */

void PairCellSPHBoundary::allocate(int n)
{
  memory->destroy(pairs);
  memory->create(pairs, n, n, "pair:boundary_pairs");
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++) pairs[i][j] = Contact{0.0, 0.0, 0.0, 0.0, 0};
}

/* ----------------------------------------------------------------------
   at init_style: what the boundary needs of the run, the support at the largest h of a fluid type
   with a boundary, the table of Phi, the triangles' edge allowance
------------------------------------------------------------------------- */

void PairCellSPHBoundary::init()
{
  if (domain->dimension != 3)
    error->all(FLERR, "Pair cell/sph: the wall boundary (pair_coeff I J wall) is 3-D only");
  if (!atom->molecule_flag)
    error->all(FLERR,
               "Pair cell/sph: the wall boundary (pair_coeff I J wall) needs cell (molecule) "
               "IDs: use atom_style angle");
  if (!force->angle)
    error->all(FLERR,
               "Pair cell/sph: the wall boundary (pair_coeff I J wall) needs the wall "
               "triangles as angles: define an angle style (angle_style zero)");
  if (!force->newton_pair)
    error->all(FLERR,
               "Pair cell/sph: the wall boundary (pair_coeff I J wall) needs newton pair on "
               "(the wall's reactions go to ghost atoms)");
  if (!atom->num_angle)
    error->all(FLERR, "Pair cell/sph: the wall boundary needs an atom style with angles");
  // the contact candidates kept between exact evaluations assume no atom has moved half the
  // skin since the last build, which LAMMPS checks every step only with these settings
  if (comm->me == 0 && (neighbor->delay > 0 || neighbor->every > 1 || !neighbor->dist_check))
    error->warning(FLERR,
                   "Pair cell/sph: the wall boundary wants neigh_modify delay 0 every 1 check "
                   "yes (now delay {} every {} check {}; the default of LAMMPS before 3 Nov "
                   "2022 is delay 10): atoms may move past the skin between builds",
                   neighbor->delay, neighbor->every, neighbor->dist_check ? "yes" : "no");
  // the support at the largest h of a fluid type with a boundary (fixed: its h)
  const int n = atom->ntypes;
  const double support = CellKernel::support(sph->kernel);
  wallsupport = 0.0;
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++)
      if (sph->setflag[i][j] && sph->boundary[i][j]) {
        const int f = sph->setflag[i][i] ? i : j;
        wallsupport =
            std::max(wallsupport,
                     support * (sph->hmode == PairCellSPH::HFIXED ? sph->h[f][f] : sph->hcap[f]));
      }
  for (int i = 0; i <= n; i++)
    for (int j = 0; j <= n; j++) pairs[i][j] = Contact{0.0, 0.0, 0.0, 0.0, 0};
  tabulate_phi();
  tris->start_run();
  find_fields();
}

/* ----------------------------------------------------------------------
   fluid-wall type pair i j (init_one): range and force of the contact, the kernel's 1/h at the
   fluid's h; returns the neighbour range, which reaches every triangle whose centroid is inside
   the kernel support (the centroid is within 2/3 of the longest edge of the triangle's keeper)
------------------------------------------------------------------------- */

double PairCellSPHBoundary::init_pair(int i, int j)
{
  const int f = sph->setflag[i][i] ? i : j, w = f == i ? j : i;
  if (!sph->setflag[f][f] || sph->setflag[w][w])
    error->all(FLERR,
               "Pair cell/sph: pair_coeff {} {} wall needs one fluid type (with pair_coeff K K "
               "cell/sph) and one wall type (without)",
               i, j);
  const int kernel = sph->kernel;
  const double hf = sph->h[f][f];
  const double support =
      CellKernel::support(kernel) * (sph->hmode == PairCellSPH::HFIXED ? hf : sph->hcap[f]);
  // contact range delta = h / CONTACT_H and force F_c = K delta^2 at the surface
  // (doc/pair_cell_sph.md)
  const double reach = hf / CONTACT_H;
  const double range = support + 2.0 / 3.0 * (tris->edge_cap() - neighbor->skin);
  pairs[i][j] = Contact{range * range, CellKernel::scale(kernel, 3, hf).invh, reach,
                        sph->bulk[f][f] * reach * reach, 1};
  pairs[j][i] = pairs[i][j];
  return range;
}

/* ----------------------------------------------------------------------
   per-atom arrays (owned and ghost) at atom->nmax
------------------------------------------------------------------------- */

void PairCellSPHBoundary::destroy()
{
  memory->destroy(deficit);
  memory->destroy(dhdef);
  memory->destroy(wallload);
  memory->destroy(deficit0);
  memory->destroy(dhdef0);
  memory->destroy(hbase);
  memory->destroy(xbase);
  memory->destroy(gradsum);
  memory->destroy(disp);
  memory->destroy(jump);
  memory->destroy(xnear);
  memory->destroy(slot);
}

void PairCellSPHBoundary::grow(int n, int peratom)
{
  destroy();
  nmax = n;
  if (peratom) {
    memory->create(dhdef, nmax, "pair:dhdef");
    memory->create(dhdef0, nmax, "pair:dhdef0");
  }
  memory->create(hbase, nmax, "pair:hbase");
  memory->create(deficit, nmax, "pair:deficit");
  memory->create(wallload, nmax, 3, "pair:wallload");
  tris->grow(nmax);
  memory->create(deficit0, nmax, "pair:deficit0");
  memory->create(xbase, nmax, 3, "pair:xbase");
  memory->create(gradsum, nmax, 3, "pair:gradsum");
  memory->create(disp, nmax, 3, "pair:disp");
  memory->create(jump, nmax, "pair:jump");
  memory->create(xnear, nmax, 3, "pair:xnear");
  memory->create(slot, nmax, "pair:slot");
  for (int i = 0; i < nmax; i++) slot[i] = -1;
}

/* ----------------------------------------------------------------------
   a step's start: the triangles and the base of ghost atoms at a neighbour build (or after the
   per-atom arrays grew), and whether this step evaluates the boundary exactly at a new base: by
   the step counter and the interval only (a build or a run's setup that continues the last step
   evaluates the last base again, rebase), when an atom moved beyond reach of its base, or at a
   setup that does not continue the last step
------------------------------------------------------------------------- */

void PairCellSPHBoundary::start_step(bool grown)
{
  rebuilt = neighbor->ago == 0 || grown;
  const bigint now = update->ntimestep;
  // a setup that does not continue the last step (atoms moved or velocities set since, a
  // minimisation, a first run) starts afresh: exact, the interval at REFRESH
  const int fresh = update->setupflag && !FixCellContinue::setup_continues(lmp);
  const int based = refreshed >= 0 && now >= refreshed && !fresh;
  if (rebuilt) {
    tris->build();
    // a triangle whose centroid is within the support of f until the next build has its
    // vertices within the support + its centroid-vertex distance + skin of f, and that
    // distance grows by < skin (doc/pair_cell_sph.md, Restrictions)
    tris->check_ghost_cutoff("the kernel support", wallsupport, 1, 2);
    sph->forward(PairCellSPH::COMM_TRIANGLES);
    if (based) restore_base();
  }
  // an atom beyond reach of its base moves too fast for the base ahead (base_positions): the
  // new base at the atoms, as a neighbour build took it before the base went with each atom
  reached = based && beyond_reach();
  refreshing = !based || now - refreshed >= every || reached;
  measuring = refreshing && based;
  rebasing = rebuilt && based;
  if (refreshing) {
    if (!based) every = pending = REFRESH, lastjump = 0.0;
    refreshed = now;
    every = pending;
  }
}

/* ----------------------------------------------------------------------
   before density pass number pass of a step: a pass after the first evaluates exactly again (at
   the converged h of h adaptive); the base ahead in dynamics only (a minimisation's velocities
   are not its motion) and not after an atom went beyond reach
------------------------------------------------------------------------- */

void PairCellSPHBoundary::start_pass(int pass)
{
  if (pass > 0) refreshing = 1, measuring = 0;
  if (refreshing) base_positions(pass == 0 && update->whichflag == 1 && !reached);
}

/* ----------------------------------------------------------------------
   the first density pass of a step, before the fluid's sums: the wall load zeroed, and the
   deficits zeroed for an exact evaluation or linearised from the base
------------------------------------------------------------------------- */

void PairCellSPHBoundary::start_sums(int peratom)
{
  const int nall = atom->nlocal + atom->nghost;
  for (int i = 0; i < nall; i++) wallload[i][0] = wallload[i][1] = wallload[i][2] = 0.0;
  if (refreshing) {
    for (int i = 0; i < nall; i++) deficit[i] = 0.0;
    if (peratom)
      for (int i = 0; i < nall; i++) dhdef[i] = 0.0;
    terms.clear();
    termlen.clear();
  } else {
    linear_deficit();
  }
}

/* ----------------------------------------------------------------------
   the wall boundary, exactly at the base positions: the triangles kept by wall atom b for fluid
   atom f, the pairs of each f in a row (split_list)
------------------------------------------------------------------------- */

void PairCellSPHBoundary::exact_terms(int peratom)
{
  const int *type = atom->type;
  const int npair = static_cast<int>(boundarypairs.size());
  for (int k = 0; k < npair;) {
    const int f = boundarypairs[k][0];
    const int start = static_cast<int>(terms.size());
    for (; k < npair && boundarypairs[k][0] == f; k++) {
      const int b = boundarypairs[k][1];
      const double delx = xbase[f][0] - xbase[b][0];
      const double dely = xbase[f][1] - xbase[b][1];
      const double delz = xbase[f][2] - xbase[b][2];
      const Contact &p = pairs[type[f]][type[b]];
      if (delx * delx + dely * dely + delz * delz < p.cutsq) {
        if (peratom)
          boundary_terms<1>(f, b, p);
        else
          boundary_terms<0>(f, b, p);
      }
    }
    for (int t = start; t < static_cast<int>(terms.size()); t++) slot[terms[t].v] = -1;
  }
}

/* ----------------------------------------------------------------------
   after the first density pass of a step with an exact evaluation: its base kept; a base ahead
   of the atoms: the linearised deficit at their positions now; the next interval measured
------------------------------------------------------------------------- */

void PairCellSPHBoundary::after_density()
{
  if (!refreshing) return;
  keep_base();
  if (predicted) linear_deficit();
  if (measuring) next_interval();
}

/* ----------------------------------------------------------------------
   after the fluid's forces: the boundary's, and the wall load of ghost atoms into their owners
------------------------------------------------------------------------- */

void PairCellSPHBoundary::forces(int evflag)
{
  if (evflag)
    wall_forces<1>();
  else
    wall_forces<0>();
  sph->reverse(PairCellSPH::COMM_LOAD);
}

/* ----------------------------------------------------------------------
   the boundary's forward comm: the triangles' tags, or the steps to the base ahead
------------------------------------------------------------------------- */

int PairCellSPHBoundary::pack_forward(int mode, int n, int *list, double *buf)
{
  if (mode == PairCellSPH::COMM_TRIANGLES) return tris->pack(n, list, buf);
  int m = 0;
  for (int k = 0; k < n; k++) {
    for (int d = 0; d < 3; d++) buf[m++] = disp[list[k]][d];
    if (mode == PairCellSPH::COMM_BASE) buf[m++] = hbase[list[k]];
  }
  return m;
}

void PairCellSPHBoundary::unpack_forward(int mode, int n, int first, double *buf)
{
  if (mode == PairCellSPH::COMM_TRIANGLES) {
    tris->unpack(n, first, buf);
    return;
  }
  int m = 0;
  for (int i = first; i < first + n; i++) {
    for (int d = 0; d < 3; d++) disp[i][d] = buf[m++];
    if (mode == PairCellSPH::COMM_BASE) hbase[i] = buf[m++];
  }
}

/* ----------------------------------------------------------------------
   the boundary's reverse comm: the jump of 1 - gamma, or the wall load
------------------------------------------------------------------------- */

int PairCellSPHBoundary::pack_reverse(int mode, int n, int first, double *buf)
{
  int m = 0;
  if (mode == PairCellSPH::COMM_JUMP) {
    for (int i = first; i < first + n; i++) buf[m++] = jump[i];
    return m;
  }
  for (int i = first; i < first + n; i++)
    for (int d = 0; d < 3; d++) buf[m++] = wallload[i][d];
  return m;
}

void PairCellSPHBoundary::unpack_reverse(int mode, int n, int *list, double *buf)
{
  int m = 0;
  if (mode == PairCellSPH::COMM_JUMP) {
    for (int k = 0; k < n; k++) jump[list[k]] += buf[m++];
    return;
  }
  for (int k = 0; k < n; k++)
    for (int d = 0; d < 3; d++) wallload[list[k]][d] += buf[m++];
}

/* ---------------------------------------------------------------------- */

double PairCellSPHBoundary::memory_usage(int peratom)
{
  double bytes = peratom ? nmax * 2.0 * sizeof(double) : 0.0;
  bytes += nmax * (15.0 * sizeof(double) + 2.0 * sizeof(int)) + tris->memory_usage() +
      terms.capacity() * sizeof(Term) + termlen.capacity() * sizeof(double) +
      (touching.capacity() + near.capacity()) * sizeof(touching[0]) +
      fluidfirst.capacity() * sizeof(int) + fluidj.capacity() * sizeof(int) +
      hsplit.capacity() * sizeof(double) + boundarypairs.capacity() * sizeof(boundarypairs[0]);
  return bytes;
}

/* ----------------------------------------------------------------------
   the terms of fluid atom f with the triangles (a, b, c) kept by wall atom b of its own cell:
   kernel deficit and its gradient at the base, summed per vertex into terms (slot[v]: v's term of
   f, with |x_v - x_f| in termlen)
------------------------------------------------------------------------- */

template <int PERATOM> void PairCellSPHBoundary::boundary_terms(int f, int b, const Contact &p)
{
  double **x = xbase;
  const double *xf = x[f];
  const double support = CellKernel::support(sph->kernel);
  for (int t = tris->first(b); t < tris->first(b) + tris->count(b); t++) {
    const int a = tris->a(t), c = tris->c(t);
    // a vertex missing on this rank is beyond the ghost cutoff: the triangle is beyond the support
    if (a < 0 || c < 0) continue;
    const double ra[3] = {x[a][0] - xf[0], x[a][1] - xf[1], x[a][2] - xf[2]};
    const double rb[3] = {x[b][0] - xf[0], x[b][1] - xf[1], x[b][2] - xf[2]};
    const double rc[3] = {x[c][0] - xf[0], x[c][1] - xf[1], x[c][2] - xf[2]};
    const double g[3] = {(ra[0] + rb[0] + rc[0]) / 3.0, (ra[1] + rb[1] + rc[1]) / 3.0,
                         (ra[2] + rb[2] + rc[2]) / 3.0};
    const double gl = sqrt(CellTriangle::dot(g, g));
    const double invh = PERATOM ? 1.0 / hbase[f] : p.invh;
    const double q = gl * invh;
    if (q >= support) continue;
    const int vert[3] = {a, b, c};
    const double *rv[3] = {ra, rb, rc};
    int s[3];
    double len[3];
    for (int v = 0; v < 3; v++) {
      if (slot[vert[v]] < 0) {
        slot[vert[v]] = static_cast<int>(terms.size());
        terms.push_back(Term{f, vert[v], {0.0, 0.0, 0.0}});
        termlen.push_back(sqrt(CellTriangle::dot(rv[v], rv[v])));
      }
      s[v] = slot[vert[v]];
      len[v] = termlen[s[v]];
    }
    double ph, dph;
    phi_beyond(q, ph, dph);
    // D_T = Phi(|g|/h) Omega_T / (4 pi), Omega_T the solid angle of T seen from f (exact: a point
    // formula (g . S_T)/|g|^3 would err by 1e-3 in gamma, 2 % in pressure); 1 - gamma_f = sum_T D_T
    double solid, dom[3][3];
    CellTriangle::solid_angle(ra, rb, rc, len, solid, dom);
    deficit[f] += ph * solid / (4.0 * M_PI);
    // per-atom h: dD_T/dh = -Phi'(q) q Omega_T / (4 pi h)
    if (PERATOM) dhdef[f] -= dph * q * invh * solid / (4.0 * M_PI);
    // dD_T/dx_v = Phi'(q) Omega g / (12 pi h |g|) + Phi / (4 pi) dOmega/dx_v (d|g|/dx_v = g / 3|g|),
    // with Phi' the derivative of the interpolated Phi, so that the force is -grad of this D_T
    const double cg = dph * solid * invh / (12.0 * M_PI * gl);
    const double co = ph / (4.0 * M_PI);
    for (int v = 0; v < 3; v++)
      for (int d = 0; d < 3; d++) terms[s[v]].grad[d] += cg * g[d] + co * dom[v][d];
  }
}

/* ----------------------------------------------------------------------
   at reneighbouring: the neighbour list split into the fluid pairs of the SPH sums and the
   fluid-wall pairs of the wall boundary (same cell), so that the steps between exact evaluations
   of the boundary do not visit the boundary pairs. With per-atom h the fluid pairs are only those
   within margin of the support of (1 + HGROW) x the larger h at the split: the list reaches GROW x
   the largest h of the run's start, most of it beyond every support once a cell has dried
   (margin = skin at a build; 2 skin on a later split, since both atoms may have moved skin/2 from
   the build positions before and move as much again after). Dropped pairs would be skipped by
   the density pass anyway, so the sums are the same.
------------------------------------------------------------------------- */

void PairCellSPHBoundary::split_list(double margin)
{
  const tagint *molecule = atom->molecule;
  const int *type = atom->type;
  const int inum = sph->list->inum;
  const int peratom = sph->hmode != PairCellSPH::HFIXED;
  double **x = atom->x;
  const double *hv = peratom ? atom->dvector[sph->ih] : nullptr;
  const double reach =
      CellKernel::support(sph->kernel) * (1.0 + PairCellSPH::HMARGIN) * (1.0 + HGROW);
  if (peratom) {
    const int nall = atom->nlocal + atom->nghost;
    hsplit.resize(nall);
    for (int i = 0; i < nall; i++) hsplit[i] = sph->fluid[type[i]] ? hv[i] : 0.0;
  }
  fluidfirst.assign(inum + 1, 0);
  fluidj.clear();
  boundarypairs.clear();
  for (int ii = 0; ii < inum; ii++) {
    const int i = sph->list->ilist[ii];
    const int *jlist = sph->list->firstneigh[i];
    fluidfirst[ii] = static_cast<int>(fluidj.size());
    for (int jj = 0; jj < sph->list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const Contact &p = pairs[type[i]][type[j]];
      // each cell's fluid is bounded by its own wall: no pair with another cell's fluid
      // (doc/pair_cell_sph.md, Wall boundary)
      if (molecule[i] != molecule[j]) continue;
      if (!p.on) {
        if (peratom && sph->fluid[type[i]] && sph->fluid[type[j]]) {
          // within margin of the support of (1 + HGROW) x the larger h (the comment above)
          const double r = reach * std::max(hv[i], hv[j]) + margin;
          const double delx = x[i][0] - x[j][0];
          const double dely = x[i][1] - x[j][1];
          const double delz = x[i][2] - x[j][2];
          if (delx * delx + dely * dely + delz * delz >= r * r) continue;
        }
        fluidj.push_back(j);
      } else
        boundarypairs.push_back(sph->fluid[type[i]] ? std::array<int, 2>{i, j}
                                                    : std::array<int, 2>{j, i});
    }
  }
  fluidfirst[inum] = static_cast<int>(fluidj.size());
  // the boundary pairs of each fluid atom in a row, in list order (a stable counting sort), so
  // that its terms are summed per vertex as they come
  const int nall = atom->nlocal + atom->nghost;
  std::vector<int> first(nall + 1, 0);
  for (const auto &fb : boundarypairs) first[fb[0] + 1]++;
  for (int i = 0; i < nall; i++) first[i + 1] += first[i];
  std::vector<std::array<int, 2>> sorted(boundarypairs.size());
  for (const auto &fb : boundarypairs) sorted[first[fb[0]]++] = fb;
  boundarypairs.swap(sorted);
}

/* ----------------------------------------------------------------------
   per-atom h: an owned or ghost fluid atom whose h grew beyond (1 + HGROW) x its h at the last
   split_list(), so that the split may lack pairs of its support (a local decision: the sums are
   the same with or without a new split)
------------------------------------------------------------------------- */

bool PairCellSPHBoundary::outgrown() const
{
  const double *hv = atom->dvector[sph->ih];
  const int nall = atom->nlocal + atom->nghost;
  if (static_cast<int>(hsplit.size()) < nall) return true;
  for (int i = 0; i < nall; i++)
    if (hv[i] > (1.0 + HGROW) * hsplit[i]) return true;
  return false;
}

/* ----------------------------------------------------------------------
   the positions of an exact evaluation, the base of the linearisation until the next: the atoms'
   own (ahead = 0, and on a neighbour build, where the contact candidates are searched), or
   half an interval ahead, x + v dt every / 2 (each atom's step at most skin/4), so that the
   linearisation's error, quadratic in the displacement from the base, is the same at both ends
   of the interval and cancels in the energy at the next exact evaluation (doc/pair_cell_sph.md)
------------------------------------------------------------------------- */

void PairCellSPHBoundary::base_positions(int ahead)
{
  double **x = atom->x;
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  // the linearisation from the last base at these positions, against the next (next_interval)
  if (measuring) {
    linear_deficit();
    for (int i = 0; i < nall; i++) jump[i] = deficit[i];
  }
  predicted = ahead;
  if (!predicted) {
    for (int i = 0; i < nall; i++)
      for (int d = 0; d < 3; d++) xbase[i][d] = x[i][d];
    store_base();
    return;
  }
  double **v = atom->v;
  const double half = 0.5 * every * update->dt;
  const double most = 0.25 * neighbor->skin;
  for (int i = 0; i < nlocal; i++) {
    const double step2 = half * half * (v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2]);
    const double k = step2 > most * most ? most / sqrt(step2) : 1.0;
    for (int d = 0; d < 3; d++) disp[i][d] = k * half * v[i][d];
  }
  sph->forward(PairCellSPH::COMM_AHEAD);
  for (int i = 0; i < nall; i++)
    for (int d = 0; d < 3; d++) xbase[i][d] = x[i][d] + disp[i][d];
  store_base();
}

/* ----------------------------------------------------------------------
   the interval to the exact evaluation after the next, from the jump of 1 - gamma of every fluid
   atom at this one (the new linearisation against the last, at the same positions: the jump of
   the energy): doubled while the largest jump is below JUMP_TOL / 4, halved above JUMP_TOL,
   between REFRESH and REFRESH_MAX steps
------------------------------------------------------------------------- */

void PairCellSPHBoundary::next_interval()
{
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  for (int i = 0; i < nall; i++) jump[i] = deficit[i] - jump[i];
  sph->reverse(PairCellSPH::COMM_JUMP);
  const int *type = atom->type;
  double most = 0.0, all = 0.0;
  for (int i = 0; i < nlocal; i++)
    if (sph->fluid[type[i]]) most = std::max(most, fabs(jump[i]));
  MPI_Allreduce(&most, &all, 1, MPI_DOUBLE, MPI_MAX, world);
  lastjump = all;
  if (all > JUMP_TOL)
    pending = std::max(every / 2, REFRESH);
  else if (all < 0.25 * JUMP_TOL)
    pending = std::min(every * 2, REFRESH_MAX);
  else
    pending = every;
}

/* ----------------------------------------------------------------------
   after an exact evaluation: the terms (one per fluid atom and vertex, grad_v D_f summed over
   the vertex's triangles) indexed per fluid atom; the deficits kept with the base positions
   (base_positions) as the base of the linearisation
------------------------------------------------------------------------- */

void PairCellSPHBoundary::keep_base()
{
  const int nall = atom->nlocal + atom->nghost;
  // the terms of fluid atom f are terms[termfirst[f]] .. terms[termfirst[f + 1] - 1], and
  // gradsum[f] = sum_v grad_v D_f = -grad_f D_f
  termfirst.assign(nall + 1, 0);
  for (const Term &tm : terms) termfirst[tm.f + 1]++;
  for (int i = 0; i < nall; i++) termfirst[i + 1] += termfirst[i];
  for (int i = 0; i < nall; i++) {
    deficit0[i] = deficit[i];
    for (int d = 0; d < 3; d++) gradsum[i][d] = 0.0;
  }
  for (const Term &tm : terms)
    for (int d = 0; d < 3; d++) gradsum[tm.f][d] += tm.grad[d];
  if (sph->hmode != PairCellSPH::HFIXED)
    for (int i = 0; i < nall; i++) dhdef0[i] = dhdef[i];
}

/* ----------------------------------------------------------------------
   between exact evaluations: 1 - gamma_f = D_f(base) + sum_v grad_v D_f . (dx_v - dx_f)
   (+ dD_f/dh (h_f - h_f(base)) with per-atom h), dx the displacement since the base, summed as
   D_f(base) - gradsum_f . dx_f + sum_v grad_v D_f . dx_v (grad_f D_f = -gradsum_f)
------------------------------------------------------------------------- */

void PairCellSPHBoundary::linear_deficit()
{
  double **x = atom->x;
  const int nall = atom->nlocal + atom->nghost;
  for (int i = 0; i < nall; i++)
    for (int d = 0; d < 3; d++) disp[i][d] = x[i][d] - xbase[i][d];
  const double *hv = sph->hmode != PairCellSPH::HFIXED ? atom->dvector[sph->ih] : nullptr;
  for (int i = 0; i < nall; i++) {
    double sum = 0.0;
    for (int k = termfirst[i]; k < termfirst[i + 1]; k++) {
      const double *dv = disp[terms[k].v];
      sum += terms[k].grad[0] * dv[0] + terms[k].grad[1] * dv[1] + terms[k].grad[2] * dv[2];
    }
    deficit[i] = deficit0[i] -
        (gradsum[i][0] * disp[i][0] + gradsum[i][1] * disp[i][1] + gradsum[i][2] * disp[i][2]) +
        sum;
    if (hv) {
      dhdef[i] = dhdef0[i];
      deficit[i] += dhdef0[i] * (hv[i] - hbase[i]);
    }
  }
}

/* ----------------------------------------------------------------------
   the wall term of each boundary pair, F_f = 2 m_f (P_f / rho_f) grad_f gamma_f (the fluid's
   own pressure mirrored across the wall), its reaction on the wall atom, tallied as wall load
------------------------------------------------------------------------- */

template <int EVFLAG> void PairCellSPHBoundary::wall_forces()
{
  double **x = atom->x;
  double **f = atom->f;
  const double *rmass = atom->rmass;
  const double *rho = atom->dvector[sph->irho];

  // the forces on the wall atoms go into wallload (zero before, from start_sums), added to f
  // at the end
  const int nall = atom->nlocal + atom->nghost;
  for (int i = 0; i < nall; i++) {
    // F = -grad E of E = sum m e(rho), rho = sum m W / gamma, 1 - gamma = D: -C_f grad_v D_f on
    // vertex v and its opposite on the fluid atom, C_f = m P / (rho gamma) (0 at the gamma floor)
    if (termfirst[i] == termfirst[i + 1]) continue;
    const double c = 1.0 - deficit[i] < GAMMA_MIN ? 0.0 : rmass[i] * sph->prho2[i] * rho[i];
    if (c == 0.0) continue;
    f[i][0] += c * gradsum[i][0];
    f[i][1] += c * gradsum[i][1];
    f[i][2] += c * gradsum[i][2];
    for (int k = termfirst[i]; k < termfirst[i + 1]; k++) {
      const Term &tm = terms[k];
      const int v = tm.v;
      const double fx = c * tm.grad[0], fy = c * tm.grad[1], fz = c * tm.grad[2];
      wallload[v][0] -= fx;
      wallload[v][1] -= fy;
      wallload[v][2] -= fz;
      if (EVFLAG)
        sph->ev_tally_xyz(i, v, atom->nlocal, 1, 0.0, 0.0, fx, fy, fz, x[i][0] - x[v][0],
                          x[i][1] - x[v][1], x[i][2] - x[v][2]);
    }
  }

  // contacts with the wall surface: the candidates of the neighbour build within reach + margin
  // (near), taken again from all of them once an atom has moved margin / 2 since
  const double margin = NEAR * neighbor->skin;
  if (rebuilt || moved_since_near(0.5 * margin)) {
    near.clear();
    for (const auto &t : touching)
      if (contact<EVFLAG>(t[0], t[1], t[2], t[3], margin)) near.push_back(t);
    for (int i = 0; i < nall; i++)
      for (int d = 0; d < 3; d++) xnear[i][d] = x[i][d];
  } else {
    for (const auto &t : near) contact<EVFLAG>(t[0], t[1], t[2], t[3], margin);
  }
  if (sph->background != 0.0) outside_pressure<EVFLAG>();
  for (int i = 0; i < nall; i++)
    for (int d = 0; d < 3; d++) f[i][d] += wallload[i][d];
}

/* ----------------------------------------------------------------------
   background pressure P_b from outside on every wall triangle kept by an owned wall atom b:
   -P_b S_T / 3 on each vertex (S_T the outward area vector), energy P_b V_T,
   V_T = x_b . S_T / 3 with x_b unwrapped (the closed wall's volume by the divergence theorem),
   tallied as wall load so that the load is the fluid's P alone (doc/pair_cell_sph.md, eq. B2)
------------------------------------------------------------------------- */

template <int EVFLAG> void PairCellSPHBoundary::outside_pressure()
{
  double **x = atom->x;
  const int nlocal = atom->nlocal;
  const double p3 = sph->background / 3.0;
  for (int b = 0; b < nlocal; b++) {
    const int t0 = tris->first(b), nt = tris->count(b);
    for (int t = t0; t < t0 + nt; t++) {
      const int a = tris->a(t), c = tris->c(t);
      if (a < 0 || c < 0)
        error->one(FLERR,
                   "Pair cell/sph: background pressure: a wall triangle of atom {} (cell {}) has "
                   "a vertex on no rank on step {} (ghost cutoff too short)",
                   atom->tag[b], atom->molecule[b], update->ntimestep);
      // S_T = (x_b - x_a) x (x_c - x_a) / 2, outward; -P_b dV/dx_k = -P_b S_T / 3 (eq. B2)
      double ab[3], ac[3], fn[3];
      for (int d = 0; d < 3; d++) {
        ab[d] = x[b][d] - x[a][d];
        ac[d] = x[c][d] - x[a][d];
      }
      fn[0] = -0.5 * p3 * (ab[1] * ac[2] - ab[2] * ac[1]);
      fn[1] = -0.5 * p3 * (ab[2] * ac[0] - ab[0] * ac[2]);
      fn[2] = -0.5 * p3 * (ab[0] * ac[1] - ab[1] * ac[0]);
      const int v[3] = {a, b, c};
      for (int k = 0; k < 3; k++)
        for (int d = 0; d < 3; d++) wallload[v[k]][d] += fn[d];
      if (!EVFLAG) continue;
      if (sph->eflag_either) {
        // P_b V_T = -x_b . F_k (F_k = -P_b S_T / 3), x_b unwrapped
        double xb[3];
        domain->unmap(x[b], atom->image[b], xb);
        const double e = -(xb[0] * fn[0] + xb[1] * fn[1] + xb[2] * fn[2]);
        if (sph->eflag_global) sph->eng_vdwl += e;
        if (sph->eflag_atom) sph->eatom[b] += e;
      }
      if (sph->vflag_either) {
        // virial sum_k x_k F_k (as F dot r over owned and ghost atoms)
        for (int k = 0; k < 3; k++) {
          const double *xk = x[v[k]];
          const double w[6] = {xk[0] * fn[0], xk[1] * fn[1], xk[2] * fn[2],
                               xk[0] * fn[1], xk[0] * fn[2], xk[1] * fn[2]};
          for (int m = 0; m < 6; m++) {
            if (sph->vflag_global) sph->virial[m] += w[m];
            if (sph->vflag_atom) sph->vatom[v[k]][m] += w[m];
          }
        }
      }
    }
  }
}

/* ----------------------------------------------------------------------
   contact of fluid atom f with triangle (a, b, c) of its own cell's wall: F = F_c (1 - d/delta)^2 e
   from the closest point p at distance d < delta, e = (x_f - p)/d, on the fluid atom and
   -lambda_v F on vertex v (newton on, the vertices' share as wall load), energy
   F_c delta (1 - d/delta)^3 / 3, so that F = -grad E for the atom and the vertices; true if
   d < delta + margin
------------------------------------------------------------------------- */

template <int EVFLAG> bool PairCellSPHBoundary::contact(int f, int a, int b, int c, double margin)
{
  const Contact &p = pairs[atom->type[f]][atom->type[b]];
  double **x = atom->x;
  const CellTriangle::Foot ft = CellTriangle::closest(x[f], x[a], x[b], x[c]);
  const double e[3] = {x[f][0] - ft.p[0], x[f][1] - ft.p[1], x[f][2] - ft.p[2]};
  const double dist = sqrt(CellTriangle::dot(e, e));
  if (dist >= p.reach) return dist < p.reach + margin;
  if (dist == 0.0)
    error->one(FLERR,
               "Pair cell/sph: fluid atom {} (cell {}) lies on its wall on step {}: the contact "
               "force has no direction; the run went unstable",
               atom->tag[f], atom->molecule[f], update->ntimestep);
  const double s = 1.0 - dist / p.reach;
  const double fd = p.fcontact * s * s / dist;
  // F = F_c (1 - d/delta)^2 (x_f - p) / d
  double force[3] = {fd * e[0], fd * e[1], fd * e[2]};
  const int v[3] = {a, b, c};
  double fv[3][3];
  double **fatom = atom->f;
  for (int d = 0; d < 3; d++) {
    fatom[f][d] += force[d];
    for (int k = 0; k < 3; k++) {
      fv[k][d] = -ft.l[k] * force[d];
      wallload[v[k]][d] += fv[k][d];
    }
  }
  if (!EVFLAG) return true;
  const double energy = p.fcontact * p.reach * s * s * s / 3.0;
  if (sph->eflag_global) sph->eng_vdwl += energy;
  if (sph->eflag_atom) sph->eatom[f] += energy;
  if (sph->vflag_either) {
    // virial about vertex c: sum over f, a, b of (x - x_c) F
    double dfc[3], dac[3], dbc[3];
    for (int d = 0; d < 3; d++) {
      dfc[d] = x[f][d] - x[c][d];
      dac[d] = x[a][d] - x[c][d];
      dbc[d] = x[b][d] - x[c][d];
    }
    sph->v_tally4(f, a, b, c, force, fv[0], fv[1], dfc, dac, dbc);
  }
  return true;
}

/* ----------------------------------------------------------------------
   true if an owned or ghost atom has moved more than dmax since the near contact candidates were
   taken (a local decision: the contacts are the same with either list)
------------------------------------------------------------------------- */

bool PairCellSPHBoundary::moved_since_near(double dmax) const
{
  double **x = atom->x;
  const int nall = atom->nlocal + atom->nghost;
  const double dmax2 = dmax * dmax;
  for (int i = 0; i < nall; i++) {
    const double dx = x[i][0] - xnear[i][0];
    const double dy = x[i][1] - xnear[i][1];
    const double dz = x[i][2] - xnear[i][2];
    if (dx * dx + dy * dy + dz * dz > dmax2) return true;
  }
  return false;
}

/* ----------------------------------------------------------------------
   Phi(q), the fraction of the 3-D kernel beyond q = r/h, and dPhi/dq = -4 pi q^2 W(q) at h = 1,
   tabulated from the kernel (3-point Gauss-Legendre per step, exact for the kernels' pieces,
   which end on table points) for cubic Hermite interpolation
------------------------------------------------------------------------- */

void PairCellSPHBoundary::tabulate_phi()
{
  const int kernel = sph->kernel;
  const double support = CellKernel::support(kernel);
  const int n = 512 * static_cast<int>(support);
  const CellKernel::Scale unit = CellKernel::scale(kernel, 3, 1.0);
  const auto shell = [&](double q) { return 4.0 * M_PI * q * q * CellKernel::W(kernel, unit, q); };
  static const double GX = 0.7745966692414834, GW0 = 8.0 / 9.0, GW1 = 5.0 / 9.0;
  phidq = support / n;
  phi.assign(n + 1, 0.0);
  dphi.assign(n + 1, 0.0);
  for (int k = n - 1; k >= 0; k--) {
    const double mid = (k + 0.5) * phidq, half = 0.5 * phidq;
    const double sum = GW0 * shell(mid) + GW1 * (shell(mid - half * GX) + shell(mid + half * GX));
    phi[k] = phi[k + 1] + half * sum;
    dphi[k] = -shell(k * phidq);
  }
}

/* ---------------------------------------------------------------------- */

void PairCellSPHBoundary::phi_beyond(double q, double &value, double &slope) const
{
  const int k = static_cast<int>(q / phidq);
  if (k >= static_cast<int>(phi.size()) - 1) {
    value = slope = 0.0;
    return;
  }
  const double t = q / phidq - k;
  const double t2 = t * t, t3 = t2 * t;
  // cubic Hermite between the table points k and k + 1, and its derivative in q
  value = (2.0 * t3 - 3.0 * t2 + 1.0) * phi[k] + (t3 - 2.0 * t2 + t) * phidq * dphi[k] +
      (3.0 * t2 - 2.0 * t3) * phi[k + 1] + (t3 - t2) * phidq * dphi[k + 1];
  slope = (6.0 * t2 - 6.0 * t) * (phi[k] - phi[k + 1]) / phidq +
      (3.0 * t2 - 4.0 * t + 1.0) * dphi[k] + (3.0 * t2 - 2.0 * t) * dphi[k + 1];
}
