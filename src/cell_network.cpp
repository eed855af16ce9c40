/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
------------------------------------------------------------------------- */

#include "cell_network.h"

#include <algorithm>
#include <cmath>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

void CellNetwork::set_edges(int ncell, std::vector<Edge> edges)
{
  auto order = [](const Edge &a, const Edge &b) { return a.i < b.i || (a.i == b.i && a.j < b.j); };
  std::sort(edges.begin(), edges.end(), order);
  n = ncell;
  graph = std::move(edges);
}

/* ---------------------------------------------------------------------- */

void CellNetwork::rates(const std::vector<double> &psi, std::vector<double> &rate) const
{
  rate.assign(n, 0.0);
  for (const Edge &e : graph) {
    // J_ij = rho_w L_cc A_ij (psi_j - psi_i) into cell i (doc/model.md §5.13)
    const double flux = e.g * (psi[e.j] - psi[e.i]);
    rate[e.i] += flux;
    rate[e.j] -= flux;
  }
}

/* ---------------------------------------------------------------------- */

double CellNetwork::stiffness(double dtw, const std::vector<double> &s) const
{
  double most = 0.0;
  // two cells relax psi_j - psi_i at the rate g (s_i + s_j) (doc/model.md §5.13)
  for (const Edge &e : graph) most = std::max(most, dtw * e.g * (s[e.i] + s[e.j]));
  return most;
}

/* ----------------------------------------------------------------------
   (I + C + dt_w L S) dM = dt_w (r - L psi), L the graph Laplacian of the g, S = diag(s), C the own
   transfer's factor z/(1 - e^-z) - 1 (an isolated cell takes its exponential Euler step), solved
   in the symmetric positive definite form x = S^1/2 dM by conjugate gradients with the diagonal
   as preconditioner (to 1e-14 of the right-hand side); the exchange is then recomputed edge by
   edge from the end-of-step potentials psi + S dM and applied antisymmetrically, so that it sums
   to zero to round-off (doc/model.md §5.13)
------------------------------------------------------------------------- */

bool CellNetwork::step(double dtw, const Cells &cells, Change &change)
{
  std::vector<double> root(n), factor(n), diag(n), b(n);
  for (int c = 0; c < n; c++) {
    root[c] = sqrt(cells.s[c]);
    const double z = cells.z[c];
    // 1 + c = z / (1 - e^-z): dM = dt_w r (1 - e^-z) / z alone (doc/model.md §5.4)
    factor[c] = z > 0.0 ? z / -expm1(-z) - 1.0 : 0.0;
    diag[c] = 1.0 + factor[c];
    b[c] = dtw * cells.rate[c];
  }
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(n + graph.size());
  for (const Edge &e : graph) {
    const double a = dtw * e.g;
    const double flux = a * (cells.psi[e.j] - cells.psi[e.i]);
    b[e.i] += flux;
    b[e.j] -= flux;
    diag[e.i] += a * cells.s[e.i];
    diag[e.j] += a * cells.s[e.j];
    entries.emplace_back(e.j, e.i, -a * root[e.i] * root[e.j]);
  }
  for (int c = 0; c < n; c++) entries.emplace_back(c, c, diag[c]);
  system.resize(n, n);
  system.setFromTriplets(entries.begin(), entries.end());
  solver.setTolerance(1e-14);
  solver.setMaxIterations(std::max(2 * n, 1000));
  solver.compute(system);
  Eigen::VectorXd rhs(n);
  for (int c = 0; c < n; c++) rhs[c] = root[c] * b[c];
  const Eigen::VectorXd x = solver.solve(rhs);
  last_iterations = (int) solver.iterations();
  if (solver.info() != Eigen::Success) return false;

  change.own.resize(n);
  change.exchange.assign(n, 0.0);
  change.gross = 0.0;
  std::vector<double> psi_end(n);
  for (int c = 0; c < n; c++) {
    // dM_own = dt_w r - C dM, psi_end = psi + s dM, dM = x / s^1/2
    change.own[c] = dtw * cells.rate[c] - factor[c] * x[c] / root[c];
    psi_end[c] = cells.psi[c] + root[c] * x[c];
  }
  for (const Edge &e : graph) {
    // dM_ij = dt_w g_ij (psi_j - psi_i) at the end of the step, + to i, - to j
    const double moved = dtw * e.g * (psi_end[e.j] - psi_end[e.i]);
    change.exchange[e.i] += moved;
    change.exchange[e.j] -= moved;
    change.gross += fabs(moved);
  }
  return true;
}
