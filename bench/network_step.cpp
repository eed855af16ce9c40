// Time of one water-network step (src/cell_network.cpp) against the number of cells: the cells of
// a periodic BCC lattice (each a truncated octahedron, Kelvin's 14-face cell; 8 hexagonal and 6
// square faces) or a simple cubic one (6 faces), one junction per face, conductances and
// stiffnesses s spread over a decade each, each cell also exchanging with the outside; the step
// stiffness dt_w g s is AMP x (1..100) (AMP default 1). Prints a table: cells, junctions, the mean
// time of a step (set_edges + step: assemble, conjugate gradients, fluxes) over the repeats, its
// CG iterations, and the water balance |sum of exchange| / gross of the last one.
// Built and run by bench/network_step.sh.
#include "cell_network.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

using LAMMPS_NS::CellNetwork;

// junctions of an m x m x m periodic lattice: bcc (2 m^3 cells) or sc (m^3)
static int lattice(int m, bool bcc, std::vector<CellNetwork::Edge> &edges)
{
  const int per = bcc ? 2 : 1, n = per * m * m * m;
  auto id = [&](int b, int x, int y, int z) {
    x = (x % m + m) % m, y = (y % m + m) % m, z = (z % m + m) % m;
    return b + per * (x + m * (y + m * z));
  };
  auto add = [&](int a, int b) {
    if (a != b) edges.push_back({std::min(a, b), std::max(a, b), 0.0});
  };
  for (int z = 0; z < m; z++)
    for (int y = 0; y < m; y++)
      for (int x = 0; x < m; x++)
        for (int b = 0; b < per; b++) {
          const int c = id(b, x, y, z);
          // square faces: the same sublattice one step along +x, +y, +z
          add(c, id(b, x + 1, y, z));
          add(c, id(b, x, y + 1, z));
          add(c, id(b, x, y, z + 1));
          // hexagonal faces: the other sublattice at the 8 corners, counted from sublattice 0
          if (bcc && b == 0)
            for (int dz = -1; dz <= 0; dz++)
              for (int dy = -1; dy <= 0; dy++)
                for (int dx = -1; dx <= 0; dx++) add(c, id(1, x + dx, y + dy, z + dz));
        }
  return n;
}

int main(int argc, char **argv)
{
  const bool bcc = argc < 2 || std::string(argv[1]) != "sc";
  const int repeats = argc > 2 ? atoi(argv[2]) : 20;
  const double amp = argc > 3 ? atof(argv[3]) : 1.0;
  setvbuf(stdout, nullptr, _IONBF, 0);
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> decade(0.0, 1.0);
  printf("# %s lattice, dt_w g s = %g x (1..100), mean of %d steps\n",
         bcc ? "bcc (14 faces)" : "sc (6 faces)", amp, repeats);
  printf("%8s %10s %10s %10s %12s\n", "cells", "junctions", "step_ms", "cg_iter", "net/gross");
  for (int m : bcc ? std::vector<int>{4, 6, 8, 10, 14, 17, 22, 30}
                   : std::vector<int>{5, 8, 10, 14, 22, 28, 38}) {
    std::vector<CellNetwork::Edge> edges;
    const int n = lattice(m, bcc, edges);
    CellNetwork::Cells cells{std::vector<double>(n), std::vector<double>(n),
                             std::vector<double>(n), std::vector<double>(n)};
    CellNetwork net;
    CellNetwork::Change change;
    double total = 0.0, balance = 0.0;
    int iterations = 0;
    for (int r = 0; r < repeats; r++) {
      // values of a tissue: psi -1..0 MPa, s (1e17 Pa/kg) and g over a decade, dt_w = 1 s
      for (auto &e : edges) e.g = amp * 1e-17 * pow(10.0, decade(rng));
      for (int c = 0; c < n; c++) {
        cells.psi[c] = -1e6 * decade(rng);
        cells.s[c] = 1e17 * pow(10.0, decade(rng));
        cells.rate[c] = -1e-15 * decade(rng);
        cells.z[c] = decade(rng);
      }
      const auto t0 = std::chrono::steady_clock::now();
      net.set_edges(n, edges);
      if (!net.step(1.0, cells, change)) {
        fprintf(stderr, "network_step: the solve failed at %d cells\n", n);
        return 1;
      }
      const double ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      total += ms;
      iterations += net.iterations();
      double sum = 0.0;
      for (double x : change.exchange) sum += x;
      balance = fabs(sum) / change.gross;
    }
    printf("%8d %10zu %10.3f %10.1f %12.2e\n", n, edges.size(), total / repeats,
           (double) iterations / repeats, balance);
  }
  return 0;
}
