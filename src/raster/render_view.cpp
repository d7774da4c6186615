#include "raster/render_view.h"

#include <Eigen/Geometry>

#include "raster/rasterizer.h"

namespace mb {

LayerStack render_view(const Scene& scene, const LightViewDesc& view, int threads) {
  LightFrame frame(view, scene.mesh.vertices);
  RasterInput input;
  input.width = input.height = view.resolution;
  input.vertices.resize(scene.mesh.vertices.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (size_t v = 0; v < scene.mesh.vertices.size(); ++v) input.vertices[v] = frame.to_raster(scene.mesh.vertices[v]);
  input.triangles = scene.mesh.triangles;
  input.facing.resize(scene.mesh.triangles.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (size_t t = 0; t < scene.mesh.triangles.size(); ++t) {
    const auto& tri = scene.mesh.triangles[t];
    const auto &a = scene.mesh.vertices[tri[0]], &b = scene.mesh.vertices[tri[1]], &c = scene.mesh.vertices[tri[2]];
    input.facing[t] = scene.two_sided[t] || (b - a).cross(c - a).dot(frame.to_light()) > 0;
  }
  LayerStack stack = rasterize(input, threads);
  stack.scene = scene.name;
  stack.view = view.name;
  stack.frame = frame.describe();
  return stack;
}

}  // namespace mb
