/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   CellWallTriangles: the wall triangles kept by their middle angle atoms (cell_wall_triangles.h)
------------------------------------------------------------------------- */

#include "cell_wall_triangles.h"

#include "atom.h"
#include "cell_compat.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "memory.h"
#include "neighbor.h"
#include "update.h"

#include <algorithm>
#include <cmath>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

CellWallTriangles::CellWallTriangles(LAMMPS *lmp, const std::string &style,
                                     const std::string &range) :
    Pointers(lmp),
    style(style), range(range), nmax(0), tricount(nullptr), trifirst(nullptr), edgemax(0.0),
    edgecap(0.0), spokemax(0.0)
{
}

/* ---------------------------------------------------------------------- */

CellWallTriangles::~CellWallTriangles()
{
  memory->destroy(tricount);
  memory->destroy(trifirst);
}

/* ---------------------------------------------------------------------- */

void CellWallTriangles::grow(int n)
{
  if (n <= nmax) return;
  nmax = n;
  memory->destroy(tricount);
  memory->destroy(trifirst);
  memory->create(tricount, nmax, "cell/wall/triangles:tricount");
  memory->create(trifirst, nmax, "cell/wall/triangles:trifirst");
}

/* ---------------------------------------------------------------------- */

void CellWallTriangles::start_run()
{
  edgecap = 1.5 * longest_edge(lmp) + neighbor->skin;
}

/* ----------------------------------------------------------------------
   longest edge b-a, b-c of the wall triangles now, over the angles of owned atoms whose other
   atoms this rank has (all at the start; enough to measure the wall), over all ranks; 0 without
   any
------------------------------------------------------------------------- */

double CellWallTriangles::longest_edge(LAMMPS *lmp)
{
  Atom *atom = lmp->atom;
  double **x = atom->x;
  double edge = 0.0, all = 0.0;
  // 0 where the atom style has no angles
  for (int i = 0; atom->num_angle && i < atom->nlocal; i++)
    for (int m = 0; m < atom->num_angle[i]; m++)
      for (tagint tag : {atom->angle_atom1[i][m], atom->angle_atom3[i][m]}) {
        const int k = atom->map(tag);
        if (k < 0 || atom->angle_atom2[i][m] != atom->tag[i]) continue;
        double del[3] = {x[k][0] - x[i][0], x[k][1] - x[i][1], x[k][2] - x[i][2]};
        lmp->domain->minimum_image(del);
        edge = std::max(edge, del[0] * del[0] + del[1] * del[1] + del[2] * del[2]);
      }
  MPI_Allreduce(&edge, &all, 1, MPI_DOUBLE, MPI_MAX, lmp->world);
  return sqrt(all);
}

/* ----------------------------------------------------------------------
   the triangles each owned wall atom keeps (it is the middle atom b of the angle a b c), as local
   indices of a and c, each the image closest to b; ghosts get theirs in unpack()
------------------------------------------------------------------------- */

void CellWallTriangles::build()
{
  double **x = atom->x;
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  double edge = 0.0, spoke = 0.0;
  tagint edgetag[2] = {0, 0};
  trivert.clear();
  tritag.clear();
  for (int i = 0; i < nlocal; i++) {
    tricount[i] = 0;
    trifirst[i] = static_cast<int>(trivert.size()) / 2;
    for (int m = 0; m < atom->num_angle[i]; m++) {
      if (atom->angle_atom2[i][m] != atom->tag[i]) continue;
      if (tricount[i] == MAXTRI)
        error->one(FLERR,
                   "{}: wall atom {} is the middle atom of more than {} wall triangles (angles), "
                   "the most one wall atom may keep",
                   style, atom->tag[i], MAXTRI);
      for (tagint tag : {atom->angle_atom1[i][m], atom->angle_atom3[i][m]}) {
        const int k = atom->map(tag);
        const int v = k < 0 ? -1 : domain->closest_image(i, k);
        if (v >= 0) {
          const double del[3] = {x[v][0] - x[i][0], x[v][1] - x[i][1], x[v][2] - x[i][2]};
          const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
          if (rsq > edge) {
            edge = rsq;
            edgetag[0] = atom->tag[i];
            edgetag[1] = tag;
          }
        }
        trivert.push_back(v);
        tritag.push_back(tag);
      }
      const int a = trivert[trivert.size() - 2], c = trivert.back();
      if (a >= 0 && c >= 0)
        for (int v : {a, i, c}) {
          // centroid g = (x_a + x_b + x_c) / 3 to vertex v (doc/pair_cell_sph.md, Restrictions)
          double del[3];
          for (int d = 0; d < 3; d++) del[d] = x[v][d] - (x[a][d] + x[i][d] + x[c][d]) / 3.0;
          spoke = std::max(spoke, del[0] * del[0] + del[1] * del[1] + del[2] * del[2]);
        }
      tricount[i]++;
    }
  }
  // longest edge b-a, b-c until the next reneighbouring: now + the skin (each end moves < skin/2)
  const double mine[2] = {sqrt(edge), sqrt(spoke)};
  double all[2];
  MPI_Allreduce(mine, all, 2, MPI_DOUBLE, MPI_MAX, world);
  edgemax = all[0] + neighbor->skin;
  spokemax = all[1];
  if (edgemax > edgecap) {
    // name the edge: the atoms of the rank with the longest one (the lowest such rank)
    int me, owner;
    MPI_Comm_rank(world, &me);
    const int holder = (mine[0] == all[0]) ? me : comm->nprocs;
    MPI_Allreduce(&holder, &owner, 1, MPI_INT, MPI_MIN, world);
    MPI_Bcast(edgetag, 2, MPI_LMP_TAGINT, owner, world);
    error->all(FLERR,
               "{}: the wall edge of atoms {} and {} grew to {:.4g} m on step {}, beyond the "
               "{:.4g} m {} allows in this run (1.5 x the longest edge at the run's start): "
               "split the run (each run command measures the wall again)",
               style, edgetag[0], edgetag[1], edgemax - neighbor->skin, update->ntimestep,
               edgecap - neighbor->skin, range);
  }
  for (int i = nlocal; i < nall; i++) tricount[i] = 0;
}

/* ----------------------------------------------------------------------
   a rank has the atoms within the ghost cutoff of its subdomain at the build, so every vertex
   within that cutoff of an owned atom (none on one rank in a box without periodic dimensions);
   the owner's range from the owned atom is term + spokes x spoke + skins x skin
   (doc/pair_cell_sph.md and doc/pair_cell_wall.md, Restrictions)
------------------------------------------------------------------------- */

void CellWallTriangles::check_ghost_cutoff(const char *what, double term, int spokes,
                                           int skins) const
{
  if (comm->nprocs == 1 && !domain->xperiodic && !domain->yperiodic && !domain->zperiodic) return;
  const double cut = CellCompat::ghost_cutoff(comm, neighbor);
  const double skin = neighbor->skin;
  const double range = term + spokes * spokemax + skins * skin;
  if (cut < range)
    error->all(FLERR,
               "{}: the ghost cutoff {:.4g} m is shorter than the {:.4g} m from an owned atom "
               "within which the wall triangles' vertices must be on its rank on step {} ({} "
               "{:.4g} m + {} x the longest centroid-vertex distance {:.4g} m + {} x the skin "
               "{:.4g} m): use 'comm_modify cutoff {:.3g}' or longer",
               style, cut, range, update->ntimestep, what, term, spokes, spokemax, skins, skin,
               1.01 * range);
}

/* ---------------------------------------------------------------------- */

int CellWallTriangles::pack(int n, const int *list, double *buf) const
{
  int m = 0;
  for (int k = 0; k < n; k++) {
    const int i = list[k];
    buf[m++] = tricount[i];
    for (int v = 2 * trifirst[i]; v < 2 * (trifirst[i] + tricount[i]); v++)
      buf[m++] = ubuf(tritag[v]).d;
  }
  return m;
}

/* ---------------------------------------------------------------------- */

void CellWallTriangles::unpack(int n, int first, const double *buf)
{
  double **x = atom->x;
  const double capsq = edgecap * edgecap;
  int m = 0;
  for (int i = first; i < first + n; i++) {
    tricount[i] = static_cast<int>(buf[m++]);
    trifirst[i] = static_cast<int>(trivert.size()) / 2;
    for (int v = 0; v < 2 * tricount[i]; v++) {
      const tagint tag = static_cast<tagint>(ubuf(buf[m++]).i);
      const int k = atom->map(tag);
      int w = k < 0 ? -1 : domain->closest_image(i, k);
      // the closest image this rank has may be another periodic image than the vertex's (which
      // lies beyond the ghost cutoff): farther than the run's edge allowance, it is not the
      // vertex; the triangle is then not on this rank (doc/pair_cell_sph.md, Cost control)
      if (w >= 0) {
        const double del[3] = {x[w][0] - x[i][0], x[w][1] - x[i][1], x[w][2] - x[i][2]};
        if (del[0] * del[0] + del[1] * del[1] + del[2] * del[2] > capsq) w = -1;
      }
      trivert.push_back(w);
      tritag.push_back(tag);
    }
  }
}

/* ---------------------------------------------------------------------- */

double CellWallTriangles::memory_usage() const
{
  return 2.0 * nmax * sizeof(int) + trivert.capacity() * sizeof(int) +
      tritag.capacity() * sizeof(tagint);
}
