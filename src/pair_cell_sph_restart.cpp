/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   pair_style cell/sph: restart files (the settings and the pair_coeff values of every format
   version, refusing the settings of removed keywords) and data files
------------------------------------------------------------------------- */

#include "pair_cell_sph.h"

#include "atom.h"
#include "cell_restart.h"
#include "comm.h"
#include "error.h"

#include <algorithm>
#include <climits>
#include <functional>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

// 2: per type pair, whether it is a wall boundary pair; 3: the smoothing-length mode and eta;
// 4: the temperature of the viscosity (temp, Tref); 5: shift; 6: tensile (eps, n, dp); 7: the
// wall boundary's adhesion W per type pair; 8: grow; 9: background; 10: background auto lag;
// 11: background auto's P_b now; 12: without the removed eos, Tref, shift, tensile, adhesion W,
// grow and lag (read_settings reads them from older files); 13: the wall boundary's schedule of
// exact evaluations (the base itself is per atom, in fix cellsph_base)
static const int RESTART_VERSION = 13;
// the last version of a setting still written
static const int WRITTEN = INT_MAX;

// per type pair, after setflag: the wall boundary flag (version 2 on)
static bool has_boundary_flag(int version)
{
  return version >= 2;
}

// per type pair: rho0, K, mu, h, and in versions 7-11 the removed wall adhesion W
static int pair_values(int version)
{
  return version >= 7 && version < 12 ? 5 : 4;
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (setflag[i][j]) {
        fwrite(&boundary[i][j], sizeof(int), 1, fp);
        fwrite(&rho0[i][j], sizeof(double), 1, fp);
        fwrite(&bulk[i][j], sizeof(double), 1, fp);
        fwrite(&mu[i][j], sizeof(double), 1, fp);
        fwrite(&h[i][j], sizeof(double), 1, fp);
      }
    }
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  const int me = comm->me;
  double adhesion = 0.0;    // versions 7-11: the removed wall adhesion W, refused if > 0
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
      if (!setflag[i][j]) continue;
      if (has_boundary_flag(restart_version)) {
        if (me == 0) utils::sfread(FLERR, &boundary[i][j], sizeof(int), 1, fp, nullptr, error);
        MPI_Bcast(&boundary[i][j], 1, MPI_INT, 0, world);
      }
      double values[5] = {0.0, 0.0, 0.0, 0.0, 0.0};
      const int nvalues = pair_values(restart_version);
      if (me == 0) utils::sfread(FLERR, values, sizeof(double), nvalues, fp, nullptr, error);
      MPI_Bcast(values, 5, MPI_DOUBLE, 0, world);
      rho0[i][j] = values[0];
      bulk[i][j] = values[1];
      mu[i][j] = values[2];
      h[i][j] = values[3];
      adhesion = std::max(adhesion, values[4]);
    }
  if (adhesion > 0.0)
    error->all(FLERR,
               "Pair cell/sph: the restart file has a wall boundary with adhesion W = {} J/m^2, "
               "which was removed: the wall boundary with 'background auto' (or a background "
               "P_b) holds the fluid on the wall",
               adhesion);
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::write_restart_settings(FILE *fp)
{
  // version 1 (no marker) began with the kernel index >= 0; later versions with -version
  const int marker = -RESTART_VERSION;
  fwrite(&marker, sizeof(int), 1, fp);
  fwrite(&kernel, sizeof(int), 1, fp);
  fwrite(&cut_global, sizeof(double), 1, fp);
  fwrite(&hmode, sizeof(int), 1, fp);
  fwrite(&eta, sizeof(double), 1, fp);
  // temp (flag, number, variable name)
  fwrite(&temp_set, sizeof(int), 1, fp);
  fwrite(&temp.value, sizeof(double), 1, fp);
  const int len = static_cast<int>(temp.name.size());
  fwrite(&len, sizeof(int), 1, fp);
  if (len > 0) fwrite(temp.name.data(), sizeof(char), len, fp);
  // background (number, variable name, auto flag, P_min), auto's P_b now and whether it has one
  fwrite(&background_in.value, sizeof(double), 1, fp);
  const int blen = static_cast<int>(background_in.name.size());
  fwrite(&blen, sizeof(int), 1, fp);
  if (blen > 0) fwrite(background_in.name.data(), sizeof(char), blen, fp);
  fwrite(&background_auto, sizeof(int), 1, fp);
  fwrite(&background_min, sizeof(double), 1, fp);
  fwrite(&background, sizeof(double), 1, fp);
  fwrite(&background_set, sizeof(int), 1, fp);
  // the wall boundary's schedule (pair_cell_sph_boundary.h), none without it
  const PairCellSPHBoundary::Schedule sched =
      walls ? wall.schedule() : PairCellSPHBoundary::Schedule{-1, 0, 0, 0.0};
  fwrite(&sched.refreshed, sizeof(bigint), 1, fp);
  fwrite(&sched.every, sizeof(int), 1, fp);
  fwrite(&sched.pending, sizeof(int), 1, fp);
  fwrite(&sched.lastjump, sizeof(double), 1, fp);
}

/* ----------------------------------------------------------------------
   the settings of a restart file of any version (on rank 0), after the version and the kernel:
   each field in file order with the first and last versions that hold it; those of the removed
   keywords (version < 12: eos, Tref, shift, tensile eps n dp, grow, background auto lag) into old
------------------------------------------------------------------------- */

void PairCellSPH::read_settings(FILE *fp, Removed &old, std::string &name, std::string &bname,
                                double &pb, PairCellSPHBoundary::Schedule &sched)
{
  const auto get = [&](auto *value, int n = 1) {
    utils::sfread(FLERR, value, sizeof(*value), n, fp, nullptr, error);
  };
  const auto text = [&](std::string &str) {
    int n = 0;
    get(&n);
    std::vector<char> chars(n);
    if (n > 0) get(chars.data(), n);
    str.assign(chars.begin(), chars.end());
  };
  int tensile_n = 0;
  double tensile_dp = 0.0;
  // the fields in file order: the first and the last version that hold each, and its reader
  const struct {
    int first, last;
    std::function<void()> read;
  } fields[] = {
      {1, 11, [&] { get(&old.eos); }},
      {1, WRITTEN, [&] { get(&cut_global); }},
      {3, WRITTEN, [&] { get(&hmode); }},
      {3, WRITTEN, [&] { get(&eta); }},
      {4, WRITTEN, [&] { get(&temp_set); }},
      {4, WRITTEN, [&] { get(&temp.value); }},
      {4, 11, [&] { get(&old.tref); }},
      {4, WRITTEN, [&] { text(name); }},
      {5, 11, [&] { get(&old.shift); }},
      {6, 11, [&] { get(&old.tensile); }},
      {6, 11, [&] { get(&tensile_n); }},
      {6, 11, [&] { get(&tensile_dp); }},
      {8, 11, [&] { get(&old.grow); }},
      {9, WRITTEN, [&] { get(&background_in.value); }},
      {9, WRITTEN, [&] { text(bname); }},
      {9, WRITTEN, [&] { get(&background_auto); }},
      {9, WRITTEN, [&] { get(&background_min); }},
      {10, 11, [&] { get(&old.lag); }},
      {11, WRITTEN, [&] { get(&pb); }},
      {11, WRITTEN, [&] { get(&background_set); }},
      {13, WRITTEN, [&] { get(&sched.refreshed); }},
      {13, WRITTEN, [&] { get(&sched.every); }},
      {13, WRITTEN, [&] { get(&sched.pending); }},
      {13, WRITTEN, [&] { get(&sched.lastjump); }},
  };
  for (const auto &field : fields)
    if (restart_version >= field.first && restart_version <= field.last) field.read();
}

/* ----------------------------------------------------------------------
   the removed keyword whose setting an older restart file has on (the first of the list), or
   nullptr; grow, which changed the neighbour range only, is read and ignored
------------------------------------------------------------------------- */

const char *PairCellSPH::removed_setting(const Removed &old) const
{
  const std::pair<bool, const char *> settings[] = {{old.eos != 0, "eos tait"},
                                                    {hmode == 1, "h mass"},
                                                    {temp_set && old.tref != TREF, "Tref"},
                                                    {old.shift > 0.0, "shift"},
                                                    {old.tensile > 0.0, "tensile"},
                                                    {old.lag >= 0.0, "background auto ... lag"}};
  for (const auto &setting : settings)
    if (setting.first) return setting.second;
  return nullptr;
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::read_restart_settings(FILE *fp)
{
  Removed old;
  std::string name, bname;
  double pb = 0.0;
  PairCellSPHBoundary::Schedule sched{-1, 0, 0, 0.0};
  hmode = HFIXED;
  eta = 0.0;
  temp_set = 0;
  temp.value = 0.0;
  background_in = CellQuantity();
  background_auto = background_set = 0;
  background_min = 0.0;
  if (comm->me == 0) {
    int first;
    utils::sfread(FLERR, &first, sizeof(int), 1, fp, nullptr, error);
    restart_version = CellRestart::version(first);
    if (first < 0) utils::sfread(FLERR, &first, sizeof(int), 1, fp, nullptr, error);
    kernel = first;
    read_settings(fp, old, name, bname, pb, sched);
  }
  MPI_Bcast(&restart_version, 1, MPI_INT, 0, world);
  CellRestart::refuse_newer(error, FLERR, "Pair cell/sph", restart_version, RESTART_VERSION);
  double values[10] = {cut_global, eta,      temp.value, background_in.value, background_min,
                       pb,         old.tref, old.shift,  old.tensile,         old.lag};
  MPI_Bcast(values, 10, MPI_DOUBLE, 0, world);
  int flags[6] = {kernel, hmode, temp_set, background_auto, background_set, old.eos};
  MPI_Bcast(flags, 6, MPI_INT, 0, world);
  cut_global = values[0], eta = values[1], temp.value = values[2];
  background_in.value = values[3], background_min = values[4], pb = values[5];
  old.tref = values[6], old.shift = values[7], old.tensile = values[8], old.lag = values[9];
  kernel = flags[0], hmode = flags[1], temp_set = flags[2];
  background_auto = flags[3], background_set = flags[4], old.eos = flags[5];
  const char *gone = removed_setting(old);
  if (gone)
    error->all(FLERR,
               "Pair cell/sph: the restart file (format version {}) uses '{}', which was removed "
               "(doc/pair_cell_sph.md, removed keywords): continue it with an older cellsph",
               restart_version, gone);
  // version 11: a P_b it has is one that steps have advanced
  if (restart_version == 11 && background_set) background_set = BACKGROUND_STEPPED;
  background = background_auto && background_set ? pb : background_in.value;
  for (std::string *str : {&name, &bname}) {
    int n = static_cast<int>(str->size());
    MPI_Bcast(&n, 1, MPI_INT, 0, world);
    str->resize(n);
    if (n > 0) MPI_Bcast(&(*str)[0], n, MPI_CHAR, 0, world);
  }
  MPI_Bcast(&sched.refreshed, 1, MPI_LMP_BIGINT, 0, world);
  int ints[2] = {sched.every, sched.pending};
  MPI_Bcast(ints, 2, MPI_INT, 0, world);
  MPI_Bcast(&sched.lastjump, 1, MPI_DOUBLE, 0, world);
  sched.every = ints[0], sched.pending = ints[1];
  wall.resume(sched);
  temp.name = name;
  background_in.name = bname;
  temp.ivar = -1;
  muscale = 1.0;
}

/* ----------------------------------------------------------------------
   Pair Coeffs: pair I I only; cross pairs are not mixed, so they need 'write_data ... pair ij'
------------------------------------------------------------------------- */

void PairCellSPH::write_data(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++)
    fprintf(fp, "%d %.16g %.16g %.16g %.16g\n", i, rho0[i][i], bulk[i][i], mu[i][i], h[i][i]);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i + 1; j <= atom->ntypes; j++)
      if (setflag[i][j])
        error->warning(FLERR,
                       "Pair cell/sph: the Pair Coeffs section cannot hold pair_coeff {} {} "
                       "(cell/sph does not mix): use 'write_data <file> pair ij'",
                       i, j);
}

/* ---------------------------------------------------------------------- */

void PairCellSPH::write_data_all(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (boundary[i][j])
        fprintf(fp, "%d %d wall\n", i, j);
      else
        fprintf(fp, "%d %d %.16g %.16g %.16g %.16g\n", i, j, rho0[i][j], bulk[i][j], mu[i][j],
                h[i][j]);
}
