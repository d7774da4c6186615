#include "scatter/scatter_frames.h"

#include <omp.h>

#include <cmath>
#include <numbers>

#include "raster/render_view.h"
#include "util/parallel_errors.h"

namespace mb {

namespace {

// A camera's view rays, the surfaces they end at and those surfaces' attenuated radiance.
struct CameraRays {
  std::vector<ScatterRay> rays;
  std::vector<Eigen::Vector3d> surface;
};

// L_s of the nearest surface: its diffuse colour times max(0, n . l) / pi, shadowed by the same
// map (offset 1.5 texels along its normal against acne), then attenuated by exp(-sigma_t s).
// Only the images show it; no error reads it.
CameraRays camera_rays(const ScatterScene& s, const CameraDesc& camera, const CameraImage& image,
                       const LightDepthMap& light, double max_distance) {
  const CameraFrame frame(camera);
  const Eigen::Vector3d to_light = light.frame->to_light();
  const double offset = 1.5 * light.frame->world_per_texel();
  CameraRays out;
  out.rays.resize(size_t(image.width) * image.height);
  out.surface.assign(out.rays.size(), Eigen::Vector3d::Zero());
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const size_t p = size_t(y) * image.width + x;
      ScatterRay& ray = out.rays[p];
      ray.direction = frame.ray(x, y), ray.pixel = p, ray.length = max_distance;
      if (image.offsets[p] == image.offsets[p + 1]) continue;
      const size_t f = image.offsets[p];
      ray.length = (image.point[f] - frame.position()).norm();
      const auto& tri = s.scene.mesh.triangles[image.triangle[f]];
      const auto& v = s.scene.mesh.vertices;
      Eigen::Vector3d n = (v[tri[1]] - v[tri[0]]).cross(v[tri[2]] - v[tri[0]]).normalized();
      if (s.scene.two_sided[image.triangle[f]] && n.dot(to_light) < 0) n = -n;
      const double cosine = n.dot(to_light);
      if (!(cosine > 0) || !light.lit(image.point[f] + offset * n)) continue;
      out.surface[p] = s.scene.color[s.scene.part[image.triangle[f]]] *
                       (cosine / std::numbers::pi) * std::exp(-s.medium.extinction * ray.length);
    }
  return out;
}

}  // namespace

std::shared_ptr<const ScatterLight> render_scatter_light(const Scene& scene, LightViewDesc view,
                                                         const ScatterRunOptions& options,
                                                         int threads) {
  auto light = std::make_shared<ScatterLight>();
  view.resolution = options.reference_resolution;
  check_render_memory(view.resolution, "scatter.reference_resolution");
  light->view = view;
  {
    const LayerStack stack = render_view(scene, view, threads);
    light->frame = std::make_unique<LightFrame>(view, scene.mesh.vertices);  // render_view's
    light->map = std::make_unique<LightDepthMap>(*light->frame, stack);
  }
  // The prefiltered rows' map: the same view at scatter.light_resolution (render_view fits the
  // same projection to the scene at any resolution).
  if (options.light_resolution != options.reference_resolution) {
    LightViewDesc low = view;
    low.resolution = options.light_resolution;
    check_render_memory(low.resolution, "scatter.light_resolution");
    const LayerStack stack = render_view(scene, low, threads);
    light->rectify_frame = std::make_unique<LightFrame>(low, scene.mesh.vertices);
    light->rectify_map = std::make_unique<LightDepthMap>(*light->rectify_frame, stack);
  }
  return light;
}

ScatterSetup ScatterFrame::setup() const {
  return {light->map.get(),         &scene->scene,    &light->view, camera, camera->position,
          scene->medium.extinction, &light->rectify()};
}

std::string ScatterFrame::name() const {
  return scene->scene.name + "/" + light->view.name + "/" + camera->name;
}

ScatterFrame make_scatter_frame(const ScatterScene& scene,
                                std::shared_ptr<const ScatterLight> light, const CameraDesc& camera,
                                const CameraImage& image, const ScatterRunOptions& options) {
  ScatterFrame f;
  f.scene = &scene, f.light = std::move(light), f.camera = &camera;
  f.width = image.width, f.height = image.height;
  CameraRays rays = camera_rays(scene, camera, image, *f.light->map, options.max_distance);
  f.rays = std::move(rays.rays);
  f.surface = std::move(rays.surface);
  const double epipole_cos = std::cos(options.epipole_degrees * std::numbers::pi / 180);
  const Eigen::Vector3d to_light = f.light->frame->to_light();
  const MediumDesc& medium = scene.medium;
  f.factor.resize(f.rays.size());
  f.s_max.resize(f.rays.size());
  for (size_t p = 0; p < f.rays.size(); ++p) {
    const ScatterRay& ray = f.rays[p];
    if (std::abs(ray.direction.dot(to_light)) > epipole_cos) ++f.epipole_pixels;
    f.factor[p] = scattering_factor(medium, to_light, ray.direction);
    f.s_max[p] = f.factor[p] * transmittance_integral(0, ray.length, medium.extinction);
  }
  return f;
}

std::vector<ScatterFrame> prepare_scatter_frames(const std::vector<ScatterScene>& scenes,
                                                 const ScatterRunOptions& options, int threads) {
  std::vector<ScatterFrame> frames;
  for (const ScatterScene& s : scenes) {
    std::vector<CameraImage> images;
    for (const auto& camera : s.scene.cameras)
      images.push_back(render_camera(s.scene, camera, threads));
    for (const LightViewDesc& view : s.scene.views) {
      const auto light = render_scatter_light(s.scene, view, options, threads);
      for (size_t c = 0; c < s.scene.cameras.size(); ++c)
        frames.push_back(make_scatter_frame(s, light, s.scene.cameras[c], images[c], options));
    }
  }
  return frames;
}

std::vector<double> frame_inscatter(const ScatterTechnique& technique, const ScatterFrame& frame,
                                    int threads) {
  std::vector<double> out(frame.rays.size());
  const int rows = frame.height;
  const size_t width = size_t(frame.width);
  ParallelErrors parallel;
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1)
  for (int y = 0; y < rows; ++y)
    parallel.capture([&] {
      for (size_t p = size_t(y) * width; p < size_t(y + 1) * width; ++p)
        out[p] = technique.lit_length(frame.rays[p]) * frame.factor[p];
    });
  parallel.rethrow();
  return out;
}

}  // namespace mb
