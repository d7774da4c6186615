#pragma once
// A perspective camera that looks at a scene (issue 34: camera views of the techniques' shadows).
// World points map to raster coordinates (x right, y down, pixel (i, j) centred at (i + .5, j +
// .5)) and a depth in [0, 1] that is affine in raster space (1 / distance, rescaled), so the light
// views' rasterizer interpolates it exactly.
#include <string>

#include "util/eigen.h"

namespace mb {

struct CameraDesc {
  std::string name;
  Eigen::Vector3d position = Eigen::Vector3d(0, 4, 8);
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  double fov_deg = 45;  // vertical field of view
  int width = 480, height = 320;
};

class CameraFrame {
 public:
  explicit CameraFrame(const CameraDesc& desc);
  // Distance along the view direction (negative or below `near()`: behind the camera).
  double distance(const Eigen::Vector3d& world) const { return (world - position_).dot(forward_); }
  // Clip planes, each a signed distance >= 0 inside: the near plane, and four side planes a
  // thousand image widths out (a guard band: clipping there changes no visible pixel, and keeps
  // raster coordinates within the rasterizer's range).
  static constexpr int kClipPlanes = 5;
  double clip_distance(int plane, const Eigen::Vector3d& world) const;
  // (x, y) in pixels, z in [0, 1]; `world` must lie inside the clip planes.
  Eigen::Vector3d to_raster(const Eigen::Vector3d& world) const;
  // The ray through pixel (x, y)'s centre: origin and unit direction.
  const Eigen::Vector3d& position() const { return position_; }
  Eigen::Vector3d ray(int x, int y) const;
  double near() const { return near_; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  Eigen::Vector3d position_, forward_, right_, up_;
  double tan_half_, aspect_, near_, far_;
  int width_, height_;
};

}  // namespace mb
