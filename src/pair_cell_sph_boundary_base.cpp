/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   the wall boundary of pair_style cell/sph (pair_cell_sph_boundary.h): its linearisation's base
   kept with each atom (fix FIELDS), so that a neighbour build, a run's setup and a restart
   evaluate the same linearisation again at it (doc/notes/2026-12-07-run-split.md), and the
   contact candidates of a build
------------------------------------------------------------------------- */

#include "pair_cell_sph_boundary.h"

#include "atom.h"
#include "cell_styles.h"
#include "cell_triangle.h"
#include "cell_wall_triangles.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "modify.h"
#include "neighbor.h"
#include "pair_cell_sph.h"

using namespace LAMMPS_NS;

// as soon as an atom is REACH x skin from its base, the boundary is evaluated exactly, so that the
// pairs of a neighbour build include every pair of the base within range (rebase)
static const double REACH = 0.5;
// the per-atom fix holding each atom's base (property/atom, no ghosts: theirs are sent shifted)
static const char *FIELDS = CellField::BASEFIX;
static const char *XFIELD = CellField::XBASE;
static const char *HFIELD = CellField::HBASE;

/* ----------------------------------------------------------------------
   the per-atom base xbase (3 values) and hbase in fix FIELDS, made here if no fix has them (after
   read_restart at the first run: the fix then gets each atom's base from the restart file)
------------------------------------------------------------------------- */

void PairCellSPHBoundary::find_fields()
{
  int flag, cols;
  if (atom->find_custom(XFIELD, flag, cols) < 0 && modify->find_fix(FIELDS) < 0)
    modify->add_fix(fmt::format("{} all property/atom d2_{} 3 d_{}", FIELDS, XFIELD, HFIELD));
  // internal: no section in data files (an input reading them does not define the fix); restart
  // files carry the base
  const int ifix = modify->find_fix(FIELDS);
  if (ifix >= 0) modify->fix[ifix]->wd_section = 0;
  int hflag, hcols;
  ixfield = atom->find_custom(XFIELD, flag, cols);
  ihfield = atom->find_custom(HFIELD, hflag, hcols);
  if (ixfield < 0 || flag != 1 || cols != 3 || ihfield < 0 || hflag != 1 || hcols != 0)
    error->all(FLERR,
               "Pair cell/sph: the wall boundary needs the per-atom array {} (3 values) and "
               "vector {} of fix {} (the pair style makes it; a fix of that ID without them "
               "conflicts)",
               XFIELD, HFIELD, FIELDS);
}

/* ----------------------------------------------------------------------
   the schedule of a restart file (or of a pair style before a version that kept it: none)
------------------------------------------------------------------------- */

void PairCellSPHBoundary::resume(const Schedule &s)
{
  refreshed = s.refreshed;
  every = s.every;
  pending = s.pending;
  lastjump = s.lastjump;
}

/* ----------------------------------------------------------------------
   at a neighbour build: each owned atom's base from fix FIELDS (its x the image nearest the atom,
   which the build may have wrapped), the ghost atoms' as their owners' step from the atom
------------------------------------------------------------------------- */

void PairCellSPHBoundary::restore_base()
{
  double **x = atom->x;
  double **xf = atom->darray[ixfield];
  const double *hf = atom->dvector[ihfield];
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  for (int i = 0; i < nlocal; i++) {
    double d[3] = {xf[i][0] - x[i][0], xf[i][1] - x[i][1], xf[i][2] - x[i][2]};
    const double raw[3] = {d[0], d[1], d[2]};
    domain->minimum_image(d);
    if (d[0] != raw[0] || d[1] != raw[1] || d[2] != raw[2])
      for (int k = 0; k < 3; k++) xf[i][k] = x[i][k] + d[k];
    for (int k = 0; k < 3; k++) {
      xbase[i][k] = xf[i][k];
      disp[i][k] = xf[i][k] - x[i][k];
    }
    hbase[i] = hf[i];
  }
  sph->forward(PairCellSPH::COMM_BASE);
  for (int i = nlocal; i < nall; i++)
    for (int k = 0; k < 3; k++) xbase[i][k] = x[i][k] + disp[i][k];
}

/* ----------------------------------------------------------------------
   true (on every rank) if an owned atom has no base or is more than REACH x skin from it
------------------------------------------------------------------------- */

bool PairCellSPHBoundary::beyond_reach()
{
  double **x = atom->x;
  double **xf = atom->darray[ixfield];
  const double *hf = atom->dvector[ihfield];
  const double reach = REACH * neighbor->skin;
  int out = 0, any = 0;
  for (int i = 0; i < atom->nlocal && !out; i++) {
    const double dx = xf[i][0] - x[i][0], dy = xf[i][1] - x[i][1], dz = xf[i][2] - x[i][2];
    out = !(hf[i] > 0.0) || dx * dx + dy * dy + dz * dz > reach * reach;
  }
  MPI_Allreduce(&out, &any, 1, MPI_INT, MPI_MAX, world);
  return any != 0;
}

/* ----------------------------------------------------------------------
   after a neighbour build with a base (also at a run's setup): the linearisation evaluated again
   at the base positions and h of its last exact evaluation (the same affine function, to
   round-off, on the atoms' new order and ranks)
------------------------------------------------------------------------- */

void PairCellSPHBoundary::rebase(int peratom)
{
  if (!rebasing) return;
  const int nall = atom->nlocal + atom->nghost;
  for (int i = 0; i < nall; i++) deficit[i] = 0.0;
  if (peratom)
    for (int i = 0; i < nall; i++) dhdef[i] = 0.0;
  terms.clear();
  termlen.clear();
  exact_terms(peratom);
  keep_base();
}

/* ----------------------------------------------------------------------
   at a neighbour build: the fluid atoms and wall triangles that may come into contact before the
   next build (each atom moves less than skin/2), at the atoms' positions
------------------------------------------------------------------------- */

void PairCellSPHBoundary::search_contacts()
{
  double **x = atom->x;
  const int *type = atom->type;
  const double edgemax = tris->edge_max();
  touching.clear();
  for (const auto &fb : boundarypairs) {
    const int f = fb[0], b = fb[1];
    const double touch = pairs[type[f]][type[b]].reach + neighbor->skin;
    const double *xf = x[f];
    for (int t = tris->first(b); t < tris->first(b) + tris->count(b); t++) {
      const int a = tris->a(t), c = tris->c(t);
      if (a < 0 || c < 0) continue;
      // the centroid within touch + 2/3 of the longest edge, the closest point within touch
      double g[3];
      for (int d = 0; d < 3; d++) g[d] = (x[a][d] + x[b][d] + x[c][d]) / 3.0 - xf[d];
      const double lim = touch + 2.0 / 3.0 * edgemax;
      if (CellTriangle::dot(g, g) >= lim * lim) continue;
      const CellTriangle::Foot ft = CellTriangle::closest(xf, x[a], x[b], x[c]);
      const double e[3] = {xf[0] - ft.p[0], xf[1] - ft.p[1], xf[2] - ft.p[2]};
      if (CellTriangle::dot(e, e) < touch * touch) touching.push_back({f, a, b, c});
    }
  }
}

/* ----------------------------------------------------------------------
   a new base: h at it (the fluid atoms' own, 1 on other atoms: it marks a base), and that of the
   owned atoms into fix FIELDS
------------------------------------------------------------------------- */

void PairCellSPHBoundary::store_base()
{
  const int *type = atom->type;
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  const double *hv = sph->hmode != PairCellSPH::HFIXED ? atom->dvector[sph->ih] : nullptr;
  for (int i = 0; i < nall; i++)
    hbase[i] = !sph->fluid[type[i]] ? 1.0 : hv ? hv[i] : sph->h[type[i]][type[i]];
  double **xf = atom->darray[ixfield];
  double *hf = atom->dvector[ihfield];
  for (int i = 0; i < nlocal; i++) {
    for (int d = 0; d < 3; d++) xf[i][d] = xbase[i][d];
    hf[i] = hbase[i];
  }
}
