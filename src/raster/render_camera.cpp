#include "raster/render_camera.h"

#include <array>
#include <cmath>

#include "raster/rasterizer.h"
#include "util/eigen.h"

namespace mb {

CameraImage render_camera(const Scene& scene, const CameraDesc& camera, int threads) {
  const CameraFrame frame(camera);
  const TriangleMesh& mesh = scene.mesh;
  // Clip every triangle to the camera's frustum (a ground plane usually reaches behind the camera,
  // where the perspective division would fold it over the image).
  std::vector<Eigen::Vector3d> world;
  RasterInput input;
  input.width = camera.width;
  input.height = camera.height;
  input.keep_triangles = true;
  std::vector<uint32_t> source;  // scene triangle of each clipped triangle
  std::vector<Eigen::Vector3d> polygon, clipped;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    polygon.clear();
    for (int k = 0; k < 3; ++k) polygon.push_back(mesh.vertices[mesh.triangles[t][k]]);
    // Sutherland-Hodgman against each of the frustum's clip planes in turn.
    for (int plane = 0; plane < CameraFrame::kClipPlanes && !polygon.empty(); ++plane) {
      clipped.clear();
      for (size_t k = 0; k < polygon.size(); ++k) {
        const Eigen::Vector3d &a = polygon[k], &b = polygon[(k + 1) % polygon.size()];
        const double da = frame.clip_distance(plane, a), db = frame.clip_distance(plane, b);
        if (da >= 0) clipped.push_back(a);
        if ((da >= 0) != (db >= 0)) clipped.push_back(a + (b - a) * (da / (da - db)));
      }
      polygon.swap(clipped);
    }
    if (polygon.size() < 3) continue;
    const uint32_t first = uint32_t(world.size());
    world.insert(world.end(), polygon.begin(), polygon.end());
    for (size_t k = 1; k + 1 < polygon.size(); ++k) {
      input.triangles.push_back({first, uint32_t(first + k), uint32_t(first + k + 1)});
      source.push_back(uint32_t(t));
    }
  }
  input.vertices.resize(world.size());
  for (size_t k = 0; k < world.size(); ++k) input.vertices[k] = frame.to_raster(world[k]);
  input.facing.assign(input.triangles.size(), 1);
  const LayerStack stack = rasterize(input, threads);

  CameraImage image;
  image.width = camera.width;
  image.height = camera.height;
  image.offsets.assign(stack.texel_count() + 1, 0);
  const bool translucent = scene.translucent();
  // Per pixel into its own slot first (parallel), then packed.
  std::vector<std::vector<std::pair<uint32_t, Eigen::Vector3d>>> seen(stack.texel_count());
  std::vector<std::vector<double>> seen_alpha(stack.texel_count());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (size_t p = 0; p < stack.texel_count(); ++p) {
    const Eigen::Vector3d ray = frame.ray(int(p % camera.width), int(p / camera.width));
    for (uint64_t f = stack.offsets[p]; f < stack.offsets[p + 1]; ++f) {
      const uint32_t t = source[stack.triangle[f]];
      const auto& tri = mesh.triangles[t];
      const Eigen::Vector3d& a = mesh.vertices[tri[0]];
      const Eigen::Vector3d normal = (mesh.vertices[tri[1]] - a).cross(mesh.vertices[tri[2]] - a);
      const double facing = normal.dot(ray);
      // A triangle seen edge-on covers the pixel's centre only by rounding: an opaque scene shows
      // background there, a translucent one what lies behind.
      if (!(std::abs(facing) > 1e-12 * normal.norm())) {
        if (translucent) continue;
        break;
      }
      const Eigen::Vector3d point =
          frame.position() + ray * (normal.dot(a - frame.position()) / facing);
      const double alpha = translucent ? scene.opacity[scene.part[t]].at(point) : 1.0;
      if (alpha <= 0) continue;  // fully transparent: nothing to see
      seen[p].push_back({t, point});
      seen_alpha[p].push_back(std::min(alpha, 1.0));
      if (alpha >= 1 || !translucent) break;
    }
  }
  for (size_t p = 0; p < stack.texel_count(); ++p) {
    for (size_t k = 0; k < seen[p].size(); ++k) {
      image.triangle.push_back(seen[p][k].first);
      image.point.push_back(seen[p][k].second);
      image.alpha.push_back(seen_alpha[p][k]);
    }
    image.offsets[p + 1] = image.triangle.size();
  }
  return image;
}

}  // namespace mb
