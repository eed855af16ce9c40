/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
------------------------------------------------------------------------- */

#include "fix_cell_turgor_network.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <utility>

using namespace LAMMPS_NS;

/* ----------------------------------------------------------------------
   a bin of exponent e holds n 2^(b - 1074), b = e - 1 (0 for e = 0), |n| < 2^63: its digits
   n << (b % 32) go to limbs b / 32 and up
------------------------------------------------------------------------- */

void CellExactSum::flush()
{
  for (int e = lo; e <= std::min(hi, 2046); e++) {
    if (bin[e] == 0) continue;
    const int b = e > 0 ? e - 1 : 0, k = b >> 5, shift = b & 31;
    const int64_t s = bin[e] < 0 ? -1 : 0;
    const uint64_t n = (uint64_t) ((bin[e] ^ s) - s), mask = 0xffffffffu;
    bin[e] = 0;
    // |n| in 32-bit digits shifted: below 2^33 each
    const uint64_t d0 = (n & mask) << shift, d1 = (n >> 32) << shift;
    const int64_t digits[3] = {(int64_t) (d0 & mask), (int64_t) ((d0 >> 32) + (d1 & mask)),
                               (int64_t) (d1 >> 32)};
    for (int j = 0; j < 3; j++) limb[k + j] += (digits[j] ^ s) - s;
  }
  limb[LIMBS] += bin[2047];
  bin[2047] = 0;
  pending = 0;
  lo = 2047;
  hi = 0;
  carry(limb);
}

/* ---------------------------------------------------------------------- */

void CellExactSum::carry(int64_t *digits)
{
  for (int k = 0; k < LIMBS - 1; k++) {
    // floor division by 2^32 (arithmetic shift): the digit stays in [0, 2^32)
    const int64_t up = digits[k] >> 32;
    digits[k] -= up * (INT64_C(1) << 32);
    digits[k + 1] += up;
  }
}

/* ---------------------------------------------------------------------- */

double CellExactSum::value()
{
  flush();
  if (limb[LIMBS]) return NAN;
  int64_t digits[LIMBS];
  const bool negative = limb[LIMBS - 1] < 0;
  // |sum| with its carries propagated again (the digits of a negative sum negated)
  for (int k = 0; k < LIMBS; k++) digits[k] = negative ? -limb[k] : limb[k];
  carry(digits);
  int top = LIMBS - 1;
  while (top > 0 && digits[top] == 0) top--;
  // the three leading digits (at least 65 bits), weights 2^(32 k - 1074)
  double sum = 0.0;
  for (int k = top; k >= 0 && k > top - 3; k--) sum += ldexp((double) digits[k], 32 * k - 1074);
  return negative ? -sum : sum;
}

/* ---------------------------------------------------------------------- */

void CellExactSum::allreduce(CellExactSum *sums, int count, MPI_Comm comm)
{
  std::vector<int64_t> limbs((size_t) count * (LIMBS + 1));
  for (int k = 0; k < count; k++) {
    sums[k].flush();
    std::copy(sums[k].limb, sums[k].limb + LIMBS + 1, &limbs[(size_t) k * (LIMBS + 1)]);
  }
  MPI_Allreduce(MPI_IN_PLACE, limbs.data(), (int) limbs.size(), MPI_INT64_T, MPI_SUM, comm);
  for (int k = 0; k < count; k++)
    std::copy(&limbs[(size_t) k * (LIMBS + 1)], &limbs[(size_t) (k + 1) * (LIMBS + 1)],
              sums[k].limb);
}

/* ----------------------------------------------------------------------
   local indices: own cells in the given order, then the halo ordered by (rank, global index), so
   that the cells a rank sends (its own cells joined to the receiver's, ascending) arrive in the
   receiver's order without a set-up exchange: both ranks hold the junctions between them
------------------------------------------------------------------------- */

void TurgorNetwork::set_edges(const std::vector<int> &cells, const std::vector<Edge> &edges,
                              const std::function<int(int)> &rank_of)
{
  nown = (int) cells.size();
  auto own = [&](int c) {
    auto it = std::lower_bound(cells.begin(), cells.end(), c);
    return it != cells.end() && *it == c ? (int) (it - cells.begin()) : -1;
  };
  // per edge the local index of each end (halo ends numbered below), the halo as (rank, global)
  std::vector<std::pair<int, int>> far;
  std::vector<int> ends(2 * edges.size());
  for (size_t e = 0; e < edges.size(); e++)
    for (int k = 0; k < 2; k++) {
      const int c = k ? edges[e].j : edges[e].i;
      ends[2 * e + k] = own(c);
      if (ends[2 * e + k] < 0) far.push_back({rank_of(c), c});
    }
  std::sort(far.begin(), far.end());
  far.erase(std::unique(far.begin(), far.end()), far.end());
  global = cells;
  neighbours.clear();
  haloend.clear();
  for (size_t n = 0; n < far.size(); n++) {
    global.push_back(far[n].second);
    if (n > 0 && far[n].first != far[n - 1].first) haloend.push_back(nown + (int) n);
    if (n == 0 || far[n].first != far[n - 1].first) neighbours.push_back(far[n].first);
  }
  ntotal = (int) global.size();
  if (!far.empty()) haloend.push_back(ntotal);

  // each own cell's junctions, by the other cell's global index; the own cells each neighbour
  // rank needs
  std::vector<std::vector<std::pair<int, double>>> rows(nown);
  std::vector<std::vector<int>> sends(neighbours.size());
  cross = 0;
  for (size_t e = 0; e < edges.size(); e++) {
    int &a = ends[2 * e], &b = ends[2 * e + 1];
    for (int k = 0; k < 2; k++) {
      int &end = k ? b : a;
      if (end >= 0) continue;
      const int c = k ? edges[e].j : edges[e].i, rank = rank_of(c);
      end = nown +
          (int) (std::lower_bound(far.begin(), far.end(), std::make_pair(rank, c)) - far.begin());
      const size_t n =
          std::lower_bound(neighbours.begin(), neighbours.end(), rank) - neighbours.begin();
      sends[n].push_back(k ? a : b);
    }
    if ((a >= nown) != (b >= nown) && a < nown) cross++;
    if (a < nown) rows[a].push_back({b, edges[e].g});
    if (b < nown) rows[b].push_back({a, edges[e].g});
  }
  start.assign(1, 0);
  other.clear();
  cond.clear();
  auto by_global = [&](int a, int b) { return global[a] < global[b]; };
  for (auto &row : rows) {
    std::sort(row.begin(), row.end(),
              [&](const std::pair<int, double> &x, const std::pair<int, double> &y) {
                return by_global(x.first, y.first);
              });
    for (const auto &entry : row) {
      other.push_back(entry.first);
      cond.push_back(entry.second);
    }
    start.push_back((int) other.size());
  }
  sendstart.assign(1, 0);
  sendcells.clear();
  for (auto &send : sends) {
    std::sort(send.begin(), send.end(), by_global);
    send.erase(std::unique(send.begin(), send.end()), send.end());
    sendcells.insert(sendcells.end(), send.begin(), send.end());
    sendstart.push_back((int) sendcells.size());
  }
}

/* ---------------------------------------------------------------------- */

void TurgorNetwork::halo(std::vector<double> &v) const
{
  const int n = (int) neighbours.size();
  std::vector<double> send(sendcells.size());
  for (size_t k = 0; k < sendcells.size(); k++) send[k] = v[sendcells[k]];
  std::vector<MPI_Request> requests(2 * n);
  for (int k = 0; k < n; k++) {
    const int from = k ? haloend[k - 1] : nown;
    MPI_Irecv(&v[from], haloend[k] - from, MPI_DOUBLE, neighbours[k], 0, world, &requests[k]);
  }
  for (int k = 0; k < n; k++)
    MPI_Isend(&send[sendstart[k]], sendstart[k + 1] - sendstart[k], MPI_DOUBLE, neighbours[k], 0,
              world, &requests[n + k]);
  MPI_Waitall(2 * n, requests.data(), MPI_STATUSES_IGNORE);
}

/* ---------------------------------------------------------------------- */

void TurgorNetwork::set_cells(const Cells &cells)
{
  state = cells;
  psi.assign(ntotal, 0.0);
  s.assign(ntotal, 0.0);
  std::copy(cells.psi.begin(), cells.psi.end(), psi.begin());
  std::copy(cells.s.begin(), cells.s.end(), s.begin());
  halo(psi);
  halo(s);
}

/* ---------------------------------------------------------------------- */

void TurgorNetwork::rates(std::vector<double> &rate) const
{
  rate.assign(nown, 0.0);
  for (int c = 0; c < nown; c++)
    // J_ij = rho_w L_cc A_ij (psi_j - psi_i) into cell i (doc/model.md §5.13)
    for (int k = start[c]; k < start[c + 1]; k++)
      rate[c] += scale * cond[k] * (psi[other[k]] - psi[c]);
}

/* ---------------------------------------------------------------------- */

void TurgorNetwork::conductances(std::vector<double> &g) const
{
  g.assign(nown, 0.0);
  // L_ii = sum_j g_ij, the diagonal of the graph Laplacian (doc/model.md §5.13)
  for (int c = 0; c < nown; c++)
    for (int k = start[c]; k < start[c + 1]; k++) g[c] += scale * cond[k];
}

/* ---------------------------------------------------------------------- */

double TurgorNetwork::stiffness(double dtw) const
{
  double most = 0.0, all;
  // two cells relax psi_j - psi_i at the rate g (s_i + s_j) (doc/model.md §5.13)
  for (int c = 0; c < nown; c++)
    for (int k = start[c]; k < start[c + 1]; k++)
      most = std::max(most, dtw * scale * cond[k] * (s[c] + s[other[k]]));
  MPI_Allreduce(&most, &all, 1, MPI_DOUBLE, MPI_MAX, world);
  return all;
}

/* ----------------------------------------------------------------------
   (I + C + dt_w L S) dM = dt_w (r - L psi), L the graph Laplacian of the g, S = diag(s), C the own
   transfer's factor z/(1 - e^-z) - 1 (an isolated cell takes its exponential Euler step), solved
   in the symmetric positive definite form x = S^1/2 dM by conjugate gradients with the diagonal
   as preconditioner (to 1e-14 of the right-hand side; Eigen's algorithm, from x = 0); each rank
   its own rows, the search direction's halo exchanged once per iteration, the dot products
   exact. The exchange is then recomputed edge by edge from the end-of-step potentials
   psi + S dM, the same operands on both ends' ranks, and applied antisymmetrically, so that it
   sums to zero to round-off (doc/model.md §5.13)
------------------------------------------------------------------------- */

bool TurgorNetwork::step(double dtw, Change &change)
{
  const System sys = assemble(dtw);
  std::vector<double> x;
  if (!solve(sys, x)) return false;
  finish(dtw, sys, x, change);
  return true;
}

/* ----------------------------------------------------------------------
   the system of step() on this rank's rows: S^1/2, the own transfer's factor C, the diagonal and
   its inverse, the right-hand side b = dt_w (r - L psi) and the off-diagonal entries
------------------------------------------------------------------------- */

TurgorNetwork::System TurgorNetwork::assemble(double dtw) const
{
  System sys{std::vector<double>(ntotal), std::vector<double>(nown),
             std::vector<double>(nown),   std::vector<double>(nown),
             std::vector<double>(nown),   std::vector<double>(other.size())};
  for (int c = 0; c < ntotal; c++) sys.root[c] = sqrt(s[c]);
  // the system's off-diagonal entries -dt_w g_ij s_i^1/2 s_j^1/2, lower index's root first
  for (int c = 0; c < nown; c++) {
    const double z = state.z[c];
    // 1 + c = z / (1 - e^-z): dM = dt_w r (1 - e^-z) / z alone (doc/model.md §5.4)
    sys.factor[c] = z > 0.0 ? z / -expm1(-z) - 1.0 : 0.0;
    sys.diag[c] = 1.0 + sys.factor[c];
    sys.b[c] = dtw * state.rate[c];
    for (int k = start[c]; k < start[c + 1]; k++) {
      const int j = other[k];
      const double a = dtw * scale * cond[k];
      // + dt_w g_ij (psi_j - psi_i) on the right, dt_w g_ij s_i on the diagonal
      sys.b[c] += a * (psi[j] - psi[c]);
      sys.diag[c] += a * s[c];
      sys.off[k] =
          global[c] < global[j] ? -a * sys.root[c] * sys.root[j] : -a * sys.root[j] * sys.root[c];
    }
    sys.invdiag[c] = 1.0 / sys.diag[c];
  }
  return sys;
}

/* ----------------------------------------------------------------------
   exact dot products over all ranks' own cells of the given pairs of vectors (at most 2)
------------------------------------------------------------------------- */

void TurgorNetwork::dots(std::initializer_list<std::pair<const double *, const double *>> pairs,
                         double *out) const
{
  CellExactSum sums[2];
  int n = 0;
  for (const auto &pair : pairs) {
    for (int c = 0; c < nown; c++) sums[n].add(pair.first[c] * pair.second[c]);
    n++;
  }
  CellExactSum::allreduce(sums, n, world);
  for (int k = 0; k < n; k++) out[k] = sums[k].value();
}

/* ----------------------------------------------------------------------
   conjugate gradients on (I + C + dt_w S^1/2 L S^1/2) x = S^1/2 b from x = 0, preconditioned by
   the diagonal; false if |r| did not fall below STEP_TOL |S^1/2 b|
------------------------------------------------------------------------- */

bool TurgorNetwork::solve(const System &sys, std::vector<double> &x)
{
  x.assign(nown, 0.0);
  std::vector<double> r(nown), z(nown), p(ntotal, 0.0), q(nown);
  for (int c = 0; c < nown; c++) r[c] = sys.root[c] * sys.b[c];
  double rhs2, norms[2];
  dots({{r.data(), r.data()}}, &rhs2);
  int ncell = nown;
  MPI_Allreduce(MPI_IN_PLACE, &ncell, 1, MPI_INT, MPI_SUM, world);
  const int most = std::max(2 * ncell, 1000);
  // |r|^2 < tol^2 |b|^2 (at least the smallest normal double) ends the iteration
  const double threshold = std::max(STEP_TOL * STEP_TOL * rhs2, DBL_MIN);
  double r2 = rhs2;
  int it = 0;
  if (rhs2 > 0.0 && r2 >= threshold) {
    for (int c = 0; c < nown; c++) p[c] = sys.invdiag[c] * r[c];
    double rz;
    dots({{r.data(), p.data()}}, &rz);
    while (it < most) {
      halo(p);
      for (int c = 0; c < nown; c++) {
        // rows in a fixed order: the diagonal, then the junctions by the other cell's index
        double sum = sys.diag[c] * p[c];
        for (int k = start[c]; k < start[c + 1]; k++) sum += sys.off[k] * p[other[k]];
        q[c] = sum;
      }
      double pq;
      dots({{p.data(), q.data()}}, &pq);
      const double alpha = rz / pq;
      for (int c = 0; c < nown; c++) {
        x[c] += alpha * p[c];
        r[c] -= alpha * q[c];
        z[c] = sys.invdiag[c] * r[c];
      }
      dots({{r.data(), r.data()}, {r.data(), z.data()}}, norms);
      r2 = norms[0];
      if (r2 < threshold) break;
      const double beta = norms[1] / rz;
      rz = norms[1];
      for (int c = 0; c < nown; c++) p[c] = z[c] + beta * p[c];
      it++;
    }
  }
  last_iterations = it;
  return rhs2 == 0.0 || sqrt(r2 / rhs2) <= STEP_TOL;
}

/* ----------------------------------------------------------------------
   the mass changes from the solution x = S^1/2 dM: the own transfer's, and the exchange edge by
   edge from the end-of-step potentials, applied antisymmetrically; its gross and net sums
------------------------------------------------------------------------- */

void TurgorNetwork::finish(double dtw, const System &sys, const std::vector<double> &x,
                           Change &change) const
{
  change.own.resize(nown);
  change.exchange.assign(nown, 0.0);
  std::vector<double> psi_end(ntotal);
  for (int c = 0; c < nown; c++) {
    // dM_own = dt_w r - C dM, psi_end = psi + s dM, dM = x / s^1/2
    change.own[c] = dtw * state.rate[c] - sys.factor[c] * x[c] / sys.root[c];
    psi_end[c] = psi[c] + sys.root[c] * x[c];
  }
  halo(psi_end);
  CellExactSum sums[2];
  for (int c = 0; c < nown; c++) {
    for (int k = start[c]; k < start[c + 1]; k++) {
      const int j = other[k];
      const bool lower = global[c] < global[j];
      // dM_ij = dt_w g_ij (psi_j - psi_i) at the end of the step, i < j: + to i, - to j
      const double moved = lower ? dtw * scale * cond[k] * (psi_end[j] - psi_end[c])
                                 : dtw * scale * cond[k] * (psi_end[c] - psi_end[j]);
      change.exchange[c] += lower ? moved : -moved;
      if (lower) sums[0].add(fabs(moved));
    }
    sums[1].add(change.exchange[c]);
  }
  CellExactSum::allreduce(sums, 2, world);
  change.gross = sums[0].value();
  change.net = sums[1].value();
}
