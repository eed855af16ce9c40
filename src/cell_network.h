/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   CellNetwork: water exchanged between neighbouring cells, J_ij = G_ij (psi_j - psi_i), and each
   cell's own transfer, advanced together over dt_w by one linearised implicit step on per-cell
   vectors (doc/model.md §5.13). No LAMMPS state: the caller gives the cells' water potentials,
   their stiffnesses dpsi/dM and the junction graph (src/cell_junctions.h) and gets mass changes.
------------------------------------------------------------------------- */

#ifndef LMP_CELL_NETWORK_H
#define LMP_CELL_NETWORK_H

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

#include <vector>

namespace LAMMPS_NS {

class CellNetwork {
 public:
  // a junction between cells i < j (indices into the per-cell vectors) of conductance
  // g = rho_w L_cc A_ij (kg Pa^-1 s^-1)
  struct Edge {
    int i, j;
    double g;
  };

  // per cell: water potential psi (Pa), stiffness s = dpsi/dM > 0 (Pa/kg), own flux r (kg/s) and
  // own step stiffness z = dt_w k >= 0 of its exchange with the outside (0, 0 when sealed)
  struct Cells {
    std::vector<double> psi, s, rate, z;
  };

  // the result of step(): per cell the mass change from the outside and from its neighbours (kg)
  struct Change {
    std::vector<double> own, exchange;
    double gross;    // sum over junctions of |water moved| (kg)
  };

  // the junctions, kept sorted by (i, j) with i < j
  void set_edges(int ncell, std::vector<Edge> edges);
  const std::vector<Edge> &edges() const { return graph; }

  // water flowing into each cell from its neighbours at the current psi (kg/s)
  void rates(const std::vector<double> &psi, std::vector<double> &rate) const;
  // largest dt_w g_ij (s_i + s_j): the two-cell stiffness (an explicit step is unstable above 2)
  double stiffness(double dtw, const std::vector<double> &s) const;
  // one implicit step over dt_w; false if the linear solver did not converge
  bool step(double dtw, const Cells &cells, Change &change);
  int iterations() const { return last_iterations; }    // of the last step's solve

 private:
  using Matrix = Eigen::SparseMatrix<double>;
  int n = 0, last_iterations = 0;
  std::vector<Edge> graph;
  Matrix system;    // lower triangle of the symmetric system
  Eigen::ConjugateGradient<Matrix, Eigen::Lower, Eigen::DiagonalPreconditioner<double>> solver;
};

}    // namespace LAMMPS_NS

#endif
