// Quantization transforms (docs/reference.md §12; seed 000 §4.3, seed 004 §2.5): exact ranges,
// the seed's gains, the hull-volume bounds and the search.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "basis/basis.h"
#include "moments/quantization_transform.h"
#include "util/error.h"

namespace mb {
namespace {

Basis power(int m) {
  std::vector<std::string> names;
  for (int k = 1; k <= m; ++k) names.push_back(k == 1 ? "z" : "z^" + std::to_string(k));
  return Basis::parse(names);
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST(QuantizationTransform, Explore) {
  for (int m : {2, 3, 4, 5, 6}) {
    const Basis b = power(m);
    auto t0 = std::chrono::steady_clock::now();
    const OptimizedTransform o = optimize_transform(b);
    const double ts = seconds_since(t0);
    t0 = std::chrono::steady_clock::now();
    const GainBounds g = gain_bounds(b);
    const double tb = seconds_since(t0);
    std::printf("m=%d gain %.4f (%.2fs) hull %.6g diff %.6g bound %.4f %.4f (%.2fs) viol %.3g\n", m,
                o.gain_bits, ts, g.hull_volume, g.difference_volume, g.hull_bound_bits,
                g.difference_bound_bits, tb, admissibility_violation(b, o.transform));
  }
}

}  // namespace
}  // namespace mb
