#include "report/camera_views.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <stdexcept>

#include "raster/rasterizer.h"
#include "report/colour_bar.h"
#include "report/eval_report.h"
#include "scene/light_view.h"
#include "util/eigen.h"
#include "util/error.h"
#include "util/image_writer.h"
#include "util/progress.h"

namespace mb {

namespace {

constexpr float kAmbient = 0.3f, kAlbedo = 0.8f;
constexpr float kSky[3] = {0.62f, 0.74f, 0.88f};

float to_srgb(float linear) {
  return std::pow(std::clamp(linear, 0.0f, 1.0f), 1.0f / 2.2f);
}

}  // namespace

CameraView camera_view(const Scene& scene, const LightViewDesc& light, const ViewData& light_view,
                       const CameraDesc& camera, const EvalSettings& settings) {
  const CameraImage image = render_camera(scene, camera, settings.threads);
  const LightFrame frame(light, scene.mesh.vertices);  // render_view's projection
  const ShadowMap& map = light_view.map;
  CameraView out;
  out.camera = camera.name;
  out.width = image.width;
  out.height = image.height;
  const Eigen::Vector3d to_light = frame.to_light();
  const CameraFrame eye(camera);
  struct Receiver {
    uint32_t pixel, texel;
    double zf, gx, gy;
    uint64_t surface;
  };
  std::vector<Receiver> receivers;
  const size_t pixels = image.offsets.size() - 1;
  out.diffuse.assign(pixels, -1.0f);
  out.surface_offsets = image.offsets;
  out.surface_diffuse.assign(image.triangle.size(), 0.0f);
  out.surface_share.assign(image.triangle.size(), 0.0f);
  out.surface_receiver.assign(image.triangle.size(), -1);
  for (size_t p = 0; p < pixels; ++p) {
    float transmitted = 1;  // front to back (docs/reference.md §7)
    for (uint64_t s = image.offsets[p]; s < image.offsets[p + 1]; ++s) {
      out.surface_share[s] = transmitted * float(image.alpha[s]);
      transmitted *= float(1 - image.alpha[s]);
      const auto& tri = scene.mesh.triangles[image.triangle[s]];
      const Eigen::Vector3d &a = scene.mesh.vertices[tri[0]], &b = scene.mesh.vertices[tri[1]],
                            &c = scene.mesh.vertices[tri[2]];
      Eigen::Vector3d n = (b - a).cross(c - a).normalized();
      const bool two_sided = scene.two_sided[image.triangle[s]];
      // A two-sided surface is lit on the side the camera sees; a one-sided one only from outside.
      if (two_sided && n.dot(eye.position() - image.point[s]) < 0) n = -n;
      const double lambert = n.dot(to_light);
      out.surface_diffuse[s] = float(std::max(0.0, lambert));
      if (s == image.offsets[p]) out.diffuse[p] = out.surface_diffuse[s];
      // Receivers face the light (docs/reference.md §3); the others are in their own shadow.
      if (!(lambert > 0)) continue;
      const std::optional<Eigen::Vector2d> gradient =
          plane_gradient(frame.to_raster(a), frame.to_raster(b), frame.to_raster(c));
      if (!gradient || !gradient->allFinite()) {
        out.surface_diffuse[s] = 0;  // edge-on to the light: grazing, unlit
        if (s == image.offsets[p]) out.diffuse[p] = 0;
        continue;
      }
      const double gx = gradient->x(), gy = gradient->y();
      const Eigen::Vector3d r = frame.to_raster(image.point[s]);
      const int x = std::clamp(int(std::floor(r.x())), 0, map.width - 1),
                y = std::clamp(int(std::floor(r.y())), 0, map.height - 1);
      // The receiver is tested at its texel's centre, on its own plane: the shadow map is sampled
      // there, and delta_f covers the kernel's reach from the centre (docs/reference.md §3), not
      // the extra half texel from an arbitrary point in it (which made the ground shadow itself in
      // a texel-periodic pattern). So a camera pixel gets exactly its light texel's receiver test.
      const double zf = r.z() + gx * (x + 0.5 - r.x()) + gy * (y + 0.5 - r.y());
      receivers.push_back({uint32_t(p), uint32_t(size_t(y) * map.width + x), zf, gx, gy, s});
    }
  }
  // Texel order (then pixel order), as collect_receivers lists a light view's fragments, so that
  // the LP techniques' warm-start runs cut the same way.
  std::stable_sort(receivers.begin(), receivers.end(),
                   [](const Receiver& u, const Receiver& v) { return u.texel < v.texel; });
  out.receivers.scene = light_view.scene;
  out.receivers.view = light_view.view + "@" + camera.name;
  out.receivers.map = map;
  Fragments& f = out.receivers.fragments;
  f.width = map.width;
  f.height = map.height;
  f.kernel_taps = settings.kernel.size * settings.kernel.size;
  for (const Receiver& r : receivers) {
    const ReceiverTest test =
        receiver_test(map, settings.kernel, settings.bias, int(r.texel % map.width),
                      int(r.texel / map.width), r.zf, r.gx, r.gy);
    out.surface_receiver[r.surface] = int64_t(out.pixel.size());
    out.pixel.push_back(r.pixel);
    f.texel.push_back(r.texel);
    f.layer.push_back(0);
    f.zf.push_back(r.zf);
    f.ztest.push_back(test.ztest);
    f.oracle.push_back(test.oracle);
    f.pcf.push_back(test.pcf);
    f.covered_taps.push_back(uint32_t(test.covered_taps));
  }
  // Under an area light the camera's receivers take its shadow as their reference, and keep what
  // the soft techniques read (docs/soft-shadows.md §1), as the light view's own receivers do.
  if (light_view.soft.angle_deg > 0) {
    std::vector<double> gx, gy;
    for (const Receiver& r : receivers) gx.push_back(r.gx), gy.push_back(r.gy);
    out.receivers.soft = light_receivers(
        scene, light, f, std::move(gx), std::move(gy), settings.kernel, settings.bias,
        AreaLight{light_view.soft.angle_deg, settings.light.directions}, settings.threads);
  }
  return out;
}

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
                         const std::vector<std::vector<double>>& shadows, const std::string& base,
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
    // The reference has no difference: PCF, or under an area light its shadow (pcf is then the
    // hard shadow, which has).
    const bool soft = view.receivers.soft.angle_deg > 0;
    const bool reference = names[k] == "area_light" || (names[k] == "pcf" && !soft);
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

void check_dataset_cameras(const std::vector<Scene>& scenes, const DatasetDesc& dataset) {
  for (const auto& scene : scenes)
    if (!scene.cameras.empty()) return;
  throw InputError("camera_images: no scene of dataset " + dataset.name +
                   " names a camera (add `cameras:` with position, target, fov and resolution to "
                   "a scene file)");
}

// Every camera of every scene, lit by each of the scene's light views (report/camera_views.h).
void write_dataset_camera_views(const std::vector<Scene>& scenes, const DatasetDesc& dataset,
                                const std::vector<ViewData>& views,
                                const std::vector<std::string>& techniques, int resolution,
                                const EvalSettings& settings, double scale,
                                const std::filesystem::path& dir, bool quiet) {
  size_t total = 0;
  for (const auto& scene : scenes)
    total += scene.cameras.size() * rendered_views(scene, dataset, resolution, settings).size();
  std::filesystem::create_directories(dir);
  ProgressBar bar("cameras", total, quiet);
  for (const auto& scene : scenes)
    for (const auto& camera : scene.cameras)
      for (const LightViewDesc& light : rendered_views(scene, dataset, resolution, settings)) {
        const auto it = std::find_if(views.begin(), views.end(), [&](const ViewData& v) {
          return v.scene == scene.name && v.view == light.name;
        });
        if (it == views.end())
          throw std::logic_error("camera views: light view " + scene.name + "/" + light.name +
                                 " was not rendered");
        const CameraView view = camera_view(scene, light, *it, camera, settings);
        std::vector<std::string> names;
        std::vector<std::vector<double>> shadows;
        if (view.receivers.soft.angle_deg > 0) {  // the area light's shadow leads the sheet
          names.push_back("area_light");
          shadows.push_back(view.receivers.fragments.pcf);
        }
        for (const auto& name : techniques) {
          names.push_back(name);
          shadows.push_back(evaluate_technique(view.receivers, name, settings, nullptr).shadow);
        }
        write_camera_images(view, names, shadows,
                            (dir / (scene.name + "_" + light.name + "_" + camera.name)).string(),
                            scale);
        bar.advance();
      }
  bar.finish();
}

}  // namespace mb
