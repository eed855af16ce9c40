/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   fix cell/bond/history: per-bond reference state, stored per atom for each of its bond slots.
   LAMMPS 29 Sep 2021 has neither the BPM package nor fix bond/history, so cellsph keeps its own.
------------------------------------------------------------------------- */

#include "fix_cell_bond_history.h"

#include "atom.h"
#include "atom_vec.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neighbor.h"

#include <algorithm>

using namespace LAMMPS_NS;
using namespace FixConst;

/* ----------------------------------------------------------------------
   fix ID all cell/bond/history ndata
------------------------------------------------------------------------- */

FixCellBondHistory::FixCellBondHistory(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), ndata(0), values(nullptr), width(0)
{
  if (narg != 4)
    error->all(FLERR,
               "Illegal fix cell/bond/history command: expected 'fix <ID> all "
               "cell/bond/history <values per bond>'");
  if (!atom->avec->bonds_allow)
    error->all(FLERR, "Fix cell/bond/history: the atom style has no bonds");
  ndata = utils::inumeric(FLERR, arg[3], false, lmp);
  if (ndata < 1)
    error->all(FLERR, "Fix cell/bond/history: values per bond = {} must be >= 1", ndata);

  restart_peratom = 1;
  create_attribute = 1;
  scalar_flag = 1;
  global_freq = 1;
  extscalar = 0;

  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
}

/* ---------------------------------------------------------------------- */

FixCellBondHistory::~FixCellBondHistory()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(values);
}

/* ---------------------------------------------------------------------- */

int FixCellBondHistory::setmask()
{
  return POST_NEIGHBOR | MIN_POST_NEIGHBOR;
}

/* ----------------------------------------------------------------------
   drop broken (type <= 0) bonds from the bond list: 29 Sep 2021 lists them until the next run,
   where bond_style hybrid has no sub-style for type 0
------------------------------------------------------------------------- */

void FixCellBondHistory::post_neighbor()
{
  int **bondlist = neighbor->bondlist;
  int n = 0;
  for (int k = 0; k < neighbor->nbondlist; k++) {
    if (bondlist[k][2] <= 0) continue;
    if (n != k) std::copy(bondlist[k], bondlist[k] + 3, bondlist[n]);
    n++;
  }
  neighbor->nbondlist = n;
}

void FixCellBondHistory::setup_post_neighbor()
{
  post_neighbor();
}

void FixCellBondHistory::min_post_neighbor()
{
  post_neighbor();
}

/* ----------------------------------------------------------------------
   number of broken bonds (type 0) in the system
------------------------------------------------------------------------- */

double FixCellBondHistory::compute_scalar()
{
  const tagint *tag = atom->tag;
  const int newton_bond = force->newton_bond;
  bigint nlocal_broken = 0;
  for (int i = 0; i < atom->nlocal; i++)
    for (int m = 0; m < atom->num_bond[i]; m++)
      if (atom->bond_type[i][m] == 0 && (newton_bond || tag[i] < atom->bond_atom[i][m]))
        nlocal_broken++;
  bigint nbroken = 0;
  MPI_Allreduce(&nlocal_broken, &nbroken, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  return (double) nbroken;
}

/* ---------------------------------------------------------------------- */

int FixCellBondHistory::slot(int i, tagint j, int type) const
{
  for (int m = 0; m < atom->num_bond[i]; m++)
    if (atom->bond_atom[i][m] == j && atom->bond_type[i][m] == type) return m;
  return -1;
}

/* ----------------------------------------------------------------------
   one row per atom of bond_per_atom * ndata values, every slot unset at creation; the row widens
   (new slots unset) when a later read_data ... add raises bond_per_atom
------------------------------------------------------------------------- */

void FixCellBondHistory::grow_arrays(int nmax)
{
  const int wanted = atom->bond_per_atom * ndata;
  if (wanted == width) {
    memory->grow(values, nmax, std::max(width, 1), "cell/bond/history:values");
    return;
  }
  if (wanted < width)
    error->one(FLERR, "Fix cell/bond/history: bonds per atom fell from {} to {}", width / ndata,
               atom->bond_per_atom);
  double **wider = nullptr;
  memory->create(wider, nmax, wanted, "cell/bond/history:values");
  const int nold = values ? std::min(nmax, atom->nlocal + atom->nghost) : 0;
  for (int i = 0; i < nmax; i++) {
    std::fill(wider[i], wider[i] + wanted, UNSET);
    if (i < nold) std::copy(values[i], values[i] + width, wider[i]);
  }
  memory->destroy(values);
  values = wider;
  width = wanted;
}

/* ---------------------------------------------------------------------- */

void FixCellBondHistory::copy_arrays(int i, int j, int)
{
  std::copy(values[i], values[i] + width, values[j]);
}

/* ---------------------------------------------------------------------- */

void FixCellBondHistory::set_arrays(int i)
{
  std::fill(values[i], values[i] + width, UNSET);
}

/* ---------------------------------------------------------------------- */

int FixCellBondHistory::pack_exchange(int i, double *buf)
{
  std::copy(values[i], values[i] + width, buf);
  return width;
}

/* ---------------------------------------------------------------------- */

int FixCellBondHistory::unpack_exchange(int nlocal, double *buf)
{
  std::copy(buf, buf + width, values[nlocal]);
  return width;
}

/* ----------------------------------------------------------------------
   restart: the count of values (width + 1) first, as every fix with per-atom restart data
------------------------------------------------------------------------- */

int FixCellBondHistory::pack_restart(int i, double *buf)
{
  buf[0] = width + 1;
  std::copy(values[i], values[i] + width, buf + 1);
  return width + 1;
}

/* ---------------------------------------------------------------------- */

void FixCellBondHistory::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  const int stored = static_cast<int>(extra[nlocal][m]) - 1;
  set_arrays(nlocal);
  std::copy(&extra[nlocal][m + 1], &extra[nlocal][m + 1] + std::min(stored, width), values[nlocal]);
}

/* ---------------------------------------------------------------------- */

int FixCellBondHistory::size_restart(int)
{
  return width + 1;
}

int FixCellBondHistory::maxsize_restart()
{
  return width + 1;
}

double FixCellBondHistory::memory_usage()
{
  return (double) atom->nmax * width * sizeof(double);
}
