#include "scene/camera.h"

#include <cmath>
#include <numbers>

#include "util/eigen.h"

namespace mb {

CameraFrame::CameraFrame(const CameraDesc& desc)
    : position_(desc.position),
      tan_half_(std::tan(desc.fov_deg * std::numbers::pi / 360)),
      aspect_(double(desc.width) / desc.height),
      width_(desc.width),
      height_(desc.height) {
  forward_ = (desc.target - desc.position).normalized();
  // World up is +y; a camera looking straight down takes -z as its screen's up.
  const Eigen::Vector3d world_up =
      std::abs(forward_.y()) > 0.999 ? Eigen::Vector3d(0, 0, -1) : Eigen::Vector3d(0, 1, 0);
  right_ = forward_.cross(world_up).normalized();
  up_ = right_.cross(forward_);
  // Depth is 1 / distance rescaled between near and far; its precision is irrelevant here (the
  // visible point is recomputed exactly from its triangle), only its order.
  const double extent = (desc.target - desc.position).norm();
  near_ = 1e-3 * extent;
  far_ = 1e3 * extent;
}

Eigen::Vector3d CameraFrame::to_raster(const Eigen::Vector3d& world) const {
  const Eigen::Vector3d d = world - position_;
  const double z = d.dot(forward_);
  const double x = d.dot(right_) / (z * tan_half_ * aspect_), y = d.dot(up_) / (z * tan_half_);
  const double depth = (1 / near_ - 1 / z) / (1 / near_ - 1 / far_);
  return {(x + 1) / 2 * width_, (1 - y) / 2 * height_, depth};
}

double CameraFrame::clip_distance(int plane, const Eigen::Vector3d& world) const {
  constexpr double kGuard = 1000;
  const Eigen::Vector3d d = world - position_;
  const double z = d.dot(forward_);
  switch (plane) {
    case 0:
      return z - near_;
    case 1:
      return kGuard * z * tan_half_ * aspect_ - d.dot(right_);
    case 2:
      return kGuard * z * tan_half_ * aspect_ + d.dot(right_);
    case 3:
      return kGuard * z * tan_half_ - d.dot(up_);
    default:
      return kGuard * z * tan_half_ + d.dot(up_);
  }
}

Eigen::Vector3d CameraFrame::ray(int px, int py) const {
  const double x = (2 * (px + 0.5) / width_ - 1) * tan_half_ * aspect_;
  const double y = (1 - 2 * (py + 0.5) / height_) * tan_half_;
  return (forward_ + x * right_ + y * up_).normalized();
}

}  // namespace mb
