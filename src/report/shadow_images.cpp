#include "report/shadow_images.h"

#include <cmath>
#include <cstdio>

#include "report/colour_bar.h"
#include "util/image_writer.h"

namespace mb {

void write_shadow_images(const ViewData& view, std::span<const double> shadow,
                         const std::string& base, double error_scale) {
  const Fragments& f = view.fragments;
  const int w = f.width, h = f.height;
  std::vector<float> g(size_t(w) * h, 0.0f), visible(size_t(w) * h * 3), error(size_t(w) * h * 3);
  // Texels without a layer-0 receiver (empty, or facing away): dark blue in the PNGs, 0 in the EXR.
  for (size_t t = 0; t < g.size(); ++t) {
    for (int ch = 0; ch < 3; ++ch)
      visible[t * 3 + ch] = error[t * 3 + ch] = ch == 2 ? 0.25f : 0.08f;
  }
  for (size_t k = 0; k < f.size(); ++k) {
    if (f.layer[k] != 0) continue;
    const size_t t = f.texel[k];
    g[t] = float(shadow[k]);
    for (int ch = 0; ch < 3; ++ch) visible[t * 3 + ch] = float(1 - shadow[k]);
    if (error_scale > 0) {
      auto c = colormap(std::abs(f.pcf[k] - shadow[k]) / error_scale);
      for (int ch = 0; ch < 3; ++ch) error[t * 3 + ch] = c[ch];
    }
  }
  write_image(base + "_shadow.exr", w, h, 1, g);
  write_image(base + "_shadow.png", w, h, 3, visible);
  if (error_scale > 0)
    write_with_colour_bar(base + "_error.png", error, w, h,
                          magnitude_bar(error_scale, "|G - PCF|, shadow fraction"));
}

}  // namespace mb
