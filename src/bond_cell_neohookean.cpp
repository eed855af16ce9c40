/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   bond_style cell/neohookean: one wall bond of a triangulated Neo-Hookean membrane.
   Rest length of each bond from the per-atom reference positions (d2_xref 3) of its atoms, so it
   moves with the atoms across ranks and through restart and data files.
------------------------------------------------------------------------- */

#include "bond_cell_neohookean.h"

#include "atom.h"
#include "cell_params.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neighbor.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

using namespace LAMMPS_NS;

static const char *const LAW_NAMES[] = {"neohookean", "linear"};

/* ---------------------------------------------------------------------- */

BondCellNeoHookean::BondCellNeoHookean(LAMMPS *lmp) :
    Bond(lmp), shear(nullptr), thickness(nullptr), gamma(nullptr), law(nullptr), kappa(nullptr),
    l0max(nullptr), ixref(-1)
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
    memory->destroy(kappa);
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

    double fbond = -stretch_force(type, r, rest_length(i1, i2), ebond) / r;

    // F^d = -gamma ((v1 - v2) . e) e: damps stretching, not rigid motion (design.md section 1)
    if (gamma[type] > 0.0) {
      const double vr = (v[i1][0] - v[i2][0]) * delx + (v[i1][1] - v[i2][1]) * dely +
          (v[i1][2] - v[i2][2]) * delz;
      fbond -= gamma[type] * vr / (r * r);
    }

    if (newton_bond || i1 < nlocal) {
      f[i1][0] += delx * fbond;
      f[i1][1] += dely * fbond;
      f[i1][2] += delz * fbond;
    }
    if (newton_bond || i2 < nlocal) {
      f[i2][0] -= delx * fbond;
      f[i2][1] -= dely * fbond;
      f[i2][2] -= delz * fbond;
    }
    if (evflag) ev_tally(i1, i2, nlocal, newton_bond, ebond, fbond, delx, dely, delz);
  }
}

/* ----------------------------------------------------------------------
   tension (dU/dl) of a bond of type at length r with rest length l0; energy U into u
------------------------------------------------------------------------- */

double BondCellNeoHookean::stretch_force(int type, double r, double l0, double &u) const
{
  const double k = kappa[type];
  if (law[type] == LINEAR) {
    // F = 2 sqrt(3) G t0 (l - l0): the small-strain tangent of the Neo-Hookean law
    const double dl = r - l0;
    u = 3.0 * k * dl * dl;
    return 6.0 * k * dl;
  }
  // F = (G t0 l0 / sqrt3)(lambda - lambda^-5), U = (sqrt3 G t0 l0^2 / 12)(2 lambda^2 + lambda^-4 - 3)
  // (model-notes.md 5.1, law 3: exact equibiaxial Neo-Hookean membrane tension)
  const double lam = r / l0;
  const double lam2 = lam * lam;
  const double lam4 = lam2 * lam2;
  u = 0.25 * k * l0 * l0 * (2.0 * lam2 + 1.0 / lam4 - 3.0);
  return k * l0 * (lam - 1.0 / (lam4 * lam));
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
  memory->create(kappa, n, "bond:kappa");
  memory->create(l0max, n, "bond:l0max");
  memory->create(setflag, n, "bond:setflag");
  for (int i = 0; i < n; i++) {
    setflag[i] = 0;
    kappa[i] = l0max[i] = 0.0;
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
    g_one = params.positive("wall_G");
    t_one = params.positive("wall_t0");
    gamma_one = params.nonnegative("wall_gamma");
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
   check the per-atom fields, precompute G t0 / sqrt3 and the longest rest length per type
------------------------------------------------------------------------- */

void BondCellNeoHookean::init_style()
{
  int flag, cols;
  ixref = atom->find_custom("xref", flag, cols);
  if (ixref < 0 || flag != 1 || cols != 3)
    error->all(FLERR,
               "Bond style cell/neohookean needs per-atom reference positions: add "
               "'fix <ID> all property/atom d2_xref 3 ghost yes' before read_data");

  bool damped = false;
  for (int i = 1; i <= atom->nbondtypes; i++) {
    kappa[i] = shear[i] * thickness[i] / sqrt(3.0);
    damped = damped || gamma[i] > 0.0;
  }
  if (damped && !comm->ghost_velocity)
    error->all(FLERR,
               "Bond style cell/neohookean with damping gamma > 0 needs ghost velocities: "
               "use 'comm_modify vel yes'");

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
  const int n = atom->nbondtypes;
  fwrite(&shear[1], sizeof(double), n, fp);
  fwrite(&thickness[1], sizeof(double), n, fp);
  fwrite(&gamma[1], sizeof(double), n, fp);
  fwrite(&law[1], sizeof(int), n, fp);
}

/* ---------------------------------------------------------------------- */

void BondCellNeoHookean::read_restart(FILE *fp)
{
  allocate();
  const int n = atom->nbondtypes;
  if (comm->me == 0) {
    utils::sfread(FLERR, &shear[1], sizeof(double), n, fp, nullptr, error);
    utils::sfread(FLERR, &thickness[1], sizeof(double), n, fp, nullptr, error);
    utils::sfread(FLERR, &gamma[1], sizeof(double), n, fp, nullptr, error);
    utils::sfread(FLERR, &law[1], sizeof(int), n, fp, nullptr, error);
  }
  MPI_Bcast(&shear[1], n, MPI_DOUBLE, 0, world);
  MPI_Bcast(&thickness[1], n, MPI_DOUBLE, 0, world);
  MPI_Bcast(&gamma[1], n, MPI_DOUBLE, 0, world);
  MPI_Bcast(&law[1], n, MPI_INT, 0, world);
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
  double u;
  fforce = -stretch_force(type, r, rest_length(i, j), u) / r;
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
