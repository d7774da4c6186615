#include "shadow/compositing.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "util/error.h"

namespace mb {

PixelFragments pixel_of(const DeepFrame& frame, size_t p) {
  const size_t begin = frame.offsets[p], count = frame.offsets[p + 1] - begin;
  PixelFragments px;
  px.depth = std::span(frame.depth).subspan(begin, count);
  px.alpha = std::span(frame.alpha).subspan(begin, count);
  px.color = std::span(frame.color).subspan(begin, count);
  px.behind = frame.behind[p];
  return px;
}

DepthWarp DepthWarp::between(double nearest, double farthest, WarpKind kind) {
  DepthWarp w;
  w.linear = kind == WarpKind::Linear;
  w.near = w.linear ? nearest : std::log(nearest);
  w.range = (w.linear ? farthest : std::log(farthest)) - w.near;
  return w;
}

double DepthWarp::operator()(double z) const {
  if (!(range > 0)) return 0;
  return std::clamp(((linear ? z : std::log(z)) - near) / range, 0.0, 1.0);
}

WarpKind warp_kind(const std::string& name) {
  if (name == "logarithmic") return WarpKind::Logarithmic;
  if (name == "linear") return WarpKind::Linear;
  throw InputError("oit.warp: '" + name + "': expected logarithmic or linear");
}

DepthRangeKind depth_range_kind(const std::string& name) {
  if (name == "fragments") return DepthRangeKind::Fragments;
  if (name == "bounding_sphere") return DepthRangeKind::BoundingSphere;
  throw InputError("oit.depth_range: '" + name + "': expected fragments or bounding_sphere");
}

DepthWarp frame_warp(const DeepFrame& frame, WarpKind kind, DepthRangeKind range) {
  if (range == DepthRangeKind::Fragments)
    return DepthWarp::between(frame.nearest(), frame.farthest(), kind);
  if (!std::isfinite(frame.sphere_near) || !std::isfinite(frame.sphere_far))
    throw InputError("oit.depth_range: bounding_sphere: camera " + frame.camera +
                     " has no bounding sphere of transparent geometry (expected a frame rendered "
                     "from its scene)");
  return DepthWarp::between(std::min(frame.sphere_near, frame.nearest()),
                            std::max(frame.sphere_far, frame.farthest()), kind);
}

double absorbance(double alpha) {
  return alpha >= 1 ? std::numeric_limits<double>::infinity() : -std::log1p(-alpha);
}

void exact_transmittance(const PixelFragments& px, std::span<double> transmittance) {
  for (size_t l = 0; l < px.size(); ++l) {
    double t = 1;
    for (size_t k = 0; k < px.size(); ++k)
      if (px.depth[k] < px.depth[l]) t *= 1 - px.alpha[k];
    transmittance[l] = t;
  }
}

void submission_transmittance(const PixelFragments& px, std::span<double> transmittance) {
  double t = 1;
  for (size_t l = px.size(); l-- > 0;) {
    transmittance[l] = t;
    t *= 1 - px.alpha[l];
  }
}

double total_transmittance(const PixelFragments& px) {
  double t = 1;
  for (double a : px.alpha) t *= 1 - a;
  return t;
}

Rgb composite(const PixelFragments& px, std::span<const double> transmittance, double total) {
  double c[3] = {total * px.behind[0], total * px.behind[1], total * px.behind[2]};
  for (size_t l = 0; l < px.size(); ++l)
    for (int k = 0; k < 3; ++k) c[k] += px.color[l][k] * px.alpha[l] * transmittance[l];
  return {float(c[0]), float(c[1]), float(c[2])};
}

}  // namespace mb
