/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   fix cell/turgor's restart file and per-atom storage: the per-cell state and the global values
   in the restart file, format versions 1-8; per atom, the relative mass change of the transfer
   waiting to be applied, migrating with its atom and in restart files
------------------------------------------------------------------------- */

#include "fix_cell_turgor.h"

#include "atom.h"
#include "cell_restart.h"
#include "comm.h"
#include "error.h"
#include "memory.h"

#include <algorithm>
#include <cmath>

using namespace LAMMPS_NS;

// 8: + the wall's water per cell; 7: + the wall edges of accel; 6: + the water and time of the
// transfer waiting to be applied (per atom: its mass change); 5: + water exchanged between cells;
// 4: + accel auto state; 3: + solids per cell; 2: begins with -version; 1: none
static const int RESTART_VERSION = 8;

// global restart values after the number of cells: physical time, water moved (1-3), adapted
// accel (0: not auto), open and sealed samples, lag estimate and its error (4), water exchanged
// between cells (5), water and physical time of the waiting transfer, the step of the last
// transfer's evaluation (6), the shortest and the last longest wall edge, its growth (7)
static int restart_globals(int version)
{
  return version >= 7 ? 14 : version >= 6 ? 11 : version >= 5 ? 8 : (version >= 4 ? 7 : 2);
}

/* ---------------------------------------------------------------------- */

void FixCellTurgor::write_restart(FILE *fp)
{
  std::vector<double> cellstate;
  const int ncell = state.gather_restart(RESTART_VERSION, cellstate);
  if (comm->me != 0) return;
  // version 1 (no marker) began with the number of cells >= 0; later versions with -version
  std::vector<double> list = {(double) -RESTART_VERSION, (double) ncell, physical_time,
                              water_moved};
  accel.write(list);
  list.push_back(water_exchanged);
  list.push_back(moved_pending);
  list.push_back(time_pending);
  list.push_back((double) evaluated);
  accel.write_edges(list);
  list.insert(list.end(), cellstate.begin(), cellstate.end());
  const int size = (int) (list.size() * sizeof(double));
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(list.data(), sizeof(double), list.size(), fp);
}

/* ---------------------------------------------------------------------- */

void FixCellTurgor::restart(char *buf)
{
  const double *list = (double *) buf;
  const int version = CellRestart::version(list[0]);
  CellRestart::refuse_newer(error, FLERR, "Fix cell/turgor", version, RESTART_VERSION);
  if (version >= 2) list++;
  const double count = list[0];
  if (!(count >= 0.0 && count == floor(count)))
    error->all(FLERR,
               "Fix cell/turgor: the restart file's state (format version {}) is not valid: "
               "number of cells = {}",
               version, count);
  const int n = (int) count;
  physical_time = list[1];
  water_moved = list[2];
  // accel auto continues from the adapted accel and its window when the file has them (4)
  const bool adapted = version >= 4 && accel.read(&list[3]);
  if (version >= 5) water_exchanged = list[8];
  if (version >= 6) moved_pending = list[9], time_pending = list[10], evaluated = (bigint) list[11];
  if (version >= 7) accel.read_edges(&list[12]);
  state.clear();
  bool other_pi0 = false, other_solids = false;
  const int nvalues = TurgorState::restart_values(version);
  for (int k = 0; k < n; k++) {
    const double *v = &list[1 + restart_globals(version) + nvalues * k];
    // version 1 files written before the offset was stored had 4 values per cell: caught here
    if (!(v[0] >= 1.0 && v[0] == floor(v[0]) && (v[3] == 0.0 || v[3] == 1.0)))
      error->all(FLERR,
                 "Fix cell/turgor: the restart file's state (format version {}) is not valid at "
                 "cell {} of {}: ID = {}, warned = {}",
                 version, k + 1, n, v[0], v[3]);
    // solids from version 3 on; older files: from 'solids' and M0 at the first evaluation
    const double solids = version >= 3 ? v[5] : 0.0;
    TurgorState::Cell cell{v[1], v[2], (int) v[3], v[4], solids, 0.0, 0.0, 0.0, {}};
    if (adapted) std::copy(v + 6, v + 6 + TurgorAccel::NPROBE, cell.probe);
    // the wall's water from version 8 on; older files: the wall first seen at the next evaluation
    if (version >= 8) {
      cell.wall_dry = v[16], cell.wall_x0 = v[17];
      cell.wall_x = v[18], cell.wall_dx = v[19];
    }
    // every rank holds every cell until init() keeps its home cells
    state[(tagint) v[0]] = cell;
    other_pi0 = other_pi0 || v[2] != pi0;
    other_solids = other_solids ||
        (solids > 0.0 && osmotic_model.solids_fraction > 0.0 &&
         fabs(solids - osmotic_model.solids(v[1])) > 1e-12 * solids);
  }
  if (other_pi0 && comm->me == 0)
    error->warning(FLERR,
                   "Fix cell/turgor: cells continue with the osmotic pressure pi0 stored in the "
                   "restart file, not pi0 = {}",
                   pi0);
  if (other_solids && comm->me == 0)
    error->warning(
        FLERR,
        "Fix cell/turgor: cells continue with the dry solids stored in the restart file, "
        "not those of solids = {}",
        osmotic_model.solids_fraction);
}

/* ---------------------------------------------------------------------- */

int FixCellTurgor::pack_forward_comm(int n, int *list, double *buf, int, int *)
{
  for (int k = 0; k < n; k++) buf[k] = atom->rmass[list[k]];
  return n;
}

/* ---------------------------------------------------------------------- */

void FixCellTurgor::unpack_forward_comm(int n, int first, double *buf)
{
  for (int k = 0; k < n; k++) atom->rmass[first + k] = buf[k];
}

/* ----------------------------------------------------------------------
   per atom: the waiting transfer's relative mass change (0 for atoms that get none)
------------------------------------------------------------------------- */

void FixCellTurgor::grow_arrays(int nmax)
{
  memory->grow(pending, nmax, "cell/turgor:pending");
}

void FixCellTurgor::copy_arrays(int i, int j, int)
{
  pending[j] = pending[i];
}

void FixCellTurgor::set_arrays(int i)
{
  pending[i] = 0.0;
}

int FixCellTurgor::pack_exchange(int i, double *buf)
{
  buf[0] = pending[i];
  return 1;
}

int FixCellTurgor::unpack_exchange(int nlocal, double *buf)
{
  pending[nlocal] = buf[0];
  return 1;
}

/* ----------------------------------------------------------------------
   restart: the count of values (2) first, as every fix with per-atom restart data
------------------------------------------------------------------------- */

int FixCellTurgor::pack_restart(int i, double *buf)
{
  buf[0] = 2;
  buf[1] = pending[i];
  return 2;
}

void FixCellTurgor::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  pending[nlocal] = extra[nlocal][m + 1];
}

int FixCellTurgor::size_restart(int)
{
  return 2;
}

int FixCellTurgor::maxsize_restart()
{
  return 2;
}

double FixCellTurgor::memory_usage()
{
  return (double) atom->nmax * sizeof(double);
}
