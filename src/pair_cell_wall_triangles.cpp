/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   pair_style cell/wall's triangles and selftriangles terms: a wall atom against the triangles of
   the other cells' walls, and of its own wall that it is not a vertex of (WCA of the distance to
   the triangle's closest point); the touching (atom, triangle) pairs found at each neighbour
   build, and the stop when a wall atom is behind the face of its nearest such triangle
   (doc/pair_cell_wall.md, Triangles, Selftriangles, Crossing stop)
------------------------------------------------------------------------- */

#include "pair_cell_wall.h"

#include "atom.h"
#include "cell_compat.h"
#include "cell_triangle.h"
#include "cell_wall_triangles.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "math_special.h"
#include "memory.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include <cmath>

using namespace LAMMPS_NS;
using MathSpecial::cube;

// a wall atom behind its nearest face has crossed it only if nearer than CROSS_DEPTH x the reach:
// an atom that goes through a face passes d = 0 and is first seen behind it at about one step's
// displacement; a face that comes within reach with the atom already behind it is a fold of that
// wall turning its back to the atom (doc/pair_cell_wall.md, Crossing stop)
static constexpr double CROSS_DEPTH = 0.5;

/* ----------------------------------------------------------------------
   at each neighbour build: every (wall atom, triangle of another cell) whose closest point is
   within the triangles' reach + margin, and with selftriangles every (wall atom, triangle of its
   own wall that it is not a vertex of) within that term's reach + margin, from the list's pairs
   (wall atom, the triangle's keeper b) of type pairs with the term and, for the own wall, from
   the bonded partners (special list) whose pairs LAMMPS dropped from the list; the rest cannot
   come within reach before the next build (the distance moves by less than the displacements of
   the atom and of one vertex)
------------------------------------------------------------------------- */

void PairCellWall::find_touching(double margin)
{
  double **x = atom->x;
  const int *type = atom->type;
  const tagint *molecule = atom->molecule;
  const double edge = tris->edge_max();
  touching.clear();
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const Coeff &c = coeffs[type[i]][type[j]];
      const bool self = molecule[i] == molecule[j];
      if (!(c.terms & (self ? SELFTRIANGLES : TRIANGLES))) continue;
      // a triangle within reach of x has its keeper within reach + its longest edge b-a, b-c
      const double reach = (self ? c.sreach : c.treach) + margin;
      const double keep = reach + edge;
      const double delx = x[i][0] - x[j][0];
      const double dely = x[i][1] - x[j][1];
      const double delz = x[i][2] - x[j][2];
      if (delx * delx + dely * dely + delz * delz >= keep * keep) continue;
      touch_kept(i, j, reach, self);
      touch_kept(j, i, reach, self);
    }
  }
  // bonded partners of an owned atom whose class LAMMPS leaves out of the list (special_bonds lj
  // and coul 0): their triangles without the atom are in its 2-ring (1-2) or beyond; each
  // partner's triangles once, by the atom's owner (the special lists are symmetric)
  if (!atom->molecular) return;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *nspecial = atom->nspecial[i];
    for (int m = 0; m < nspecial[2]; m++) {
      const int order = m < nspecial[0] ? 1 : m < nspecial[1] ? 2 : 3;
      if (neighbor->special_flag[order] != 0) continue;
      const int k = atom->map(atom->special[i][m]);
      if (k < 0) continue;    // a missing bonded atom stops the bonded styles
      const int j = domain->closest_image(i, k);
      const Coeff &c = coeffs[type[i]][type[j]];
      if (molecule[i] != molecule[j] || !(c.terms & SELFTRIANGLES)) continue;
      touch_kept(i, j, c.sreach + margin, true);
    }
  }
}

/* ----------------------------------------------------------------------
   the triangles kept by atom b within reach of wall atom w; of the own wall (self) only those w
   is not a vertex of
------------------------------------------------------------------------- */

void PairCellWall::touch_kept(int w, int b, double reach, bool self)
{
  double **x = atom->x;
  const tagint *tag = atom->tag;
  for (int t = tris->first(b); t < tris->first(b) + tris->count(b); t++) {
    const int a = tris->a(t), v = tris->c(t);
    // a vertex missing on this rank: the ghost cutoff, checked at the build, holds every vertex
    // of a triangle within reach + skin of w, so this one stays out of reach until the next build
    if (a < 0 || v < 0) continue;
    // a triangle w is a vertex of is no contact (doc/pair_cell_wall.md, Selftriangles)
    if (self && (tag[a] == tag[w] || tag[v] == tag[w])) continue;
    const CellTriangle::Foot ft = CellTriangle::closest(x[w], x[a], x[b], x[v]);
    const double e[3] = {x[w][0] - ft.p[0], x[w][1] - ft.p[1], x[w][2] - ft.p[2]};
    if (CellTriangle::dot(e, e) < reach * reach) touching.push_back({w, a, b, v});
  }
}

/* ----------------------------------------------------------------------
   the contact of each wall atom w with the triangles (a, b, c) it touches (of other cells, or of
   its own wall and w not a vertex): WCA of the distance d to the closest point p,
   E = 4 eps [(sigma/d)^12 - (sigma/d)^6] + eps for d < 2^(1/6) sigma; F_w = -dE/dd (x_w - p)/d,
   and -lambda_v F_w on vertex v (lambda the barycentric coordinates of p), so that F = -grad E
   and the forces sum to zero (doc/pair_cell_wall.md, Triangles); each atom's nearest such
   triangle of another cell, and of its own wall, goes into nearest
------------------------------------------------------------------------- */

template <int EVFLAG> void PairCellWall::triangle_contacts()
{
  double **x = atom->x;
  double **f = atom->f;
  const int *type = atom->type;
  const tagint *tag = atom->tag;
  const int nall = atom->nlocal + atom->nghost;
  if (atom->nmax > nmax_near) {
    nmax_near = atom->nmax;
    memory->destroy(nearest);
    memory->create(nearest, nmax_near, 2 * NEAR, "pair:nearest");
  }
  for (int i = 0; i < nall; i++) nearest[i][0] = nearest[i][NEAR] = -1.0;
  for (const auto &t : touching) {
    const int w = t[0], a = t[1], b = t[2], c = t[3];
    const Coeff &k = coeffs[type[w]][type[b]];
    const bool self = atom->molecule[w] == atom->molecule[b];
    const double eps = self ? k.seps : k.teps;
    const double sigsq = self ? k.ssigsq : k.tsigsq;
    const double reach = self ? k.sreach : k.treach;
    const CellTriangle::Foot ft = CellTriangle::closest(x[w], x[a], x[b], x[c]);
    const double e[3] = {x[w][0] - ft.p[0], x[w][1] - ft.p[1], x[w][2] - ft.p[2]};
    const double dsq = CellTriangle::dot(e, e);
    if (dsq >= reach * reach) continue;
    double *near = nearest[w] + (self ? NEAR : 0);
    if (near[0] < 0.0 || dsq < near[0]) {
      // behind the face: in the face region, (x_w - p) . n <= 0, n = (b - a) x (c - a) outward,
      // and nearer than CROSS_DEPTH x the reach (on the face, d = 0, the wall atom has no side)
      double behind = dsq == 0.0 ? 1.0 : 0.0;
      if (ft.face && dsq > 0.0 && dsq < CROSS_DEPTH * CROSS_DEPTH * reach * reach) {
        const double ab[3] = {x[b][0] - x[a][0], x[b][1] - x[a][1], x[b][2] - x[a][2]};
        const double ac[3] = {x[c][0] - x[a][0], x[c][1] - x[a][1], x[c][2] - x[a][2]};
        double n[3];
        CellTriangle::cross(ab, ac, n);
        behind = CellTriangle::dot(n, e) <= 0.0 ? 1.0 : 0.0;
      }
      near[0] = dsq;
      near[1] = behind;
      near[2] = ubuf(atom->molecule[b]).d;
      near[3] = ubuf(tag[a]).d;
      near[4] = ubuf(tag[b]).d;
      near[5] = ubuf(tag[c]).d;
    }
    if (dsq == 0.0) continue;    // on the face: check_crossing() stops the run
    const double s3 = cube(sigsq / dsq);
    // F_w = 24 eps [2 (sigma/d)^12 - (sigma/d)^6] (x_w - p) / d^2 (doc/pair_cell_wall.md, eq. T1)
    const double fd = 24.0 * eps * s3 * (2.0 * s3 - 1.0) / dsq;
    const double fw[3] = {fd * e[0], fd * e[1], fd * e[2]};
    double fv[3][3];
    const int v[3] = {a, b, c};
    for (int m = 0; m < 3; m++)
      for (int d = 0; d < 3; d++) {
        fv[m][d] = -ft.l[m] * fw[d];
        f[v[m]][d] += fv[m][d];
      }
    for (int d = 0; d < 3; d++) f[w][d] += fw[d];
    if (EVFLAG) {
      // E = 4 eps [(sigma/d)^12 - (sigma/d)^6] + eps, zero at the reach
      const double energy = 4.0 * eps * s3 * (s3 - 1.0) + eps;
      if (eflag_global) eng_vdwl += energy;
      if (eflag_atom) eatom[w] += energy;
      if (vflag_either) {
        // virial about vertex c: sum over w, a, b of (x - x_c) F
        double dwc[3], dac[3], dbc[3];
        for (int d = 0; d < 3; d++) {
          dwc[d] = x[w][d] - x[c][d];
          dac[d] = x[a][d] - x[c][d];
          dbc[d] = x[b][d] - x[c][d];
        }
        double force[3] = {fw[0], fw[1], fw[2]};
        v_tally4(w, a, b, c, force, fv[0], fv[1], dwc, dac, dbc);
      }
    }
  }
}

/* ----------------------------------------------------------------------
   the walls have crossed if a wall atom is behind the face of its nearest triangle of another
   cell within reach (a wall atom outside a cell thinner than the reach may be behind a far face,
   but is nearer to the face in front of it), and a wall has passed through itself if a wall atom
   is behind the face of its nearest own triangle within reach that it is not a vertex of; the
   nearest over all ranks' pairs by reverse comm, only when some rank has an atom behind one
------------------------------------------------------------------------- */

void PairCellWall::check_crossing()
{
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  int mine = 0, any = 0;
  for (int i = 0; i < nall && !mine; i++)
    for (int s = 0; s < 2 * NEAR; s += NEAR)
      if (nearest[i][s] >= 0.0 && nearest[i][s + 1] > 0.0) mine = 1;
  MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, world);
  if (!any) return;
  comm_nearest = 1;
  CellCompat::reverse_comm(comm, this);
  comm_nearest = 0;
  for (int i = 0; i < nlocal; i++) {
    const double *near = nearest[i];
    const tagint cell = static_cast<tagint>(ubuf(near[2]).i);
    if (near[0] >= 0.0 && near[1] > 0.0)
      error->one(FLERR,
                 "Pair cell/wall: walls of cells {} and {} crossed on step {}: wall atom {} (cell "
                 "{}) is {:.4g} m behind the face of triangle {} {} {} (cell {}), its nearest "
                 "triangle of another cell",
                 atom->molecule[i], cell, update->ntimestep, atom->tag[i], atom->molecule[i],
                 sqrt(near[0]), static_cast<tagint>(ubuf(near[3]).i),
                 static_cast<tagint>(ubuf(near[4]).i), static_cast<tagint>(ubuf(near[5]).i), cell);
    const double *own = near + NEAR;
    if (own[0] >= 0.0 && own[1] > 0.0)
      error->one(FLERR,
                 "Pair cell/wall: the wall of cell {} passed through itself on step {}: wall atom "
                 "{} is {:.4g} m behind the face of triangle {} {} {} of its own wall, its nearest "
                 "own triangle that it is not a vertex of",
                 atom->molecule[i], update->ntimestep, atom->tag[i], sqrt(own[0]),
                 static_cast<tagint>(ubuf(own[3]).i), static_cast<tagint>(ubuf(own[4]).i),
                 static_cast<tagint>(ubuf(own[5]).i));
  }
}

template void PairCellWall::triangle_contacts<0>();
template void PairCellWall::triangle_contacts<1>();
