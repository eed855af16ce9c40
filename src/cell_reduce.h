/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   The per-cell sums of fluid and wall (doc/model.md §5.2), shared by fix cell/turgor and compute
   cell/props, on a CellRegistry (cell_registry.h). A cell is a molecule ID > 0; its fluid and wall
   atoms are told apart by type. Each reduce() sums over owned atoms and wall triangles of the
   cells this rank touches and totals each cell on its home rank, so cells may straddle ranks and
   periodic boundaries; the totals (get(), mass(), ...) are there only, for the home cells.
------------------------------------------------------------------------- */

#ifndef LMP_CELL_REDUCE_H
#define LMP_CELL_REDUCE_H

#include "cell_registry.h"
#include "pointers.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class CellReduce : protected Pointers {
 public:
  // per-cell sums; wall positions are relative to the cell's reference point
  enum Column {
    MASS,           // fluid mass sum m
    FLUIDVOL,       // fluid volume sum m/rho
    PRESSUREVOL,    // sum P m/rho
    NFLUID,         // fluid atoms
    BADRHO,         // fluid atoms without a positive density
    VOLUME6,        // 6 V: sum over wall triangles of a . (b x c)
    AREA2,          // 2 A: sum of |(b - a) x (c - a)|
    REFAREA2,       // 2 A of the triangles at the reference positions xref (0 without xref)
    NTRI,           // wall triangles
    NWALL,          // wall atoms
    WX,             // sum of wall positions x, y, z
    WY,
    WZ,
    WXX,    // sum of wall position products xx, yy, zz, xy, xz, yz
    WYY,
    WZZ,
    WXY,
    WXZ,
    WYZ,
    GT0,        // sum of G t0 over the wall bonds inside the cell (only with bond weights)
    NBOND,      // those bonds
    LOADVIR,    // sum of (x - ref) . F over wall atoms, F = force on them from the cell's fluid
    LOADX,      // sum of F, x y z
    LOADY,
    LOADZ,
    SURFAREA2,    // 2 A of the wall triangles whose three corners are in the surface group
    NCOLUMN
  };

  // how the cell's turgor P_T (the load of the fluid on the wall) is measured: set by init() from
  // the wall-fluid model in use
  enum Turgor {
    TURGOR_WALL,    // the wall load itself: pair cell/wall's particle model (the seed's)
    TURGOR_SPH      // the volume-weighted mean SPH pressure: the SPH wall boundary, or no load
  };

  // fluid_sums false: wall geometry only (compute cell/shape): fluidtype is not used, reduce() sums
  // no fluid and init() needs neither masses, SPH fields nor a wall load
  CellReduce(class LAMMPS *, const std::string &command, int igroup, int fluidtype, int walltype,
             bool fluid_sums = true);

  // the group whose wall triangles (all three corners in it) reduce() sums as SURFAREA2
  void set_surface(int surface_groupbit) { surfacebit = surface_groupbit; }
  void find_cells() { cells.find_cells(); }
  void init();
  // triangles, if given, receives each counted wall triangle as 10 numbers: cell index, then the
  // corners a, b, c relative to the cell's reference point, unwrapped as for the volume; corners,
  // if given, their atom IDs (3 per triangle)
  void reduce(const double *bond_gt0 = nullptr, std::vector<double> *triangles = nullptr,
              std::vector<tagint> *corners = nullptr);
  // the triangles and corner IDs of reduce() from every rank to the home rank of their cell: home
  // holds those of this rank's home cells only, each cell's in the order of their corner IDs
  // (middle, first, last), the same on any number of ranks. Collective, O(triangles sent)
  void home_triangles(const std::vector<double> &mine, const std::vector<tagint> &mycorners,
                      class CellTriangles &home) const;
  // wall triangles held for an evaluation (those of reduce() plus those at home): the most on one
  // rank, the sum over ranks, and the wall triangles counted once. Collective (two MPI_Allreduce)
  void held_triangles(const std::vector<double> &mine, const class CellTriangles &home,
                      double held[3]) const;

  // the cells, their home ranks, the exchange of per-cell values
  CellRegistry &registry() { return cells; }
  const CellRegistry &registry() const { return cells; }
  int ncell() const { return cells.ncell(); }
  tagint id(int c) const { return cells.id(c); }
  // this rank's home cells, ascending: get() and the values below are defined for these
  const std::vector<int> &home_cells() const { return cells.home_cells(); }
  double get(int c, Column k) const { return total[(size_t) cells.home_slot(c) * NCOLUMN + k]; }
  // cell index of each owned atom at the last reduce(), -1 if it belongs to no cell of the group
  const std::vector<int> &cell_of_atom() const { return cells.cell_of_atom(); }
  // reference point of cell c (unwrapped), the origin of the triangles of reduce()
  const double *reference(int c) const { return cells.reference(c); }

  double mass(int c) const { return get(c, MASS); }
  double volume(int c) const { return get(c, VOLUME6) / 6.0; }
  double area(int c) const { return 0.5 * get(c, AREA2); }
  double ref_area(int c) const { return 0.5 * get(c, REFAREA2); }
  double surface_area(int c) const { return 0.5 * get(c, SURFAREA2); }
  double fluid_volume(int c) const { return get(c, FLUIDVOL); }
  double turgor(int c) const { return measure == TURGOR_WALL ? wall_turgor(c) : sph_turgor(c); }
  double sph_turgor(int c) const;
  double wall_turgor(int c) const;
  bool has_wall_load() const { return !loads.empty(); }
  // the particle wall-fluid model (pair cell/wall): P_T from the wall load (after init())
  bool wall_measure() const { return measure == TURGOR_WALL; }
  double mean_gt0(int c) const;
  void gyration(int c, double s[6]) const;

 private:
  std::string command, group_name;
  int fluidtype, walltype, surfacebit;
  int irho, ipressure, ixref;
  int measure;
  bool geometry_only;
  std::vector<class CellWallLoad *> loads;    // the pair styles that tally the wall load
  std::vector<double **> loadnow;             // their loads at this reduce()
  CellRegistry cells;
  std::vector<double> local, total;    // sums per touched cell, totals per home cell

  void init_fluid();
  bool particle_wall_model() const;
  void add_fluid(int i, double *s);
  void add_wall(int i, int c, double *s, double b[3]);
  void add_triangles(int i, int c, const double *b, double *s, std::vector<double> *triangles,
                     std::vector<tagint> *corners);
  void add_bonds(int i, const double *bond_gt0, double *s);
  void check_cells();
  int custom_vector(const char *name) const;
};

// the wall triangles of this rank's home cells (CellReduce::home_triangles): home cell h (slot in
// home_cells()) has ntri(h) triangles, 9 coordinates each (corners a b c relative to the cell's
// reference point, outward) from xyz(h), and their 3 corner atom IDs each from ids(h)
class CellTriangles {
 public:
  int ntri(int h) const { return first[h + 1] - first[h]; }
  const double *xyz(int h) const { return &coords[9 * (size_t) first[h]]; }
  const tagint *ids(int h) const { return &tags[3 * (size_t) first[h]]; }
  int size() const { return (int) tags.size() / 3; }

 private:
  friend class CellReduce;
  std::vector<double> coords;
  std::vector<tagint> tags;
  std::vector<int> first;
};

}    // namespace LAMMPS_NS

#endif
