#pragma once
// CPU rasterization of triangles into a LayerStack: every triangle covering a texel centre gives a
// fragment, not only the nearest (docs/reference.md §3).
#include <array>
#include <optional>
#include <vector>

#include "raster/layer_stack.h"
#include "util/eigen.h"

namespace mb {

struct RasterInput {
  int width = 0, height = 0;
  // Vertices in raster space: x, y in texels (texel (i, j) has its centre at (i + .5, j + .5)),
  // z = depth in [0, 1].
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<uint32_t, 3>> triangles;
  std::vector<uint8_t> facing;  // per triangle
  bool keep_triangles = false;  // fill LayerStack::triangle (camera images need the surface)
};

// dz/dx and dz/dy of the plane through three raster-space points (the rasterizer's fragment
// gradients); nullopt when the points are collinear in (x, y).
std::optional<Eigen::Vector2d> plane_gradient(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                              const Eigen::Vector3d& c);

// Watertight: coverage is decided exactly (vertices snapped to 1/256 texel, integer edge
// functions, top-left tie rule), so an edge shared by two triangles covers each texel centre on it
// exactly once. Depth and gradient come from the unsnapped plane in double. The output is the
// same for every thread count: fragments are sorted by (texel, depth, triangle index).
LayerStack rasterize(const RasterInput& input, int threads);

}  // namespace mb
