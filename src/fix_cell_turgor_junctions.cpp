/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
------------------------------------------------------------------------- */

#include "fix_cell_turgor_junctions.h"

#include "atom.h"
#include "bond.h"
#include "bond_hybrid.h"
#include "cell_registry.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "tokenizer.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

TurgorJunctions::TurgorJunctions(LAMMPS *lmp, const std::string &command_in, int bondtype,
                                 const std::string &areas) :
    Pointers(lmp),
    command(command_in), type(bondtype), area(0.0), counted(-1), areas_file(areas)
{
  if (!atom->molecular)
    error->all(FLERR, "{}: exchange needs bonds (atom_style angle or molecular)", command);
  if (type < 1 || type > atom->nbondtypes)
    error->all(FLERR, "{}: exchange bond type {} is out of range 1 to {}", command, type,
               atom->nbondtypes);
  if (!areas_file.empty()) read_areas();
}

/* ----------------------------------------------------------------------
   cellgen tissue .junctions: 'cell_i cell_j image_x image_y image_z area bonds' per face, from
   each side; per pair of cells (lines with cell_i < cell_j, summed over the faces with bonds) the
   contact area per bond. Read on rank 0, broadcast.
------------------------------------------------------------------------- */

void TurgorJunctions::read_areas()
{
  std::vector<double> flat;
  if (comm->me == 0) {
    FILE *fp = fopen(areas_file.c_str(), "r");
    if (!fp) error->one(FLERR, "{}: cannot open the junction areas file {}", command, areas_file);
    std::map<std::pair<tagint, tagint>, std::pair<double, double>> sums;
    char line[1024];
    int number = 0;
    while (fgets(line, sizeof(line), fp)) {
      number++;
      const std::string text = utils::trim(line);
      if (text.empty() || text[0] == '#') continue;
      ValueTokenizer words(text);
      tagint a = 0, b = 0;
      double face = -1.0, bonds = -1.0;
      try {
        a = words.next_tagint();
        b = words.next_tagint();
        for (int k = 0; k < 3; k++) words.next_int();
        face = words.next_double();
        bonds = words.next_double();
      } catch (TokenizerException &) {
        a = 0;
      }
      if (a < 1 || b < 1 || a == b || !(face >= 0.0) || !(bonds >= 0.0) || words.has_next())
        error->one(FLERR,
                   "{}: {} line {} is not 'cell_i cell_j image_x image_y image_z area bonds' "
                   "(cellgen tissue .junctions): {}",
                   command, areas_file, number, text);
      if (a > b || bonds == 0.0) continue;
      auto &sum = sums[{a, b}];
      sum.first += face;
      sum.second += bonds;
    }
    fclose(fp);
    for (const auto &kv : sums)
      flat.insert(
          flat.end(),
          {(double) kv.first.first, (double) kv.first.second, kv.second.first / kv.second.second});
  }
  int n = (int) flat.size();
  MPI_Bcast(&n, 1, MPI_INT, 0, world);
  flat.resize(n);
  MPI_Bcast(flat.data(), n, MPI_DOUBLE, 0, world);
  for (int k = 0; k < n; k += 3) pair_area[{(tagint) flat[k], (tagint) flat[k + 1]}] = flat[k + 2];
}

/* ---------------------------------------------------------------------- */

void TurgorJunctions::init()
{
  Bond *lamella = force->bond_match("cell/lamella");
  bool owned = lamella && lamella->setflag && lamella->setflag[type];
  if (owned && strcmp(force->bond_style, "hybrid") == 0) {
    // under bond_style hybrid the type must belong to the cell/lamella sub-style alone
    auto *hybrid = (BondHybrid *) force->bond;
    for (int m = 0; m < hybrid->nstyles; m++)
      if (hybrid->styles[m] != lamella && hybrid->styles[m]->setflag &&
          hybrid->styles[m]->setflag[type])
        owned = false;
  }
  if (!owned)
    error->all(FLERR,
               "{}: exchange bond type {} is not of bond_style cell/lamella (bond style {}): the "
               "junction area comes from its coefficients",
               command, type, force->bond_style ? force->bond_style : "none");
  int dim;
  area = ((double *) lamella->extract("area", dim))[type];
  counted = -1;
}

/* ----------------------------------------------------------------------
   bonds of the type stored on this rank, each once: with newton_bond off both atoms store it and
   the one with the lower ID counts it; broken bonds have type 0
------------------------------------------------------------------------- */

bigint TurgorJunctions::conducting() const
{
  const int *num_bond = atom->num_bond;
  int **bond_type = atom->bond_type;
  tagint **bond_atom = atom->bond_atom;
  const tagint *tag = atom->tag;
  const bool both = !force->newton_bond;
  bigint mine = 0, all = 0;
  for (int i = 0; i < atom->nlocal; i++)
    for (int m = 0; m < num_bond[i]; m++)
      if (bond_type[i][m] == type && !(both && bond_atom[i][m] < tag[i])) mine++;
  MPI_Allreduce(&mine, &all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  return all;
}

/* ---------------------------------------------------------------------- */

bool TurgorJunctions::gather(CellRegistry &registry, bool recount)
{
  const bigint now = conducting();
  if (!recount && now == counted) return false;
  counted = now;

  const int *num_bond = atom->num_bond;
  int **bond_type = atom->bond_type;
  tagint **bond_atom = atom->bond_atom;
  const tagint *tag = atom->tag, *molecule = atom->molecule;
  const bool both = !force->newton_bond;
  std::map<std::pair<int, int>, int> mine;
  for (int i = 0; i < atom->nlocal; i++)
    for (int m = 0; m < num_bond[i]; m++) {
      if (bond_type[i][m] != type || (both && bond_atom[i][m] < tag[i])) continue;
      const int j = atom->map(bond_atom[i][m]);
      if (j < 0)
        error->one(FLERR, "{}: junction bond {}-{} has its atom {} missing on this rank", command,
                   tag[i], bond_atom[i][m], bond_atom[i][m]);
      const int a = registry.index(molecule[i]), b = registry.index(molecule[j]);
      // junctions to cells outside the fix's group carry no water; a same-cell junction is
      // stopped by bond_style cell/lamella at the first force evaluation
      if (a < 0 || b < 0 || a == b) continue;
      mine[{std::min(a, b), std::max(a, b)}]++;
    }

  // each pair's bonds on this rank to the home ranks of its two cells: rows (cell, other, bonds)
  std::vector<double> rows, got;
  for (const auto &kv : mine) {
    const int a = kv.first.first, b = kv.first.second;
    rows.insert(rows.end(), {(double) a, (double) b, (double) kv.second});
    if (registry.home(b) != registry.home(a))
      rows.insert(rows.end(), {(double) b, (double) a, (double) kv.second});
  }
  registry.send_home(3, rows, got);
  // a face cut by the rank boundary has bonds on both ranks: integer sums, the same on any layout
  std::map<std::pair<int, int>, int> merged;
  for (size_t k = 0; k < got.size(); k += 3) {
    const int a = (int) got[k], b = (int) got[k + 1];
    merged[{std::min(a, b), std::max(a, b)}] += (int) got[k + 2];
  }
  list.clear();
  int failed = registry.ncell();
  std::string message;
  for (const auto &kv : merged) {
    const int a = kv.first.first, b = kv.first.second, bonds = kv.second;
    double per = area;
    if (!areas_file.empty()) {
      auto it = pair_area.find({registry.id(a), registry.id(b)});
      if (it == pair_area.end()) {
        if (a < failed) {
          failed = a;
          message = fmt::format("{}: junction bonds of type {} join cells {} and {}, which the "
                                "junction areas file {} does not list",
                                command, type, registry.id(a), registry.id(b), areas_file);
        }
        continue;
      }
      per = it->second;
    }
    list.push_back({a, b, bonds, bonds * per});
  }
  registry.settle(failed, message, {});
  return true;
}
