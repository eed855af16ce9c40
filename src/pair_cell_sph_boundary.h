/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   the wall boundary of pair_style cell/sph (pair_coeff <fluid> <wall> wall), owned by PairCellSPH:
   each fluid atom's kernel is completed across its own cell's wall, the wall entering as the
   surface integral of its triangles; the wall term of the pressure force, the contact with the
   wall surface and the background pressure from outside, their reactions tallied as wall load
   (doc/pair_cell_sph.md, wall boundary)
------------------------------------------------------------------------- */

#ifndef LMP_PAIR_CELL_SPH_BOUNDARY_H
#define LMP_PAIR_CELL_SPH_BOUNDARY_H

#include "cell_kernel.h"
#include "pointers.h"

#include <array>
#include <vector>

namespace LAMMPS_NS {

class PairCellSPH;

class PairCellSPHBoundary : protected Pointers {
 public:
  PairCellSPHBoundary(class LAMMPS *, PairCellSPH *);
  ~PairCellSPHBoundary() override;

  // init_style: the checks, the longest support, the table of Phi, the triangles' edge allowance
  void init();
  void find_fields();
  // init_one of fluid-wall type pair i j: its constants; returns its neighbour range
  double init_pair(int, int);
  void allocate(int);     // per type pair constants for ntypes + 1
  void grow(int, int);    // per-atom arrays at atom->nmax (and those of per-atom h)
  void destroy();

  // compute(): at a step's start (the triangles at a neighbour build, the schedule of exact
  // evaluations), after a build the linearisation again from its base (rebase) and the contact
  // candidates, each density pass's base positions, the sums' start and the exact evaluation
  void start_step(bool grown);
  void rebase(int peratom);
  void search_contacts();
  void start_pass(int pass);
  void start_sums(int peratom);
  void exact_terms(int peratom);
  void after_density();
  void split_list(double);
  bool outgrown() const;
  void linear_deficit();
  // the wall term, the contacts and the background pressure, into f and the wall load
  void forces(int evflag);

  // the schedule of exact evaluations, kept over runs and in the pair's restart data
  struct Schedule {
    bigint refreshed;    // step of the last exact evaluation, -1: no base yet
    int every;           // steps from it to the next
    int pending;         // steps from the next to the one after
    double lastjump;     // largest jump of 1 - gamma at the last measurement
  };
  Schedule schedule() const { return {refreshed, every, pending, lastjump}; }
  void resume(const Schedule &);

  int pack_forward(int mode, int, int *, double *);
  void unpack_forward(int mode, int, int, double *);
  int pack_reverse(int mode, int, int, double *);
  void unpack_reverse(int mode, int, int *, double *);
  double memory_usage(int peratom);

  // read by the fluid pair
  static constexpr double GAMMA_MIN = 0.25;    // floor of the kernel fraction gamma inside the cell
  double *deficit;                             // 1 - gamma_i of fluid atom i
  double *dhdef;                               // per-atom h: d(1 - gamma_i)/dh_i
  double **wallload;    // force of the cell's own fluid on wall atom w through the boundary
  int refreshing;       // 1 if this step evaluates the kernel completion exactly at a new base
  int rebuilt;          // 1 on a neighbour build: contact candidates are searched
  int every;            // steps to the next exact evaluation
  double lastjump;      // largest jump of 1 - gamma (all ranks) at the last measurement
  std::vector<int> fluidfirst, fluidj;    // the list's fluid pairs: fluidj[fluidfirst[ii]]..

 private:
  PairCellSPH *sph;    // the owner: kernel, h, P/rho^2, tallies and comm

  // per fluid-wall type pair: (neighbour range)^2, the kernel's 1/h at the fluid's h, and the
  // contact with the wall surface: range delta and force F_c at the surface
  struct Contact {
    double cutsq, invh, reach, fcontact;
    int on;    // 1 for a type pair of the wall boundary
  };
  Contact **pairs;

  double wallsupport;    // the longest kernel support of a fluid type with a boundary in this run
  double phidq;          // q step of the table of Phi(q) = kernel fraction beyond q = r/h
  std::vector<double> phi, dphi;    // Phi and dPhi/dq at the table points
  // the wall triangles, each kept by its middle angle atom b (cell_wall_triangles.h); the
  // boundary pairs' cutoff is the kernel support + 2/3 of the run's edge allowance
  class CellWallTriangles *tris;
  struct Term {
    int f, v;          // fluid atom, wall vertex
    double grad[3];    // grad_v D_f: derivative of 1 - gamma_f in the vertex's position
  };
  std::vector<Term> terms;    // per fluid atom and vertex of the triangles in its kernel support
  std::vector<double> termlen;    // |x_v - x_f| of each term at the exact evaluation (scratch)
  double *deficit0;               // 1 - gamma at the last exact evaluation (partial sums per rank)
  double *dhdef0;                 // per-atom h: d(1 - gamma)/dh at the last exact evaluation
  double *hbase;                  // h at the last exact evaluation (fluid atoms; 1 on others)
  double **xbase;                 // positions of the last exact evaluation (base_positions)
  // the base of owned atoms, kept with each atom in fix FIELDS (property/atom: it migrates, is
  // sorted and goes into restart files): x (3 values) and h, as in xbase and hbase
  int ixfield, ihfield;
  double **gradsum;              // sum_v grad_v D_f of fluid atom f's terms (= -grad_f D_f)
  double **disp;                 // x - xbase; in base_positions() the step to the base
  double *jump;                  // change of 1 - gamma at an exact evaluation (partial per rank)
  double **xnear;                // positions when the near contact candidates were taken
  std::vector<int> termfirst;    // terms of fluid atom f: terms[termfirst[f]] .. [termfirst[f+1]-1]
  int *slot;                     // the term of vertex v of the fluid atom being evaluated, else -1
  int predicted;                 // 1 if the last exact evaluation's base is ahead of the atoms
  int measuring;                 // 1 if this exact evaluation measures the jump (next_interval)
  int rebasing;                  // 1 at a build with a base: the linearisation evaluated again
  int reached;                   // 1 if an owned atom is beyond reach of its base (beyond_reach)
  int pending;                   // steps from the next exact evaluation to the one after
  bigint refreshed;              // step of the last exact evaluation
  std::vector<std::array<int, 4>> touching;    // fluid atom and triangle that may be in contact
  std::vector<std::array<int, 4>> near;        // those of them near contact (forces)
  std::vector<std::array<int, 2>> boundarypairs;    // the list's fluid-wall pairs, same cell, by f
  std::vector<double> hsplit;                       // per-atom h at the last split_list()
  int nmax;                                         // length of the per-atom arrays

  template <int PERATOM> void boundary_terms(int, int, const Contact &);
  void base_positions(int);
  void store_base();
  void restore_base();
  bool beyond_reach();
  void keep_base();
  void next_interval();
  template <int EVFLAG> void wall_forces();
  template <int EVFLAG> void outside_pressure();
  template <int EVFLAG> bool contact(int, int, int, int, double);
  bool moved_since_near(double) const;
  void tabulate_phi();
  void phi_beyond(double q, double &value, double &slope) const;
};

}    // namespace LAMMPS_NS

#endif
