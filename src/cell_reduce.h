/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   A style's view of the per-cell sums of fluid and wall (doc/model.md §5.2): fix cell/turgor,
   compute cell/props and compute cell/shape each hold one. The sums and the cells' registry belong
   to the cell set (cell_set.h), one per group and wall type, shared by every view over the same
   cells and summed once per step; a view keeps its style's settings (turgor measure, surface group)
   and names its style in messages. A cell is a molecule ID > 0; its fluid and wall atoms are told
   apart by type. Each reduce() sums over owned atoms and wall triangles of the cells this rank
   touches and totals each cell on its home rank, so cells may straddle ranks and periodic
   boundaries; the totals (get(), mass(), ...) are there only, for the home cells.
------------------------------------------------------------------------- */

#ifndef LMP_CELL_REDUCE_H
#define LMP_CELL_REDUCE_H

#include "cell_registry.h"
#include "cell_set.h"
#include "pointers.h"

#include <memory>
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
  // no fluid and init() needs neither masses, SPH fields nor a wall load. Joins the cell set of
  // the group and wall type (CellSet::join)
  CellReduce(class LAMMPS *, const std::string &command, int igroup, int fluidtype, int walltype,
             bool fluid_sums = true);

  // the group whose wall triangles (all three corners in it) reduce() sums as SURFAREA2
  void set_surface(int surface_groupbit);
  void find_cells() { set->find_cells(command); }
  void init();
  // the sums of this step (CellSet::reduce): bond_gt0[type] = G t0 per bond type for the bond
  // sums, or nullptr; triangles: keep the counted wall triangles (triangles(), home_triangles())
  void reduce(const double *bond_gt0 = nullptr, bool triangles = false)
  {
    set->reduce(command, bond_gt0, triangles);
  }
  // the wall triangles of reduce(), 10 numbers each (cell index, then the corners a, b, c relative
  // to the cell's reference point, unwrapped as for the volume), and their corner atom IDs
  const std::vector<double> &triangles() const { return set->triangles(); }
  const std::vector<tagint> &corners() const { return set->corners(); }
  // those at the home rank of their cell (CellSet::home_triangles). Collective
  const CellTriangles &home_triangles() { return set->home_triangles(command); }
  // wall triangles held for an evaluation (those of reduce() plus those at home): the most on one
  // rank, the sum over ranks, and the wall triangles counted once. Collective
  void held_triangles(double held[3]) { set->held_triangles(command, held); }

  // the cells, their home ranks, the exchange of per-cell values
  CellRegistry &registry() { return set->registry(); }
  const CellRegistry &registry() const { return set->registry(); }
  int ncell() const { return registry().ncell(); }
  tagint id(int c) const { return registry().id(c); }
  // this rank's home cells, ascending: get() and the values below are defined for these
  const std::vector<int> &home_cells() const { return registry().home_cells(); }
  double get(int c, Column k) const
  {
    return set->totals()[(size_t) registry().home_slot(c) * NCOLUMN + k];
  }
  // cell index of each owned atom at the last reduce(), -1 if it belongs to no cell of the group
  const std::vector<int> &cell_of_atom() const { return registry().cell_of_atom(); }
  // reference point of cell c (unwrapped), the origin of the triangles of reduce()
  const double *reference(int c) const { return registry().reference(c); }

  double mass(int c) const { return get(c, MASS); }
  double volume(int c) const { return get(c, VOLUME6) / 6.0; }
  double area(int c) const { return 0.5 * get(c, AREA2); }
  double ref_area(int c) const { return 0.5 * get(c, REFAREA2); }
  double surface_area(int c) const { return 0.5 * get(c, SURFAREA2); }
  double fluid_volume(int c) const { return get(c, FLUIDVOL); }
  double turgor(int c) const { return measure == TURGOR_WALL ? wall_turgor(c) : sph_turgor(c); }
  double sph_turgor(int c) const;
  double wall_turgor(int c) const;
  bool has_wall_load() const { return set->has_wall_load(); }
  // the particle wall-fluid model (pair cell/wall): P_T from the wall load (after init())
  bool wall_measure() const { return measure == TURGOR_WALL; }
  double mean_gt0(int c) const;
  void gyration(int c, double s[6]) const;

 private:
  std::string command;
  int igroup, fluidtype, walltype;
  int measure;
  std::shared_ptr<CellSet> set;
};

}    // namespace LAMMPS_NS

#endif
