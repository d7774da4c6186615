#pragma once
// What `oit` measures of a technique against the exact composite (docs/transparency.md §4):
// per transparent fragment, the transmittance the composite weighs it with, |T_ref - T| weighted
// by alpha and split into over- and under-estimation; per pixel that shows transparent geometry,
// the composite's RGB error and its CIELAB difference.
#include <cstdint>
#include <span>
#include <vector>

#include "oit/color_difference.h"
#include "techniques/oit/oit_technique.h"

namespace mb {

// One pixel's contribution, summed over its transparent fragments.
struct PixelError {
  uint32_t fragments = 0;
  double alpha = 0, over = 0, under = 0;  // sum alpha_l; sum alpha_l (T_l - T_ref)+; (T_ref - T_l)+
  double rgb = 0;                         // mean over channels of |C - C_ref|
  double delta_e = 0, delta_e76 = 0;      // CIEDE2000 and CIE 1976 between the composites
};

struct OitStats {
  uint64_t fragments = 0, pixels = 0, failures = 0;
  double alpha = 0, over = 0, under = 0, rgb_sum = 0, rgb_max = 0, delta_e_sum = 0,
         delta_e76_sum = 0;
  std::vector<float> delta_e;  // per pixel, in pixel order: percentiles and maximum

  // Pixels without transparent fragments are left out (every technique shows them exactly).
  void add(const PixelError& e);
  void merge(const OitStats& other);
  // Alpha-weighted mean |T_ref - T| over fragments, and its parts where T is too high (the
  // fragment and what lies behind it get too much weight) and too low.
  double transmittance_error() const { return alpha > 0 ? (over + under) / alpha : 0; }
  double transmittance_over() const { return alpha > 0 ? over / alpha : 0; }
  double transmittance_under() const { return alpha > 0 ? under / alpha : 0; }
  double rgb_error() const { return pixels ? rgb_sum / double(pixels) : 0; }
  double delta_e_mean() const { return pixels ? delta_e_sum / double(pixels) : 0; }
  double delta_e76_mean() const { return pixels ? delta_e76_sum / double(pixels) : 0; }
  // The q-quantile (q in [0, 1]) of the per-pixel CIEDE2000, nearest rank; 0 without pixels.
  double delta_e_quantile(double q) const;
};

// A pixel's error: `reference` and `transmittance` are the exact and the technique's weights
// (T_ref and the transmittance the composite used, techniques/oit/oit_technique.h
// effective_transmittance); `reference_color` the exact composite and `reference_lab` its CIELAB
// value (computed once per pixel, not per technique), `color` the technique's composite.
PixelError pixel_error(const PixelFragments& px, std::span<const double> reference,
                       std::span<const double> transmittance, const Rgb& reference_color,
                       const Lab& reference_lab, const Rgb& color, const LabConverter& lab);

}  // namespace mb
