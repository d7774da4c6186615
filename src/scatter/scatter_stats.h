#pragma once
// `scatter`'s error measures (docs/scattering.md §4): over a view's pixels, the L1 error of the
// in-scattered radiance divided by the sum of what every ray could scatter, S_max (seed 000 §3.2's
// measure, so a short ray weighs less than a long one), split into where a technique is too bright
// and too dark, and the largest per-pixel |I - I_ref| / S_max.
#include <algorithm>
#include <cmath>
#include <cstddef>

namespace mb {

struct ScatterStats {
  double abs_sum = 0, bright_sum = 0, dark_sum = 0, s_max_sum = 0, max_error = 0;
  size_t pixels = 0;

  void add(double inscatter, double reference, double s_max) {
    const double d = inscatter - reference;
    abs_sum += std::abs(d);
    (d > 0 ? bright_sum : dark_sum) += std::abs(d);
    s_max_sum += s_max;
    if (s_max > 0) max_error = std::max(max_error, std::abs(d) / s_max);
    ++pixels;
  }
  void merge(const ScatterStats& o) {
    abs_sum += o.abs_sum, bright_sum += o.bright_sum, dark_sum += o.dark_sum;
    s_max_sum += o.s_max_sum, max_error = std::max(max_error, o.max_error), pixels += o.pixels;
  }
  double ratio(double sum) const { return s_max_sum > 0 ? sum / s_max_sum : 0; }
  double mean_error() const { return ratio(abs_sum); }
  double too_bright() const { return ratio(bright_sum); }
  double too_dark() const { return ratio(dark_sum); }
};

}  // namespace mb
