#pragma once
// A directional light's view of a scene: an orthographic projection fitted to the scene bounds,
// mapping world points to raster coordinates (x right, y down, in texels) and depth in [0, 1]
// (docs/reference.md §3: depth normalized to [0,1], empty texels at the far plane 1).
#include <string>
#include <vector>

#include "util/eigen.h"

namespace mb {

struct LightViewDesc {
  std::string name;
  double azimuth_deg = 0;     // around +y, 0 = light from +z
  double elevation_deg = 45;  // above the horizon, 90 = straight down
  int resolution = 512;       // square shadow map
  double margin = 0.02;       // added on every side, as a fraction of the scene's extent
  // The light's angular diameter in degrees (docs/soft-shadows.md §1); below 0: the dataset's.
  double light_angle_deg = -1;
};

// Unit vector pointing from the scene towards the light.
Eigen::Vector3d direction_to_light(double azimuth_deg, double elevation_deg);

class LightFrame {
 public:
  // Fits the projection to the bounding box of `points` (scene vertices) with `desc.margin`.
  LightFrame(const LightViewDesc& desc, const std::vector<Eigen::Vector3d>& points);

  // (x, y) in texels, z in [0, 1] growing away from the light.
  Eigen::Vector3d to_raster(const Eigen::Vector3d& world) const;
  // Its inverse: the world point at raster (x, y) and depth z.
  Eigen::Vector3d to_world(const Eigen::Vector3d& raster) const;
  const Eigen::Vector3d& to_light() const { return to_light_; }
  int resolution() const { return resolution_; }
  // World units per texel and per unit of depth, for converting gradients back to slopes.
  double world_per_texel() const { return 1.0 / texels_per_world_; }
  double world_per_depth() const { return depth_range_; }
  // "u v w origin scale" for file headers, so a stack records its projection.
  std::string describe() const;

 private:
  Eigen::Vector3d to_light_, u_, v_, w_;
  double u_center_, v_center_, w_min_, depth_range_, texels_per_world_;
  int resolution_;
};

}  // namespace mb
