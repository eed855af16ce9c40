/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
------------------------------------------------------------------------- */

#include "cell_reduce.h"

#include "atom.h"
#include "cell_styles.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"

#include <algorithm>
#include <cmath>
#include <numeric>

using namespace LAMMPS_NS;

// |u x w|
static double cross_norm(const double *u, const double *w)
{
  const double cx = u[1] * w[2] - u[2] * w[1];
  const double cy = u[2] * w[0] - u[0] * w[2];
  const double cz = u[0] * w[1] - u[1] * w[0];
  return sqrt(cx * cx + cy * cy + cz * cz);
}

/* ---------------------------------------------------------------------- */

CellReduce::CellReduce(LAMMPS *lmp, const std::string &command_in, int igroup, int fluid, int wall,
                       bool fluid_sums) :
    Pointers(lmp),
    command(command_in), group_name(group->names[igroup]), fluidtype(fluid), walltype(wall),
    surfacebit(0), irho(-1), ipressure(-1), ixref(-1), measure(TURGOR_SPH),
    geometry_only(!fluid_sums), cells(lmp, command_in, igroup)
{
  for (int type : {geometry_only ? wall : fluid, wall})
    if (type < 1 || type > atom->ntypes)
      error->all(FLERR, "{}: atom type {} is out of range 1 to {}", command, type, atom->ntypes);
  if (fluid == wall && !geometry_only)
    error->all(FLERR, "{}: fluid and wall atom types must differ (both {})", command, fluid);
  if (!atom->molecule_flag)
    error->all(FLERR, "{}: needs molecule (cell) IDs: use atom_style angle", command);
}

/* ----------------------------------------------------------------------
   per-atom fields, each cell's reference point (mean unwrapped wall position) and home rank
------------------------------------------------------------------------- */

void CellReduce::init()
{
  if (!geometry_only) init_fluid();
  int flag, cols;
  ixref = atom->find_custom(CellField::XREF, flag, cols);
  if (flag != 1 || cols != 3) ixref = -1;
  cells.init(walltype);
}

/* ----------------------------------------------------------------------
   the fluid's per-atom fields and the pairs that tally the wall load
------------------------------------------------------------------------- */

void CellReduce::init_fluid()
{
  if (!atom->rmass)
    error->all(FLERR,
               "{}: needs per-atom masses: add 'fix cellatoms all property/atom rmass d2_xref 3 "
               "d_aref ghost yes' before read_data",
               command);
  irho = custom_vector(CellField::RHO);
  ipressure = custom_vector(CellField::PRESSURE);
  // the wall load comes from pair cell/wall (also as a hybrid sub-style) and from the wall
  // boundary of pair cell/sph (pair_coeff I J wall), when these are defined
  loads.clear();
  for (CellWallLoad *load : cell_wall_loads(force))
    if (load->request_wall_load(fluidtype, walltype, command)) loads.push_back(load);
  measure = particle_wall_model() ? TURGOR_WALL : TURGOR_SPH;
}

/* ----------------------------------------------------------------------
   true if the fluid is held by pair cell/wall's wall-fluid terms alone (the seed's particle model),
   whose mean SPH pressure is ~21 % above the wall load; false under the SPH wall boundary of pair
   cell/sph (P_SPH = P_W within 0.2 % with background auto), also with cell/wall's adhesion beside
   it (examples/tissue), and without any wall load (doc/model.md §1.4, §5.3)
------------------------------------------------------------------------- */

bool CellReduce::particle_wall_model() const
{
  auto tallies = [this](const char *style) {
    auto *load = dynamic_cast<CellWallLoad *>(force->pair_match(style, 0));
    return load && std::find(loads.begin(), loads.end(), load) != loads.end();
  };
  return tallies("cell/wall") && !tallies("cell/sph");
}

/* ---------------------------------------------------------------------- */

int CellReduce::custom_vector(const char *name) const
{
  int flag, cols;
  const int index = atom->find_custom(name, flag, cols);
  if (index < 0 || flag != 1 || cols != 0)
    error->all(FLERR,
               "{}: needs the per-atom SPH field '{}' (written by pair cell/sph): add 'fix cellsph "
               "all property/atom d_rho d_pressure ghost yes' before read_data",
               command, name);
  return index;
}

/* ----------------------------------------------------------------------
   sum the columns of the cells this rank touches over owned atoms, total them on the home ranks.
   Each triangle (angle a b c, b the middle atom) is counted once, by the owner of b: angles are
   stored with b for newton_bond on and off. Vertices are unwrapped around b, relative to the
   cell's reference point. bond_gt0[type] = G t0 of each bond type, or nullptr for no bond sums.
   triangles, if not nullptr, is filled with the counted triangles of the owned atoms.
------------------------------------------------------------------------- */

void CellReduce::reduce(const double *bond_gt0, std::vector<double> *triangles,
                        std::vector<tagint> *corners)
{
  // the ghosts' positions as their owned atoms' now: a fix's end_of_step may have moved or remapped
  // the owned atoms since the step's communication (fix press/berendsen ... dilate all), and the
  // triangles take their corners from ghosts (the same values on any number of ranks)
  comm->forward_comm();
  cells.map_atoms();
  const std::vector<int> &cellof = cells.cell_of_atom();
  local.assign(NCOLUMN * cells.touched().size(), 0.0);
  if (triangles) triangles->clear();
  if (corners) corners->clear();
  loadnow.clear();
  for (const CellWallLoad *l : loads) loadnow.push_back(l->wall_load());

  const int *type = atom->type;
  for (int i = 0; i < atom->nlocal; i++) {
    const int c = cellof[i];
    if (c < 0) continue;
    double *s = &local[NCOLUMN * cells.slot(c)];
    if (type[i] == fluidtype) {
      if (!geometry_only) add_fluid(i, s);
      continue;
    }
    if (type[i] != walltype) continue;
    double b[3];
    add_wall(i, c, s, b);
    add_triangles(i, c, b, s, triangles, corners);
    if (bond_gt0) add_bonds(i, bond_gt0, s);
  }

  cells.reduce(NCOLUMN, local, total);
  check_cells();
}

/* ----------------------------------------------------------------------
   fluid atom i's mass, volume and pressure in its cell's sums s
------------------------------------------------------------------------- */

void CellReduce::add_fluid(int i, double *s)
{
  const double *rmass = atom->rmass;
  const double *rho = atom->dvector[irho];
  const double *pressure = atom->dvector[ipressure];
  if (!(rho[i] > 0.0)) {
    s[BADRHO] += 1.0;
    return;
  }
  const double vol = rmass[i] / rho[i];
  s[MASS] += rmass[i];
  s[FLUIDVOL] += vol;
  s[PRESSUREVOL] += pressure[i] * vol;
  s[NFLUID] += 1.0;
}

/* ----------------------------------------------------------------------
   wall atom i of cell c: its position b (unwrapped, relative to the cell's reference point), its
   moments and the wall load on it in the cell's sums s
------------------------------------------------------------------------- */

void CellReduce::add_wall(int i, int c, double *s, double b[3])
{
  const double *ref = cells.reference(c);
  domain->unmap(atom->x[i], atom->image[i], b);
  for (int d = 0; d < 3; d++) b[d] -= ref[d];
  s[NWALL] += 1.0;
  s[WX] += b[0];
  s[WY] += b[1];
  s[WZ] += b[2];
  s[WXX] += b[0] * b[0];
  s[WYY] += b[1] * b[1];
  s[WZZ] += b[2] * b[2];
  s[WXY] += b[0] * b[1];
  s[WXZ] += b[0] * b[2];
  s[WYZ] += b[1] * b[2];
  for (double **l : loadnow)
    if (l) {
      s[LOADVIR] += b[0] * l[i][0] + b[1] * l[i][1] + b[2] * l[i][2];
      s[LOADX] += l[i][0];
      s[LOADY] += l[i][1];
      s[LOADZ] += l[i][2];
    }
}

/* ----------------------------------------------------------------------
   the wall triangles whose middle atom is wall atom i (at b) in the sums s of its cell c, and in
   triangles/corners if given
------------------------------------------------------------------------- */

void CellReduce::add_triangles(int i, int c, const double *b, double *s,
                               std::vector<double> *triangles, std::vector<tagint> *corners)
{
  double **x = atom->x;
  double **xref = ixref >= 0 ? atom->darray[ixref] : nullptr;
  const tagint *tag = atom->tag;
  const int *mask = atom->mask;
  for (int m = 0; atom->num_angle && m < atom->num_angle[i]; m++) {
    if (atom->angle_atom2[i][m] != tag[i] || atom->angle_type[i][m] <= 0) continue;
    int ia = atom->map(atom->angle_atom1[i][m]);
    int ic = atom->map(atom->angle_atom3[i][m]);
    if (ia < 0 || ic < 0)
      error->one(FLERR, "{}: atoms of wall triangle {} {} {} missing on rank {}", command,
                 atom->angle_atom1[i][m], tag[i], atom->angle_atom3[i][m], comm->me);
    ia = domain->closest_image(i, ia);
    ic = domain->closest_image(i, ic);
    double a[3], cc[3], ab[3], ac[3];
    for (int d = 0; d < 3; d++) {
      a[d] = b[d] + x[ia][d] - x[i][d];
      cc[d] = b[d] + x[ic][d] - x[i][d];
      ab[d] = b[d] - a[d];
      ac[d] = cc[d] - a[d];
    }
    // 6 V = sum a . (b x c) over outward triangles (divergence theorem, doc/model.md §5.2)
    s[VOLUME6] += a[0] * (b[1] * cc[2] - b[2] * cc[1]) + a[1] * (b[2] * cc[0] - b[0] * cc[2]) +
        a[2] * (b[0] * cc[1] - b[1] * cc[0]);
    // 2 A = sum |(b - a) x (c - a)|
    const double area2 = cross_norm(ab, ac);
    s[AREA2] += area2;
    // exposed area: the triangles with all three corners in the surface group (doc/model.md §5.8)
    if (surfacebit && (mask[i] & mask[ia] & mask[ic] & surfacebit)) s[SURFAREA2] += area2;
    s[NTRI] += 1.0;
    if (triangles)
      triangles->insert(triangles->end(),
                        {(double) c, a[0], a[1], a[2], b[0], b[1], b[2], cc[0], cc[1], cc[2]});
    if (corners)
      corners->insert(corners->end(), {atom->angle_atom1[i][m], tag[i], atom->angle_atom3[i][m]});
    if (xref) {
      double u[3] = {xref[ia][0] - xref[i][0], xref[ia][1] - xref[i][1], xref[ia][2] - xref[i][2]};
      double w[3] = {xref[ic][0] - xref[i][0], xref[ic][1] - xref[i][1], xref[ic][2] - xref[i][2]};
      domain->minimum_image(u[0], u[1], u[2]);
      domain->minimum_image(w[0], w[1], w[2]);
      // 2 A_ref = |(xref_a - xref_b) x (xref_c - xref_b)|
      s[REFAREA2] += cross_norm(u, w);
    }
  }
}

/* ----------------------------------------------------------------------
   G t0 of wall atom i's bonds inside its cell (each bond once) in the sums s
------------------------------------------------------------------------- */

void CellReduce::add_bonds(int i, const double *bond_gt0, double *s)
{
  const tagint *tag = atom->tag;
  const tagint *molecule = atom->molecule;
  const int newton_bond = force->newton_bond;
  for (int m = 0; m < atom->num_bond[i]; m++) {
    const int btype = atom->bond_type[i][m];
    const tagint partner = atom->bond_atom[i][m];
    if (btype <= 0 || (!newton_bond && partner < tag[i])) continue;
    const int j = atom->map(partner);
    if (j < 0 || molecule[j] != molecule[i]) continue;
    s[GT0] += bond_gt0[btype];
    s[NBOND] += 1.0;
  }
}

/* ----------------------------------------------------------------------
   the first bad cell (home ranks) stops every rank
------------------------------------------------------------------------- */

void CellReduce::check_cells()
{
  int bad = ncell();
  std::string why;
  for (int c : cells.home_cells()) {
    if (get(c, NTRI) == 0.0)
      why = fmt::format("{}: cell {} has no wall triangles (angles whose middle atom is a type {} "
                        "atom of group {})",
                        command, id(c), walltype, group_name);
    else if (get(c, BADRHO) > 0.0)
      why = fmt::format("{}: cell {} has {} fluid atoms without a density rho > 0 (is pair "
                        "cell/sph computing it?)",
                        command, id(c), (bigint) get(c, BADRHO));
    else
      continue;
    bad = c;
    break;
  }
  cells.settle(bad, why, {});
}

/* ----------------------------------------------------------------------
   the triangles of reduce() (10 numbers each: cell index, corners; 3 corner IDs) to the home ranks
   (CellRegistry::send_home), grouped by home cell and ordered by corner IDs there
------------------------------------------------------------------------- */

void CellReduce::home_triangles(const std::vector<double> &mine,
                                const std::vector<tagint> &mycorners, CellTriangles &home) const
{
  std::vector<double> got;
  std::vector<tagint> gotids;
  cells.send_home(10, mine, got, 3, &mycorners, &gotids);
  const int ntri = (int) got.size() / 10;

  // grouped by home slot (counting sort), each cell's ordered by middle, first, last corner ID
  home.first.assign(cells.home_cells().size() + 1, 0);
  std::vector<int> slot(ntri), order(ntri);
  for (int t = 0; t < ntri; t++) {
    slot[t] = cells.home_slot((int) got[10 * (size_t) t]);
    if (slot[t] < 0)
      error->one(FLERR, "{}: rank {} got a wall triangle of another rank's cell", command,
                 comm->me);
    home.first[slot[t] + 1]++;
  }
  std::partial_sum(home.first.begin(), home.first.end(), home.first.begin());
  std::vector<int> next(home.first.begin(), home.first.end() - 1);
  for (int t = 0; t < ntri; t++) order[next[slot[t]]++] = t;
  const tagint *g = gotids.data();
  const auto by_corners = [g](int u, int w) {
    const tagint *p = g + 3 * (size_t) u, *q = g + 3 * (size_t) w;
    if (p[1] != q[1]) return p[1] < q[1];
    if (p[0] != q[0]) return p[0] < q[0];
    return p[2] < q[2];
  };
  for (int h = 0; h + 1 < (int) home.first.size(); h++)
    std::sort(order.begin() + home.first[h], order.begin() + home.first[h + 1], by_corners);

  home.coords.resize(9 * (size_t) ntri);
  home.tags.resize(3 * (size_t) ntri);
  for (int s = 0; s < ntri; s++) {
    const int t = order[s];
    std::copy_n(&got[10 * (size_t) t + 1], 9, &home.coords[9 * (size_t) s]);
    std::copy_n(&gotids[3 * (size_t) t], 3, &home.tags[3 * (size_t) s]);
  }
}

/* ---------------------------------------------------------------------- */

void CellReduce::held_triangles(const std::vector<double> &mine, const CellTriangles &home,
                                double held[3]) const
{
  const double own = (double) (mine.size() / 10);
  const double here = own + home.size();
  const double sums[2] = {here, own};
  double total[2];
  MPI_Allreduce(&here, &held[0], 1, MPI_DOUBLE, MPI_MAX, world);
  MPI_Allreduce(sums, total, 2, MPI_DOUBLE, MPI_SUM, world);
  held[1] = total[0];
  held[2] = total[1];
}

/* ----------------------------------------------------------------------
   SPH turgor = sum P m/rho / sum m/rho (volume-weighted mean, doc/model.md §5.2); 0 without fluid
------------------------------------------------------------------------- */

double CellReduce::sph_turgor(int c) const
{
  return get(c, FLUIDVOL) > 0.0 ? get(c, PRESSUREVOL) / get(c, FLUIDVOL) : 0.0;
}

/* ----------------------------------------------------------------------
   wall turgor = sum (x - xc) . F / 3 V over the wall atoms, F the force of the cell's fluid on them,
   xc their centroid: a uniform pressure P on a closed surface gives the integral of x . P n dA =
   3 P V (divergence theorem)
------------------------------------------------------------------------- */

double CellReduce::wall_turgor(int c) const
{
  const double n = get(c, NWALL);
  if (get(c, VOLUME6) == 0.0 || n == 0.0) return 0.0;
  const double shift =
      (get(c, WX) * get(c, LOADX) + get(c, WY) * get(c, LOADY) + get(c, WZ) * get(c, LOADZ)) / n;
  return 2.0 * (get(c, LOADVIR) - shift) / get(c, VOLUME6);
}

/* ----------------------------------------------------------------------
   mean G t0 of the cell's wall bonds, 0 if there are none
------------------------------------------------------------------------- */

double CellReduce::mean_gt0(int c) const
{
  return get(c, NBOND) > 0.0 ? get(c, GT0) / get(c, NBOND) : 0.0;
}

/* ----------------------------------------------------------------------
   gyration tensor of the wall atoms, xx yy zz xy xz yz: S = <r r> - <r><r>
------------------------------------------------------------------------- */

void CellReduce::gyration(int c, double s[6]) const
{
  const double n = get(c, NWALL);
  if (n == 0.0) {
    for (int k = 0; k < 6; k++) s[k] = 0.0;
    return;
  }
  const double mx = get(c, WX) / n, my = get(c, WY) / n, mz = get(c, WZ) / n;
  s[0] = get(c, WXX) / n - mx * mx;
  s[1] = get(c, WYY) / n - my * my;
  s[2] = get(c, WZZ) / n - mz * mz;
  s[3] = get(c, WXY) / n - mx * my;
  s[4] = get(c, WXZ) / n - mx * mz;
  s[5] = get(c, WYZ) / n - my * mz;
}
