/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   pair_style cell/sph: the cell fluid, summation density with per-atom mass, pressure force F^p
   and Morris viscous force F^v (doc/model.md §3.1-3.5). The class's parts: the density and
   force passes (pair_cell_sph.cpp), h adaptive (pair_cell_sph_adaptive_h.cpp), the keywords,
   coefficients and init (pair_cell_sph_settings.cpp), restart and data files
   (pair_cell_sph_restart.cpp); the wall boundary is a component of its own, the member wall
   (pair_cell_sph_boundary.h)
------------------------------------------------------------------------- */

#ifndef LMP_PAIR_CELL_SPH_H
#define LMP_PAIR_CELL_SPH_H

#include "cell_kernel.h"
#include "cell_quantity.h"
#include "cell_styles.h"
#include "pair.h"
#include "pair_cell_sph_boundary.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class PairCellSPH : public Pair, public CellWallLoad {
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
  bool request_wall_load(int, int, const std::string &) override { return has_wall_boundary(); }
  double **wall_load() const override { return walls ? wall.wallload : nullptr; }
  bool has_wall_boundary() const;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;

  // smoothing length: the pair_coeff value or eta (m/rho)^(1/3) per atom (1, h mass, was removed)
  enum HMode { HFIXED = 0, HADAPTIVE = 2 };

 protected:
  // per-atom h: the neighbour cutoff allows h up to GROW x the largest h at the run's start
  // (run_hcap; unless a cutoff is given)
  static constexpr double GROW = 1.5;
  // h adaptive: the density pass keeps the pairs within (1 + HMARGIN) x the support of the larger
  // h, so that the iterations sum over those pairs only while every h changed by less than HMARGIN
  static constexpr double HMARGIN = 1e-3;
  // the temperature (K) of the pair_coeff viscosity mu: 25 C
  static constexpr double TREF = 298.15;
  // background auto: the default relaxation time of P_b, in steps (doc/pair_cell_sph.md: 20 steps
  // let the seed cell's breathing grow in undamped dynamics, 200 damp it)
  static constexpr int AUTO_LAG = 200;

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

  struct PairConst {
    double cutsq;               // (kernel support)^2; 0 if the pair is not computed (or a wall
                                // boundary pair, pair_cell_sph_boundary.h)
    CellKernel::Scale scale;    // kernel constants at this pair's h
    double mu2;                 // mu_i + mu_j
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
  double *hcap;       // largest h the neighbour cutoff allows, per fluid type
  double **hscale;    // 1/h_i, sigma/h_i^d, sigma/h_i^(d+2), (pair range)^2 of every atom
  double *dsum;       // d(sum_j m_j W(r_ij, h_i))/dh_i
  double *d2sum;      // d^2(sum_j m_j W(r_ij, h_i))/dh_i^2
  double **hsum;      // sum_j m_j f, m_j q^2 f'/q, m_j q^2 f'' (q = r_ij/h_i) of dsum, d2sum, rho
  std::vector<double> step;    // h adaptive: Newton step of h of the list's atoms
  int hstale;    // 1 if owned h changed since the ghosts' h and every hscale were last set

  // wall boundary (pair_coeff I J wall): each fluid atom's kernel is completed across its own
  // cell's wall (pair_cell_sph_boundary.h); boundary[i][j] of pair_coeff, walls if any is set
  friend class PairCellSPHBoundary;
  int **boundary;    // 1 for a fluid-wall type pair of the wall boundary
  int walls;         // 1 if any type pair is a boundary pair (init_style)
  PairCellSPHBoundary wall;

  // what the next forward or reverse comm carries: the fluid's density pass (rho, pressure, with
  // the wall boundary's deficit), its sums only, or h; or the wall boundary's (its pack_*)
  enum {
    COMM_DENSITY,
    COMM_SUMS,
    COMM_H,
    COMM_LOAD,
    COMM_TRIANGLES,
    COMM_AHEAD,
    COMM_BASE,
    COMM_JUMP
  } commode;
  void forward(int);      // a forward comm of this kind
  void reverse(int);      // a reverse comm of this kind (ghost sums into owners, newton pair on)
  int restart_version;    // format version of the restart file read, 1 = before versions
  // the settings of the keywords removed in version 12, as an older restart file has them
  struct Removed {
    int eos = 0;             // 1: tait
    double tref = TREF;      // Tref (K)
    double shift = 0.0;      // shift A
    double tensile = 0.0;    // tensile eps
    double grow = 1.5;       // grow (ignored: the neighbour range only)
    double lag = -1.0;       // background auto lag (s); < 0: not given
  };
  void read_settings(FILE *, Removed &, std::string &, std::string &, double &,
                     PairCellSPHBoundary::Schedule &);
  const char *removed_setting(const Removed &) const;

  double *prho2;     // P / rho^2 of owned and ghost fluid atoms
  double *rhoinv;    // 1 / rho of owned and ghost fluid atoms
  int nmax;

  // pairs inside the kernel support, found by the density pass and reused by the force pass
  int *pairfirst;    // pairs of the ii-th atom of the list: pairfirst[ii] .. pairfirst[ii+1]-1
  int *pairj;        // neighbour index j
  double *pairdw;    // m_i m_j (1/r) dW/dr; per-atom h: m_i m_j (the gradients in the force pass)
  double *pairr;     // per-atom h: r_ij
  double *pairmu;    // (mu_i + mu_j) m_i m_j (1/r) dW/dr; per-atom h: (mu_i + mu_j) m_i m_j / 2;
                     // only with viscosity
  int maxfirst, maxpairs;

  // the density and force passes (pair_cell_sph.cpp)
  void grow_peratom();
  void destroy_peratom();
  void density_pass(int);
  void ghost_h();    // h adaptive: the ghosts' h sent again if owned h changed since
  template <int KERNEL, int PERATOM> void self_density();
  template <int KERNEL, int VISCOUS, int WALLS, int PERATOM> void sum_density(int);
  template <int KERNEL> void peratom_pair(double, double, double, double, double *, double *);
  template <int KERNEL> void resum_density();
  void scale_sums();
  void grow_pairs(int);
  void apply_eos();
  void unstable(int) const;
  static constexpr int FIXED_H = -1;    // sum_forces with one h per type pair
  template <int KERNEL, int VISCOUS, int EVFLAG> void sum_forces();
  void forces(int);
  // h adaptive (pair_cell_sph_adaptive_h.cpp)
  void atom_h(int &);
  void kernel_scales();
  void solve_h();
  double newton_h(int &);
  void too_long(int) const;
  void unsolvable(int, double) const;
  // pair_coeff arrays and the checks of init_style (pair_cell_sph_settings.cpp)
  void allocate();
  void create_fields();
  void find_fields();
  void check_masses();
  double run_hcap(int) const;
};

}    // namespace LAMMPS_NS

#endif
