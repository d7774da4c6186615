#pragma once
// The filter kernel shared by PCF and the moment maps (docs/reference.md §3: 9x9 Gaussian,
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

// Taps are listed row by row (kernel_distribution's order). For the kernel of the texel (dx, dy)
// away from another's: out[t] is the tap of this kernel that sees the texel tap t of the other saw,
// or t itself where that texel lies outside this kernel (the tap at the same offset then sees a
// nearby surface). Warm starts map a neighbour's LP basis through it (eval/warm_runs.h).
std::vector<int> kernel_tap_permutation(int size, int dx, int dy);

}  // namespace mb
