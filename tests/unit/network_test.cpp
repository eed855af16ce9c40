// TurgorNetwork and CellExactSum (src/fix_cell_turgor_network.h, doc/model.md §5.13): the implicit step of
// the cell-to-cell water exchange against its closed forms, and the order-independent exact sum.
// One rank (MPI_COMM_SELF); the distributed solve on 2 ranks is
// tests/parallel/fix_cell_turgor_network_distributed_solve_same_bit_for_bit_on_1_and_2_ranks.in
#include "fix_cell_turgor_network.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace LAMMPS_NS;

namespace {
TurgorNetwork chain(int n, double g)
{
  std::vector<int> cells(n);
  std::vector<TurgorNetwork::Edge> edges;
  for (int c = 0; c < n; c++) {
    cells[c] = c;
    if (c > 0) edges.push_back({c - 1, c, g});
  }
  TurgorNetwork net;
  net.set_edges(cells, edges, [](int) { return 0; });
  return net;
}
}    // namespace

// two sealed cells: (1 + dt g (s1 + s2)) dM1 = dt g (psi2 - psi1), dM2 = -dM1 (backward Euler of
// dM1/dt = g (psi2 - psi1), psi = psi0 + s dM)
TEST(Network, TwoCellsTakeTheBackwardEulerStep)
{
  const double g = 3e-12, dt = 0.7, s1 = 2e15, s2 = 5e14;
  TurgorNetwork net = chain(2, g);
  net.set_cells({{-2e5, -1e5}, {s1, s2}, {0.0, 0.0}, {0.0, 0.0}});
  TurgorNetwork::Change change;
  ASSERT_TRUE(net.step(dt, change));
  const double dm1 = dt * g * (-1e5 + 2e5) / (1.0 + dt * g * (s1 + s2));
  EXPECT_NEAR(change.exchange[0], dm1, 1e-12 * std::fabs(dm1));
  EXPECT_NEAR(change.exchange[1], -dm1, 1e-12 * std::fabs(dm1));
  EXPECT_NEAR(change.gross, std::fabs(dm1), 1e-12 * std::fabs(dm1));
  EXPECT_EQ(change.own[0], 0.0);
  EXPECT_NEAR(net.stiffness(dt), dt * g * (s1 + s2), 1e-12 * dt * g * (s1 + s2));
}

// a lone cell's own transfer is the exponential Euler step dM = dt r (1 - e^-z)/z
TEST(Network, LoneCellTakesTheExponentialStep)
{
  TurgorNetwork net = chain(1, 0.0);
  for (double z : {0.0, 1e-3, 1.0, 40.0}) {
    net.set_cells({{-1e5}, {1e15}, {2e-9}, {z}});
    TurgorNetwork::Change change;
    ASSERT_TRUE(net.step(0.5, change));
    const double expect = z > 0 ? 0.5 * 2e-9 * -std::expm1(-z) / z : 0.5 * 2e-9;
    EXPECT_NEAR(change.own[0], expect, 1e-13 * expect) << "z " << z;
  }
}

// a chain of 50 cells with random potentials, stiffnesses, own rates and z: the step solves
// (I + C + dt L S) dM = dt (r - L psi) (each row against the matrix built here, within 1e-9 of
// the largest right-hand side), and the exchange sums to zero
TEST(Network, ChainSolvesTheLinearSystem)
{
  const int n = 50;
  const double g = 1e-12, dt = 2.0;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  TurgorNetwork::Cells cells;
  for (int c = 0; c < n; c++) {
    cells.psi.push_back(-1e6 * u(rng));
    cells.s.push_back(1e14 * (1.0 + 9.0 * u(rng)));
    cells.rate.push_back(-1e-9 * u(rng));
    cells.z.push_back(c % 3 ? 2.0 * u(rng) : 0.0);
  }
  TurgorNetwork net = chain(n, g);
  net.set_cells(cells);
  TurgorNetwork::Change change;
  ASSERT_TRUE(net.step(dt, change));
  EXPECT_GT(net.iterations(), 1);
  std::vector<double> dm(n);
  for (int c = 0; c < n; c++) dm[c] = change.own[c] + change.exchange[c];
  // row c of (I + C + dt L S) dM and of dt (r - L psi)
  std::vector<double> lhs(n), rhs(n);
  double largest = 0.0, net_sum = 0.0, scale = 0.0;
  for (int c = 0; c < n; c++) {
    const double z = cells.z[c], extra = z > 0 ? z / -std::expm1(-z) - 1.0 : 0.0;
    lhs[c] = (1.0 + extra) * dm[c];
    rhs[c] = dt * cells.rate[c];
    for (int j : {c - 1, c + 1}) {
      if (j < 0 || j >= n) continue;
      lhs[c] += dt * g * (cells.s[c] * dm[c] - cells.s[j] * dm[j]);
      rhs[c] += dt * g * (cells.psi[j] - cells.psi[c]);
    }
    largest = std::max(largest, std::fabs(rhs[c]));
    net_sum += change.exchange[c];
    scale += std::fabs(change.exchange[c]);
  }
  // the solve stops at 1e-14 of the right-hand side (in S^1/2 dM); the exchange recomputed from
  // the end-of-step potentials carries that error times up to dt g s (about 4e3 here)
  for (int c = 0; c < n; c++) EXPECT_NEAR(lhs[c], rhs[c], 1e-9 * largest) << "cell " << c;
  EXPECT_NEAR(net_sum, 0.0, 1e-14 * scale);
  EXPECT_NEAR(change.net, net_sum, 1e-14 * scale);
}

// the exact sum does not depend on the order of its terms and loses none of them
TEST(ExactSum, IndependentOfOrderAndExact)
{
  CellExactSum a;
  for (double x : {1e100, 1.0, -1e100, 1e-300, 3.0}) a.add(x);
  EXPECT_EQ(a.value(), 4.0);
  std::vector<double> terms;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 5000; i++) terms.push_back(u(rng) * std::pow(10.0, 20.0 * u(rng)));
  CellExactSum forward, backward, shuffled;
  for (double x : terms) forward.add(x);
  for (auto it = terms.rbegin(); it != terms.rend(); ++it) backward.add(*it);
  std::shuffle(terms.begin(), terms.end(), rng);
  for (double x : terms) shuffled.add(x);
  const double value = forward.value();
  EXPECT_EQ(backward.value(), value);
  EXPECT_EQ(shuffled.value(), value);
  CellExactSum bad;
  bad.add(NAN);
  EXPECT_TRUE(std::isnan(bad.value()));
}

int main(int argc, char **argv)
{
  ::testing::InitGoogleTest(&argc, argv);
  MPI_Init(&argc, &argv);
  const int failed = RUN_ALL_TESTS();
  MPI_Finalize();
  return failed;
}
