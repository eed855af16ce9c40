// Time of one water-network step (src/fix_cell_turgor_network.cpp) against the number of cells: the
// cells of a periodic BCC lattice (each a truncated octahedron, Kelvin's 14-face cell; 8 hexagonal
// and 6 square faces) or a simple cubic one (6 faces), one junction per face, conductances and
// stiffnesses s spread over a decade each, each cell also exchanging with the outside; the step
// stiffness dt_w g s is AMP x (1..100) (AMP default 1). On any number of MPI ranks, each holding a
// block of consecutive cells (slabs of the lattice in z) and the junctions that touch them.
// Prints a table: cells, ranks, junctions, the mean time of a step (set_edges + set_cells + step:
// halo, assemble, conjugate gradients, fluxes; the slowest rank) over the repeats, its CG
// iterations, the water balance |sum of exchange| / gross and sum |dM| over the cells of the last
// one (the same bit for bit on any number of ranks). Built and run by bench/network_step.sh.
#include "fix_cell_turgor_network.h"

#include <mpi.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

using LAMMPS_NS::TurgorNetwork;

// junctions of an m x m x m periodic lattice: bcc (2 m^3 cells) or sc (m^3)
static int lattice(int m, bool bcc, std::vector<TurgorNetwork::Edge> &edges)
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
  MPI_Init(&argc, &argv);
  int me, nprocs;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  MPI_Comm_size(MPI_COMM_WORLD, &nprocs);
  const bool bcc = argc < 2 || std::string(argv[1]) != "sc";
  const int repeats = argc > 2 ? atoi(argv[2]) : 20;
  const double amp = argc > 3 ? atof(argv[3]) : 1.0;
  std::vector<int> sizes;
  for (int a = 4; a < argc; a++) sizes.push_back(atoi(argv[a]));
  if (sizes.empty())
    sizes = bcc ? std::vector<int>{4, 6, 8, 10, 14, 17, 22, 30}
                : std::vector<int>{5, 8, 10, 14, 22, 28, 38};
  setvbuf(stdout, nullptr, _IONBF, 0);
  std::uniform_real_distribution<double> decade(0.0, 1.0);
  if (me == 0) {
    printf("# %s lattice, dt_w g s = %g x (1..100), mean of %d steps\n",
           bcc ? "bcc (14 faces)" : "sc (6 faces)", amp, repeats);
    printf("%8s %6s %10s %10s %10s %12s %24s\n", "cells", "ranks", "junctions", "step_ms",
           "cg_iter", "net/gross", "sum|dM|");
  }
  for (int m : sizes) {
    std::vector<TurgorNetwork::Edge> all;
    const int n = lattice(m, bcc, all);
    // rank p holds the cells [n p / P, n (p + 1) / P)
    auto rank_of = [&](int c) { return (int) ((long) c * nprocs / n); };
    std::vector<int> mine;
    for (int c = 0; c < n; c++)
      if (rank_of(c) == me) mine.push_back(c);
    std::vector<TurgorNetwork::Edge> edges;
    const int nmine = (int) mine.size();
    TurgorNetwork::Cells cells{std::vector<double>(nmine), std::vector<double>(nmine),
                             std::vector<double>(nmine), std::vector<double>(nmine)};
    TurgorNetwork net(MPI_COMM_WORLD);
    TurgorNetwork::Change change;
    double total = 0.0, balance = 0.0, sum = 0.0;
    int iterations = 0;
    // the same random values on every rank count: drawn for all cells, kept for this rank's
    std::mt19937_64 rng(1);
    for (int r = 0; r < repeats; r++) {
      // values of a tissue: psi -1..0 MPa, s (1e17 Pa/kg) and g over a decade, dt_w = 1 s
      edges.clear();
      for (auto &e : all) {
        e.g = amp * 1e-17 * pow(10.0, decade(rng));
        if (rank_of(e.i) == me || rank_of(e.j) == me) edges.push_back(e);
      }
      for (int c = 0, h = 0; c < n; c++) {
        const double psi = -1e6 * decade(rng), s = 1e17 * pow(10.0, decade(rng));
        const double rate = -1e-15 * decade(rng), z = decade(rng);
        if (rank_of(c) != me) continue;
        cells.psi[h] = psi, cells.s[h] = s, cells.rate[h] = rate, cells.z[h] = z;
        h++;
      }
      MPI_Barrier(MPI_COMM_WORLD);
      const auto t0 = std::chrono::steady_clock::now();
      net.set_edges(mine, edges, rank_of);
      net.set_cells(cells);
      const bool ok = net.step(1.0, change);
      double ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      if (!ok) {
        if (me == 0) fprintf(stderr, "network_step: the solve failed at %d cells\n", n);
        MPI_Abort(MPI_COMM_WORLD, 1);
      }
      MPI_Allreduce(MPI_IN_PLACE, &ms, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
      total += ms;
      iterations += net.iterations();
      balance = fabs(change.net) / change.gross;
      LAMMPS_NS::CellExactSum dm;
      for (int h = 0; h < nmine; h++) dm.add(fabs(change.own[h] + change.exchange[h]));
      LAMMPS_NS::CellExactSum::allreduce(&dm, 1, MPI_COMM_WORLD);
      sum = dm.value();
    }
    if (me == 0)
      printf("%8d %6d %10zu %10.3f %10.1f %12.2e %24.17e\n", n, nprocs, all.size(), total / repeats,
             (double) iterations / repeats, balance, sum);
  }
  MPI_Finalize();
  return 0;
}
