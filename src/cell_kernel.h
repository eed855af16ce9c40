/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   The SPH smoothing kernels, in one place for density and forces (doc/model.md §3.1; the SPH
   package's anti-pattern is a kernel per style). W(r) = sigma_d / h^d f(q) with q = r/h and
   (1/r) dW/dr = sigma_d / h^(d+2) f'(q)/q. The dimension and h enter only through the constants
   of Scale, computed once per type pair; the shapes f(q) and f'(q)/q are templates so that a
   pair loop compiled for one kernel has no kernel or dimension branch.
------------------------------------------------------------------------- */

#ifndef LMP_CELL_KERNEL_H
#define LMP_CELL_KERNEL_H

#include <cmath>
#include <string>

namespace LAMMPS_NS {
namespace CellKernel {

  enum Type { WENDLAND = 0, CUBIC = 1, QUINTIC = 2, LUCY = 3 };
  static const char *const NAMES[] = {"wendland", "cubic", "quintic", "lucy"};
  static const int NTYPES = 4;

  // kernel by name, or -1
  inline int parse(const std::string &name)
  {
    for (int k = 0; k < NTYPES; k++)
      if (name == NAMES[k]) return k;
    return -1;
  }

  // support radius in units of h: W = 0 for r >= support(kernel) * h
  inline double support(int kernel)
  {
    static const double SUPPORT[] = {2.0, 2.0, 3.0, 1.0};
    return SUPPORT[kernel];
  }

  // sigma_d: normalisation that makes W integrate to 1 in dim (2 or 3) dimensions
  inline double sigma(int kernel, int dim)
  {
    static const double SIGMA2[] = {7.0 / (4.0 * M_PI), 10.0 / (7.0 * M_PI), 7.0 / (478.0 * M_PI),
                                    5.0 / M_PI};
    static const double SIGMA3[] = {21.0 / (16.0 * M_PI), 1.0 / M_PI, 1.0 / (120.0 * M_PI),
                                    105.0 / (16.0 * M_PI)};
    return dim == 2 ? SIGMA2[kernel] : SIGMA3[kernel];
  }

  // constants of one kernel at one h in one dimension
  struct Scale {
    double invh;    // 1/h
    double w;       // sigma_d / h^d
    double dw;      // sigma_d / h^(d+2)
  };

  inline Scale scale(int kernel, int dim, double h)
  {
    const double hd = dim == 2 ? h * h : h * h * h;
    return {1.0 / h, sigma(kernel, dim) / hd, sigma(kernel, dim) / (hd * h * h)};
  }

  // shape f(q) and slope f'(q)/q, valid for 0 <= q < support; zero beyond is the caller's cutoff;
  // curve f''(q) (d^2 W/dh^2 of h adaptive, doc/pair_cell_sph.md)
  template <int K> inline double shape(double q);
  template <int K> inline double slope(double q);
  template <int K> inline double curve(double q);

  // Wendland C2: f = (1 - q/2)^4 (1 + 2q), f'/q = -5 (1 - q/2)^3
  template <> inline double shape<WENDLAND>(double q)
  {
    const double a = 1.0 - 0.5 * q;
    const double a2 = a * a;
    return a2 * a2 * (1.0 + 2.0 * q);
  }
  template <> inline double slope<WENDLAND>(double q)
  {
    const double a = 1.0 - 0.5 * q;
    return -5.0 * a * a * a;
  }
  // f'' = (1 - q/2)^2 (10 q - 5)
  template <> inline double curve<WENDLAND>(double q)
  {
    const double a = 1.0 - 0.5 * q;
    return a * a * (10.0 * q - 5.0);
  }

  // cubic B-spline (M4): f = 1 - 3q^2/2 + 3q^3/4 (q < 1), (2 - q)^3/4 (1 <= q < 2)
  template <> inline double shape<CUBIC>(double q)
  {
    if (q < 1.0) return 1.0 - q * q * (1.5 - 0.75 * q);
    const double a = 2.0 - q;
    return 0.25 * a * a * a;
  }
  template <> inline double slope<CUBIC>(double q)
  {
    if (q < 1.0) return -3.0 + 2.25 * q;
    const double a = 2.0 - q;
    return -0.75 * a * a / q;
  }
  // f'' = -3 + 9q/2 (q < 1), 3 (2 - q)/2 (1 <= q < 2)
  template <> inline double curve<CUBIC>(double q)
  {
    if (q < 1.0) return -3.0 + 4.5 * q;
    return 1.5 * (2.0 - q);
  }

  // quintic B-spline (M6, Morris 1997): f = (3-q)+^5 - 6 (2-q)+^5 + 15 (1-q)+^5, (x)+ = max(x, 0)
  template <> inline double shape<QUINTIC>(double q)
  {
    const double a = 3.0 - q, b = fmax(2.0 - q, 0.0), c = fmax(1.0 - q, 0.0);
    const double a2 = a * a, b2 = b * b, c2 = c * c;
    return a2 * a2 * a - 6.0 * b2 * b2 * b + 15.0 * c2 * c2 * c;
  }
  template <> inline double slope<QUINTIC>(double q)
  {
    const double a = 3.0 - q, b = fmax(2.0 - q, 0.0), c = fmax(1.0 - q, 0.0);
    const double a2 = a * a, b2 = b * b, c2 = c * c;
    return (-5.0 * a2 * a2 + 30.0 * b2 * b2 - 75.0 * c2 * c2) / q;
  }
  // f'' = 20 (3-q)+^3 - 120 (2-q)+^3 + 300 (1-q)+^3
  template <> inline double curve<QUINTIC>(double q)
  {
    const double a = 3.0 - q, b = fmax(2.0 - q, 0.0), c = fmax(1.0 - q, 0.0);
    return 20.0 * a * a * a - 120.0 * b * b * b + 300.0 * c * c * c;
  }

  // Lucy quartic (support h): f = (1 + 3q)(1 - q)^3, f'/q = -12 (1 - q)^2
  template <> inline double shape<LUCY>(double q)
  {
    const double a = 1.0 - q;
    return (1.0 + 3.0 * q) * a * a * a;
  }
  template <> inline double slope<LUCY>(double q)
  {
    const double a = 1.0 - q;
    return -12.0 * a * a;
  }
  // f'' = 12 (1 - q)(3q - 1)
  template <> inline double curve<LUCY>(double q)
  {
    const double a = 1.0 - q;
    return 12.0 * a * (3.0 * q - 1.0);
  }

  // W(r) and (1/r) dW/dr for r inside the support
  template <int K> inline double W(const Scale &s, double r)
  {
    return s.w * shape<K>(r * s.invh);
  }
  template <int K> inline double dWr(const Scale &s, double r)
  {
    return s.dw * slope<K>(r * s.invh);
  }

  // the same with the kernel chosen at run time, for code outside pair loops
  inline double W(int kernel, const Scale &s, double r)
  {
    switch (kernel) {
    case CUBIC:
      return W<CUBIC>(s, r);
    case QUINTIC:
      return W<QUINTIC>(s, r);
    case LUCY:
      return W<LUCY>(s, r);
    default:
      return W<WENDLAND>(s, r);
    }
  }
  inline double dWr(int kernel, const Scale &s, double r)
  {
    switch (kernel) {
    case CUBIC:
      return dWr<CUBIC>(s, r);
    case QUINTIC:
      return dWr<QUINTIC>(s, r);
    case LUCY:
      return dWr<LUCY>(s, r);
    default:
      return dWr<WENDLAND>(s, r);
    }
  }

}    // namespace CellKernel
}    // namespace LAMMPS_NS

#endif
