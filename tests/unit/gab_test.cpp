// the GAB sorption isotherm (CellWater::Gab, src/cell_water.h; doc/model.md §5.10): the inverse
// and its slope, with apple's constants of potentials/apple.cellsph and others
#include "cell_water.h"

#include <gtest/gtest.h>

#include <cmath>

using CellWater::Gab;

static const Gab ISOTHERMS[] = {{0.1, 5.0, 0.9}, {0.2, 20.0, 0.75}, {0.05, 1.5, 1.0}};

// X(a) = Xm C K a / ((1 - K a)(1 - K a + C K a)) at a few points, written out
TEST(Gab, MoistureIsTheFormula)
{
  const Gab g{0.1, 5.0, 0.9};
  for (double a : {0.1, 0.5, 0.9}) {
    const double y = 0.9 * a;
    EXPECT_NEAR(g.moisture(a), 0.1 * 5.0 * y / ((1 - y) * (1 - y + 5.0 * y)), 1e-15);
  }
  // the monolayer X = Xm at y = K a = 1/(1 + sqrt(C)), the root of (C - 1) y^2 + 2 y - 1 = 0
  EXPECT_NEAR(g.moisture(1.0 / (1.0 + std::sqrt(5.0)) / 0.9), 0.1, 1e-15);
}

// activity() inverts moisture() over the whole range, without cancellation at small X
TEST(Gab, ActivityInvertsMoisture)
{
  for (const Gab &g : ISOTHERMS)
    for (double a : {1e-8, 1e-4, 0.01, 0.2, 0.5, 0.8, 0.95, 0.999 / g.k}) {
      if (g.k * a >= 1.0) continue;
      EXPECT_NEAR(g.activity(g.moisture(a)), a, 1e-12 * a) << "Xm " << g.xm << " a " << a;
    }
}

// activity_slope() is da/dX: against central finite differences of activity()
TEST(Gab, SlopeMatchesFiniteDifferences)
{
  for (const Gab &g : ISOTHERMS)
    for (double a : {0.05, 0.3, 0.6, 0.9}) {
      const double x = g.moisture(a), dx = 1e-6 * x;
      const double fd = (g.activity(x + dx) - g.activity(x - dx)) / (2 * dx);
      EXPECT_NEAR(g.activity_slope(x), fd, 1e-7 * std::fabs(fd)) << "a " << a;
    }
}
