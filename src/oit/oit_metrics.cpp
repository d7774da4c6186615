#include "oit/oit_metrics.h"

#include <algorithm>
#include <cmath>

namespace mb {

void OitStats::add(const PixelError& e) {
  if (e.fragments == 0) return;
  fragments += e.fragments;
  ++pixels;
  alpha += e.alpha, over += e.over, under += e.under;
  rgb_sum += e.rgb, rgb_max = std::max(rgb_max, e.rgb);
  delta_e_sum += e.delta_e, delta_e76_sum += e.delta_e76;
  delta_e.push_back(float(e.delta_e));
}

void OitStats::merge(const OitStats& o) {
  fragments += o.fragments, pixels += o.pixels, failures += o.failures;
  alpha += o.alpha, over += o.over, under += o.under;
  rgb_sum += o.rgb_sum, rgb_max = std::max(rgb_max, o.rgb_max);
  delta_e_sum += o.delta_e_sum, delta_e76_sum += o.delta_e76_sum;
  delta_e.insert(delta_e.end(), o.delta_e.begin(), o.delta_e.end());
}

double OitStats::delta_e_quantile(double q) const {
  if (delta_e.empty()) return 0;
  std::vector<float> sorted = delta_e;
  const size_t rank =
      std::min(sorted.size() - 1, size_t(std::ceil(q * double(sorted.size()))) - (q > 0 ? 1 : 0));
  std::nth_element(sorted.begin(), sorted.begin() + long(rank), sorted.end());
  return sorted[rank];
}

PixelError pixel_error(const PixelFragments& px, std::span<const double> reference,
                       std::span<const double> transmittance, const Rgb& reference_color,
                       const Lab& reference_lab, const Rgb& color, const LabConverter& lab) {
  PixelError e;
  e.fragments = uint32_t(px.size());
  if (px.size() == 0) return e;
  for (size_t l = 0; l < px.size(); ++l) {
    const double d = transmittance[l] - reference[l];
    e.alpha += px.alpha[l];
    e.over += px.alpha[l] * std::max(d, 0.0);
    e.under += px.alpha[l] * std::max(-d, 0.0);
  }
  for (int c = 0; c < 3; ++c) e.rgb += std::abs(double(color[c]) - double(reference_color[c])) / 3;
  const Lab b = lab.lab(color);
  e.delta_e = delta_e_2000(reference_lab, b);
  e.delta_e76 = delta_e_76(reference_lab, b);
  return e;
}

}  // namespace mb
