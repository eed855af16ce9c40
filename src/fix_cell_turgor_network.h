/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   TurgorNetwork: water exchanged between neighbouring cells, J_ij = G_ij (psi_j - psi_i), and each
   cell's own transfer, advanced together over dt_w by one linearised implicit step on per-cell
   vectors (doc/model.md §5.13). No LAMMPS state: the caller gives the cells' water potentials,
   their stiffnesses dpsi/dM and the junction graph (src/fix_cell_turgor_junctions.h) and gets mass
   changes. Distributed over an MPI communicator: each rank holds the rows of its own cells and a
   halo of the cells of other ranks joined to them; every sum over cells is exact (CellExactSum), so
   the result is the same bit for bit on any number of ranks.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_CELL_TURGOR_NETWORK_H
#define LMP_FIX_CELL_TURGOR_NETWORK_H

#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <functional>
#include <initializer_list>
#include <utility>
#include <vector>

namespace LAMMPS_NS {

// the exact sum of doubles as a fixed-point integer of 32-bit digits in int64 limbs over the
// whole double range (2^-1074 to 2^1024), so that it does not depend on the order of the terms.
// Terms are first summed per binary exponent as integer significands (up to 1024 per exponent),
// then carried into the limbs
class CellExactSum {
 public:
  static constexpr int LIMBS = 70;    // 67 digits of the double range + headroom for carries
  // x = m 2^(b - 1074), m the 53-bit significand, b = biased exponent - 1 (0 for subnormals); the
  // biased exponent 0x7ff (inf, NaN) counts the non-finite terms
  void add(double x)
  {
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    const int exponent = (int) ((bits >> 52) & 0x7ff);
    const int64_t m =
        (int64_t) ((bits & ((UINT64_C(1) << 52) - 1)) | ((uint64_t) (exponent > 0) << 52));
    // the sign without a branch: m -> (m ^ s) - s negates m when s = -1
    const int64_t s = -(int64_t) (bits >> 63);
    bin[exponent] += exponent == 0x7ff ? 1 : (m ^ s) - s;
    lo = std::min(lo, exponent);
    hi = std::max(hi, exponent);
    if (++pending == 1024) flush();
  }
  // the sum rounded to double (to about 1 ulp; the same for the same exact sum)
  double value();
  // sums of several CellExactSum over the ranks, in place; collective
  static void allreduce(CellExactSum *sums, int count, MPI_Comm comm);

 private:
  int64_t bin[2048] = {};          // per biased exponent the sum of the signed significands
  int64_t limb[LIMBS + 1] = {};    // the digits, then the count of non-finite terms
  int pending = 0;                 // terms in the bins
  int lo = 2047, hi = 0;           // the range of bins they may be in

  // the bins into the limbs, the carries propagated
  void flush();
  // carries propagated: every digit in [0, 2^32) but the top one, which keeps the sign
  static void carry(int64_t *digits);
};

class TurgorNetwork {
 public:
  // a junction between cells i < j (global cell indices) of conductance
  // g = rho_w L_cc A_ij (kg Pa^-1 s^-1)
  struct Edge {
    int i, j;
    double g;
  };

  // per cell of this rank (in the order of its cells): water potential psi (Pa), stiffness
  // s = dpsi/dM > 0 (Pa/kg), own flux r (kg/s) and own step stiffness z = dt_w k >= 0 of its
  // exchange with the outside (0, 0 when sealed)
  struct Cells {
    std::vector<double> psi, s, rate, z;
  };

  // the result of step(): per cell of this rank the mass change from the outside and from its
  // neighbours (kg); over all cells the water moved and the exchange's net change
  struct Change {
    std::vector<double> own, exchange;
    double gross;    // sum over junctions of |water moved| (kg)
    double net;      // sum over cells of the exchange (kg, 0 to round-off)
  };

  explicit TurgorNetwork(MPI_Comm comm = MPI_COMM_SELF) : world(comm) {}

  // this rank's cells (global indices, ascending), the junctions with at least one end among
  // them (a junction between two ranks' cells given to both) and the rank of any cell. Collective
  void set_edges(const std::vector<int> &cells, const std::vector<Edge> &edges,
                 const std::function<int(int)> &rank_of);
  // a factor on every junction's g for the calls below (e.g. L_cc(T) of this step, the edges
  // carrying rho_w A_ij), so that the junctions' set-up is kept from one step to the next
  void set_scale(double factor) { scale = factor; }
  // the cells' state for the calls below; halo values from their ranks. Collective
  void set_cells(const Cells &cells);
  // water flowing into each cell of this rank from its neighbours at the current psi (kg/s)
  void rates(std::vector<double> &rate) const;
  // each cell's conductance to its neighbours, the sum of its junctions' g (kg Pa^-1 s^-1)
  void conductances(std::vector<double> &g) const;
  // largest dt_w g_ij (s_i + s_j) over all junctions: the two-cell stiffness (an explicit step is
  // unstable above 2). Collective
  double stiffness(double dtw) const;
  // one implicit step over dt_w; false (on every rank) if the solver did not converge. Collective
  bool step(double dtw, Change &change);
  int iterations() const { return last_iterations; }    // of the last step's solve
  // this rank's junctions to cells of other ranks whose lower cell is its own
  int crossing() const { return cross; }

 private:
  MPI_Comm world;
  int nown = 0, ntotal = 0, last_iterations = 0, cross = 0;
  double scale = 1.0;         // the factor on every g (set_scale)
  std::vector<int> global;    // global index of each own cell, then of each halo cell
  // per own cell (CSR: start) its junctions, ordered by the other cell's global index: the other
  // cell (local index: own or halo) and g
  std::vector<int> start, other;
  std::vector<double> cond;
  // halo exchange with each neighbour rank: own cells sent (sendcells[sendstart[k]...]) and halo
  // cells received (local indices from haloend[k - 1] or nown)
  std::vector<int> neighbours, sendstart, sendcells, haloend;
  Cells state;
  std::vector<double> psi, s;    // own then halo

  // v: a value per own cell, then room for the halo, which this fills from the cells' ranks
  void halo(std::vector<double> &v) const;

  // step(): the solve's tolerance relative to the right-hand side
  static constexpr double STEP_TOL = 1e-14;
  // step()'s system on this rank's rows: S^1/2 (own then halo), C, the diagonal, its inverse, the
  // right-hand side and the off-diagonal entries (CSR as cond)
  struct System {
    std::vector<double> root, factor, diag, invdiag, b, off;
  };
  System assemble(double dtw) const;
  void dots(std::initializer_list<std::pair<const double *, const double *>> pairs,
            double *out) const;
  bool solve(const System &sys, std::vector<double> &x);
  void finish(double dtw, const System &sys, const std::vector<double> &x, Change &change) const;
};

}    // namespace LAMMPS_NS

#endif
