/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   A style's input that is a number or an equal-style variable v_name: the variable is looked up
   at init (it may be defined after the command) and evaluated when the style needs the value.
   Shared by fix cell/turgor, fix cell/pressure and pair cell/sph.
------------------------------------------------------------------------- */

#ifndef LMP_CELL_QUANTITY_H
#define LMP_CELL_QUANTITY_H

#include "error.h"
#include "input.h"
#include "pointers.h"
#include "utils.h"
#include "variable.h"

#include <cstring>
#include <string>

namespace LAMMPS_NS {

struct CellQuantity {
  double value = 0.0;    // the number, when name is empty
  std::string name;      // equal-style variable name (without v_), or empty
  int ivar = -1;         // its index, from resolve()

  // a number or v_name, as given to a style; the variable is looked up later, by resolve();
  // 'what' names the input in the error messages, e.g. "Fix cell/turgor: psi"
  static CellQuantity parse(LAMMPS *lmp, const char *arg, const std::string &what)
  {
    if (strcmp(arg, "v_") == 0) lmp->error->all(FLERR, "{} = v_ names no variable", what);
    if (strncmp(arg, "v_", 2) == 0) return CellQuantity{0.0, arg + 2, -1};
    return CellQuantity{utils::numeric(FLERR, arg, false, lmp), "", -1};
  }

  bool is_variable() const { return !name.empty(); }

  // look the variable up; 'what' begins the error messages, e.g. "Fix cell/turgor: variable"
  void resolve(LAMMPS *lmp, const std::string &what)
  {
    if (name.empty()) return;
    ivar = lmp->input->variable->find(name.c_str());
    if (ivar < 0) lmp->error->all(FLERR, "{} {} does not exist", what, name);
    if (!lmp->input->variable->equalstyle(ivar))
      lmp->error->all(FLERR, "{} {} is not equal-style", what, name);
  }

  double get(LAMMPS *lmp) const
  {
    return name.empty() ? value : lmp->input->variable->compute_equal(ivar);
  }
};

}    // namespace LAMMPS_NS

#endif
