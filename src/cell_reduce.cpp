/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
------------------------------------------------------------------------- */

#include "cell_reduce.h"

#include "atom.h"
#include "error.h"

#include <cmath>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

CellReduce::CellReduce(LAMMPS *lmp, const std::string &command_in, int igroup_in, int fluid,
                       int wall, bool fluid_sums) :
    Pointers(lmp),
    command(command_in), igroup(igroup_in), fluidtype(fluid_sums ? fluid : 0), walltype(wall),
    measure(TURGOR_SPH)
{
  for (int type : {fluid_sums ? fluid : wall, wall})
    if (type < 1 || type > atom->ntypes)
      error->all(FLERR, "{}: atom type {} is out of range 1 to {}", command, type, atom->ntypes);
  if (fluid == wall && fluid_sums)
    error->all(FLERR, "{}: fluid and wall atom types must differ (both {})", command, fluid);
  if (!atom->molecule_flag)
    error->all(FLERR, "{}: needs molecule (cell) IDs: use atom_style angle", command);
  set = CellSet::join(lmp, igroup, walltype, fluidtype, 0);
}

/* ----------------------------------------------------------------------
   a set of the same cells that sums the surface group's wall triangles too
------------------------------------------------------------------------- */

void CellReduce::set_surface(int surface_groupbit)
{
  set = CellSet::join(lmp, igroup, walltype, fluidtype, surface_groupbit);
}

/* ----------------------------------------------------------------------
   the set's per-atom fields, wall loads, reference points and home ranks; how P_T is measured
   follows the wall-fluid model (CellSet::particle_wall_model)
------------------------------------------------------------------------- */

void CellReduce::init()
{
  set->init(command);
  measure = set->particle_wall_model() ? TURGOR_WALL : TURGOR_SPH;
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
