#pragma once
// A finite depth distribution for the closed-form tests: its CDF and its moments.
#include <cmath>
#include <numbers>
#include <vector>

namespace mb::testing_support {

struct Distribution {
  std::vector<double> z, w;
  // F_Z(at) = Z(depth < at) (docs/reference.md §1: strictly less).
  double cdf(double at) const {
    double s = 0;
    for (size_t i = 0; i < z.size(); ++i) s += z[i] < at ? w[i] : 0;
    return s;
  }
  // E[Z^1..Z^count]
  std::vector<double> power_moments(int count) const {
    std::vector<double> b(count, 0.0);
    for (size_t i = 0; i < z.size(); ++i)
      for (int j = 0; j < count; ++j) b[j] += w[i] * std::pow(z[i], j + 1);
    return b;
  }
  // E[sin 2πZ, cos 2πZ, sin 4πZ, cos 4πZ]
  std::vector<double> trig_moments() const {
    std::vector<double> b(4, 0.0);
    for (size_t i = 0; i < z.size(); ++i) {
      const double phi = 2 * std::numbers::pi * z[i];
      b[0] += w[i] * std::sin(phi);
      b[1] += w[i] * std::cos(phi);
      b[2] += w[i] * std::sin(2 * phi);
      b[3] += w[i] * std::cos(2 * phi);
    }
    return b;
  }
};

}  // namespace mb::testing_support
