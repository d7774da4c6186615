#include "scene/light_view.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "util/eigen.h"

namespace mb {

Eigen::Vector3d direction_to_light(double azimuth_deg, double elevation_deg) {
  double az = azimuth_deg * std::numbers::pi / 180, el = elevation_deg * std::numbers::pi / 180;
  return Eigen::Vector3d(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
}

LightFrame::LightFrame(const LightViewDesc& desc, const std::vector<Eigen::Vector3d>& points)
    : resolution_(desc.resolution) {
  to_light_ = direction_to_light(desc.azimuth_deg, desc.elevation_deg);
  w_ = -to_light_;  // depth grows along the light's travel
  // Raster up is the world's +y projected onto the image plane, unless the light looks straight
  // down, where +z serves instead.
  Eigen::Vector3d up =
      std::abs(w_.y()) > 0.999 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitY();
  u_ = up.cross(w_).normalized();
  v_ = w_.cross(u_);
  double inf = std::numeric_limits<double>::infinity();
  double lo[3] = {inf, inf, inf}, hi[3] = {-inf, -inf, -inf};
  for (const auto& p : points) {
    double c[3] = {u_.dot(p), v_.dot(p), w_.dot(p)};
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], c[k]), hi[k] = std::max(hi[k], c[k]);
  }
  // Square texels: the larger of the two lateral extents decides the scale.
  double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], 1e-12});
  texels_per_world_ = resolution_ / (extent * (1 + 2 * desc.margin));
  u_center_ = (lo[0] + hi[0]) / 2;
  v_center_ = (lo[1] + hi[1]) / 2;
  double depth_extent = std::max(hi[2] - lo[2], 1e-12);
  w_min_ = lo[2] - desc.margin * depth_extent;
  depth_range_ = depth_extent * (1 + 2 * desc.margin);
}

Eigen::Vector3d LightFrame::to_raster(const Eigen::Vector3d& p) const {
  return {(u_.dot(p) - u_center_) * texels_per_world_ + resolution_ / 2.0,
          (v_center_ - v_.dot(p)) * texels_per_world_ + resolution_ / 2.0,
          (w_.dot(p) - w_min_) / depth_range_};
}

Eigen::Vector3d LightFrame::to_world(const Eigen::Vector3d& r) const {
  const double u = (r.x() - resolution_ / 2.0) / texels_per_world_ + u_center_;
  const double v = v_center_ - (r.y() - resolution_ / 2.0) / texels_per_world_;
  const double w = r.z() * depth_range_ + w_min_;
  return u * u_ + v * v_ + w * w_;  // u, v, w are orthonormal
}

std::string LightFrame::describe() const {
  std::ostringstream s;
  s.precision(17);
  s << "to_light " << to_light_.transpose() << " u " << u_.transpose() << " v " << v_.transpose()
    << " center_uv " << u_center_ << " " << v_center_ << " w_min " << w_min_ << " depth_range "
    << depth_range_ << " texels_per_world " << texels_per_world_;
  return s.str();
}

}  // namespace mb
