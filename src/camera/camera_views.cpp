#include "camera/camera_views.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <stdexcept>

#include "raster/rasterizer.h"
#include "scene/light_view.h"
#include "techniques/registry.h"
#include "util/eigen.h"
#include "util/error.h"
#include "util/progress.h"

namespace mb {

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

void check_dataset_cameras(const std::vector<Scene>& scenes, const DatasetDesc& dataset) {
  for (const auto& scene : scenes)
    if (!scene.cameras.empty()) return;
  throw InputError("camera_images: no scene of dataset " + dataset.name +
                   " names a camera (add `cameras:` with position, target, fov and resolution to "
                   "a scene file)");
}

// Every camera of every scene, lit by each of the scene's light views (camera/camera_views.h).
void evaluate_camera_views(const std::vector<Scene>& scenes, const DatasetDesc& dataset,
                           const std::vector<ViewData>& views,
                           const std::vector<std::string>& techniques, int resolution,
                           const EvalSettings& settings, bool quiet,
                           const std::function<void(const CameraShadows&)>& each) {
  size_t total = 0;
  for (const auto& scene : scenes)
    total += scene.cameras.size() * rendered_views(scene, dataset, resolution, settings).size();
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
        CameraShadows out{scene.name, light.name, camera_view(scene, light, *it, camera, settings)};
        const CameraView& view = out.view;
        std::vector<std::string>& names = out.names;
        std::vector<std::vector<double>>& shadows = out.shadows;
        const double angle = view.receivers.soft.angle_deg;
        if (angle > 0) {  // the area light's shadow leads the sheet
          names.push_back(kAreaLightShadow);
          shadows.push_back(view.receivers.fragments.pcf);
          out.reference.push_back(true);
        }
        for (const auto& name : techniques) {
          names.push_back(name);
          shadows.push_back(evaluate_technique(view.receivers, name, settings, nullptr).shadow);
          out.reference.push_back(is_view_reference(name, angle));
        }
        each(out);
        bar.advance();
      }
  bar.finish();
}

}  // namespace mb
