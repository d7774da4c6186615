#include "report/colour_bar.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>

#include "util/image_writer.h"
#include "util/number_text.h"

namespace mb {

ColourBar magnitude_bar(double scale, const std::string& units) {
  return {[](double t) { return colormap(t); }, "0", "", ">= " + round_trip(scale), units};
}

ColourBar signed_difference_bar(double scale, const std::array<float, 3>& lighter,
                                const std::array<float, 3>& darker, const std::string& units) {
  // A mid grey stands for the reference's shaded grey, which varies over a picture.
  constexpr float kGrey = 0.25f;
  auto ramp = [lighter, darker](double t) {
    const double s = 2 * std::clamp(t, 0.0, 1.0) - 1;
    const std::array<float, 3>& colour = s > 0 ? darker : lighter;
    const float a = float(std::abs(s));
    return std::array<float, 3>{(1 - a) * kGrey + a * colour[0], (1 - a) * kGrey + a * colour[1],
                                (1 - a) * kGrey + a * colour[2]};
  };
  return {ramp, "<= -" + round_trip(scale), "0", ">= " + round_trip(scale), units};
}

BarredImage with_colour_bar(const std::vector<float>& rgb, int width, int height,
                            const ColourBar& bar) {
  const int size = 11;
  const auto text_width = [&](const std::string& s) {
    const OIIO::ROI r = OIIO::ImageBufAlgo::text_size(s, size, "DejaVuSans");
    return r.defined() ? r.width() : 0;
  };
  BarredImage out;
  out.width = std::max({width, text_width(bar.units) + 8,
                        text_width(bar.low) + text_width(bar.middle) + text_width(bar.high) + 24});
  out.height = height + kColourBarHeight;
  out.rgb.assign(size_t(out.width) * out.height * 3, 1.0f);
  for (int y = 0; y < height; ++y)
    std::copy(rgb.begin() + size_t(y) * width * 3, rgb.begin() + size_t(y + 1) * width * 3,
              out.rgb.begin() + size_t(y) * out.width * 3);
  // The ramp: 10 rows, 3 below the image; its labels under it, its units right of it where the
  // picture leaves room, else beneath the labels.
  const int span = std::min(out.width, 320), margin = 4, y0 = height + 3;
  const int ramp_w = std::max(1, span - 2 * margin);
  for (int y = y0; y < y0 + 10; ++y)
    for (int x = 0; x < ramp_w; ++x) {
      const auto c = bar.ramp(double(x) / std::max(1, ramp_w - 1));
      for (int ch = 0; ch < 3; ++ch) out.rgb[(size_t(y) * out.width + margin + x) * 3 + ch] = c[ch];
    }
  OIIO::ImageBuf image(OIIO::ImageSpec(out.width, out.height, 3, OIIO::TypeDesc::FLOAT),
                       out.rgb.data());
  const float black[3] = {0, 0, 0};
  using OIIO::ImageBufAlgo::TextAlignX;
  const auto text = [&](int x, int y, const std::string& s, TextAlignX align) {
    if (!s.empty())
      OIIO::ImageBufAlgo::render_text(image, x, y, s, size, "DejaVuSans", {black, 3}, align);
  };
  const int baseline = y0 + 10 + 11;
  text(margin, baseline, bar.low, TextAlignX::Left);
  text(margin + ramp_w / 2, baseline, bar.middle, TextAlignX::Center);
  text(margin + ramp_w, baseline, bar.high, TextAlignX::Right);
  if (margin + ramp_w + 6 + text_width(bar.units) <= out.width)
    text(margin + ramp_w + 6, y0 + 9, bar.units, TextAlignX::Left);
  else
    text(margin, out.height - 2, bar.units, TextAlignX::Left);
  std::vector<float> pixels(out.rgb.size());
  image.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, pixels.data());
  out.rgb = std::move(pixels);
  return out;
}

void write_with_colour_bar(const std::string& file, const std::vector<float>& rgb, int width,
                           int height, const ColourBar& bar) {
  const BarredImage image = with_colour_bar(rgb, width, height, bar);
  write_image(file, image.width, image.height, 3, image.rgb);
}

}  // namespace mb
