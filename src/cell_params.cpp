/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
------------------------------------------------------------------------- */

#include "cell_params.h"

#include "cell_limits.h"
#include "comm.h"
#include "error.h"
#include "update.h"
#include "utils.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

CellParams::CellParams(LAMMPS *lmp, const std::string &file_in, const std::string &command_in) :
    Pointers(lmp), file(file_in), command(command_in)
{
  std::string text, problem;
  if (comm->me == 0) {
    const std::string path = find_file(file);
    const std::string units = path.empty() ? "" : utils::get_potential_units(path, "parameter");
    FILE *fp = nullptr;
    if (path.empty() || !(fp = fopen(path.c_str(), "r")))
      problem = fmt::format("cannot open parameter file {}", file);
    else if (units != update->unit_style)
      problem = fmt::format("{} line 1: 'UNITS: {}' but the input uses {} units", file, units,
                            update->unit_style);
    if (fp) {
      char buf[4096];
      size_t n;
      while ((n = fread(buf, 1, sizeof(buf), fp)) > 0) text.append(buf, n);
      fclose(fp);
    }
  }
  int plen = (int) problem.size();
  MPI_Bcast(&plen, 1, MPI_INT, 0, world);
  problem.resize(plen);
  MPI_Bcast(&problem[0], plen, MPI_CHAR, 0, world);
  if (!problem.empty()) error->all(FLERR, "{}: {}", command, problem);

  int size = (int) text.size();
  MPI_Bcast(&size, 1, MPI_INT, 0, world);
  text.resize(size);
  MPI_Bcast(&text[0], size, MPI_CHAR, 0, world);

  std::istringstream in(text);
  std::string line;
  for (int lineno = 1; std::getline(in, line); lineno++) {
    const auto words = utils::split_words(utils::trim_comment(line));
    if (words.empty()) continue;
    if (words.size() != 2)
      error->all(FLERR, "{}: {} line {}: expected 'key value', got '{}'", command, file, lineno,
                 utils::trim(line));
    if (entries.count(words[0]))
      error->all(FLERR, "{}: {} line {}: '{}' set twice (first on line {})", command, file, lineno,
                 words[0], entries[words[0]].line);
    entries[words[0]] = {words[1], lineno};
  }
}

/* ----------------------------------------------------------------------
   the file as LAMMPS finds potential files, then in $LAMMPS_POTENTIALS (which Debian's LAMMPS
   29 Sep 2021 does not search); empty if not found
------------------------------------------------------------------------- */

std::string CellParams::find_file(const std::string &name)
{
  std::string path = utils::get_potential_file_path(name);
  const char *dir = getenv("LAMMPS_POTENTIALS");
  if (path.empty() && dir) {
    const std::string candidate = std::string(dir) + "/" + name;
    if (FILE *fp = fopen(candidate.c_str(), "r")) {
      fclose(fp);
      path = candidate;
    }
  }
  return path;
}

/* ---------------------------------------------------------------------- */

const CellParams::Entry &CellParams::find(const std::string &key) const
{
  auto it = entries.find(key);
  if (it == entries.end())
    error->all(FLERR, "{}: parameter file {} has no '{}' line", command, file, key);
  return it->second;
}

std::string CellParams::where(const Entry &e) const
{
  return fmt::format("{}: {} line {}", command, file, e.line);
}

std::string CellParams::word(const std::string &key) const
{
  return find(key).value;
}

double CellParams::number(const std::string &key) const
{
  const Entry &e = find(key);
  char *end = nullptr;
  errno = 0;
  const double v = strtod(e.value.c_str(), &end);
  if (*end != '\0' || errno != 0 || e.value.empty())
    error->all(FLERR, "{}: {} = '{}' is not a number", where(e), key, e.value);
  if (!std::isfinite(v))
    error->all(FLERR, "{}: {} = '{}' is not a finite number", where(e), key, e.value);
  return v;
}

double CellParams::positive(const std::string &key) const
{
  const double v = number(key);
  if (!(v > 0.0)) error->all(FLERR, "{}: {} = {} must be > 0", where(find(key)), key, v);
  return v;
}

double CellParams::nonnegative(const std::string &key) const
{
  const double v = number(key);
  if (!(v >= 0.0)) error->all(FLERR, "{}: {} = {} must be >= 0", where(find(key)), key, v);
  return v;
}

double CellParams::positive(const std::string &key, double max, const std::string &unit) const
{
  return CellLimits::within(error, where(find(key)) + ": " + key, positive(key), 0.0, max, unit,
                            true);
}

double CellParams::nonnegative(const std::string &key, double max, const std::string &unit) const
{
  return CellLimits::within(error, where(find(key)) + ": " + key, nonnegative(key), 0.0, max, unit,
                            false);
}
