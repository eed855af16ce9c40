/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   pair_style cell/wall: wall-fluid repulsion F^rw/F^rf, wall-fluid adhesion F^a and non-bonded
   wall-wall contact (doc/model.md §3.6, 3.7, 4.4)
------------------------------------------------------------------------- */

#ifndef LMP_PAIR_CELL_WALL_H
#define LMP_PAIR_CELL_WALL_H

#include "cell_styles.h"
#include "pair.h"

#include <array>
#include <string>
#include <vector>

namespace LAMMPS_NS {

class PairCellWall : public Pair, public CellWallLoad {
 public:
  PairCellWall(class LAMMPS *);
  ~PairCellWall() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  void write_data(FILE *) override;
  void write_data_all(FILE *) override;
  double single(int, int, int, int, double, double, double, double &) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;

  // per-atom force on the wall atoms from the fluid atoms of the same cell (molecule), tallied on
  // every force evaluation after a request; the request lasts until the next init
  bool request_wall_load(int fluidtype, int walltype, const std::string &who) override;
  double **wall_load() const override { return load; }

  enum Term {
    REPULSION = 1 << 0,
    ADHESION = 1 << 1,
    CONTACT = 1 << 2,
    TRIANGLES = 1 << 3,
    SELFTRIANGLES = 1 << 4
  };

  // the terms of one type pair: parameters as given, then constants precomputed in init_one()
  struct Coeff {
    int terms;                  // bitmask of Term
    double f0, r0, p1, p2;      // repulsion
    double D, alpha, ra, rc;    // adhesion
    double eps, sigma;          // contact
    double teps, tsigma;        // triangles: contact with the other walls' triangles
    double seps, ssigma;        // selftriangles: contact with the own wall's far triangles
    int half1, half2;           // p1/2, p2/2 when they are integers (powint), else 0
    double r0sq, rasq, rcsq, two_alpha_d, u_rc, u_below_ra, sigsq, contactsq;
    double tsigsq, treach;    // triangles: sigma^2, reach 2^(1/6) sigma
    double ssigsq, sreach;    // selftriangles: sigma^2, reach 2^(1/6) sigma
    double paircutsq;         // (reach of the pair terms)^2: repulsion, adhesion, contact
  };

 protected:
  double cut_global;
  Coeff **coeffs;
  int restart_version;          // format version of the restart file being read
  int load_fluid, load_wall;    // atom types of a wall-load request, 0 = none
  int nmax_load;
  double **load;
  // the list's pairs within their cutoff + margin, from each neighbour build (near_pairs)
  std::vector<int> nearfirst, nearj;
  int repulsion;    // 1 if any type pair has the wall-fluid repulsion
  // at a run's setup: no fluid atom deep inside the repulsion of a wall atom of its own cell
  void check_start_gap();

  // triangles: a wall atom against the triangles of other cells' walls, selftriangles: against
  // its own wall's triangles it is not a vertex of (doc/pair_cell_wall.md;
  // pair_cell_wall_triangles.cpp)
  int triangles;                    // 1 if any type pair has either term
  double trireach;                  // the longest reach of either term in this run
  class CellWallTriangles *tris;    // the triangles, kept by their middle angle atoms
  // (wall atom, a, b, c) within the reach + margin at the last neighbour build
  std::vector<std::array<int, 4>> touching;
  // per atom, its nearest triangle of another cell within reach this step: d^2, 1 if the atom is
  // behind its face (else 0), the triangle's cell and the tags of a, b, c (NEAR columns); then
  // the same for its nearest own triangle that it is not a vertex of (NEAR more)
  // columns of the nearest triangle per atom (triangles): d^2, behind, cell, tags of a, b, c; the
  // nearest of another cell's, then (from column NEAR) of the own wall's
  static constexpr int NEAR = 6;
  int nmax_near;
  double **nearest;
  int comm_nearest;    // 1 while reverse comm carries nearest (else the wall load)
  void find_touching(double);
  void touch_kept(int w, int b, double reach, bool self);
  template <int EVFLAG> void triangle_contacts();
  void check_crossing();

  void allocate();
  void near_pairs(double);
  template <int LOAD> void eval(int eflag);
  double evaluate(const Coeff &, double, int, double &) const;
  std::string describe(const Coeff &) const;
  void read_file(Coeff &, const char *, const char *);
  void check(const Coeff &, const std::string &);
};

}    // namespace LAMMPS_NS

#endif
