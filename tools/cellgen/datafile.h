// The LAMMPS data file cellgen writes (README.md "Output: LAMMPS data file"): atom_style angle, or
// molecular with dihedrals; bond type 1 the wall bonds, type 2 the junction bonds of tissue mode.
#pragma once

#include "geometry.h"

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace cellgen {

// What a data file holds besides the System (its particles, wall bonds, triangles and box).
struct DataExtras {
  int bondTypes = 1;              // 2 in tissue mode, junction bonds or not
  std::vector<Edge> junctions;    // bond type 2, after the wall bonds (tissue mode)
  std::vector<Quad> dihedrals;    // --dihedrals: one per wall edge (wallDihedrals)
};

void writeData(const std::string &path, const System &sys, const std::string &comment,
               const DataExtras &extras);

// An output file, closed on destruction; closeOut reports any write error.
using File = std::unique_ptr<std::FILE, int (*)(std::FILE *)>;
File openOut(const std::string &path);
void closeOut(File &f, const std::string &path);

}    // namespace cellgen
