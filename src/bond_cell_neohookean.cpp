/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   bond_style cell/neohookean: one wall bond of a triangulated Neo-Hookean membrane.
   Rest length of each bond from the per-atom reference positions (d2_xref 3) of its atoms, so it
   moves with the atoms across ranks and through restart and data files; scaled by the wall's
   stress-free stretch when a fix sets it (cell_styles.h CellWallStretch).
------------------------------------------------------------------------- */

#include "bond_cell_neohookean.h"

#include "atom.h"
#include "cell_bond.h"
#include "cell_limits.h"
#include "cell_params.h"
#include "cell_restart.h"
#include "cell_styles.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

using namespace LAMMPS_NS;

static const char *const LAW_NAMES[] = {"neohookean", "linear"};
static constexpr double SQRT3_6 = 0.28867513459481287;    // sqrt(3) / 6
static constexpr int RESTART_VERSION = 2;    // 2: the payload begins with -version (1: none)

/* ---------------------------------------------------------------------- */

BondCellNeoHookean::BondCellNeoHookean(LAMMPS *lmp) :
    Bond(lmp), shear(nullptr), thickness(nullptr), gamma(nullptr), law(nullptr), gt0(nullptr),
    l0max(nullptr), ixref(-1), iaref(-1)
{
  writedata = 1;
}

/* ---------------------------------------------------------------------- */

BondCellNeoHookean::~BondCellNeoHookean()
{
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(shear);
    memory->destroy(thickness);
    memory->destroy(gamma);
    memory->destroy(law);
    memory->destroy(gt0);
    memory->destroy(l0max);
  }
}

/* ---------------------------------------------------------------------- */

void BondCellNeoHookean::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);

  double **x = atom->x;
  double **v = atom->v;
  double **f = atom->f;
  int **bondlist = neighbor->bondlist;
  const int nbondlist = neighbor->nbondlist;
  const int nlocal = atom->nlocal;
  const int newton_bond = force->newton_bond;
  const double *stretch = stretch_last = wall_stretch();
  stretch_step = update->ntimestep;
  double ebond = 0.0;

  for (int n = 0; n < nbondlist; n++) {
    const int i1 = bondlist[n][0];
    const int i2 = bondlist[n][1];
    const int type = bondlist[n][2];

    const double delx = x[i1][0] - x[i2][0];
    const double dely = x[i1][1] - x[i2][1];
    const double delz = x[i1][2] - x[i2][2];
    const double r = sqrt(delx * delx + dely * dely + delz * delz);
    if (r == 0.0)
      error->one(FLERR, "Bond cell/neohookean: atoms {} and {} coincide", atom->tag[i1],
                 atom->tag[i2]);

    double l0, area;
    reference(i1, i2, stretch, l0, area);
    double fbond = -stretch_force(type, r, l0, area, ebond) / r;

    // F^d = -gamma ((v1 - v2) . e) e, damps stretching, not rigid motion (doc/model.md §4.3)
    if (gamma[type] > 0.0)
      fbond += CellBond::damping(v[i1], v[i2], delx, dely, delz, r, gamma[type]);

    CellBond::apply(f, i1, i2, nlocal, newton_bond, fbond, delx, dely, delz);
    if (evflag) ev_tally(i1, i2, nlocal, newton_bond, ebond, fbond, delx, dely, delz);
  }
}

/* ----------------------------------------------------------------------
   tension dU/dl of a bond of type at length r, rest length l0, reference area a; energy U into u.
   A bond carries the membrane energy of its area a: U = (G t0 a / 2)(2 lam^2 + lam^-4 - 3), the
   incompressible Neo-Hookean membrane energy per area under equibiaxial stretch (doc/model.md
   §4.1), so a closed wall under uniform stretch has exactly the tension G t0 (1 - lam^-6).
------------------------------------------------------------------------- */

double BondCellNeoHookean::stretch_force(int type, double r, double l0, double a, double &u) const
{
  const double c = gt0[type] * a;
  if (law[type] == LINEAR) {
    // F = 12 G t0 a (l - l0) / l0^2: the small-strain tangent of the Neo-Hookean law
    const double strain = (r - l0) / l0;
    u = 6.0 * c * strain * strain;
    return 12.0 * c * strain / l0;
  }
  // F = dU/dl = 2 G t0 a (lam - lam^-5) / l0
  const double lam = r / l0;
  const double lam2 = lam * lam;
  const double lam4 = lam2 * lam2;
  u = 0.5 * c * (2.0 * lam2 + 1.0 / lam4 - 3.0);
  return 2.0 * c * (lam - 1.0 / (lam4 * lam)) / l0;
}

/* ----------------------------------------------------------------------
   reference wall area of the bond between local atoms i and j: aref_i + aref_j (tools/cellgen),
   or without aref that of a bond in an equilateral mesh, sqrt(3) l0^2 / 6
------------------------------------------------------------------------- */

double BondCellNeoHookean::bond_area(int i, int j, double l0) const
{
  if (iaref < 0) return SQRT3_6 * l0 * l0;
  const double *aref = atom->dvector[iaref];
  const double a = aref[i] + aref[j];
  if (a <= 0.0)
    error->one(FLERR, "Bond cell/neohookean: bond {}-{} has reference area aref_i + aref_j = {}",
               atom->tag[i], atom->tag[j], a);
  return a;
}

/* ----------------------------------------------------------------------
   rest length l0 and area a of the bond between local atoms i and j: from xref and aref, times
   s and s^2 with a wall stretch s per atom (s the mean of the two; doc/model.md §5.15)
------------------------------------------------------------------------- */

void BondCellNeoHookean::reference(int i, int j, const double *stretch, double &l0, double &a) const
{
  l0 = rest_length(i, j);
  a = bond_area(i, j, l0);
  if (!stretch) return;
  // l0 <- s l0, a <- s^2 a: the stress-free wall shrinks in its plane (doc/model.md §5.15)
  const double s = 0.5 * (stretch[i] + stretch[j]);
  l0 *= s;
  a *= s * s;
}

/* ----------------------------------------------------------------------
   each atom's wall stretch from the one fix that sets it at this step, nullptr if none does
------------------------------------------------------------------------- */

const double *BondCellNeoHookean::wall_stretch() const
{
  const double *found = nullptr;
  for (CellWallStretch *fix : stretchers)
    if (const double *s = fix->wall_stretch()) {
      if (found)
        error->all(FLERR,
                   "Bond cell/neohookean: two fixes set the wall's stretch (wallwater of "
                   "fix cell/turgor): use one");
      found = s;
    }
  return found;
}

/* ----------------------------------------------------------------------
   rest length |xref_i - xref_j| of the bond between local atoms i and j
------------------------------------------------------------------------- */

double BondCellNeoHookean::rest_length(int i, int j) const
{
  double **xref = atom->darray[ixref];
  double d[3] = {xref[i][0] - xref[j][0], xref[i][1] - xref[j][1], xref[i][2] - xref[j][2]};
  domain->minimum_image(d[0], d[1], d[2]);
  return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

/* ---------------------------------------------------------------------- */

void BondCellNeoHookean::allocate()
{
  allocated = 1;
  const int n = atom->nbondtypes + 1;
  memory->create(shear, n, "bond:shear");
  memory->create(thickness, n, "bond:thickness");
  memory->create(gamma, n, "bond:gamma");
  memory->create(law, n, "bond:law");
  memory->create(gt0, n, "bond:gt0");
  memory->create(l0max, n, "bond:l0max");
  memory->create(setflag, n, "bond:setflag");
  for (int i = 0; i < n; i++) {
    setflag[i] = 0;
    gt0[i] = l0max[i] = 0.0;
  }
}

/* ----------------------------------------------------------------------
   bond_coeff N G t0 gamma [law neohookean|linear]
   bond_coeff N file <parameter file>     (keys wall_G, wall_t0, wall_gamma, optional wall_law)
------------------------------------------------------------------------- */

void BondCellNeoHookean::coeff(int narg, char **arg)
{
  if (!allocated) allocate();
  int ilo, ihi;
  if (narg < 1) error->all(FLERR, "Incorrect args for bond_coeff cell/neohookean");
  utils::bounds(FLERR, arg[0], 1, atom->nbondtypes, ilo, ihi, error);

  double g_one, t_one, gamma_one;
  int law_one = NEOHOOKEAN;
  if (narg == 3 && strcmp(arg[1], "file") == 0) {
    CellParams params(lmp, arg[2], "bond_coeff cell/neohookean");
    g_one = params.positive("wall_G", CellLimits::WALL_G_MAX, "Pa");
    t_one = params.positive("wall_t0", CellLimits::WALL_T0_MAX, "m");
    gamma_one = params.nonnegative("wall_gamma", CellLimits::GAMMA_MAX, "N s/m");
    if (params.has("wall_law")) law_one = parse_law(params.word("wall_law"));
  } else {
    if (narg != 4 && narg != 6)
      error->all(FLERR,
                 "Incorrect args for bond_coeff cell/neohookean: expected 'bond_coeff <type> "
                 "<G> <t0> <gamma> [law neohookean|linear]' or 'bond_coeff <type> file "
                 "<parameter file>', got {} args",
                 narg);
    g_one = utils::numeric(FLERR, arg[1], false, lmp);
    t_one = utils::numeric(FLERR, arg[2], false, lmp);
    gamma_one = utils::numeric(FLERR, arg[3], false, lmp);
    if (g_one <= 0.0)
      error->all(FLERR, "Bond_coeff cell/neohookean: shear modulus G = {} must be > 0", g_one);
    if (t_one <= 0.0)
      error->all(FLERR, "Bond_coeff cell/neohookean: wall thickness t0 = {} must be > 0", t_one);
    if (gamma_one < 0.0)
      error->all(FLERR, "Bond_coeff cell/neohookean: damping gamma = {} must be >= 0", gamma_one);
    // the ranges keep G t0 finite (doc/bond_cell_neohookean.md, Ranges)
    const std::string c = "Bond_coeff cell/neohookean: ";
    CellLimits::within(error, c + "shear modulus G", g_one, 0.0, CellLimits::WALL_G_MAX, "Pa",
                       true);
    CellLimits::within(error, c + "wall thickness t0", t_one, 0.0, CellLimits::WALL_T0_MAX, "m",
                       true);
    CellLimits::within(error, c + "damping gamma", gamma_one, 0.0, CellLimits::GAMMA_MAX, "N s/m",
                       false);
    if (narg == 6) {
      if (strcmp(arg[4], "law") != 0)
        error->all(FLERR, "Bond_coeff cell/neohookean: unknown keyword '{}' (expected 'law')",
                   arg[4]);
      law_one = parse_law(arg[5]);
    }
  }

  for (int i = ilo; i <= ihi; i++) {
    shear[i] = g_one;
    thickness[i] = t_one;
    gamma[i] = gamma_one;
    law[i] = law_one;
    setflag[i] = 1;
  }
}

/* ---------------------------------------------------------------------- */

int BondCellNeoHookean::parse_law(const std::string &name)
{
  for (int l : {NEOHOOKEAN, LINEAR})
    if (name == LAW_NAMES[l]) return l;
  error->all(FLERR, "Bond_coeff cell/neohookean: unknown law '{}' (expected neohookean or linear)",
             name);
  return NEOHOOKEAN;
}

/* ----------------------------------------------------------------------
   check the per-atom fields, precompute G t0 and the longest rest length per type
------------------------------------------------------------------------- */

void BondCellNeoHookean::init_style()
{
  int flag, cols;
  ixref = atom->find_custom(CellField::XREF, flag, cols);
  if (ixref < 0 || flag != 1 || cols != 3)
    error->all(FLERR,
               "Bond style cell/neohookean needs per-atom reference positions: add "
               "'fix <ID> all property/atom d2_xref 3 ghost yes' (or 'cell/atoms') before "
               "read_data");

  iaref = atom->find_custom(CellField::AREF, flag, cols);
  if (iaref >= 0 && (flag != 1 || cols != 0))
    error->all(FLERR, "Bond style cell/neohookean: per-atom 'aref' must be a d_aref vector");

  for (int i = 1; i <= atom->nbondtypes; i++) gt0[i] = shear[i] * thickness[i];
  stretchers = cell_fixes<CellWallStretch>(modify);
  CellBond::require_ghost_velocity(lmp, "cell/neohookean", gamma, atom->nbondtypes);

  std::vector<double> lmax(atom->nbondtypes + 1, 0.0);
  for (int i = 0; i < atom->nlocal; i++)
    for (int m = 0; m < atom->num_bond[i]; m++) {
      const int j = atom->map(atom->bond_atom[i][m]);
      const int type = atom->bond_type[i][m];
      if (j >= 0 && type > 0) lmax[type] = std::max(lmax[type], rest_length(i, j));
    }
  MPI_Allreduce(lmax.data(), l0max, atom->nbondtypes + 1, MPI_DOUBLE, MPI_MAX, world);
}

/* ---------------------------------------------------------------------- */

double BondCellNeoHookean::equilibrium_distance(int type)
{
  return l0max[type];
}

/* ---------------------------------------------------------------------- */

void BondCellNeoHookean::write_restart(FILE *fp)
{
  // version 1 (no marker) began with G of bond type 1 > 0; later versions with -version
  CellRestart::write_columns(fp, RESTART_VERSION, atom->nbondtypes, &shear[1], &thickness[1],
                             &gamma[1], &law[1]);
}

/* ---------------------------------------------------------------------- */

void BondCellNeoHookean::read_restart(FILE *fp)
{
  allocate();
  const int n = atom->nbondtypes;
  double first = 0.0;
  const int version = CellRestart::read_version(lmp, fp, FLERR, "Bond style cell/neohookean",
                                                RESTART_VERSION, &first);
  // version 1: the value read was G of bond type 1
  if (version == 1) shear[1] = first;
  const int skip = version == 1 ? 1 : 0;
  CellRestart::read_columns(lmp, fp, n - skip, &shear[1 + skip]);
  CellRestart::read_columns(lmp, fp, n, &thickness[1], &gamma[1], &law[1]);
  for (int i = 1; i <= n; i++) setflag[i] = 1;
}

/* ---------------------------------------------------------------------- */

void BondCellNeoHookean::write_data(FILE *fp)
{
  for (int i = 1; i <= atom->nbondtypes; i++)
    fprintf(fp, "%d %.16g %.16g %.16g law %s\n", i, shear[i], thickness[i], gamma[i],
            LAW_NAMES[law[i]]);
}

/* ----------------------------------------------------------------------
   conservative part only: damping needs velocities, which single() does not get
------------------------------------------------------------------------- */

double BondCellNeoHookean::single(int type, double rsq, int i, int j, double &fforce)
{
  const double r = sqrt(rsq);
  double u, l0, area;
  // the stretch of this step's compute() (a fix fills it per atom: not again per bond)
  const double *stretch = stretch_step == update->ntimestep ? stretch_last : wall_stretch();
  reference(i, j, stretch, l0, area);
  fforce = -stretch_force(type, r, l0, area, u) / r;
  return u;
}

/* ---------------------------------------------------------------------- */

void *BondCellNeoHookean::extract(const char *str, int &dim)
{
  dim = 1;
  if (strcmp(str, "G") == 0) return (void *) shear;
  if (strcmp(str, "t0") == 0) return (void *) thickness;
  if (strcmp(str, "gamma") == 0) return (void *) gamma;
  return nullptr;
}
