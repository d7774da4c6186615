#pragma once
// The rectified map of prefiltered single scattering (docs/scattering.md §3.1; seed 004 §2.2-2.3):
// a light view's hard shadow map resampled into coordinates where every view ray of one camera is
// one row at one depth. In light view space with the camera at the origin (z along the light's
// propagation), texel (u, v) stands for the light ray at distance r from the camera and azimuth phi
// around the light's axis; it holds the inclination pi - theta of that light ray's first surface
// as seen from the camera, normalised per row to [0, 1] between the row's bounds of theta (the
// camera's view rays of that row plus a guard band). A view ray keeps theta and phi along its whole
// length and its distance from the axis grows as t sin(theta), so it reads one row, up to the
// texel of its end, at one depth: the transmittance-weighted prefix sums of a row answer every view
// ray of that row at once. scatter.resample chooses how a texel reads the light map: `point`, the
// nearest light texel's depth, or `filtered`, seed 004 §2.3's Algorithm 1 (moment_resample.h):
// a trilinear moment sample over the texel's footprint turned into two depths with weights, each
// warped into an inclination, so that a texel holds a distribution of two depths.
#include <functional>
#include <span>
#include <vector>

#include "moments/storage.h"
#include "scene/camera.h"
#include "techniques/scatter/moment_resample.h"
#include "techniques/scatter/scatter_technique.h"

namespace mb {

struct RectifiedSettings {
  int resolution = 0;     // texels along r (u) and rows along phi (v): scatter.light_resolution
  double guard_band = 0;  // scatter.guard_band: depth texels left free at either end of a row
  Resample resample = Resample::Point;  // scatter.resample
};

// Where a view ray falls in the map: its row, its end along the row in texels (x = r_end / dr, the
// light-ray distance of its end over the texel width; x may exceed the width: beyond the map every
// light ray is empty), and its normalised depth.
struct RectifiedRay {
  int row = 0;
  double x = 0;
  double depth = 0;
};

class RectifiedMap {
 public:
  // `light`: layer 0 of the light view at scatter.light_resolution; `camera`: whose view rays the
  // rows must cover (every pixel's ray sets its row's bounds of theta); sigma_t weighs the texels.
  RectifiedMap(const LightDepthMap& light, const CameraDesc& camera, double extinction,
               const RectifiedSettings& settings);

  int width() const { return width_; }
  int height() const { return height_; }
  bool filtered() const { return !second_.empty(); }
  // The normalised depths of texel (u, v), 1 where the light ray meets no surface (lit all along):
  // one depth (weight 1) under point resampling; under filtered, Algorithm 1's two (the second's
  // weight 0 where the sample held one depth).
  TwoDepths texel(int u, int v) const {
    const size_t i = size_t(v) * width_ + u;
    TwoDepths t;
    t.depth[0] = t.depth[1] = depth_[i];
    if (filtered()) t.depth[1] = second_[i], t.weight[1] = second_weight_[i];
    t.weight[0] = 1 - t.weight[1];
    return t;
  }
  // Texel (u, v)'s mean normalised depth (the image of the map shows it): its one depth under
  // point resampling.
  double depth(int u, int v) const {
    const TwoDepths t = texel(u, v);
    return filtered() ? t.weight[0] * t.depth[0] + t.weight[1] * t.depth[1] : t.depth[0];
  }
  RectifiedRay locate(const Eigen::Vector3d& direction, double length) const;

  // Light view space: e_z the light's propagation (-to_light), e_x and e_y across it.
  const Eigen::Vector3d& axis(int k) const { return axes_[k]; }
  double radius(int u) const { return (u + 0.5) * dr_; }  // r of texel u's centre
  double texel_width() const { return dr_; }              // dr, in scene units
  double azimuth(int v) const { return phi_lo_ + (v + 0.5) * dphi_; }
  // The row's bounds of theta with the guard band, and a theta's normalised depth there
  // (unclamped): (hi - theta) / (hi - lo), so that the depth grows along the light's propagation.
  double theta_lo(int v) const { return rows_[v].lo; }
  double theta_hi(int v) const { return rows_[v].hi; }
  double normalise(int v, double theta) const;
  // Delta(v): the world distance along a view ray between successive texels of row v, at the mean
  // of the row's bounds of theta (seed 004 §2.2's heuristic): dr / sin(theta_mean).
  double delta(int v) const { return rows_[v].delta; }
  // w_{u,v} = ∫ exp(-sigma_t t) dt over [u Delta(v), (u + 1) Delta(v)], the part of the ray in
  // texel u (seed 004 §2.2; its texel u, centred at u Delta, is our texel u - 1/2).
  double texel_weight(int v, int u) const;
  // C(x) = the weight of the first x texels: the prefix sum of whole texels (Σ_{i < k} w_{i,v},
  // accumulated as the seed's prefix sums are) linear in x inside texel k, and beyond the map the
  // closed-form integral, every light ray there being empty.
  double weight_sum(int v, double x) const;
  // Σ_{i < k} w_{i,v}, k = 0..width.
  double prefix_weight(int v, int k) const;
  double extinction() const { return sigma_; }

 private:
  struct Row {
    double lo = 0, hi = 0, delta = 0;
  };
  int width_ = 0, height_ = 0;
  double sigma_ = 0, dr_ = 0, phi_lo_ = 0, dphi_ = 0;
  Eigen::Vector3d axes_[3];
  std::vector<Row> rows_;
  std::vector<double> depth_;   // width x height, row-major (filtered: each texel's nearer depth)
  std::vector<double> second_;  // filtered only: each texel's farther depth and its weight
  std::vector<double> second_weight_;
  std::vector<double> prefix_;  // (width + 1) per row: Σ_{i < k} w_{i,v}
  int row_of(double phi) const;
};

// The transmittance-weighted prefix sums of a row-wise vector field b(depth) (seed 004 §2.2):
// per row v and texel boundary k = 0..width the normalised mean
//   b̄(k, v) = Σ_{i < k} w_{i,v} b(d_{i,v}) / Σ_{i < k} w_{i,v}
// (k = 0: texel 0's own b). A view ray ending at x reads their weighted sums linearly in x between
// boundaries, and beyond the map adds the empty light rays' b(1), each weighted as weight_sum.
class RowPrefixSums {
 public:
  using Function = std::function<void(double depth, double* out)>;
  RowPrefixSums(const RectifiedMap& map, int channels, const Function& b);
  int channels() const { return channels_; }
  // b̄ at boundary k of row v.
  std::span<const double> at(int v, int k) const {
    return {values_.data() + (size_t(v) * (width_ + 1) + k) * channels_, size_t(channels_)};
  }
  // What a stored target holds of every b̄ and of b(1), read back as moments (store_moments then
  // load_moments): the transforms are affine, so interpolating values or moments is the same.
  void round_through(const MomentStorage& storage);
  // The mean of b over the ray's part of row `ray.row` (out has channels() values).
  void mean(const RectifiedRay& ray, double* out) const;

 private:
  std::span<double> at(int v, int k) {  // filled by the constructor
    return {values_.data() + (size_t(v) * (width_ + 1) + k) * channels_, size_t(channels_)};
  }
  const RectifiedMap& map_;
  int width_ = 0, channels_ = 0;
  std::vector<double> values_, lit_;  // lit_: b(1), the empty light ray's vector
};

// The row's own weighted distribution along a view ray (pss_exact, pss_lp): the depths of the
// texels up to the ray's end with their weights (the last texel's in part, then the empty light
// rays beyond the map at depth 1), in row order; their weights sum to weight_sum(row, x). Under
// filtered resampling a texel gives its two depths, each with its share of the texel's weight
// (one where the second's share is 0).
void ray_distribution(const RectifiedMap& map, const RectifiedRay& ray, std::vector<double>& depths,
                      std::vector<double>& weights);

}  // namespace mb
