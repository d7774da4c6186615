#include "report/camera_images.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "report/colour_bar.h"
#include "report/eval_report.h"
#include "util/image_writer.h"

namespace mb {

namespace {

constexpr float kAmbient = 0.3f, kAlbedo = 0.8f;
constexpr float kSky[3] = {0.62f, 0.74f, 0.88f};

float to_srgb(float linear) {
  return std::pow(std::clamp(linear, 0.0f, 1.0f), 1.0f / 2.2f);
}

}  // namespace

std::vector<float> shade_camera_view(const CameraView& view, const std::vector<double>& shadow) {
  const size_t pixels = view.diffuse.size();
  std::vector<float> rgb(pixels * 3);
  for (size_t p = 0; p < pixels; ++p) {
    const uint64_t first = view.surface_offsets[p], last = view.surface_offsets[p + 1];
    if (first == last) {
      std::copy(kSky, kSky + 3, &rgb[p * 3]);
      continue;
    }
    // Linear radiance composited front to back; the sky (sRGB) behind what the shares leave.
    float linear = 0, left = 1;
    for (uint64_t s = first; s < last; ++s) {
      const int64_t k = view.surface_receiver[s];
      const float lit = k >= 0 ? float(1 - shadow[size_t(k)]) : 0.0f;  // the light's visibility
      linear += view.surface_share[s] * kAlbedo *
                (kAmbient + (1 - kAmbient) * view.surface_diffuse[s] * lit);
      left -= view.surface_share[s];
    }
    for (int ch = 0; ch < 3; ++ch)
      rgb[p * 3 + ch] =
          left > 0 ? to_srgb(linear + left * std::pow(kSky[ch], 2.2f)) : to_srgb(linear);
  }
  return rgb;
}

// The difference images' colours: red darker than the reference, blue lighter.
constexpr std::array<float, 3> kDarker = {1.0f, 0.15f, 0.1f}, kLighter = {0.15f, 0.45f, 1.0f};

std::vector<float> difference_image(const CameraView& view, const std::vector<double>& shadow,
                                    double scale) {
  std::vector<float> rgb(view.diffuse.size() * 3),
      pcf = shade_camera_view(view, view.receivers.fragments.pcf);
  for (size_t p = 0; p < view.diffuse.size(); ++p) {
    const float grey = 0.5f * (pcf[p * 3] + pcf[p * 3 + 1] + pcf[p * 3 + 2]) / 3;
    for (int ch = 0; ch < 3; ++ch) rgb[p * 3 + ch] = grey;
  }
  for (size_t p = 0; p < view.diffuse.size(); ++p) {
    // The pixel's difference: its receivers' differences by their shares of it.
    double d = 0;
    bool any = false;
    for (uint64_t s = view.surface_offsets[p]; s < view.surface_offsets[p + 1]; ++s)
      if (const int64_t k = view.surface_receiver[s]; k >= 0) {
        d += view.surface_share[s] * (shadow[size_t(k)] - view.receivers.fragments.pcf[size_t(k)]);
        any = true;
      }
    if (!any) continue;
    const float t = float(std::min(1.0, std::abs(d) / scale));
    const std::array<float, 3>& colour = d > 0 ? kDarker : kLighter;
    for (int ch = 0; ch < 3; ++ch) {
      float& v = rgb[p * 3 + ch];
      v = (1 - t) * v + t * colour[ch];
    }
  }
  return rgb;
}

void write_camera_images(const CameraView& view, const std::vector<std::string>& names,
                         const std::vector<std::vector<double>>& shadows,
                         const std::vector<bool>& references, const std::string& base,
                         double scale) {
  const int w = view.width, h = view.height, label = 18, gap = 4;
  const int columns = std::max(1, int(std::ceil(std::sqrt(double(names.size())))));
  const int rows = (int(names.size()) + columns - 1) / columns;
  const int cell_w = w + gap, cell_h = label + 2 * h + gap;
  std::vector<float> white(size_t(columns * cell_w) * (rows * cell_h) * 3, 1.0f);
  OIIO::ImageBuf sheet(OIIO::ImageSpec(columns * cell_w, rows * cell_h, 3, OIIO::TypeDesc::FLOAT),
                       white.data());
  const float black[3] = {0, 0, 0};
  const ColourBar bar = signed_difference_bar(
      scale, kLighter, kDarker, "G - reference (shadow fraction): blue leaks, red over-darkens");
  for (size_t k = 0; k < names.size(); ++k) {
    const std::vector<float> image = shade_camera_view(view, shadows[k]);
    write_image(base + "_" + file_stem(names[k]) + ".png", w, h, 3, image);
    std::vector<float> diff = difference_image(view, shadows[k], scale);
    const bool reference = references[k];  // no difference: camera/camera_views.h
    if (!reference)
      write_with_colour_bar(base + "_" + file_stem(names[k]) + "_diff.png", diff, w, h, bar);
    const int x0 = int(k % columns) * cell_w, y0 = int(k / columns) * cell_h;
    const auto paste = [&](const std::vector<float>& pixels, int y) {
      OIIO::ImageBuf tile(OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::FLOAT),
                          const_cast<float*>(pixels.data()));
      OIIO::ImageBufAlgo::paste(sheet, x0, y, 0, 0, tile);
    };
    paste(image, y0 + label);
    // The reference's lower cell stays blank, as in the transparency sheet: it has no difference.
    if (!reference) paste(diff, y0 + label + h);
    // Labels need a font; without one the sheet keeps the technique order of the report.
    OIIO::ImageBufAlgo::render_text(sheet, x0 + 2, y0 + label - 4, names[k], 14, "DejaVuSans",
                                    black);
  }
  std::vector<float> pixels(white.size());
  sheet.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, pixels.data());
  write_with_colour_bar(base + "_sheet.png", pixels, columns * cell_w, rows * cell_h, bar);
}

void write_camera_images(const CameraShadows& shadows, const std::filesystem::path& dir,
                         double scale) {
  std::filesystem::create_directories(dir);
  write_camera_images(
      shadows.view, shadows.names, shadows.shadows, shadows.reference,
      (dir / (shadows.scene + "_" + shadows.light + "_" + shadows.view.camera)).string(), scale);
}

}  // namespace mb
