/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   bond_style cell/lamella: the middle lamella between the walls of two neighbouring cells, a
   linear traction-separation law per unit junction area that breaks for good at its strength
   (doc/model.md §4.6). Rest length: the bond's length at its first setup, kept per bond by the
   internal fix cell/bond/history (BondCellBase), so it moves between ranks and into restart files.
------------------------------------------------------------------------- */

#include "bond_cell_lamella.h"

#include "atom.h"
#include "cell_bond.h"
#include "cell_limits.h"
#include "cell_params.h"
#include "cell_restart.h"
#include "comm.h"
#include "error.h"
#include "fix_cell_bond_history.h"
#include "force.h"
#include "memory.h"
#include "neighbor.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

static constexpr int RESTART_VERSION = 1;    // the payload begins with -version

/* ---------------------------------------------------------------------- */

BondCellLamella::BondCellLamella(LAMMPS *lmp) :
    BondCellBase(lmp, "cell/lamella", "cellbond_lamella", 1), stiffness(nullptr), strength(nullptr),
    area(nullptr), gamma(nullptr), kbond(nullptr), dcrit(nullptr), r0max(0.0)
{
  writedata = 1;
}

/* ---------------------------------------------------------------------- */

BondCellLamella::~BondCellLamella()
{
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(stiffness);
    memory->destroy(strength);
    memory->destroy(area);
    memory->destroy(gamma);
    memory->destroy(kbond);
    memory->destroy(dcrit);
  }
}

/* ----------------------------------------------------------------------
   every bond is evaluated from its lower-tag atom to its higher-tag atom, so that every rank
   computing it (two with newton_bond off) gets the same opening, to the bit, and breaks it alike
------------------------------------------------------------------------- */

void BondCellLamella::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);

  double **x = atom->x;
  double **v = atom->v;
  double **f = atom->f;
  const tagint *tag = atom->tag;
  const tagint *molecule = atom->molecule;
  int **bondlist = neighbor->bondlist;
  const int nbondlist = neighbor->nbondlist;
  const int nlocal = atom->nlocal;
  const int newton_bond = force->newton_bond;
  double ebond = 0.0;

  for (int n = 0; n < nbondlist; n++) {
    const int type = bondlist[n][2];
    if (type <= 0) continue;
    const int i1 = tag[bondlist[n][0]] < tag[bondlist[n][1]] ? bondlist[n][0] : bondlist[n][1];
    const int i2 = i1 == bondlist[n][0] ? bondlist[n][1] : bondlist[n][0];
    if (molecule[i1] == molecule[i2])
      error->one(FLERR,
                 "Bond cell/lamella: bond {}-{} joins two atoms of the same cell {}: a junction "
                 "bond must join two cells (molecule IDs)",
                 tag[i1], tag[i2], molecule[i1]);

    const double delx = x[i1][0] - x[i2][0];
    const double dely = x[i1][1] - x[i2][1];
    const double delz = x[i1][2] - x[i2][2];
    const double r = sqrt(delx * delx + dely * dely + delz * delz);
    if (r == 0.0)
      error->one(FLERR, "Bond cell/lamella: atoms {} and {} coincide", tag[i1], tag[i2]);

    double *r0 = reference(i1, i2, type);
    if (!r0) error->one(FLERR, "Bond cell/lamella: bond {}-{} has no local copy", tag[i1], tag[i2]);
    // first setup of this bond: its rest length is its length now
    if (*r0 == FixCellBondHistory::UNSET) set_reference(i1, i2, type, &r);

    // opening delta = r - r0; traction K delta >= sigma_c breaks the bond (doc/model.md §4.6)
    const double delta = r - *r0;
    if (delta >= dcrit[type]) {
      break_bond(n, i1, i2, type);
      continue;
    }

    // F = -K A delta along the bond, U = K A delta^2 / 2 (doc/model.md §4.6)
    double fbond = -kbond[type] * delta / r;
    if (eflag) ebond = 0.5 * kbond[type] * delta * delta;

    // F^d = -gamma ((v1 - v2) . e) e, on the opening rate only (doc/model.md §4.3)
    if (gamma[type] > 0.0)
      fbond += CellBond::damping(v[i1], v[i2], delx, dely, delz, r, gamma[type]);

    CellBond::apply(f, i1, i2, nlocal, newton_bond, fbond, delx, dely, delz);
    if (evflag) ev_tally(i1, i2, nlocal, newton_bond, ebond, fbond, delx, dely, delz);
  }
}

/* ---------------------------------------------------------------------- */

void BondCellLamella::allocate()
{
  allocated = 1;
  const int n = atom->nbondtypes + 1;
  memory->create(stiffness, n, "bond:stiffness");
  memory->create(strength, n, "bond:strength");
  memory->create(area, n, "bond:area");
  memory->create(gamma, n, "bond:gamma");
  memory->create(kbond, n, "bond:kbond");
  memory->create(dcrit, n, "bond:dcrit");
  memory->create(setflag, n, "bond:setflag");
  for (int i = 0; i < n; i++) {
    setflag[i] = 0;
    stiffness[i] = strength[i] = area[i] = gamma[i] = kbond[i] = dcrit[i] = 0.0;
  }
}

/* ----------------------------------------------------------------------
   bond_coeff N K sigma_c A gamma
   bond_coeff N file <parameter file>   (keys lamella_K, lamella_sigma, lamella_area, lamella_gamma)
------------------------------------------------------------------------- */

void BondCellLamella::coeff(int narg, char **arg)
{
  if (!allocated) allocate();
  if (narg < 1) error->all(FLERR, "Incorrect args for bond_coeff cell/lamella");
  int ilo, ihi;
  utils::bounds(FLERR, arg[0], 1, atom->nbondtypes, ilo, ihi, error);

  double k_one, s_one, a_one, g_one;
  if (narg >= 2 && strcmp(arg[1], "file") == 0) {
    if (narg != 3)
      error->all(FLERR,
                 "Incorrect args for bond_coeff cell/lamella: expected 'bond_coeff <type> "
                 "file <parameter file>', got {} args",
                 narg);
    CellParams params(lmp, arg[2], "bond_coeff cell/lamella");
    k_one = params.positive("lamella_K", CellLimits::LAMELLA_K_MAX, "Pa/m");
    s_one = params.positive("lamella_sigma");
    a_one = params.positive("lamella_area", CellLimits::LAMELLA_AREA_MAX, "m^2");
    g_one = params.nonnegative("lamella_gamma", CellLimits::GAMMA_MAX, "N s/m");
  } else {
    if (narg >= 2 && !utils::is_double(arg[1]))
      error->all(FLERR,
                 "Bond_coeff cell/lamella: unknown keyword '{}' (expected 'file' or numbers)",
                 arg[1]);
    if (narg != 5) {
      error->all(FLERR,
                 "Incorrect args for bond_coeff cell/lamella: expected 'bond_coeff <type> <K> "
                 "<sigma_c> <A> <gamma>' or 'bond_coeff <type> file <parameter file>', got {} args",
                 narg);
    }
    k_one = utils::numeric(FLERR, arg[1], false, lmp);
    s_one = utils::numeric(FLERR, arg[2], false, lmp);
    a_one = utils::numeric(FLERR, arg[3], false, lmp);
    g_one = utils::numeric(FLERR, arg[4], false, lmp);
    if (k_one <= 0.0)
      error->all(FLERR, "Bond_coeff cell/lamella: stiffness K = {} must be > 0", k_one);
    if (s_one <= 0.0)
      error->all(FLERR, "Bond_coeff cell/lamella: strength sigma_c = {} must be > 0", s_one);
    if (a_one <= 0.0)
      error->all(FLERR, "Bond_coeff cell/lamella: junction area per bond A = {} must be > 0",
                 a_one);
    if (g_one < 0.0)
      error->all(FLERR, "Bond_coeff cell/lamella: damping gamma = {} must be >= 0", g_one);
    // the ranges keep K A finite; sigma_c has no upper bound (doc/bond_cell_lamella.md, Ranges)
    const std::string c = "Bond_coeff cell/lamella: ";
    CellLimits::within(error, c + "stiffness K", k_one, 0.0, CellLimits::LAMELLA_K_MAX, "Pa/m",
                       true);
    CellLimits::within(error, c + "junction area per bond A", a_one, 0.0,
                       CellLimits::LAMELLA_AREA_MAX, "m^2", true);
    CellLimits::within(error, c + "damping gamma", g_one, 0.0, CellLimits::GAMMA_MAX, "N s/m",
                       false);
  }

  for (int i = ilo; i <= ihi; i++) {
    stiffness[i] = k_one;
    strength[i] = s_one;
    area[i] = a_one;
    gamma[i] = g_one;
    setflag[i] = 1;
  }
  init_history();    // from here on f_<history ID> can be used in thermo_style
}

/* ----------------------------------------------------------------------
   molecule IDs, ghost velocities for damping, the history fix, constants, longest rest length
------------------------------------------------------------------------- */

void BondCellLamella::init_style()
{
  if (!atom->molecule_flag)
    error->all(FLERR,
               "Bond style cell/lamella needs molecule (cell) IDs: use atom_style angle "
               "(or bond, molecular, full)");

  for (int i = 1; i <= atom->nbondtypes; i++) {
    kbond[i] = stiffness[i] * area[i];        // k = K A
    dcrit[i] = strength[i] / stiffness[i];    // delta_c = sigma_c / K
  }
  CellBond::require_ghost_velocity(lmp, "cell/lamella", gamma, atom->nbondtypes);

  init_history();

  double lmax = 0.0;
  for (int i = 0; i < atom->nlocal; i++)
    for (int m = 0; m < atom->num_bond[i]; m++) {
      const int type = atom->bond_type[i][m];
      if (type > 0 && setflag[type]) lmax = std::max(lmax, history->value(i, m, 0));
    }
  MPI_Allreduce(&lmax, &r0max, 1, MPI_DOUBLE, MPI_MAX, world);
}

/* ---------------------------------------------------------------------- */

double BondCellLamella::equilibrium_distance(int)
{
  return r0max;
}

/* ---------------------------------------------------------------------- */

void BondCellLamella::write_restart(FILE *fp)
{
  CellRestart::write_columns(fp, RESTART_VERSION, atom->nbondtypes, &stiffness[1], &strength[1],
                             &area[1], &gamma[1]);
}

/* ---------------------------------------------------------------------- */

void BondCellLamella::read_restart(FILE *fp)
{
  allocate();
  const int n = atom->nbondtypes;
  CellRestart::read_version(lmp, fp, FLERR, "Bond style cell/lamella", RESTART_VERSION);
  CellRestart::read_columns(lmp, fp, n, &stiffness[1], &strength[1], &area[1], &gamma[1]);
  for (int i = 1; i <= n; i++) setflag[i] = 1;
}

/* ---------------------------------------------------------------------- */

void BondCellLamella::write_data(FILE *fp)
{
  for (int i = 1; i <= atom->nbondtypes; i++)
    fprintf(fp, "%d %.16g %.16g %.16g %.16g\n", i, stiffness[i], strength[i], area[i], gamma[i]);
}

/* ----------------------------------------------------------------------
   conservative part of an intact bond; zero before its first setup
------------------------------------------------------------------------- */

double BondCellLamella::single(int type, double rsq, int i, int j, double &fforce)
{
  fforce = 0.0;
  const double *r0 = reference(i, j, type);
  if (!r0 || *r0 == FixCellBondHistory::UNSET) return 0.0;
  const double r = sqrt(rsq);
  const double delta = r - *r0;
  fforce = -kbond[type] * delta / r;
  return 0.5 * kbond[type] * delta * delta;
}

/* ---------------------------------------------------------------------- */

void *BondCellLamella::extract(const char *str, int &dim)
{
  dim = 1;
  if (strcmp(str, "K") == 0) return (void *) stiffness;
  if (strcmp(str, "sigma") == 0) return (void *) strength;
  if (strcmp(str, "area") == 0) return (void *) area;
  if (strcmp(str, "gamma") == 0) return (void *) gamma;
  return nullptr;
}
