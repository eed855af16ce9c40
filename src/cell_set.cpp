/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
------------------------------------------------------------------------- */

#include "cell_set.h"

#include "atom.h"
#include "cell_reduce.h"
#include "cell_styles.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "neighbor.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

using namespace LAMMPS_NS;
using R = CellReduce;

// |u x w|
static double cross_norm(const double *u, const double *w)
{
  const double cx = u[1] * w[2] - u[2] * w[1];
  const double cy = u[2] * w[0] - u[0] * w[2];
  const double cz = u[0] * w[1] - u[1] * w[0];
  return sqrt(cx * cx + cy * cy + cz * cz);
}

// the sets of every LAMMPS instance in this process; a set lives as long as a style holds it
static std::vector<std::pair<LAMMPS *, std::weak_ptr<CellSet>>> &all_sets()
{
  static std::vector<std::pair<LAMMPS *, std::weak_ptr<CellSet>>> sets;
  return sets;
}

/* ---------------------------------------------------------------------- */

std::shared_ptr<CellSet> CellSet::join(LAMMPS *lmp, int igroup, int walltype, int fluidtype,
                                       int surfacebit)
{
  auto &sets = all_sets();
  sets.erase(
      std::remove_if(sets.begin(), sets.end(), [](const auto &s) { return s.second.expired(); }),
      sets.end());
  for (auto &s : sets) {
    std::shared_ptr<CellSet> set = s.second.lock();
    if (s.first != lmp || !set->compatible(igroup, walltype, fluidtype, surfacebit)) continue;
    // the set sums what each of its styles needs: the fluid, the surface group's triangles
    set->fluidtype = std::max(set->fluidtype, fluidtype);
    set->surfacebit = std::max(set->surfacebit, surfacebit);
    set->taken.valid = false;
    return set;
  }
  auto set = std::make_shared<CellSet>(lmp, igroup, walltype, fluidtype, surfacebit);
  sets.emplace_back(lmp, set);
  return set;
}

/* ---------------------------------------------------------------------- */

CellSet::CellSet(LAMMPS *lmp, int igroup_in, int wall, int fluid, int surface) :
    Pointers(lmp), igroup(igroup_in), groupbit(group->bitmask[igroup_in]), walltype(wall),
    fluidtype(fluid), surfacebit(surface), group_name(group->names[igroup_in]), irho(-1),
    ipressure(-1), ixref(-1), cells(lmp, "", igroup_in)
{
}

/* ---------------------------------------------------------------------- */

bool CellSet::compatible(int group_index, int wall, int fluid, int surface) const
{
  return group_index == igroup && group->bitmask[group_index] == groupbit && wall == walltype &&
      (fluid == 0 || fluidtype == 0 || fluid == fluidtype) &&
      (surface == 0 || surfacebit == 0 || surface == surfacebit);
}

/* ---------------------------------------------------------------------- */

void CellSet::find_cells(const std::string &who)
{
  taken.valid = false;
  cells.name(who);
  cells.find_cells();
}

/* ----------------------------------------------------------------------
   per-atom fields, each cell's reference point (mean unwrapped wall position) and home rank
------------------------------------------------------------------------- */

void CellSet::init(const std::string &who)
{
  taken.valid = false;
  if (fluid_sums()) init_fluid(who);
  int flag, cols;
  ixref = atom->find_custom(CellField::XREF, flag, cols);
  if (flag != 1 || cols != 3) ixref = -1;
  cells.name(who);
  cells.init(walltype);
}

/* ----------------------------------------------------------------------
   the fluid's per-atom fields and the pairs that tally the wall load
------------------------------------------------------------------------- */

void CellSet::init_fluid(const std::string &who)
{
  if (!atom->rmass)
    error->all(FLERR,
               "{}: needs per-atom masses: add 'fix cellatoms all property/atom rmass d2_xref 3 "
               "d_aref ghost yes' (or 'cell/atoms') before read_data",
               who);
  irho = custom_vector(CellField::RHO, who);
  ipressure = custom_vector(CellField::PRESSURE, who);
  // the wall load comes from pair cell/wall (also as a hybrid sub-style) and from the wall
  // boundary of pair cell/sph (pair_coeff I J wall), when these are defined
  loads.clear();
  for (CellWallLoad *load : cell_wall_loads(force))
    if (load->request_wall_load(fluidtype, walltype, who)) loads.push_back(load);
}

/* ---------------------------------------------------------------------- */

int CellSet::custom_vector(const char *name, const std::string &who) const
{
  int flag, cols;
  const int index = atom->find_custom(name, flag, cols);
  if (index < 0 || flag != 1 || cols != 0)
    error->all(FLERR,
               "{}: needs the per-atom SPH field '{}' (written by pair cell/sph): add 'fix cellsph "
               "all property/atom d_rho d_pressure ghost yes' before read_data",
               who, name);
  return index;
}

/* ---------------------------------------------------------------------- */

void CellSet::box(double b[9]) const
{
  for (int d = 0; d < 3; d++) {
    b[d] = domain->boxlo[d];
    b[3 + d] = domain->boxhi[d];
  }
  b[6] = domain->xy;
  b[7] = domain->xz;
  b[8] = domain->yz;
}

/* ----------------------------------------------------------------------
   the last sums are of this state: the same step, box and neighbour-list build since the last
   find_cells() or init(). Atoms move, change their mass or migrate only in a new step, a new run
   (init) or a new neighbour build, or with the box (fix press/berendsen ... dilate all at the end
   of a step)
------------------------------------------------------------------------- */

bool CellSet::current() const
{
  if (!taken.valid || taken.step != update->ntimestep || taken.builds != neighbor->ncalls)
    return false;
  double now[9];
  box(now);
  return std::equal(now, now + 9, taken.box);
}

/* ----------------------------------------------------------------------
   sum the columns of the cells this rank touches over owned atoms, total them on the home ranks,
   unless the last sums are of this state (current()) and took what is asked. Each triangle (angle
   a b c, b the middle atom) is counted once, by the owner of b: angles are stored with b for
   newton_bond on and off. Vertices are unwrapped around b, relative to the cell's reference point.
------------------------------------------------------------------------- */

void CellSet::reduce(const std::string &who, const double *bond_gt0, bool triangles)
{
  const bool same = current();
  if (same && (!triangles || taken.triangles) && (!bond_gt0 || taken.gt0)) return;
  // the sums of this state asked for again with more: with what the last sums took too
  if (same) {
    triangles = triangles || taken.triangles;
    if (!bond_gt0) bond_gt0 = taken.gt0;
  }

  // the ghosts' positions as their owned atoms' now: a fix's end_of_step may have moved or remapped
  // the owned atoms since the step's communication (fix press/berendsen ... dilate all), and the
  // triangles take their corners from ghosts (the same values on any number of ranks)
  comm->forward_comm();
  cells.name(who);
  cells.map_atoms();
  const std::vector<int> &cellof = cells.cell_of_atom();
  local.assign(R::NCOLUMN * cells.touched().size(), 0.0);
  tri.clear();
  tricorners.clear();
  home_ready = false;
  loadnow.clear();
  for (const CellWallLoad *l : loads) loadnow.push_back(l->wall_load());

  const int *type = atom->type;
  for (int i = 0; i < atom->nlocal; i++) {
    const int c = cellof[i];
    if (c < 0) continue;
    double *s = &local[R::NCOLUMN * cells.slot(c)];
    if (type[i] == fluidtype) {
      add_fluid(i, s);
      continue;
    }
    if (type[i] != walltype) continue;
    double b[3];
    add_wall(i, c, s, b);
    add_triangles(i, c, b, s, triangles, who);
    if (bond_gt0) add_bonds(i, bond_gt0, s);
  }

  cells.reduce(R::NCOLUMN, local, total);
  taken.valid = true;
  taken.step = update->ntimestep;
  taken.builds = neighbor->ncalls;
  box(taken.box);
  taken.triangles = triangles;
  taken.gt0 = bond_gt0;
  check_cells(who);
}

/* ----------------------------------------------------------------------
   fluid atom i's mass, volume and pressure in its cell's sums s
------------------------------------------------------------------------- */

void CellSet::add_fluid(int i, double *s)
{
  const double *rmass = atom->rmass;
  const double *rho = atom->dvector[irho];
  const double *pressure = atom->dvector[ipressure];
  if (!(rho[i] > 0.0)) {
    s[R::BADRHO] += 1.0;
    return;
  }
  const double vol = rmass[i] / rho[i];
  s[R::MASS] += rmass[i];
  s[R::FLUIDVOL] += vol;
  s[R::PRESSUREVOL] += pressure[i] * vol;
  s[R::NFLUID] += 1.0;
}

/* ----------------------------------------------------------------------
   wall atom i of cell c: its position b (unwrapped, relative to the cell's reference point), its
   moments and the wall load on it in the cell's sums s
------------------------------------------------------------------------- */

void CellSet::add_wall(int i, int c, double *s, double b[3])
{
  const double *ref = cells.reference(c);
  domain->unmap(atom->x[i], atom->image[i], b);
  for (int d = 0; d < 3; d++) b[d] -= ref[d];
  s[R::NWALL] += 1.0;
  s[R::WX] += b[0];
  s[R::WY] += b[1];
  s[R::WZ] += b[2];
  s[R::WXX] += b[0] * b[0];
  s[R::WYY] += b[1] * b[1];
  s[R::WZZ] += b[2] * b[2];
  s[R::WXY] += b[0] * b[1];
  s[R::WXZ] += b[0] * b[2];
  s[R::WYZ] += b[1] * b[2];
  for (double **l : loadnow)
    if (l) {
      s[R::LOADVIR] += b[0] * l[i][0] + b[1] * l[i][1] + b[2] * l[i][2];
      s[R::LOADX] += l[i][0];
      s[R::LOADY] += l[i][1];
      s[R::LOADZ] += l[i][2];
    }
}

/* ----------------------------------------------------------------------
   the wall triangles whose middle atom is wall atom i (at b) in the sums s of its cell c, and in
   the kept triangles if keep
------------------------------------------------------------------------- */

void CellSet::add_triangles(int i, int c, const double *b, double *s, bool keep,
                            const std::string &who)
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
      error->one(FLERR, "{}: atoms of wall triangle {} {} {} missing on rank {}", who,
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
    s[R::VOLUME6] += a[0] * (b[1] * cc[2] - b[2] * cc[1]) + a[1] * (b[2] * cc[0] - b[0] * cc[2]) +
        a[2] * (b[0] * cc[1] - b[1] * cc[0]);
    // 2 A = sum |(b - a) x (c - a)|
    const double area2 = cross_norm(ab, ac);
    s[R::AREA2] += area2;
    // exposed area: the triangles with all three corners in the surface group (doc/model.md §5.8)
    if (surfacebit && (mask[i] & mask[ia] & mask[ic] & surfacebit)) s[R::SURFAREA2] += area2;
    s[R::NTRI] += 1.0;
    if (keep) {
      tri.insert(tri.end(), {(double) c, a[0], a[1], a[2], b[0], b[1], b[2], cc[0], cc[1], cc[2]});
      tricorners.insert(tricorners.end(),
                        {atom->angle_atom1[i][m], tag[i], atom->angle_atom3[i][m]});
    }
    if (xref) {
      double u[3] = {xref[ia][0] - xref[i][0], xref[ia][1] - xref[i][1], xref[ia][2] - xref[i][2]};
      double w[3] = {xref[ic][0] - xref[i][0], xref[ic][1] - xref[i][1], xref[ic][2] - xref[i][2]};
      domain->minimum_image(u[0], u[1], u[2]);
      domain->minimum_image(w[0], w[1], w[2]);
      // 2 A_ref = |(xref_a - xref_b) x (xref_c - xref_b)|
      s[R::REFAREA2] += cross_norm(u, w);
    }
  }
}

/* ----------------------------------------------------------------------
   G t0 of wall atom i's bonds inside its cell (each bond once) in the sums s
------------------------------------------------------------------------- */

void CellSet::add_bonds(int i, const double *bond_gt0, double *s)
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
    s[R::GT0] += bond_gt0[btype];
    s[R::NBOND] += 1.0;
  }
}

/* ----------------------------------------------------------------------
   the first bad cell (home ranks) stops every rank
------------------------------------------------------------------------- */

void CellSet::check_cells(const std::string &who)
{
  int bad = cells.ncell();
  std::string why;
  const std::vector<int> &mine = cells.home_cells();
  for (int h = 0; h < (int) mine.size(); h++) {
    const double *t = &total[(size_t) h * R::NCOLUMN];
    if (t[R::NTRI] == 0.0)
      why = fmt::format("{}: cell {} has no wall triangles (angles whose middle atom is a type {} "
                        "atom of group {})",
                        who, cells.id(mine[h]), walltype, group_name);
    else if (t[R::BADRHO] > 0.0)
      why = fmt::format("{}: cell {} has {} fluid atoms without a density rho > 0 (is pair "
                        "cell/sph computing it?)",
                        who, cells.id(mine[h]), (bigint) t[R::BADRHO]);
    else
      continue;
    bad = mine[h];
    break;
  }
  cells.settle(bad, why, {});
}

/* ----------------------------------------------------------------------
   the kept triangles (10 numbers each: cell index, corners; 3 corner IDs) to the home ranks
   (CellRegistry::send_home), grouped by home cell and ordered by corner IDs there; once per
   reduction
------------------------------------------------------------------------- */

const CellTriangles &CellSet::home_triangles(const std::string &who)
{
  if (home_ready) return home;
  std::vector<double> got;
  std::vector<tagint> gotids;
  cells.send_home(10, tri, got, 3, &tricorners, &gotids);
  const int ntri = (int) got.size() / 10;

  // grouped by home slot (counting sort), each cell's ordered by middle, first, last corner ID
  home.first.assign(cells.home_cells().size() + 1, 0);
  std::vector<int> slot(ntri), order(ntri);
  for (int t = 0; t < ntri; t++) {
    slot[t] = cells.home_slot((int) got[10 * (size_t) t]);
    if (slot[t] < 0)
      error->one(FLERR, "{}: rank {} got a wall triangle of another rank's cell", who, comm->me);
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
  home_ready = true;
  return home;
}

/* ---------------------------------------------------------------------- */

void CellSet::held_triangles(const std::string &who, double held[3])
{
  const double own = (double) (tri.size() / 10);
  const double here = own + home_triangles(who).size();
  const double sums[2] = {here, own};
  double all[2];
  MPI_Allreduce(&here, &held[0], 1, MPI_DOUBLE, MPI_MAX, world);
  MPI_Allreduce(sums, all, 2, MPI_DOUBLE, MPI_SUM, world);
  held[1] = all[0];
  held[2] = all[1];
}

/* ----------------------------------------------------------------------
   true if the fluid is held by pair cell/wall's wall-fluid terms alone (the seed's particle model),
   whose mean SPH pressure is ~21 % above the wall load; false under the SPH wall boundary of pair
   cell/sph (P_SPH = P_W within 0.2 % with background auto), also with cell/wall's adhesion beside
   it (examples/tissue), and without any wall load (doc/model.md §1.4, §5.3)
------------------------------------------------------------------------- */

bool CellSet::particle_wall_model() const
{
  auto tallies = [this](const char *style) {
    auto *load = dynamic_cast<CellWallLoad *>(force->pair_match(style, 0));
    return load && std::find(loads.begin(), loads.end(), load) != loads.end();
  };
  return tallies("cell/wall") && !tallies("cell/sph");
}
