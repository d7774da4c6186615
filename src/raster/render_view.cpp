#include "raster/render_view.h"

#include <sys/resource.h>

#include <cstdint>
#include <fstream>
#include <limits>

#include "raster/rasterizer.h"
#include "util/eigen.h"
#include "util/error.h"

namespace mb {

namespace {

// A lower bound of the bytes a layer stack needs per texel: its offset (8), one fragment's depth,
// facing and gradient (25), the rasterizer's fragment record and sort scratch (~24) and the
// layer-0 shadow map the evaluation keeps (8). Real scenes hold 1-3 fragments a texel.
constexpr double kBytesPerTexel = 64;

double available_bytes() {
  double available = std::numeric_limits<double>::infinity();
  std::ifstream meminfo("/proc/meminfo");
  for (std::string key; meminfo >> key;) {
    double kib = 0;
    meminfo >> kib;
    if (key == "MemAvailable:") available = std::min(available, kib * 1024);
    meminfo.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
  }
  std::ifstream max_file("/sys/fs/cgroup/memory.max"),
      current_file("/sys/fs/cgroup/memory.current");
  std::string max_text;
  double current = 0;
  if (max_file >> max_text && max_text != "max" && current_file >> current)
    available = std::min(available, std::stod(max_text) - current);
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
    available = std::min(available, double(limit.rlim_cur));
  return available;
}

}  // namespace

void check_render_memory(int resolution, const std::string& where) {
  const double needed = double(resolution) * double(resolution) * kBytesPerTexel,
               available = available_bytes();
  if (needed > available)
    throw InputError(where + ": a " + std::to_string(resolution) + "x" +
                     std::to_string(resolution) + " layer stack needs at least " +
                     std::to_string(int64_t(needed / (1 << 20))) + " MiB, but only " +
                     std::to_string(int64_t(available / (1 << 20))) +
                     " MiB are available; lower the resolution");
}

LayerStack render_view(const Scene& scene, const LightViewDesc& view, int threads) {
  return render_view(scene, view, threads, RasterShear{});
}

LayerStack render_view(const Scene& scene, const LightViewDesc& view, int threads,
                       const RasterShear& shear) {
  const int size = view.resolution + 2 * shear.pad;
  check_render_memory(size, "view " + scene.name + "/" + view.name);
  LightFrame frame(view, scene.mesh.vertices);
  RasterInput input;
  input.width = input.height = size;
  input.vertices.resize(scene.mesh.vertices.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (size_t v = 0; v < scene.mesh.vertices.size(); ++v)
    input.vertices[v] = shear.apply(frame.to_raster(scene.mesh.vertices[v]));
  input.triangles = scene.mesh.triangles;
  input.facing.resize(scene.mesh.triangles.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (size_t t = 0; t < scene.mesh.triangles.size(); ++t) {
    const auto& tri = scene.mesh.triangles[t];
    const auto &a = scene.mesh.vertices[tri[0]], &b = scene.mesh.vertices[tri[1]],
               &c = scene.mesh.vertices[tri[2]];
    input.facing[t] = scene.two_sided[t] || (b - a).cross(c - a).dot(frame.to_light()) > 0;
  }
  // Translucent parts (docs/reference.md §7): each fragment's alpha from its triangle's part,
  // at the world point of its texel centre and depth.
  input.keep_triangles = scene.translucent();
  LayerStack stack = rasterize(input, threads);
  if (input.keep_triangles) {
    stack.alpha.resize(stack.fragment_count());
#pragma omp parallel for schedule(static) num_threads(threads)
    for (size_t t = 0; t < stack.texel_count(); ++t)
      for (uint64_t f = stack.offsets[t]; f < stack.offsets[t + 1]; ++f) {
        const Eigen::Vector3d raster(double(t % stack.width) + 0.5, double(t / stack.width) + 0.5,
                                     stack.depth[f]);
        const OpacityDesc& o = scene.opacity[scene.part[stack.triangle[f]]];
        stack.alpha[f] = float(o.at(frame.to_world(shear.invert(raster))));
      }
    // The triangles stay: an unsorted blend draws in their order (BlendOrder::Submission).
  }
  stack.scene = scene.name;
  stack.view = view.name;
  stack.frame = frame.describe();
  return stack;
}

}  // namespace mb
