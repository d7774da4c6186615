#include "report/colour_bar.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>

#include "util/image_writer.h"
#include "util/number_text.h"

namespace mb {

namespace {

// A tick's value: short, as a scale is read (%g), unlike round_trip's every digit.
std::string tick(double v) {
  return format_number(v, "%g");
}

}  // namespace

ColourBar magnitude_bar(double scale, const std::string& units) {
  return {[](double t) { return colormap(t); },
          "0",
          tick(scale / 2),
          ">= " + round_trip(scale),
          units,
          tick(scale / 4),
          tick(3 * scale / 4)};
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
  return {ramp,
          "<= -" + round_trip(scale),
          "0",
          ">= " + round_trip(scale),
          units,
          tick(-scale / 2),
          tick(scale / 2)};
}

int colour_bar_font(int width) {
  return std::clamp(width / 64, 11, 20);
}

int colour_bar_height(int width) {
  const int size = colour_bar_font(width);
  // 3 rows of gap, the ramp (size - 1 rows), its ticks (3), the labels, the units' line, margins.
  return 3 + (size - 1) + 3 + size + 3 + size + 3;
}

BarredImage with_colour_bar(const std::vector<float>& rgb, int width, int height,
                            const ColourBar& bar) {
  const int size = colour_bar_font(width);
  const auto text_width = [&](const std::string& s) {
    const OIIO::ROI r = OIIO::ImageBufAlgo::text_size(s, size, "DejaVuSans");
    return r.defined() ? r.width() : 0;
  };
  BarredImage out;
  out.width = std::max({width, text_width(bar.units) + 8,
                        text_width(bar.low) + text_width(bar.quarter) + text_width(bar.middle) +
                            text_width(bar.three_quarters) + text_width(bar.high) + 40});
  out.height = height + colour_bar_height(width);
  out.rgb.assign(size_t(out.width) * out.height * 3, 1.0f);
  for (int y = 0; y < height; ++y)
    std::copy(rgb.begin() + size_t(y) * width * 3, rgb.begin() + size_t(y + 1) * width * 3,
              out.rgb.begin() + size_t(y) * out.width * 3);
  // The ramp: size - 1 rows, 3 below the image; ticks under it at its quarters, their labels
  // beneath; its units right of it where the picture leaves room, else beneath the labels.
  const int span = std::min(out.width, std::max(320, out.width * 3 / 5)), margin = 4,
            y0 = height + 3, ramp_h = size - 1;
  const int ramp_w = std::max(1, span - 2 * margin);
  for (int y = y0; y < y0 + ramp_h; ++y)
    for (int x = 0; x < ramp_w; ++x) {
      const auto c = bar.ramp(double(x) / std::max(1, ramp_w - 1));
      for (int ch = 0; ch < 3; ++ch) out.rgb[(size_t(y) * out.width + margin + x) * 3 + ch] = c[ch];
    }
  const std::string* labels[5] = {&bar.low, &bar.quarter, &bar.middle, &bar.three_quarters,
                                  &bar.high};
  for (int q = 0; q < 5; ++q) {
    if (labels[q]->empty()) continue;
    const int x = margin + std::min(ramp_w - 1, (ramp_w - 1) * q / 4);
    for (int y = y0 + ramp_h; y < y0 + ramp_h + 3; ++y)
      for (int ch = 0; ch < 3; ++ch) out.rgb[(size_t(y) * out.width + x) * 3 + ch] = 0;
  }
  OIIO::ImageBuf image(OIIO::ImageSpec(out.width, out.height, 3, OIIO::TypeDesc::FLOAT),
                       out.rgb.data());
  const float black[3] = {0, 0, 0};
  using OIIO::ImageBufAlgo::TextAlignX;
  const auto text = [&](int x, int y, const std::string& s, TextAlignX align) {
    if (!s.empty())
      OIIO::ImageBufAlgo::render_text(image, x, y, s, size, "DejaVuSans", {black, 3}, align);
  };
  const int baseline = y0 + ramp_h + 3 + size;
  text(margin, baseline, bar.low, TextAlignX::Left);
  text(margin + (ramp_w - 1) / 4, baseline, bar.quarter, TextAlignX::Center);
  text(margin + (ramp_w - 1) / 2, baseline, bar.middle, TextAlignX::Center);
  text(margin + (ramp_w - 1) * 3 / 4, baseline, bar.three_quarters, TextAlignX::Center);
  text(margin + ramp_w, baseline, bar.high, TextAlignX::Right);
  if (margin + ramp_w + 6 + text_width(bar.units) <= out.width)
    text(margin + ramp_w + 6, y0 + ramp_h - 1, bar.units, TextAlignX::Left);
  else
    text(margin, out.height - 4, bar.units, TextAlignX::Left);
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
