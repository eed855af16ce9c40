/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   CellWallTriangles: the wall triangles (angles a b c, outward) on this rank, each kept by its
   middle atom b as the local indices of a and c, found again on every reneighbouring: owned atoms
   from their angle arrays, ghosts from the tags their owners send by forward comm, each vertex the
   image closest to b (for a ghost b none beyond the edge allowance: that is another periodic
   image). The longest edge b-a, b-c until the next build is checked against the run's
   allowance (1.5 x the longest at the run's start), which sets the owner's neighbour range. Owned
   by pair cell/sph (wall boundary) and pair cell/wall (triangle contact); the owner routes its
   forward comm to pack()/unpack() (doc/pair_cell_sph.md, doc/pair_cell_wall.md).
------------------------------------------------------------------------- */

#ifndef LMP_CELL_WALL_TRIANGLES_H
#define LMP_CELL_WALL_TRIANGLES_H

#include "pointers.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class CellWallTriangles : protected Pointers {
 public:
  // the triangles one wall atom keeps (it is their middle angle atom), at most
  static constexpr int MAXTRI = 8;
  // doubles per atom of the forward comm: the count and the tags of a, c of each triangle
  static constexpr int COMM_SIZE = 1 + 2 * MAXTRI;

  // style: the owner's name in messages ("Pair cell/sph"); range: what the edge allowance sets
  CellWallTriangles(class LAMMPS *, const std::string &style, const std::string &range);
  ~CellWallTriangles() override;

  // per-atom arrays for atom->nmax atoms
  void grow(int nmax);
  // at a run's start: the allowance edgecap = 1.5 x the longest edge now + the skin
  void start_run();
  // on reneighbouring: the owned atoms' triangles, the longest edge (stops beyond the allowance)
  // and centroid-vertex distance; the owner then forward-communicates (pack/unpack) for the
  // ghosts'
  void build();
  // after build(), with the ghost cutoff of this build: stop unless it reaches the range within
  // which the owner needs the vertices of a triangle about an owned atom, term (named what) +
  // spokes x the longest centroid-vertex distance + skins x the skin
  void check_ghost_cutoff(const char *what, double term, int spokes, int skins) const;
  int pack(int n, const int *list, double *buf) const;
  void unpack(int n, int first, const double *buf);

  // triangles kept by atom b: t = first(b) .. first(b) + count(b) - 1, vertices a(t), b, c(t)
  // (local indices, -1 if not on this rank)
  int first(int b) const { return trifirst[b]; }
  int count(int b) const { return tricount[b]; }
  int a(int t) const { return trivert[2 * t]; }
  int c(int t) const { return trivert[2 * t + 1]; }
  // longest edge b-a, b-c of a kept triangle now + the skin (every end moves < skin/2 until the
  // next build), and the run's allowance for it
  double edge_max() const { return edgemax; }
  double edge_cap() const { return edgecap; }
  // longest edge b-a, b-c now over the owned atoms' angles whose other atoms this rank has (all
  // ranks; also fix cell/turgor's accel guard)
  static double longest_edge(class LAMMPS *lmp);
  double memory_usage() const;

 private:
  std::string style, range;
  int nmax;
  int *tricount, *trifirst;      // triangles kept by atom i: trivert[2 trifirst[i]] ...
  std::vector<int> trivert;      // a, c of each kept triangle (-1: not on this rank)
  std::vector<tagint> tritag;    // their tags
  double edgemax, edgecap;
  double spokemax;    // longest distance from a kept triangle's centroid to a vertex at the build
};

}    // namespace LAMMPS_NS

#endif
