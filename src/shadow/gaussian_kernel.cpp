#include "shadow/gaussian_kernel.h"

#include <cmath>
#include <string>

#include "util/error.h"
#include "util/number_text.h"

namespace mb {

GaussianKernel make_gaussian_kernel(int size, double sigma) {
  if (size <= 0 || size % 2 == 0)
    throw InputError("kernel.size: expected an odd number of taps >= 1, got " +
                     std::to_string(size));
  if (!(sigma > 0) || !std::isfinite(sigma))
    throw InputError("kernel.sigma: expected a positive number of texels, got " +
                     round_trip(sigma));
  GaussianKernel k;
  k.size = size;
  k.sigma = sigma;
  k.weights.resize(size);
  double total = 0;
  for (int i = 0; i < size; ++i) {
    double d = i - k.radius();
    total += k.weights[i] = std::exp(-d * d / (2 * sigma * sigma));
  }
  for (double& w : k.weights) w /= total;
  return k;
}

std::vector<int> kernel_tap_permutation(int size, int dx, int dy) {
  std::vector<int> out(size_t(size) * size);
  for (int t = 0; t < size * size; ++t) {
    const int x = t % size - dx, y = t / size - dy;
    out[t] = x >= 0 && y >= 0 && x < size && y < size ? y * size + x : t;
  }
  return out;
}

}  // namespace mb
