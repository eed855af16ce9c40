/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   A cellsph parameter file (potentials/<name>.cellsph): 'key value' lines, '#' comments, first line
   tagged 'UNITS: si' like every LAMMPS potential file. Found and unit-checked through
   utils::open_potential (current folder, then $LAMMPS_POTENTIALS). Read on rank 0, broadcast.
   Each style takes the keys it needs; errors name the command, the file, the line and the value.
------------------------------------------------------------------------- */

#ifndef LMP_CELL_PARAMS_H
#define LMP_CELL_PARAMS_H

#include "pointers.h"

#include <map>
#include <string>

namespace LAMMPS_NS {

class CellParams : protected Pointers {
 public:
  CellParams(class LAMMPS *, const std::string &file, const std::string &command);

  bool has(const std::string &key) const { return entries.count(key) > 0; }
  std::string word(const std::string &key) const;
  double number(const std::string &key) const;
  double positive(const std::string &key) const;       // > 0
  double nonnegative(const std::string &key) const;    // >= 0
  // (0, max] and [0, max]: the error names the file, the line, the key and the range in unit
  double positive(const std::string &key, double max, const std::string &unit) const;
  double nonnegative(const std::string &key, double max, const std::string &unit) const;

 private:
  struct Entry {
    std::string value;
    int line;
  };
  std::string file, command;
  std::map<std::string, Entry> entries;

  static std::string find_file(const std::string &);
  const Entry &find(const std::string &key) const;
  std::string where(const Entry &e) const;
};

}    // namespace LAMMPS_NS

#endif
