/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   The section of a closed, outward triangulated wall by a plane and the 2-D shape descriptors of
   image analysis (ImageJ "Measure" with "Shape descriptors", Feret's diameter and "Fit ellipse")
   of that section: doc/compute_cell_shape.md, doc/model.md §5.11
------------------------------------------------------------------------- */

#ifndef LMP_CELL_SECTION_H
#define LMP_CELL_SECTION_H

#include "lmptype.h"

#include <vector>

namespace CellSection {

// the section's descriptors (all 0 if the plane misses the wall)
struct Shape {
  int loops = 0;             // closed curves of the section
  double area = 0.0;         // A, signed sum over the curves (holes subtract)
  double perimeter = 0.0;    // P, total length of the curves
  double feret = 0.0;        // largest caliper width
  double minferet = 0.0;     // smallest caliper width
  double major = 0.0;        // fitted ellipse: axis ratio from the second moments, area A
  double minor = 0.0;
  double convex_area = 0.0;         // area of the convex hull of the section
  double convex_perimeter = 0.0;    // perimeter of the convex hull of the section
};

// The plane through p with unit normal n (in-plane axes e1, e2, e1 x e2 = n) cuts the ntri
// triangles tri (9 coordinates each, corners a b c, (b - a) x (c - a) outward) whose corners have
// the atom IDs ids (3 each). A corner on the plane counts as above it. Returns false if the cut
// curves do not close (the triangles are not a closed surface).
bool measure(const double *tri, const LAMMPS_NS::tagint *ids, int ntri, const double *p,
             const double *n, const double *e1, const double *e2, Shape &shape);

// convex hull of 2-D points (x y pairs), counter-clockwise, without collinear points (Andrew's
// monotone chain)
std::vector<double> convex_hull(std::vector<double> points);

}    // namespace CellSection

#endif
