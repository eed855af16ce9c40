// the SPH kernels (src/cell_kernel.h, doc/model.md §3.1): each integrates to 1 in 2 and 3
// dimensions, (1/r) dW/dr is the derivative of W, W and its slope vanish at the support's edge,
// and the run-time choice is the compiled one
#include "cell_kernel.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace LAMMPS_NS;

namespace {
// integral of W over the plane (dim 2: 2 pi r dr) or space (dim 3: 4 pi r^2 dr), Simpson's rule
double integral(int kernel, int dim, double h)
{
  const CellKernel::Scale s = CellKernel::scale(kernel, dim, h);
  const double rc = CellKernel::support(kernel) * h;
  const int n = 20000;
  double sum = 0.0;
  for (int i = 0; i <= n; i++) {
    const double r = rc * i / n;
    const double weight = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    const double shell = dim == 2 ? 2.0 * M_PI * r : 4.0 * M_PI * r * r;
    sum += weight * shell * (i == n ? 0.0 : CellKernel::W(kernel, s, r));
  }
  return sum * rc / n / 3.0;
}
}    // namespace

TEST(Kernel, EveryKernelIntegratesToOne)
{
  for (int k = 0; k < CellKernel::NTYPES; k++)
    for (int dim : {2, 3})
      for (double h : {1.0, 12.5e-6})
        EXPECT_NEAR(integral(k, dim, h), 1.0, 1e-9)
            << CellKernel::NAMES[k] << " in " << dim << " dimensions, h " << h;
}

// (1/r) dW/dr against central finite differences of W, inside each piece of the cubic and
// quintic splines and across their joints
TEST(Kernel, DerivativeMatchesFiniteDifferences)
{
  for (int k = 0; k < CellKernel::NTYPES; k++)
    for (int dim : {2, 3}) {
      const double h = 1.3;
      const CellKernel::Scale s = CellKernel::scale(k, dim, h);
      const double rc = CellKernel::support(k) * h;
      for (int i = 1; i < 40; i++) {
        const double r = rc * (i + 0.37) / 40.5, dr = 1e-6 * h;
        const double fd = (CellKernel::W(k, s, r + dr) - CellKernel::W(k, s, r - dr)) / (2 * dr);
        EXPECT_NEAR(r * CellKernel::dWr(k, s, r), fd, 1e-7 * s.w / h)
            << CellKernel::NAMES[k] << " dim " << dim << " r/h " << r / h;
      }
    }
}

// compact support: W and dW/dr go to zero continuously at the edge
TEST(Kernel, VanishesAtTheSupport)
{
  for (int k = 0; k < CellKernel::NTYPES; k++) {
    const CellKernel::Scale s = CellKernel::scale(k, 3, 1.0);
    const double rc = CellKernel::support(k) * (1.0 - 1e-12);
    EXPECT_NEAR(CellKernel::W(k, s, rc), 0.0, 1e-12) << CellKernel::NAMES[k];
    EXPECT_NEAR(rc * CellKernel::dWr(k, s, rc), 0.0, 1e-9) << CellKernel::NAMES[k];
    EXPECT_GT(CellKernel::W(k, s, 0.0), 0.0);
  }
}

// names and the run-time dispatch (W(kernel, ...)) give the compiled kernels
TEST(Kernel, NamesAndRunTimeChoice)
{
  for (int k = 0; k < CellKernel::NTYPES; k++)
    EXPECT_EQ(CellKernel::parse(CellKernel::NAMES[k]), k);
  EXPECT_EQ(CellKernel::parse("gauss"), -1);
  const CellKernel::Scale s = CellKernel::scale(CellKernel::QUINTIC, 3, 2.0);
  EXPECT_EQ(CellKernel::W(CellKernel::QUINTIC, s, 1.7), CellKernel::W<CellKernel::QUINTIC>(s, 1.7));
  EXPECT_EQ(CellKernel::dWr(CellKernel::CUBIC, s, 1.7), CellKernel::dWr<CellKernel::CUBIC>(s, 1.7));
  EXPECT_EQ(CellKernel::W(CellKernel::LUCY, s, 0.7), CellKernel::W<CellKernel::LUCY>(s, 0.7));
}
