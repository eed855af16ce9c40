/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   dihedral_style cell/bending: the bending energy of a triangulated thin wall, one term per
   interior edge b-c shared by the wall triangles (a, b, c) and (d, c, b), both outward.
   Rest angle and stiffness of each edge come from the per-atom reference positions (d2_xref 3)
   of its four atoms, so the reference shape carries no bending energy (doc/dihedral_cell_bending.md).
------------------------------------------------------------------------- */

#include "dihedral_cell_bending.h"

#include "atom.h"
#include "cell_limits.h"
#include "cell_params.h"
#include "cell_restart.h"
#include "cell_styles.h"
#include "cell_triangle.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neighbor.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

static const char *const REFERENCE_NAMES[] = {"xref", "flat"};
static const char *const FORM_NAMES[] = {"cos", "tan"};
// 1: -version, G, t0, reference per type; 2: and form per type (version 1: cos)
static constexpr int RESTART_VERSION = 2;

namespace {

using CellTriangle::cross;
using CellTriangle::dot;

// the hinge of the triangles (a, b, c) and (d, c, b) about the edge e = x_c - x_b, with
// u1 = x_a - x_b and u2 = x_d - x_b
struct Hinge {
  double n1[3], n2[3];    // e x u1 and u2 x e: outward normals, |n| = twice the triangle area
  double nn1, nn2;        // |n1|^2, |n2|^2
  double ee;              // |e|^2
  double c, s;            // cos and sin of the bend angle theta (> 0 where the wall is convex)
};

// false if a triangle has zero area
bool hinge(const double *e, const double *u1, const double *u2, Hinge &h)
{
  cross(e, u1, h.n1);
  cross(u2, e, h.n2);
  h.nn1 = dot(h.n1, h.n1);
  h.nn2 = dot(h.n2, h.n2);
  h.ee = dot(e, e);
  if (h.nn1 == 0.0 || h.nn2 == 0.0) return false;
  const double inv = 1.0 / sqrt(h.nn1 * h.nn2);
  double m[3];
  cross(h.n1, h.n2, m);
  // theta = angle from n1 to n2 about e (doc/dihedral_cell_bending.md)
  h.c = dot(h.n1, h.n2) * inv;
  h.s = dot(m, e) * inv / sqrt(h.ee);
  return true;
}

// energy and dE/dtheta of a dihedral with bending modulus kappa at hinge h about its reference h0
// (flat: theta0 = 0; tanform: form tan, else cos); false where form tan is infinite
bool bend(double kappa, bool flat, bool tanform, const Hinge &h, const Hinge &h0, double &edihedral,
          double &dedth)
{
  // k = kappa l0^2 / (A1 + A2), reference edge length and triangle areas (doc/model.md §4.2)
  const double k = 2.0 * kappa * h0.ee / (sqrt(h0.nn1) + sqrt(h0.nn2));
  const double c0 = flat ? 1.0 : h0.c;
  const double s0 = flat ? 0.0 : h0.s;

  // 1 - cos(theta - theta0) and sin(theta - theta0)
  const double omc = 1.0 - h.c * c0 - h.s * s0;
  const double sin_bend = h.s * c0 - h.c * s0;
  if (tanform) {
    const double opc = 2.0 - omc;    // 1 + cos(theta - theta0)
    if (opc <= 0.0) return false;
    // E = 2k tan^2((theta - theta0)/2) = 2k (1 - cos)/(1 + cos), dE/dtheta = 4k sin/(1 + cos)^2
    // (doc/dihedral_cell_bending.md, form tan)
    edihedral = 2.0 * k * omc / opc;
    dedth = 4.0 * k * sin_bend / (opc * opc);
  } else {
    // E = k (1 - cos(theta - theta0)), dE/dtheta = k sin(theta - theta0)
    edihedral = k * omc;
    dedth = k * sin_bend;
  }

  return true;
}

}    // namespace

/* ---------------------------------------------------------------------- */

DihedralCellBending::DihedralCellBending(LAMMPS *lmp) :
    Dihedral(lmp), shear(nullptr), thickness(nullptr), reference(nullptr), form(nullptr),
    kappa(nullptr), ixref(-1)
{
  writedata = 1;
}

/* ---------------------------------------------------------------------- */

DihedralCellBending::~DihedralCellBending()
{
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(shear);
    memory->destroy(thickness);
    memory->destroy(reference);
    memory->destroy(form);
    memory->destroy(kappa);
  }
}

/* ---------------------------------------------------------------------- */

void DihedralCellBending::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);

  double **x = atom->x;
  double **f = atom->f;
  double **xref = atom->darray[ixref];
  tagint *tag = atom->tag;
  int **dihedrallist = neighbor->dihedrallist;
  const int ndihedrallist = neighbor->ndihedrallist;
  const int nlocal = atom->nlocal;
  const int newton_bond = force->newton_bond;

  for (int n = 0; n < ndihedrallist; n++) {
    const int i1 = dihedrallist[n][0];
    const int i2 = dihedrallist[n][1];
    const int i3 = dihedrallist[n][2];
    const int i4 = dihedrallist[n][3];
    const int type = dihedrallist[n][4];

    // current hinge (atoms are the closest images of each other)
    const double e[3] = {x[i3][0] - x[i2][0], x[i3][1] - x[i2][1], x[i3][2] - x[i2][2]};
    const double u1[3] = {x[i1][0] - x[i2][0], x[i1][1] - x[i2][1], x[i1][2] - x[i2][2]};
    const double u2[3] = {x[i4][0] - x[i2][0], x[i4][1] - x[i2][1], x[i4][2] - x[i2][2]};
    Hinge h;
    if (!hinge(e, u1, u2, h))
      error->one(FLERR, "Dihedral cell/bending: a triangle of dihedral {}-{}-{}-{} has zero area",
                 tag[i1], tag[i2], tag[i3], tag[i4]);

    // reference hinge from xref (minimum image: xref is not unwrapped with the ghosts)
    double e0[3] = {xref[i3][0] - xref[i2][0], xref[i3][1] - xref[i2][1],
                    xref[i3][2] - xref[i2][2]};
    double v1[3] = {xref[i1][0] - xref[i2][0], xref[i1][1] - xref[i2][1],
                    xref[i1][2] - xref[i2][2]};
    double v2[3] = {xref[i4][0] - xref[i2][0], xref[i4][1] - xref[i2][1],
                    xref[i4][2] - xref[i2][2]};
    domain->minimum_image(e0[0], e0[1], e0[2]);
    domain->minimum_image(v1[0], v1[1], v1[2]);
    domain->minimum_image(v2[0], v2[1], v2[2]);
    Hinge h0;
    if (!hinge(e0, v1, v2, h0))
      error->one(FLERR,
                 "Dihedral cell/bending: a reference (xref) triangle of dihedral {}-{}-{}-{} has "
                 "zero area",
                 tag[i1], tag[i2], tag[i3], tag[i4]);
    // an edge over 3 x its reference length means a wrong periodic image (ghost cutoff too short)
    if (dot(e, e) > 9.0 * dot(e0, e0) || dot(u1, u1) > 9.0 * dot(v1, v1) ||
        dot(u2, u2) > 9.0 * dot(v2, v2))
      error->one(FLERR,
                 "Dihedral cell/bending: dihedral {}-{}-{}-{} spans over 3 x its reference edge "
                 "lengths: an atom was taken from another periodic image (set comm_modify cutoff "
                 "above the longest dihedral span) or the wall is torn",
                 tag[i1], tag[i2], tag[i3], tag[i4]);

    double edihedral, dedth;
    if (!bend(kappa[type], reference[type] == FLAT, form[type] == TAN, h, h0, edihedral, dedth))
      error->one(FLERR,
                 "Dihedral cell/bending: dihedral {}-{}-{}-{} is folded flat onto itself "
                 "(theta - theta0 = pi), where the energy of form tan is infinite",
                 tag[i1], tag[i2], tag[i3], tag[i4]);

    // dtheta/dx_a = -|e| n1 / |n1|^2, dtheta/dx_d = -|e| n2 / |n2|^2; the edge atoms take
    // -(1 - s) and -s of them, s the position of a (d) projected on the edge, so that the forces
    // sum to zero and exert no torque (doc/dihedral_cell_bending.md)
    const double len = sqrt(h.ee);
    const double sa = dot(u1, e) / h.ee;
    const double sd = dot(u2, e) / h.ee;
    const double ca = dedth * len / h.nn1;
    const double cd = dedth * len / h.nn2;
    double f1[3], f2[3], f3[3], f4[3];
    for (int d = 0; d < 3; d++) {
      f1[d] = ca * h.n1[d];
      f4[d] = cd * h.n2[d];
      f3[d] = -sa * f1[d] - sd * f4[d];
      f2[d] = -f1[d] - f3[d] - f4[d];
    }

    if (newton_bond || i1 < nlocal)
      for (int d = 0; d < 3; d++) f[i1][d] += f1[d];
    if (newton_bond || i2 < nlocal)
      for (int d = 0; d < 3; d++) f[i2][d] += f2[d];
    if (newton_bond || i3 < nlocal)
      for (int d = 0; d < 3; d++) f[i3][d] += f3[d];
    if (newton_bond || i4 < nlocal)
      for (int d = 0; d < 3; d++) f[i4][d] += f4[d];

    if (evflag)
      ev_tally(i1, i2, i3, i4, nlocal, newton_bond, edihedral, f1, f3, f4, u1[0], u1[1], u1[2],
               e[0], e[1], e[2], u2[0] - e[0], u2[1] - e[1], u2[2] - e[2]);
  }
}

/* ---------------------------------------------------------------------- */

void DihedralCellBending::allocate()
{
  allocated = 1;
  const int n = atom->ndihedraltypes + 1;
  memory->create(shear, n, "dihedral:shear");
  memory->create(thickness, n, "dihedral:thickness");
  memory->create(reference, n, "dihedral:reference");
  memory->create(form, n, "dihedral:form");
  memory->create(kappa, n, "dihedral:kappa");
  memory->create(setflag, n, "dihedral:setflag");
  for (int i = 0; i < n; i++) {
    setflag[i] = 0;
    kappa[i] = 0.0;
  }
}

/* ---------------------------------------------------------------------- */

void DihedralCellBending::settings(int narg, char **arg)
{
  if (narg > 0)
    error->all(FLERR, "Dihedral_style cell/bending takes no arguments, got '{}'", arg[0]);
}

/* ----------------------------------------------------------------------
   dihedral_coeff N G t0 [reference xref|flat] [form cos|tan]
   dihedral_coeff N file <parameter file> [reference xref|flat] [form cos|tan]
   (file keys wall_G, wall_t0)
------------------------------------------------------------------------- */

void DihedralCellBending::coeff(int narg, char **arg)
{
  if (!allocated) allocate();
  if (narg < 3 || narg % 2 == 0)
    error->all(FLERR,
               "Incorrect args for dihedral_coeff cell/bending: expected 'dihedral_coeff <type> "
               "<G> <t0> [reference xref|flat] [form cos|tan]' or 'dihedral_coeff <type> file "
               "<parameter file> [reference xref|flat] [form cos|tan]', got {} args",
               narg);
  int ilo, ihi;
  utils::bounds(FLERR, arg[0], 1, atom->ndihedraltypes, ilo, ihi, error);

  double g_one, t_one;
  if (strcmp(arg[1], "file") == 0) {
    CellParams params(lmp, arg[2], "dihedral_coeff cell/bending");
    g_one = params.positive("wall_G", CellLimits::WALL_G_MAX, "Pa");
    t_one = params.positive("wall_t0", CellLimits::WALL_T0_MAX, "m");
  } else {
    g_one = utils::numeric(FLERR, arg[1], false, lmp);
    t_one = utils::numeric(FLERR, arg[2], false, lmp);
    if (g_one <= 0.0)
      error->all(FLERR, "Dihedral_coeff cell/bending: shear modulus G = {} must be > 0", g_one);
    if (t_one <= 0.0)
      error->all(FLERR, "Dihedral_coeff cell/bending: wall thickness t0 = {} must be > 0", t_one);
    // the ranges keep kappa = G t0^3 / 3 finite (doc/dihedral_cell_bending.md, Ranges)
    const std::string c = "Dihedral_coeff cell/bending: ";
    CellLimits::within(error, c + "shear modulus G", g_one, 0.0, CellLimits::WALL_G_MAX, "Pa",
                       true);
    CellLimits::within(error, c + "wall thickness t0", t_one, 0.0, CellLimits::WALL_T0_MAX, "m",
                       true);
  }
  int ref_one = XREF;
  int form_one = COS;
  for (int iarg = 3; iarg < narg; iarg += 2) {
    if (strcmp(arg[iarg], "reference") == 0)
      ref_one = parse_reference(arg[iarg + 1]);
    else if (strcmp(arg[iarg], "form") == 0)
      form_one = parse_form(arg[iarg + 1]);
    else
      error->all(FLERR,
                 "Dihedral_coeff cell/bending: unknown keyword '{}' (expected 'reference' or "
                 "'form')",
                 arg[iarg]);
  }

  for (int i = ilo; i <= ihi; i++) {
    shear[i] = g_one;
    thickness[i] = t_one;
    reference[i] = ref_one;
    form[i] = form_one;
    setflag[i] = 1;
  }
}

/* ---------------------------------------------------------------------- */

int DihedralCellBending::parse_reference(const std::string &name)
{
  for (int r : {XREF, FLAT})
    if (name == REFERENCE_NAMES[r]) return r;
  error->all(FLERR, "Dihedral_coeff cell/bending: unknown reference '{}' (expected xref or flat)",
             name);
  return XREF;
}

/* ---------------------------------------------------------------------- */

int DihedralCellBending::parse_form(const std::string &name)
{
  for (int f : {COS, TAN})
    if (name == FORM_NAMES[f]) return f;
  error->all(FLERR, "Dihedral_coeff cell/bending: unknown form '{}' (expected cos or tan)", name);
  return COS;
}

/* ----------------------------------------------------------------------
   check the reference positions, precompute the bending rigidity per type
------------------------------------------------------------------------- */

void DihedralCellBending::init_style()
{
  int flag, cols;
  ixref = atom->find_custom(CellField::XREF, flag, cols);
  if (ixref < 0 || flag != 1 || cols != 3)
    error->all(FLERR,
               "Dihedral style cell/bending needs per-atom reference positions: add "
               "'fix <ID> all property/atom d2_xref 3 ghost yes' (or 'cell/atoms') before "
               "read_data");
  // kappa = G t0^3 / 3: thin incompressible shell, E = 3 G, nu = 1/2 (doc/model.md §4.2)
  for (int i = 1; i <= atom->ndihedraltypes; i++)
    kappa[i] = shear[i] * thickness[i] * thickness[i] * thickness[i] / 3.0;
}

/* ---------------------------------------------------------------------- */

void DihedralCellBending::write_restart(FILE *fp)
{
  CellRestart::write_columns(fp, RESTART_VERSION, atom->ndihedraltypes, &shear[1], &thickness[1],
                             &reference[1], &form[1]);
}

/* ---------------------------------------------------------------------- */

void DihedralCellBending::read_restart(FILE *fp)
{
  allocate();
  const int n = atom->ndihedraltypes;
  const int version =
      CellRestart::read_version(lmp, fp, FLERR, "Dihedral style cell/bending", RESTART_VERSION);
  CellRestart::read_columns(lmp, fp, n, &shear[1], &thickness[1], &reference[1]);
  if (version >= 2)
    CellRestart::read_column(lmp, fp, n, &form[1]);
  else
    for (int i = 1; i <= n; i++) form[i] = COS;    // version 1 had the cos form only
  for (int i = 1; i <= n; i++) setflag[i] = 1;
}

/* ---------------------------------------------------------------------- */

void DihedralCellBending::write_data(FILE *fp)
{
  for (int i = 1; i <= atom->ndihedraltypes; i++)
    fprintf(fp, "%d %.16g %.16g reference %s form %s\n", i, shear[i], thickness[i],
            REFERENCE_NAMES[reference[i]], FORM_NAMES[form[i]]);
}
