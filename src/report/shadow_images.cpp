#include "report/shadow_images.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <cmath>
#include <cstdio>

#include "util/image_writer.h"

namespace mb {

namespace {

// Appends a horizontal colour ramp with its end values under the image (labels need a font;
// without one the ramp stays and the scale is in the report).
void write_with_colour_bar(const std::string& file, int width, int height, std::vector<float> rgb,
                           double scale) {
  const int bar = 28, total = height + bar;
  rgb.resize(size_t(width) * total * 3, 1.0f);
  for (int y = height + 4; y < height + 14; ++y)
    for (int x = 0; x < width; ++x) {
      auto c = colormap(double(x) / std::max(1, width - 1));
      for (int ch = 0; ch < 3; ++ch) rgb[(size_t(y) * width + x) * 3 + ch] = c[ch];
    }
  OIIO::ImageBuf image(OIIO::ImageSpec(width, total, 3, OIIO::TypeDesc::FLOAT), rgb.data());
  char high[32];
  std::snprintf(high, sizeof high, "%g", scale);
  const float black[3] = {0, 0, 0};
  const int size = 11;
  OIIO::ImageBufAlgo::render_text(image, 1, total - 2, "0", size, "DejaVuSans", black);
  OIIO::ImageBufAlgo::render_text(image, std::max(0, width - 7 * int(std::string(high).size()) - 2),
                                  total - 2, high, size, "DejaVuSans", black);
  std::vector<float> pixels(rgb.size());
  image.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, pixels.data());
  write_image(file, width, total, 3, pixels);
}

}  // namespace

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
    write_with_colour_bar(base + "_error.png", w, h, std::move(error), error_scale);
}

}  // namespace mb
