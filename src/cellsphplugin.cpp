/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   Plugin entry point: checks that the running LAMMPS is the one this plugin was compiled for,
   then registers every cellsph style. A new style is one line in the table below.
------------------------------------------------------------------------- */

#include "lammpsplugin.h"

#include "library.h"
#include "lmptype.h"
#include "version.h"

#include "bond_cell_lamella.h"
#include "bond_cell_neohookean.h"
#include "cell_atoms.h"
#include "compute_cell_props.h"
#include "compute_cell_shape.h"
#include "dihedral_cell_bending.h"
#include "fix_cell_bond_history.h"
#include "fix_cell_continue.h"
#include "fix_cell_pressure.h"
#include "fix_cell_turgor.h"
#include "pair_cell_sph.h"
#include "pair_cell_wall.h"

#include <cstdio>
#include <string>

using namespace LAMMPS_NS;

// the LAMMPS version this plugin was compiled for (overridden only to test the check below)
#ifndef CELLSPH_ABI_VERSION
#define CELLSPH_ABI_VERSION LMP_VERSION_NUM
#endif

namespace {

template <class Style> void *create_v1(void *lmp)
{
  return (void *) new Style((LAMMPS *) lmp);
}

template <class Style> void *create_v2(void *lmp, int narg, char **arg)
{
  return (void *) new Style((LAMMPS *) lmp, narg, arg);
}

struct StyleEntry {
  const char *kind;    // pair, bond, dihedral, fix, compute, command
  const char *name;
  const char *info;
  lammpsplugin_factory1 *v1;    // pair, bond and dihedral styles, commands
  lammpsplugin_factory2 *v2;    // fix and compute styles
};

const StyleEntry STYLES[] = {
    {"bond", "cell/neohookean", "Neo-Hookean cell-wall bond with damping",
     &create_v1<BondCellNeoHookean>, nullptr},
    {"dihedral", "cell/bending", "bending stiffness of the cell wall across each wall edge",
     &create_v1<DihedralCellBending>, nullptr},
    {"bond", "cell/lamella", "middle lamella: breakable junction between the walls of two cells",
     &create_v1<BondCellLamella>, nullptr},
    {"command", "cell/atoms", "defines the per-atom fields of a cellsph data file (fix cellatoms)",
     &create_v1<CellAtoms>, nullptr},
    {"fix", "cell/bond/history", "per-bond reference state of cellsph bond styles (internal)",
     nullptr, &create_v2<FixCellBondHistory>},
    {"fix", "cell/continue",
     "the last step's velocities for the forces of a run's setup that continues it (internal)",
     nullptr, &create_v2<FixCellContinue>},
    {"fix", "cell/pressure", "imposed turgor pressure on closed cell walls", nullptr,
     &create_v2<FixCellPressure>},
    {"fix", "cell/turgor", "water transfer through the cell wall (turgor, osmosis, permeability)",
     nullptr, &create_v2<FixCellTurgor>},
    {"compute", "cell/props", "per-cell mass, volume, area, turgor, osmotic pressure and shape",
     nullptr, &create_v2<ComputeCellProps>},
    {"compute", "cell/shape", "per-cell section descriptors (ImageJ) and wall wrinkling", nullptr,
     &create_v2<ComputeCellShape>},
    {"pair", "cell/sph", "SPH cell fluid: summation density, pressure and Morris viscosity",
     &create_v1<PairCellSPH>, nullptr},
    {"pair", "cell/wall", "wall repulsion, adhesion, contact", &create_v1<PairCellWall>, nullptr},
};

// why this LAMMPS cannot run this plugin, or an empty string if it can
std::string abi_mismatch(void *lmp)
{
  const int running = lammps_version(lmp);
  if (running != CELLSPH_ABI_VERSION)
    return "it was compiled for LAMMPS version " + std::to_string(CELLSPH_ABI_VERSION) +
        " but this LAMMPS is version " + std::to_string(running);
  const struct {
    const char *name;
    int size;
  } sizes[] = {{"bigint", (int) sizeof(bigint)},
               {"tagint", (int) sizeof(tagint)},
               {"imageint", (int) sizeof(imageint)}};
  for (const auto &s : sizes) {
    const int host = lammps_extract_setting(lmp, s.name);
    if (host != s.size)
      return std::string("integer size of ") + s.name + " is " + std::to_string(host) +
          " bytes in LAMMPS but " + std::to_string(s.size) + " in the plugin";
  }
#if LMP_VERSION_NUM < 20230615
#ifdef LAMMPS_EXCEPTIONS
  const int plugin_exceptions = 1;
#else
  const int plugin_exceptions = 0;
#endif
  if (lammps_config_has_exceptions() != plugin_exceptions)
    return std::string("LAMMPS was built ") + (plugin_exceptions ? "without" : "with") +
        " -DLAMMPS_EXCEPTIONS and the plugin " + (plugin_exceptions ? "with" : "without");
#endif
  return "";
}

}    // namespace

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  const std::string why = abi_mismatch(lmp);
  if (!why.empty()) {
    fprintf(stderr, "ERROR: cellsph plugin not registered: %s. Rebuild it against this LAMMPS.\n",
            why.c_str());
    return;
  }
  auto register_plugin = (lammpsplugin_regfunc) regfunc;
  for (const StyleEntry &s : STYLES) {
    lammpsplugin_t plugin;
    plugin.version = LAMMPS_VERSION;
    plugin.style = s.kind;
    plugin.name = s.name;
    plugin.info = s.info;
    plugin.author = "cellsph developers";
    if (s.v1)
      plugin.creator.v1 = s.v1;
    else
      plugin.creator.v2 = s.v2;
    plugin.handle = handle;
    (*register_plugin)(&plugin, lmp);
  }
}
