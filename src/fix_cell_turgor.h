/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   fix cell/turgor: water transfer through the cell wall driven by turgor, osmotic pressure and the
   external water potential, or air of a given temperature and humidity (doc/model.md §5).
   Its parts, each in fix_cell_turgor_<part>.{h,cpp}: drive (T, psi_ext, air, curve), osmotic
   (pi), accel (time-scale bridging), state (per-cell state), junctions and network (water
   between cells), restart (restart file, per-atom storage: a .cpp of this class), wallwater (the
   wall's own water and stretch); cell_water.h its pure water physics
------------------------------------------------------------------------- */

#ifndef LMP_FIX_CELL_TURGOR_H
#define LMP_FIX_CELL_TURGOR_H

#include "cell_quantity.h"
#include "cell_styles.h"
#include "fix.h"
#include "fix_cell_turgor_accel.h"
#include "fix_cell_turgor_drive.h"
#include "fix_cell_turgor_network.h"
#include "fix_cell_turgor_osmotic.h"
#include "fix_cell_turgor_state.h"
#include "fix_cell_turgor_wallwater.h"

#include <memory>
#include <string>
#include <vector>

namespace LAMMPS_NS {

class TurgorJunctions;
class CellReduce;
class CellRegistry;

class FixCellTurgor : public Fix, public CellWallStretch {
 public:
  FixCellTurgor(class LAMMPS *, int, char **);
  ~FixCellTurgor() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void end_of_step() override;
  void pre_force(int) override;
  double compute_vector(int) override;
  int modify_param(int, char **) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  double memory_usage() override;
  const double *wall_stretch() override;

  // the water of a cell as the last evaluation saw it (compute cell/props columns 18-22)
  struct Water {
    double moisture;       // X = M / S, dry basis (kg/kg); 0 without solids
    double relative;       // X / X0 = M / M0
    double temperature;    // T (K)
    double psi_surface;    // water potential just outside the wall (Pa)
    double rate;           // dM/dt into the cell (kg/s)
  };

  bool osmotic(tagint cell, double mass, double &pi) const;
  // P_T at the state whose mean SPH pressure is psph (with the offset D of the last evaluation)
  bool turgor(tagint cell, double psph, double &pt) const;
  bool water(tagint cell, double mass, Water &w) const;
  // the cells and their home ranks, where the per-cell state is kept (cell_registry.h)
  const CellRegistry &registry() const;

 protected:
  enum Limit { LIMIT_ERROR = 0, LIMIT_WARN = 1 };
  // the wall's permeability L_P at Tref (m s^-1 Pa^-1) is lp everywhere; rho_w L_P(T) per area
  // (kg m^-2 s^-1 Pa^-1) is rho_lp; a cell's conductance G = d(dM/dt)/d(-psi_cell), rho_w L_P A
  // for psi (kg s^-1 Pa^-1), is conductance (doc/model.md §5.1, §5.8)
  double lp, pi0, rhow;
  TurgorAccel accel;              // accel, fixed or auto
  double ea;                      // activation energy of L_P (J/mol)
  TurgorOsmotic osmotic_model;    // pi(T, M): solutes, dry solids, GAB; Tref
  TurgorDrive drive;              // T and psi_ext, air or a curve: each cell's flux
  double tau;                     // MD time of the running mean of the offset (s), 0 = 100 N dt
  double bulk;      // fluid bulk modulus K from the 'bulk' keyword, 0 = from pair cell/sph
  double kfluid;    // K in use
  int limit, limit_set, fluidtype, walltype;
  std::unique_ptr<CellReduce> cells;
  TurgorState state;            // per cell, on its home rank
  std::vector<double> gt0;      // G t0 per bond type from the bond style, empty without it
  TurgorWallWater wallwater;    // the wall's own water and stretch (doc/model.md §5.15)

  double physical_time, water_moved, max_imbalance, max_stiffness;
  // a transfer evaluated at the end of a step is applied before the next step's forces, so that
  // the forces, densities and pressures of every step are those of its masses, and a run's setup
  // recomputes the state the previous run ended with: per atom, the relative mass change to apply
  // (migrates with the atom, in restart files); the water and the physical time it moves;
  // whether any is waiting
  double *pending = nullptr;
  double moved_pending = 0.0, time_pending = 0.0;
  bool any_pending = false;
  bigint evaluated = -1;    // the step whose end evaluated the last transfer
  // the state before that evaluation when it fell on a run's last step, to evaluate it again at
  // the next run's setup: the step (-1: none kept; not in restart files)
  bigint saved = -1;
  TurgorAccel::Saved accel_saved{};
  double exchanged_saved = 0.0;
  double busiest;                       // the most cells one rank summed at the last evaluation
  double exposed_flux, exposed_area;    // air: mean vapour flux over the exposed area, the area
  // a cell's problem found on its home rank, stopping every rank (CellRegistry::settle)
  struct Failure {
    int cell;
    std::string message;
  };
  Failure failure;                      // the first of this rank's home cells at this evaluation
  std::vector<std::string> warnings;    // of this rank's home cells at this evaluation

  // exchange: water between cells through their junctions at L_cc (doc/model.md §5.13)
  CellQuantity lcc;
  std::unique_ptr<TurgorJunctions> junctions;    // nullptr without 'exchange'
  std::unique_ptr<TurgorNetwork> network;
  double water_exchanged;       // sum over transfers and junctions of |water moved| (kg)
  double exchange_net;          // sum over cells of the exchange's mass change, last transfer (kg)
  double exchange_stiffness;    // largest dt_w g_ij (s_i + s_j) of the last evaluation
  int crossing;     // junctions between cells of different home ranks, at the last count
  int every = 1;    // N: a transfer every N steps
  bool network_stale = true;    // the network's junctions to set up again (new home ranks)

  // what the fix command's keywords set besides the members, for the checks after them
  struct Keywords {
    bool lp_set = false, pi0_set = false;
    bool exchanging = false;    // 'exchange' given
    int bondtype = 0;           // 'exchange ... bondtype N'
    std::string areas;          // 'exchange ... areas FILE'
    bool lcc_file = false;      // 'exchange file ...': L_cc from the parameter file
    double file_lcc = -1.0;     // turgor_Lcc of the last 'file', -1 if none
  };
  int parse_keyword(int narg, char **arg, Keywords &given);
  int parse_exchange(int narg, char **arg, Keywords &given);
  void parse_limit(const char *value);
  void removed_keyword(const std::string &key, const char *value);
  void read_file(const char *file, Keywords &given);
  void check_keywords(const Keywords &given);

  // one evaluation: per home cell, in the order of the registry's home cells
  struct Evaluation {
    const std::vector<int> &home;       // the home cells
    TurgorAccel::Cycle cycle;           // the transfer's place in the accel cycle
    double dtw;                         // physical time of the transfer (s), 0 when sealed
    std::vector<double> turgor;         // flux turgor P_T (Pa)
    std::vector<double> conductance;    // G (kg s^-1 Pa^-1)
    std::vector<double> scale;          // the transfer's dM/M
    double moved;                       // water moved into the home cells (kg)
    double first_accel;                 // accel auto: the smallest first accel, HUGE_VAL: none
    TurgorNetwork::Cells net;           // exchange: psi, dpsi/dM, rate and z
    std::vector<double> net_mass;       // exchange: M (kg)
    double air[2];                      // air: the exposed cells' vapour flux and area
    double arrhenius;                   // L_P(T)/L_P = L_cc(T)/L_cc at the drive's T
    double rho_lp;                      // rho_w L_P(T) at the drive's T
  };
  void evaluate(bool transfer);
  Evaluation begin_evaluation(bool transfer);
  void check_cells(Evaluation &e, bool transfer);
  void cool_surface(const Evaluation &e);
  bool cell_flux(Evaluation &e, int pos, bool transfer);
  bool own_transfer(Evaluation &e, int pos, double mass, double rate, double z, double turgor,
                    double pi);
  void gather_maxima(Evaluation &e);
  void network_transfer(Evaluation &e, bool transfer);
  void spread(const Evaluation &e);
  void control(const TurgorAccel::Cycle &cycle, bool limit, bool transfer,
               const std::vector<double> &turgors, const std::vector<double> &conductances);
  void apply_pending();
  void wall_water(Evaluation &e, bool transfer);
  void apply_wall_water();
  void share_wall_water();
  void transfer();
  void exchange(const TurgorNetwork::Cells &in, bool transfer, double dtw, double factor,
                std::vector<double> &dmass);
  void check_lp(double value, const std::string &who) const;
  void check_lcc(double value, const std::string &when) const;
  double offset_time() const;
  bool check_limit(int c, TurgorState::Cell &s, double turgor, double pi, double demand);
  double flux_turgor(int c, TurgorState::Cell &s, bool advance);
  double arrhenius_factor(double t) const;    // L_P(T)/L_P (and L_cc), 1 without Ea
  double rho_lp(double t) const;              // rho_w L_P(T)
  double pair_bulk_modulus();
};

}    // namespace LAMMPS_NS

#endif
