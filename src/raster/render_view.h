#pragma once
// One light view of a scene -> its LayerStack: the fitted orthographic projection (scene/), then
// the rasterizer. Facing comes from the world-space normal: n . to_light > 0, or two-sided.
#include <string>

#include "raster/layer_stack.h"
#include "scene/scene.h"
#include "util/eigen.h"

namespace mb {

LayerStack render_view(const Scene& scene, const LightViewDesc& view, int threads);

// One direction of an area light (docs/soft-shadows.md §1) as a shear of the view's raster space:
// a point at raster (x, y, z) lands at (x + sx (z - 1/2) + pad, y + sy (z - 1/2) + pad), depth
// unchanged, in a map of resolution + 2 pad texels a side. Planes stay planes and the order along
// every ray stays the depth order, so layer 0 of that stack is the direction's shadow map. The
// zero shear is the view itself, bit for bit.
struct RasterShear {
  double sx = 0, sy = 0;  // texels of lateral shift per unit of depth
  int pad = 0;            // texels added on every side, so no sheared receiver leaves the map
  Eigen::Vector3d apply(const Eigen::Vector3d& r) const {
    return {r.x() + sx * (r.z() - 0.5) + pad, r.y() + sy * (r.z() - 0.5) + pad, r.z()};
  }
  Eigen::Vector3d invert(const Eigen::Vector3d& r) const {
    return {r.x() - pad - sx * (r.z() - 0.5), r.y() - pad - sy * (r.z() - 0.5), r.z()};
  }
};
LayerStack render_view(const Scene& scene, const LightViewDesc& view, int threads,
                       const RasterShear& shear);

// Refuses (InputError with both figures) a resolution whose layer stack cannot fit in the memory
// this process may use (the smallest of MemAvailable, the cgroup's limit and RLIMIT_AS): checked
// before rendering, since running out inside the rasterizer's threads aborts.
void check_render_memory(int resolution, const std::string& where);

}  // namespace mb
