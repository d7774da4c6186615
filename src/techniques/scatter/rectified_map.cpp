#include "techniques/scatter/rectified_map.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include "util/error.h"
#include "util/number_text.h"

namespace mb {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// Any unit vector across `z` (the light's axis has no preferred azimuth: seed 004 §2.2 chooses the
// other axes "arbitrarily but orthogonal").
Eigen::Vector3d across(const Eigen::Vector3d& z) {
  const Eigen::Vector3d up =
      std::abs(z.y()) < 0.9 ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitX();
  return z.cross(up).normalized();
}

}  // namespace

RectifiedMap::RectifiedMap(const LightDepthMap& light, const CameraDesc& camera, double extinction,
                           const RectifiedSettings& settings)
    : width_(settings.resolution), height_(settings.resolution), sigma_(extinction) {
  if (settings.resolution < 1)
    throw std::logic_error("RectifiedMap: resolution " + std::to_string(settings.resolution));
  if (!(2 * settings.guard_band < settings.resolution))
    throw InputError("scatter.guard_band: " + round_trip(settings.guard_band) +
                     " depth texels at either end leave no depth range of a row of " +
                     std::to_string(settings.resolution) +
                     " (scatter.light_resolution); expected below half of it");
  axes_[2] = -light.frame->to_light().normalized();
  axes_[0] = across(axes_[2]);
  axes_[1] = axes_[2].cross(axes_[0]);
  const Eigen::Vector3d p = camera.position;

  // The view rays' azimuths and inclinations: phi spans the smallest arc holding every pixel's
  // (the complement of the largest gap between them, all of [0, 2 pi) when the light's axis is in
  // view), theta per row the range of the pixels that row answers.
  const CameraFrame frame(camera);
  std::vector<std::pair<double, double>> rays;  // (phi, theta) per pixel
  rays.reserve(size_t(frame.width()) * frame.height());
  for (int y = 0; y < frame.height(); ++y)
    for (int x = 0; x < frame.width(); ++x) {
      const Eigen::Vector3d w = frame.ray(x, y);
      const double lx = w.dot(axes_[0]), ly = w.dot(axes_[1]), lz = w.dot(axes_[2]);
      rays.push_back({std::atan2(ly, lx), std::atan2(std::hypot(lx, ly), lz)});
    }
  std::vector<double> phis;
  for (const auto& ray : rays) phis.push_back(ray.first);
  std::sort(phis.begin(), phis.end());
  double gap = phis.front() + kTwoPi - phis.back();
  phi_lo_ = phis.front();
  for (size_t i = 1; i < phis.size(); ++i)
    if (phis[i] - phis[i - 1] > gap) gap = phis[i] - phis[i - 1], phi_lo_ = phis[i];
  dphi_ = std::max(kTwoPi - gap, 1e-12) / height_;

  rows_.assign(size_t(height_), {std::numbers::pi, 0, 0});
  double all_lo = std::numbers::pi, all_hi = 0;
  for (const auto& [phi, theta] : rays) {
    Row& row = rows_[size_t(row_of(phi))];
    row.lo = std::min(row.lo, theta), row.hi = std::max(row.hi, theta);
    all_lo = std::min(all_lo, theta), all_hi = std::max(all_hi, theta);
  }
  // A row no pixel reads takes the whole frustum's bounds; a row of one inclination at least one
  // depth texel of [0, pi]. The frustum's range fills the middle 1 - 2 g / n of [0, 1].
  const double fill = 1 - 2 * settings.guard_band / settings.resolution;
  for (Row& row : rows_) {
    if (row.lo > row.hi) row.lo = all_lo, row.hi = all_hi;
    const double mid = 0.5 * (row.lo + row.hi);
    const double half =
        0.5 * std::max(row.hi - row.lo, std::numbers::pi / settings.resolution) / fill;
    row.lo = mid - half, row.hi = mid + half;
  }

  // r covers every light ray of the light's map: beyond its square every light ray is empty.
  double r_max = 0;
  const double n = light.resolution;
  for (const double cx : {0.0, n})
    for (const double cy : {0.0, n}) {
      const Eigen::Vector3d d = light.frame->to_world({cx, cy, 0}) - p;
      r_max = std::max(r_max, (d - d.dot(axes_[2]) * axes_[2]).norm());
    }
  dr_ = std::max(r_max, 1e-12) / width_;
  for (Row& row : rows_) row.delta = dr_ / std::max(std::sin(0.5 * (row.lo + row.hi)), 1e-9);

  // Each texel's light ray: the first surface's raster depth D over it gives its distance along
  // the axis from the camera's plane, lambda = (D - z(q)) / (dz / dlambda), and its inclination
  // theta = atan2(r, lambda) as seen from the camera.
  const Eigen::Vector3d r0 = light.frame->to_raster(p);
  const double dz = light.frame->to_raster(p + axes_[2]).z() - r0.z();
  depth_.resize(size_t(width_) * height_);
  prefix_.resize(size_t(width_ + 1) * height_);
  // Filtered (seed 004 §2.3): the texel's footprint in light texels is the larger of its extents
  // along r and across it (dr and r dphi), as a GPU's trilinear filter takes the larger
  // derivative; depth 1 of the moment map is an empty light ray, lit all along.
  std::unique_ptr<LightMomentMap> moments;
  if (settings.resample == Resample::Filtered) {
    moments = std::make_unique<LightMomentMap>(light);
    second_.resize(depth_.size()), second_weight_.resize(depth_.size());
  }
  const double texels_per_world = 1 / light.frame->world_per_texel();
  for (int v = 0; v < height_; ++v) {
    const double phi = azimuth(v);
    const Eigen::Vector3d out = std::cos(phi) * axes_[0] + std::sin(phi) * axes_[1];
    for (int u = 0; u < width_; ++u) {
      const double r = radius(u);
      const Eigen::Vector3d q = light.frame->to_raster(p + r * out);
      const auto warp = [&](double z) {
        return std::clamp(normalise(v, std::atan2(r, (z - q.z()) / dz)), 0.0, 1.0);
      };
      const size_t i = size_t(v) * width_ + u;
      if (!moments) {
        const double stored = light.at(q.x(), q.y());
        depth_[i] = std::isinf(stored) ? 1 : warp(stored);
        continue;
      }
      double b[3];
      moments->sample(q.x(), q.y(), std::max(dr_, r * dphi_) * texels_per_world, b);
      const TwoDepths two = two_depths(b[0], b[1], b[2]);
      depth_[i] = two.depth[0] < 1 ? warp(two.depth[0]) : 1;
      second_[i] = two.depth[1] < 1 ? warp(two.depth[1]) : 1;
      second_weight_[i] = two.weight[1];
    }
    double* sums = prefix_.data() + size_t(v) * (width_ + 1);
    sums[0] = 0;
    for (int u = 0; u < width_; ++u) sums[u + 1] = sums[u] + texel_weight(v, u);
  }
}

int RectifiedMap::row_of(double phi) const {
  const double offset = phi - phi_lo_ - kTwoPi * std::floor((phi - phi_lo_) / kTwoPi);
  const double span = dphi_ * height_;
  if (offset < span) return std::min(int(offset / dphi_), height_ - 1);
  return offset - span < kTwoPi - offset ? height_ - 1 : 0;  // outside the range: nearer end
}

double RectifiedMap::normalise(int v, double theta) const {
  const Row& row = rows_[size_t(v)];
  return (row.hi - theta) / (row.hi - row.lo);
}

RectifiedRay RectifiedMap::locate(const Eigen::Vector3d& direction, double length) const {
  const double lx = direction.dot(axes_[0]), ly = direction.dot(axes_[1]);
  const double lz = direction.dot(axes_[2]), across = std::hypot(lx, ly);
  RectifiedRay ray;
  ray.row = row_of(std::atan2(ly, lx));
  ray.x = length * across / direction.norm() / dr_;
  ray.depth = std::clamp(normalise(ray.row, std::atan2(across, lz)), 0.0, 1.0);
  return ray;
}

double RectifiedMap::texel_weight(int v, int u) const {
  const double delta = rows_[size_t(v)].delta;
  return transmittance_integral(u * delta, (u + 1) * delta, sigma_);
}

double RectifiedMap::prefix_weight(int v, int k) const {
  return prefix_[size_t(v) * (width_ + 1) + k];
}

double RectifiedMap::weight_sum(int v, double x) const {
  if (!(x > 0)) return 0;
  if (x < width_) {
    const int k = int(x);
    return prefix_weight(v, k) + (x - k) * texel_weight(v, k);
  }
  const double delta = rows_[size_t(v)].delta;
  return prefix_weight(v, width_) + transmittance_integral(width_ * delta, x * delta, sigma_);
}

void RowPrefixSums::round_through(const MomentStorage& storage) {
  const auto round_trip = [&](std::span<double> b) {
    store_moments(storage, b);
    load_moments(storage, b);
  };
  for (size_t at = 0; at < values_.size(); at += size_t(channels_))
    round_trip({values_.data() + at, size_t(channels_)});
  round_trip(lit_);
}

RowPrefixSums::RowPrefixSums(const RectifiedMap& map, int channels, const Function& b)
    : map_(map), width_(map.width()), channels_(channels) {
  values_.resize(size_t(map.height()) * (width_ + 1) * channels_);
  lit_.resize(size_t(channels_));
  b(1.0, lit_.data());
  std::vector<double> sum(static_cast<size_t>(channels_)), texel(static_cast<size_t>(channels_));
  std::vector<double> second(static_cast<size_t>(channels_));
  // b of texel (u, v): of its depth, or under filtered resampling its two depths' b blended by
  // their weights (seed 004 §2.3: "linearly combine the two resulting vectors").
  const auto texel_b = [&](int u, int v, double* out) {
    const TwoDepths t = map.texel(u, v);
    b(t.depth[0], out);
    if (!(t.weight[1] > 0)) return;
    b(t.depth[1], second.data());
    for (int j = 0; j < channels_; ++j)
      out[j] = t.weight[0] * out[j] + t.weight[1] * second[size_t(j)];
  };
  for (int v = 0; v < map.height(); ++v) {
    texel_b(0, v, at(v, 0).data());
    std::fill(sum.begin(), sum.end(), 0.0);
    for (int u = 0; u < width_; ++u) {
      texel_b(u, v, texel.data());
      const double w = map.texel_weight(v, u), total = map.prefix_weight(v, u + 1);
      const std::span<double> out = at(v, u + 1);
      for (int j = 0; j < channels_; ++j) {
        sum[size_t(j)] += w * texel[size_t(j)];
        out[size_t(j)] = sum[size_t(j)] / total;
      }
    }
  }
}

void RowPrefixSums::mean(const RectifiedRay& ray, double* out) const {
  const int v = ray.row;
  const double total = map_.weight_sum(v, ray.x);
  if (!(total > 0)) {
    const std::span<const double> first = at(v, 0);
    std::copy(first.begin(), first.end(), out);
    return;
  }
  if (ray.x < width_) {
    const int k = int(ray.x);
    const double f = ray.x - k;
    const double a = (1 - f) * map_.prefix_weight(v, k), b = f * map_.prefix_weight(v, k + 1);
    const std::span<const double> lo = at(v, k), hi = at(v, k + 1);
    for (int j = 0; j < channels_; ++j) out[j] = (a * lo[size_t(j)] + b * hi[size_t(j)]) / total;
    return;
  }
  const double inside = map_.prefix_weight(v, width_);
  const std::span<const double> last = at(v, width_);
  for (int j = 0; j < channels_; ++j)
    out[j] = (inside * last[size_t(j)] + (total - inside) * lit_[size_t(j)]) / total;
}

void ray_distribution(const RectifiedMap& map, const RectifiedRay& ray, std::vector<double>& depths,
                      std::vector<double>& weights) {
  depths.clear(), weights.clear();
  // Texel u's depths, weighing `weight` in all.
  const auto add = [&](int u, double weight) {
    const TwoDepths t = map.texel(u, ray.row);
    depths.push_back(t.depth[0]), weights.push_back(weight * t.weight[0]);
    if (t.weight[1] > 0) depths.push_back(t.depth[1]), weights.push_back(weight * t.weight[1]);
  };
  if (!(ray.x > 0)) {  // a ray of length 0 or along the light's axis reads its row's first texel
    add(0, 1);
    return;
  }
  const int whole = int(std::min(std::floor(ray.x), double(map.width())));
  for (int u = 0; u < whole; ++u) add(u, map.texel_weight(ray.row, u));
  if (whole < map.width()) {
    const double part = (ray.x - whole) * map.texel_weight(ray.row, whole);
    if (part > 0) add(whole, part);
  } else if (ray.x > map.width()) {
    const double beyond = map.weight_sum(ray.row, ray.x) - map.prefix_weight(ray.row, map.width());
    if (beyond > 0) depths.push_back(1), weights.push_back(beyond);
  }
}

}  // namespace mb
