/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   pair_style cell/sph: the cell fluid, summation density with per-atom mass, pressure force F^p
   and Morris viscous force F^v (doc/model.md §3.1-3.5)
------------------------------------------------------------------------- */

#ifndef LMP_PAIR_CELL_SPH_H
#define LMP_PAIR_CELL_SPH_H

#include "cell_kernel.h"
#include "cell_quantity.h"
#include "pair.h"

#include <array>
#include <string>
#include <vector>

namespace LAMMPS_NS {

class PairCellSPH : public Pair {
 public:
  PairCellSPH(class LAMMPS *);
  ~PairCellSPH() override;
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
  void *extract(const char *, int &) override;
  // the wall boundary's force of each cell's fluid on its wall atoms (owned atoms), or nullptr
  double **wall_load() const { return walls ? wallload : nullptr; }
  bool has_wall_boundary() const;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;

  // smoothing length: the pair_coeff value or eta (m/rho)^(1/3) per atom (1, h mass, was removed)
  enum HMode { HFIXED = 0, HADAPTIVE = 2 };

 protected:
  int kernel;
  double cut_global;    // neighbour cutoff from pair_style; 0 = the kernel support
  int hmode;            // HFIXED or HADAPTIVE (pair_style keyword h)
  double eta;           // h = eta (m/rho)^(1/3) per atom
  double hdrift;        // h adaptive: largest relative change of h since the last density pass

  double **rho0, **bulk, **mu, **h;    // pair_coeff values per type pair

  // pair_style keyword temp T: every mu scaled by mu_w(T)/mu_w(25 C) of liquid water
  // (doc/model.md §5.9); T a number or an equal-style variable evaluated once per step
  int temp_set;          // 1 if pair_style has 'temp'
  CellQuantity temp;     // T (K): a number or an equal-style variable
  double muscale;        // mu_w(T)/mu_w(25 C) applied to pc[][].mu2, 1 without temp
  double temperature;    // the T of the last evaluation (K)
  void update_viscosity();

  // background pressure (pair_style keyword background P_b): the fluid's forces use P_b + P, and
  // every wall triangle of a cell with the wall boundary carries P_b from outside, so the wall
  // feels P alone (doc/pair_cell_sph.md, background pressure)
  CellQuantity background_in;    // P_b (Pa): a number or an equal-style variable
  double background;             // P_b of this step (Pa), 0 = off
  // auto: P_b has no value yet (0), one from a setup with no step since, or one steps advanced
  enum { BACKGROUND_NONE, BACKGROUND_SETUP, BACKGROUND_STEPPED };
  int background_set;
  int background_auto;      // background auto P_min: P_b relaxes to P_min - the fluid's mean P
  double background_min;    // P_min (Pa)
  int parse_background(int, char **);
  void update_background();
  template <int EVFLAG> void outside_pressure();

  struct PairConst {
    double cutsq;               // (kernel support)^2; 0 if the pair is not computed
    CellKernel::Scale scale;    // kernel constants at this pair's h (the fluid's for a boundary)
    double mu2;                 // mu_i + mu_j
    int boundary;               // 1: fluid-wall pair of the wall boundary, no SPH sums
    double reach;               // boundary: range delta of the contact with the wall surface
    double fcontact;            // boundary: contact force F_c at the surface
  };
  PairConst **pc;    // per type pair, from init_one()

  double *wself;          // W(0) at the h of pair_coeff I I: self term of the density, per type
  double *invrho0;        // 1 / rho0 per type (equation of state of pair_coeff I I)
  int *fluid;             // 1 if the type takes part in cell/sph
  int viscous;            // 1 if any computed pair has mu > 0
  double shared[2];       // rho0 and K shared by all fluid types, for extract()
  int irho, ipressure;    // custom per-atom vectors rho and pressure
  // per-atom h (h adaptive): custom vectors h and omega (Omega = 1 + h/(3 rho) drho/dh),
  // the kernel constants 1/h, sigma/h^d, sigma/h^(d+2) of each atom, dS/dh of S = sum m W
  int ih, iomega;
  double *hcap;                // largest h the neighbour cutoff allows, per fluid type
  double **hscale;             // 1/h_i, sigma/h_i^d, sigma/h_i^(d+2), (pair range)^2 of every atom
  double *dsum;                // d(sum_j m_j W(r_ij, h_i))/dh_i
  double *dhdef;               // wall boundary: d(1 - gamma_i)/dh_i
  double *dhdef0;              // the same at the last exact evaluation (partial sums per rank)
  double *hbase;               // h at the last exact evaluation
  std::vector<double> step;    // Newton step of h of the list's atoms

  // wall boundary (pair_coeff I J wall): each fluid atom's kernel is completed across its own
  // cell's wall; the wall enters as the surface integral of its triangles (doc/pair_cell_sph.md)
  int **boundary;        // 1 for a fluid-wall type pair of the wall boundary
  int walls;             // 1 if any type pair is a boundary pair
  double wallsupport;    // the longest kernel support of a fluid type with a boundary in this run
  double gamma_min;      // floor of the kernel fraction gamma inside the cell
  double phidq;          // q step of the table of Phi(q) = kernel fraction beyond q = r/h
  std::vector<double> phi, dphi;    // Phi and dPhi/dq at the table points
  double *deficit;                  // 1 - gamma_i of fluid atom i
  double **wallload;    // force of the cell's own fluid on wall atom w through the boundary
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
  double **xbase;                 // positions of the last exact evaluation (base_positions)
  double **gradsum;               // sum_v grad_v D_f of fluid atom f's terms (= -grad_f D_f)
  double **disp;                  // x - xbase; in base_positions() the step to the base
  double *jump;                   // change of 1 - gamma at an exact evaluation (partial per rank)
  double **xnear;                 // positions when the near contact candidates were taken
  std::vector<int> termfirst;    // terms of fluid atom f: terms[termfirst[f]] .. [termfirst[f+1]-1]
  int *slot;                     // the term of vertex v of the fluid atom being evaluated, else -1
  int refreshing;                // 1 if this step evaluates the kernel completion exactly
  int rebuilt;                   // 1 on a neighbour build: contact candidates are searched
  int predicted;                 // 1 if the last exact evaluation's base is ahead of the atoms
  int measuring;                 // 1 if this exact evaluation measures the jump (next_interval)
  int every, pending;            // steps to the next exact evaluation, and from it to the one after
  double lastjump;               // largest jump of 1 - gamma (all ranks) at the last measurement
  bigint refreshed;              // step of the last exact evaluation
  std::vector<std::array<int, 4>> touching;    // fluid atom and triangle that may be in contact
  std::vector<std::array<int, 4>> near;        // those of them near contact (wall_forces)
  std::vector<int> fluidfirst, fluidj;         // the list's fluid pairs: fluidj[fluidfirst[ii]]..
  std::vector<std::array<int, 2>> boundarypairs;    // the list's fluid-wall pairs, same cell, by f
  std::vector<double> hsplit;                       // per-atom h at the last split_list()
  enum {
    COMM_DENSITY,
    COMM_SUMS,
    COMM_H,
    COMM_LOAD,
    COMM_TRIANGLES,
    COMM_AHEAD,
    COMM_JUMP
  } commode;
  int restart_version;    // format version of the restart file read, 1 = before versions
  // the settings of the keywords removed in version 12, as an older restart file has them
  struct Removed {
    int eos = 0;             // 1: tait
    double tref = 298.15;    // Tref (K)
    double shift = 0.0;      // shift A
    double tensile = 0.0;    // tensile eps
    double grow = 1.5;       // grow (ignored: the neighbour range only)
    double lag = -1.0;       // background auto lag (s); < 0: not given
  };
  void read_settings(FILE *, Removed &, std::string &, std::string &, double &);

  double *prho2;     // P / rho^2 of owned and ghost fluid atoms
  double *rhoinv;    // 1 / rho of owned and ghost fluid atoms
  int nmax;

  // pairs inside the kernel support, found by the density pass and reused by the force pass
  int *pairfirst;     // pairs of the ii-th atom of the list: pairfirst[ii] .. pairfirst[ii+1]-1
  int *pairj;         // neighbour index j
  double *pairdw;     // m_i m_j (1/r) dW/dr (per-atom h: at h_i)
  double *pairdwj;    // per-atom h: m_i m_j (1/r) dW/dr at h_j
  double *pairr;      // per-atom h: r_ij
  double *pairmu;     // (mu_i + mu_j) m_i m_j (1/r) dW/dr, only with viscosity
  int maxfirst, maxpairs;

  void allocate();
  void grow_peratom();
  void destroy_peratom();
  void unstable(int) const;
  template <int KERNEL, int VISCOUS, int WALLS, int PERATOM> void sum_density(int);
  template <int VISCOUS, int EVFLAG, int PERATOM> void sum_forces();
  template <int KERNEL, int VISCOUS>
  void peratom_pair(int, int, double, double, int, double &, double &);
  template <int KERNEL, int VISCOUS> void resum_density();
  void density_pass(int);
  void atom_h(int &);
  void kernel_scales();
  double newton_h();
  void solve_h();
  void too_long(int) const;
  double run_hcap(int) const;
  void unsolvable(int, double) const;
  template <int EVFLAG> void wall_forces();
  template <int PERATOM> void boundary_terms(int, int, const PairConst &);
  void split_list(double);
  bool outgrown() const;
  void base_positions(int);
  void keep_base();
  void next_interval();
  void linear_deficit();
  template <int EVFLAG> bool contact(int, int, int, int, double);
  bool moved_since_near(double) const;
  void tabulate_phi();
  void phi_beyond(double q, double &value, double &slope) const;
  void apply_eos();
  void grow_pairs(int);
};

}    // namespace LAMMPS_NS

#endif
