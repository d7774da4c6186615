#include "util/image_writer.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>

#include "util/error.h"

namespace mb {

void write_image(const std::string& file, int width, int height, int channels,
                 const std::vector<float>& values, bool sixteen_bit) {
  bool exr = file.size() > 4 && file.substr(file.size() - 4) == ".exr";
  OIIO::TypeDesc format = exr           ? OIIO::TypeDesc::FLOAT
                          : sixteen_bit ? OIIO::TypeDesc::UINT16
                                        : OIIO::TypeDesc::UINT8;
  OIIO::ImageSpec spec(width, height, channels, format);
  // OpenImageIO stamps the time of writing unless DateTime is given; empty, it writes none, so that
  // a file is a function of its pixels (the same run gives the same bytes, whatever the thread
  // count and the second it finishes in).
  spec.attribute("DateTime", "");
  auto out = OIIO::ImageOutput::create(file);
  if (!out || !out->open(file, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, values.data()) ||
      !out->close())
    throw InputError(file + ": cannot write image: " + (out ? out->geterror() : OIIO::geterror()));
}

std::array<float, 3> colormap(double t) {
  // Stops sampled from matplotlib's viridis (public colour map definition).
  static const float stops[9][3] = {
      {0.267f, 0.005f, 0.329f}, {0.279f, 0.175f, 0.483f}, {0.230f, 0.322f, 0.546f},
      {0.173f, 0.449f, 0.558f}, {0.128f, 0.567f, 0.551f}, {0.153f, 0.683f, 0.502f},
      {0.369f, 0.789f, 0.383f}, {0.678f, 0.864f, 0.190f}, {0.993f, 0.906f, 0.144f}};
  if (!std::isfinite(t)) t = 0;
  double x = std::clamp(t, 0.0, 1.0) * 8;
  int k = std::min(int(x), 7);
  float f = float(x - k);
  return {stops[k][0] + f * (stops[k + 1][0] - stops[k][0]),
          stops[k][1] + f * (stops[k + 1][1] - stops[k][1]),
          stops[k][2] + f * (stops[k + 1][2] - stops[k][2])};
}

}  // namespace mb
