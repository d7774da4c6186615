#include "moments/chebyshev.h"

#include <algorithm>
#include <cmath>

namespace mb {

double vsm_bound(const double* b, double zf, double min_variance) {
  const double mean = b[0], variance = std::max(b[1] - b[0] * b[0], min_variance);
  if (zf <= mean) return 0;
  const double d = zf - mean;
  return d * d / (variance + d * d);
}

double esm_bound(double b1, double zf, double c) {
  return std::max(0.0, 1.0 - b1 * std::exp(-c * zf));
}

}  // namespace mb
