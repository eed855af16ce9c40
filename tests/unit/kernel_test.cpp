// the SPH kernels (src/cell_kernel.h, doc/model.md §3.1): each integrates to 1 in 2 and 3
// dimensions, (1/r) dW/dr is the derivative of W, the h derivatives of h adaptive from f, f'/q and
// f'' match finite differences in h, W and its slope vanish at the support's edge, and the
// run-time choice is the compiled one
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

// h adaptive's sums (PairCellSPH::scale_sums): dW/dh = -sigma/h^(d+1) (d f + q^2 f'/q) and
// d2W/dh2 = sigma/h^(d+2) (d (d+1) f + 2 (d+1) q^2 f'/q + q^2 f'') against central finite
// differences of W(r, h) in h, inside each piece of the splines and across their joints
TEST(Kernel, HDerivativesMatchFiniteDifferences)
{
  using namespace CellKernel;
  for (int k = 0; k < NTYPES; k++)
    for (int dim : {2, 3}) {
      const double h = 1.3, dh = 1e-4 * h;
      const Scale s = scale(k, dim, h), sp = scale(k, dim, h + dh), sm = scale(k, dim, h - dh);
      const double w00 = W(k, s, 0.0);    // the scale of W and its derivatives
      for (int i = 1; i < 40; i++) {
        const double r = support(k) * (h - dh) * (i + 0.37) / 40.5, q = r / h;
        double f = 0.0, g = 0.0, c = 0.0;
        switch (k) {
        case CUBIC:
          f = shape<CUBIC>(q), g = q * q * slope<CUBIC>(q), c = q * q * curve<CUBIC>(q);
          break;
        case QUINTIC:
          f = shape<QUINTIC>(q), g = q * q * slope<QUINTIC>(q), c = q * q * curve<QUINTIC>(q);
          break;
        case LUCY:
          f = shape<LUCY>(q), g = q * q * slope<LUCY>(q), c = q * q * curve<LUCY>(q);
          break;
        default:
          f = shape<WENDLAND>(q), g = q * q * slope<WENDLAND>(q), c = q * q * curve<WENDLAND>(q);
        }
        const double d1 = -s.w / h * (dim * f + g);
        const double d2 = s.w / (h * h) * (dim * (dim + 1.0) * f + 2.0 * (dim + 1.0) * g + c);
        const double wp = W(k, sp, r), w0 = W(k, s, r), wm = W(k, sm, r);
        EXPECT_NEAR(d1, (wp - wm) / (2 * dh), 1e-7 * w00 / h)
            << NAMES[k] << " dim " << dim << " r/h " << q;
        EXPECT_NEAR(d2, (wp - 2 * w0 + wm) / (dh * dh), 1e-6 * w00 / (h * h))
            << NAMES[k] << " dim " << dim << " r/h " << q;
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
