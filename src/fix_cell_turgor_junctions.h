/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   TurgorJunctions: which cells touch, from the unbroken junction bonds of one bond_style
   cell/lamella type between atoms of two cells, counted once per bond across ranks (newton_bond
   on or off) and sent to the home ranks of the two cells (doc/model.md §5.2); each bond stands
   for the junction area A of its type, or for its pair's contact area over its bonds from a
   cellgen tissue .junctions file (doc/model.md §4.6, §5.13). Used by fix cell/turgor's
   'exchange' for the water network.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_CELL_TURGOR_JUNCTIONS_H
#define LMP_FIX_CELL_TURGOR_JUNCTIONS_H

#include "pointers.h"

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace LAMMPS_NS {

class TurgorJunctions : protected Pointers {
 public:
  // cells i < j (indices of the registry's cells) joined by this many bonds through this junction
  // area (m^2)
  struct Junction {
    int i, j, bonds;
    double area;
  };

  // areas: a cellgen tissue .junctions file, or empty for the bond type's A
  TurgorJunctions(class LAMMPS *, const std::string &command, int bondtype,
                  const std::string &areas);
  // checks that the bond type is of bond_style cell/lamella, takes its junction area per bond
  void init();
  double bond_area() const { return area; }
  int bond_type() const { return type; }
  // the junctions of the registry's home cells on this rank (a junction between cells of two
  // home ranks on both); counted again when the number of conducting bonds changed since the last
  // call (a bond broke), or always with recount; true if counted. Collective
  bool gather(class CellRegistry &registry, bool recount);
  const std::vector<Junction> &junctions() const { return list; }

 private:
  std::string command;
  int type;
  double area;                   // junction area per bond of the type (m^2)
  bigint counted;                // conducting bonds at the last count, -1 before
  std::vector<Junction> list;    // sorted by (i, j)
  std::string areas_file;
  // from the file: per pair of cell IDs (lower first) the contact area per bond (m^2)
  std::map<std::pair<tagint, tagint>, double> pair_area;

  bigint conducting() const;
  void read_areas();
};

}    // namespace LAMMPS_NS

#endif
