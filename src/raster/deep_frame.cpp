#include "raster/deep_frame.h"

#include <algorithm>
#include <limits>
#include <numeric>

#include "raster/render_camera.h"
#include "scene/light_view.h"

namespace mb {

double DeepFrame::nearest() const {
  return depth.empty() ? 0.0 : *std::min_element(depth.begin(), depth.end());
}

double DeepFrame::farthest() const {
  return depth.empty() ? 0.0 : *std::max_element(depth.begin(), depth.end());
}

namespace {

// Lambert with an ambient term; a two-sided surface is lit on the side the camera sees.
Rgb shade(const Scene& scene, uint32_t triangle, const Eigen::Vector3d& point,
          const Eigen::Vector3d& eye, const Eigen::Vector3d& to_light) {
  const auto& tri = scene.mesh.triangles[triangle];
  const Eigen::Vector3d &a = scene.mesh.vertices[tri[0]], &b = scene.mesh.vertices[tri[1]],
                        &c = scene.mesh.vertices[tri[2]];
  Eigen::Vector3d n = (b - a).cross(c - a).normalized();
  if (scene.two_sided[triangle] && n.dot(eye - point) < 0) n = -n;
  const double light = kOitAmbient + (1 - kOitAmbient) * std::max(0.0, n.dot(to_light));
  const Eigen::Vector3d& albedo = scene.color[scene.part[triangle]];
  return {float(albedo.x() * light), float(albedo.y() * light), float(albedo.z() * light)};
}

// The bounding sphere of the scene's transparent triangles: the centre of their bounding box, and
// the largest distance of a vertex from it (a sphere that holds them, not the least one; seed 003
// names no construction). Its depth range along the view, the near end at least the camera's near
// plane (every fragment lies beyond it), so that the logarithmic warp is defined.
void set_sphere_range(const Scene& scene, const CameraFrame& eye, DeepFrame& frame) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  const auto transparent = [&](size_t t) { return !scene.opacity[scene.part[t]].opaque(); };
  for (size_t t = 0; t < scene.mesh.triangles.size(); ++t)
    if (transparent(t))
      for (uint32_t v : scene.mesh.triangles[t])
        lo = lo.cwiseMin(scene.mesh.vertices[v]), hi = hi.cwiseMax(scene.mesh.vertices[v]);
  if (!(lo.x() <= hi.x())) return;  // no transparent geometry
  const Eigen::Vector3d centre = (lo + hi) / 2;
  double radius = 0;
  for (size_t t = 0; t < scene.mesh.triangles.size(); ++t)
    if (transparent(t))
      for (uint32_t v : scene.mesh.triangles[t])
        radius = std::max(radius, (scene.mesh.vertices[v] - centre).norm());
  const double d = eye.distance(centre);
  frame.sphere_near = std::max(d - radius, eye.near());
  frame.sphere_far = std::max(d + radius, frame.sphere_near);
}

}  // namespace

DeepFrame render_deep_frame(const Scene& scene, const CameraDesc& camera, int threads) {
  const CameraImage image = render_camera(scene, camera, threads);
  const CameraFrame eye(camera);
  const Eigen::Vector3d to_light =
      scene.views.empty()
          ? Eigen::Vector3d(0, 1, 0)
          : direction_to_light(scene.views[0].azimuth_deg, scene.views[0].elevation_deg);
  DeepFrame frame;
  frame.camera = camera.name;
  frame.width = image.width;
  frame.height = image.height;
  const size_t pixels = image.offsets.size() - 1;
  frame.offsets.assign(pixels + 1, 0);
  frame.behind.assign(pixels, kBackground);
  frame.behind_depth.assign(pixels, std::numeric_limits<double>::infinity());
  std::vector<uint64_t> order;
  for (size_t p = 0; p < pixels; ++p) {
    // Surfaces come nearest first, up to the first opaque one (render_camera).
    order.clear();
    for (uint64_t s = image.offsets[p]; s < image.offsets[p + 1]; ++s) {
      if (image.alpha[s] >= 1) {
        frame.behind[p] = shade(scene, image.triangle[s], image.point[s], eye.position(), to_light);
        frame.behind_depth[p] = eye.distance(image.point[s]);
        break;
      }
      order.push_back(s);
    }
    // Submission order: the scene's triangle order, as a GPU draws them (nearer first on ties).
    std::stable_sort(order.begin(), order.end(),
                     [&](uint64_t u, uint64_t v) { return image.triangle[u] < image.triangle[v]; });
    for (uint64_t s : order) {
      frame.depth.push_back(eye.distance(image.point[s]));
      frame.alpha.push_back(image.alpha[s]);
      frame.color.push_back(
          shade(scene, image.triangle[s], image.point[s], eye.position(), to_light));
    }
    frame.offsets[p + 1] = frame.depth.size();
  }
  set_sphere_range(scene, eye, frame);
  return frame;
}

}  // namespace mb
