/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   The one owner of a cell set's per-step state: the cells of a group with walls of one atom type,
   their registry (cell_registry.h) and their per-cell sums (doc/model.md §5.2). Every style over
   those cells (fix cell/turgor, compute cell/props, compute cell/shape) holds it through its view,
   CellReduce (cell_reduce.h); the first style made makes the set and the others find it with
   CellSet::join by group, wall type, fluid type and surface group. reduce() sums once per step:
   called again at the same step, box and neighbour-list build, asking for nothing the last sums
   left out (the wall triangles, the bond sums), it keeps them: the computes at an output step
   share one reduction, with the fix too when it sums at that step.
------------------------------------------------------------------------- */

#ifndef LMP_CELL_SET_H
#define LMP_CELL_SET_H

#include "cell_registry.h"
#include "pointers.h"

#include <memory>
#include <string>
#include <vector>

namespace LAMMPS_NS {

// the wall triangles of this rank's home cells (CellSet::home_triangles): home cell h (slot in
// home_cells()) has ntri(h) triangles, 9 coordinates each (corners a b c relative to the cell's
// reference point, outward) from xyz(h), and their 3 corner atom IDs each from ids(h)
class CellTriangles {
 public:
  int ntri(int h) const { return first[h + 1] - first[h]; }
  const double *xyz(int h) const { return &coords[9 * (size_t) first[h]]; }
  const tagint *ids(int h) const { return &tags[3 * (size_t) first[h]]; }
  int size() const { return (int) tags.size() / 3; }

 private:
  friend class CellSet;
  std::vector<double> coords;
  std::vector<tagint> tags;
  std::vector<int> first;
};

class CellSet : protected Pointers {
 public:
  // the set of the cells of group igroup with walls of type walltype, made if no style holds a
  // set it can share: fluidtype 0 (wall geometry only) shares a set of any fluid type,
  // surfacebit 0 (no surface group) one of any surface group
  static std::shared_ptr<CellSet> join(class LAMMPS *, int igroup, int walltype, int fluidtype,
                                       int surfacebit);
  CellSet(class LAMMPS *, int igroup, int walltype, int fluidtype, int surfacebit);

  // the registry's cells (collective); who names the asking style in messages
  void find_cells(const std::string &who);
  // per-atom fields, wall loads, reference points and home ranks (collective, once per run)
  void init(const std::string &who);
  // the sums of this step (collective): bond_gt0[type] = G t0 of each bond type or nullptr;
  // triangles: keep the counted wall triangles (triangles(), corners(), home_triangles())
  void reduce(const std::string &who, const double *bond_gt0, bool triangles);
  // ncol sums per home cell, in the order of home_cells() (CellReduce::Column)
  const std::vector<double> &totals() const { return total; }
  // the wall triangles of the last reduce() that kept them, 10 numbers each: cell index, then
  // corners a, b, c relative to the cell's reference point; their corner atom IDs, 3 each
  const std::vector<double> &triangles() const { return tri; }
  const std::vector<tagint> &corners() const { return tricorners; }
  // those triangles on the home rank of their cell, each cell's in the order of their corner IDs
  // (middle, first, last), the same on any number of ranks. Collective once per reduction
  const CellTriangles &home_triangles(const std::string &who);
  // wall triangles held at the last reduction: the most on one rank, the sum over ranks, each
  // counted once. Collective (two MPI_Allreduce)
  void held_triangles(const std::string &who, double held[3]);

  CellRegistry &registry() { return cells; }
  const CellRegistry &registry() const { return cells; }
  bool has_wall_load() const { return !loads.empty(); }
  // true if the fluid is held by pair cell/wall's wall-fluid terms alone (the seed's particle
  // model): P_T is then the wall load (after init())
  bool particle_wall_model() const;
  bool fluid_sums() const { return fluidtype > 0; }

 private:
  int igroup, groupbit, walltype, fluidtype, surfacebit;
  std::string group_name;
  int irho, ipressure, ixref;
  std::vector<class CellWallLoad *> loads;    // the pair styles that tally the wall load
  std::vector<double **> loadnow;             // their loads at this reduce()
  CellRegistry cells;
  std::vector<double> local, total;    // sums per touched cell, totals per home cell
  std::vector<double> tri;             // the wall triangles of the last reduce() (see triangles())
  std::vector<tagint> tricorners;
  CellTriangles home;    // and at home (home_triangles), valid if home_ready
  bool home_ready = false;
  // the last reduction: its step, box and neighbour-list build, what it took; valid = false
  // until the first one after find_cells() or init()
  struct Taken {
    bool valid = false;
    bigint step = -1, builds = -1;
    double box[9] = {};
    bool triangles = false;
    const double *gt0 = nullptr;    // the G t0 per bond type of the bond sums, nullptr: none
  } taken;

  bool compatible(int group, int wall, int fluid, int surface) const;
  bool current() const;
  void box(double b[9]) const;
  void init_fluid(const std::string &who);
  int custom_vector(const char *name, const std::string &who) const;
  void add_fluid(int i, double *s);
  void add_wall(int i, int c, double *s, double b[3]);
  void add_triangles(int i, int c, const double *b, double *s, bool keep, const std::string &who);
  void add_bonds(int i, const double *bond_gt0, double *s);
  void check_cells(const std::string &who);
};

}    // namespace LAMMPS_NS

#endif
