#pragma once
// The filter kernel shared by PCF and the moment maps (REFERENCE.md §3: 9x9 Gaussian,
// sigma = 2.4 texels, weights normalised). Separable: w(dx, dy) = w1(dx) * w1(dy).
#include <vector>

namespace mb {

struct GaussianKernel {
  int size = 9;                 // odd, taps per axis
  double sigma = 2.4;           // texels
  std::vector<double> weights;  // one axis, normalised to sum 1 (so the 2D weights do too)
  int radius() const { return size / 2; }
  double weight(int dx, int dy) const { return weights[dx + radius()] * weights[dy + radius()]; }
};

// Rejects (InputError) an even or non-positive size and sigma <= 0.
GaussianKernel make_gaussian_kernel(int size, double sigma);

}  // namespace mb
