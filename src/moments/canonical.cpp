#include "moments/canonical.h"

#include <numbers>

namespace mb {

int cubic_roots(double c3, double c2, double c1, double c0, double* roots) {
  const double a = c2 / c3, b = c1 / c3, c = c0 / c3;
  // z = t - a/3: t^3 + p t + q = 0.
  const double p = b - a * a / 3, q = 2 * a * a * a / 27 - a * b / 3 + c;
  int count = 0;
  if (p < 0) {
    const double r = 2 * std::sqrt(-p / 3);
    const double argument = std::clamp(3 * q / (p * r), -1.0, 1.0);
    const double phi = std::acos(argument) / 3;
    for (int k = 0; k < 3; ++k) roots[count++] = r * std::cos(phi - 2 * std::numbers::pi * k / 3) - a / 3;
  } else {
    roots[count++] = std::cbrt(-q) - a / 3;  // one real root (only from rounding here)
  }
  for (int k = 0; k < count; ++k)
    for (int step = 0; step < 2; ++step) {
      double z = roots[k];
      double f = ((z + a) * z + b) * z + c, df = (3 * z + 2 * a) * z + b;
      if (df != 0) roots[k] = z - f / df;
    }
  std::sort(roots, roots + count);
  return count;
}

}  // namespace mb
