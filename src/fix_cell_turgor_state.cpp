/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   fix cell/turgor's per-cell state on the cells' home ranks (doc/model.md §5.2)
------------------------------------------------------------------------- */

#include "fix_cell_turgor_state.h"

#include "cell_registry.h"
#include "comm.h"

#include <algorithm>

using namespace LAMMPS_NS;

// a cell's state moved between ranks at init: its restart values, psi_surface, rate
static const int STATE_VALUES = 22;
static const int WALL_AT = 6 + TurgorAccel::NPROBE;    // where the wall's water begins

/* ---------------------------------------------------------------------- */

TurgorState::TurgorState(LAMMPS *lmp) : Pointers(lmp) {}

/* ---------------------------------------------------------------------- */

int TurgorState::restart_values(int version)
{
  return version >= 8 ? 20 : version >= 4 ? 16 : (version >= 3 ? 6 : 5);
}

/* ---------------------------------------------------------------------- */

const TurgorState::Cell *TurgorState::find(tagint id) const
{
  auto it = cells.find(id);
  return it == cells.end() ? nullptr : &it->second;
}

/* ---------------------------------------------------------------------- */

void TurgorState::keep_home(const std::vector<double> &list, const CellRegistry &reg, double pi0)
{
  cells.clear();
  for (size_t at = 0; at < list.size(); at += STATE_VALUES) {
    const int c = reg.index((tagint) list[at]);
    if (c >= 0 ? reg.home(c) == comm->me : comm->me == 0) {
      const double *v = &list[at];
      Cell &s = cells[(tagint) v[0]];
      s = Cell{v[1], v[2], (int) v[3], v[4], v[5], 0.0, 0.0, {}};
      std::copy(v + 6, v + 6 + TurgorAccel::NPROBE, s.probe);
      s.wall_dry = v[WALL_AT], s.wall_x0 = v[WALL_AT + 1], s.wall_x = v[WALL_AT + 2];
      s.wall_dx = v[WALL_AT + 3];
      s.psi_surface = v[WALL_AT + 4];
      s.rate = v[WALL_AT + 5];
    }
  }
  for (int c : reg.home_cells())
    if (cells.find(reg.id(c)) == cells.end()) {
      cells[reg.id(c)] = Cell{0.0, pi0, 0, 0.0, 0.0, 0.0, 0.0, {}};
    }
}

/* ---------------------------------------------------------------------- */

int TurgorState::gather_restart(int version, std::vector<double> &list) const
{
  std::vector<double> all;
  gather(false, all);
  list.clear();
  if (comm->me != 0) return 0;
  const int nvalues = restart_values(version);
  std::map<tagint, size_t> order;
  for (size_t at = 0; at < all.size(); at += nvalues) order.emplace((tagint) all[at], at);
  for (const auto &kv : order) list.insert(list.end(), &all[kv.second], &all[kv.second] + nvalues);
  return (int) order.size();
}

/* ----------------------------------------------------------------------
   this rank's cell states, the current restart values each: ID, mass0, pi0, warned, offset,
   solids, the accel auto sums, the wall's water; full: + the last evaluation's psi_surface and
   rate
------------------------------------------------------------------------- */

void TurgorState::pack(std::vector<double> &list, bool full) const
{
  list.clear();
  for (const auto &kv : cells) {
    const Cell &s = kv.second;
    list.insert(list.end(),
                {(double) kv.first, s.mass0, s.pi0, (double) s.warned, s.offset, s.solids});
    list.insert(list.end(), s.probe, s.probe + TurgorAccel::NPROBE);
    list.insert(list.end(), {s.wall_dry, s.wall_x0, s.wall_x, s.wall_dx});
    if (full) list.insert(list.end(), {s.psi_surface, s.rate});
  }
}

/* ----------------------------------------------------------------------
   every rank's cell states (full with everywhere) on every rank, or on rank 0 only
------------------------------------------------------------------------- */

void TurgorState::gather(bool everywhere, std::vector<double> &list) const
{
  std::vector<double> mine;
  pack(mine, everywhere);
  const int n = (int) mine.size(), nprocs = comm->nprocs;
  std::vector<int> counts(nprocs), displs(nprocs, 0);
  if (everywhere)
    MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  else
    MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, world);
  for (int p = 1; p < nprocs; p++) displs[p] = displs[p - 1] + counts[p - 1];
  list.resize(everywhere || comm->me == 0 ? displs.back() + counts.back() : 0);
  if (everywhere)
    MPI_Allgatherv(mine.data(), n, MPI_DOUBLE, list.data(), counts.data(), displs.data(),
                   MPI_DOUBLE, world);
  else
    MPI_Gatherv(mine.data(), n, MPI_DOUBLE, list.data(), counts.data(), displs.data(), MPI_DOUBLE,
                0, world);
}
