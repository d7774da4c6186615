// Filtered resampling of the rectified map (docs/scattering.md §3.1; seed 004 §2.3): Algorithm 1
// gives back the two depths and weights of a two-depth distribution, the light's moment map
// samples a step edge bilinearly and its mip chain by 2 x 2 means, a constant-depth light map
// gives the same rectified map filtered as point-sampled.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <utility>
#include <vector>

#include "raster/render_view.h"
#include "techniques/scatter/moment_resample.h"
#include "techniques/scatter/rectified_map.h"

namespace mb {
namespace {

void power3(double z2, double z3, double w3, double b[3]) {
  for (int j = 0; j < 3; ++j) b[j] = (1 - w3) * std::pow(z2, j + 1) + w3 * std::pow(z3, j + 1);
}

// The Wasserstein-1 distance of two distributions on the line: the integral of |F - G|.
double transport_distance(std::vector<std::pair<double, double>> p,
                          std::vector<std::pair<double, double>> q) {
  std::vector<double> points;
  for (const auto& [z, w] : p) points.push_back(z);
  for (const auto& [z, w] : q) points.push_back(z);
  std::sort(points.begin(), points.end());
  const auto cdf = [](const std::vector<std::pair<double, double>>& d, double x) {
    double sum = 0;
    for (const auto& [z, w] : d) sum += z <= x ? w : 0;
    return sum;
  };
  double distance = 0;
  for (size_t i = 0; i + 1 < points.size(); ++i)
    distance += std::abs(cdf(p, points[i]) - cdf(q, points[i])) * (points[i + 1] - points[i]);
  return distance;
}

TEST(TechniquesMomentResample, AlgorithmOneGivesBackTwoDepthsAndTheirWeights) {
  std::mt19937_64 rng(59);
  std::uniform_real_distribution<double> unit(0, 1), weight(0.01, 0.99), gap(-3, 0);
  for (int i = 0; i < 20000; ++i) {
    const double z2 = unit(rng);
    const double z3 = i % 4 == 0 ? 1.0 : std::min(z2 + std::pow(10.0, gap(rng)), 1.0);
    const double w3 = weight(rng);
    if (!((1 - w3) * w3 * (z3 - z2) * (z3 - z2) > 1e-6)) continue;
    double b[3];
    power3(z2, z3, w3, b);
    const TwoDepths t = two_depths(b[0], b[1], b[2]);
    ASSERT_NEAR(t.depth[0], z2, 1e-9) << z2 << " " << z3 << " " << w3;
    ASSERT_NEAR(t.depth[1], z3, 1e-9) << z2 << " " << z3 << " " << w3;
    // A weight is as ill-conditioned as the depths are close: its error times their gap, its
    // effect on the moments, is what rounding of the moments leaves.
    ASSERT_LT(std::abs(t.weight[1] - w3) * (z3 - z2), 1e-9) << z2 << " " << z3 << " " << w3;
    ASSERT_NEAR(t.weight[0] + t.weight[1], 1, 1e-15);
  }
  // Three depths: the first three moments are matched, the fourth is not (z_1 went to infinity).
  const double z[3] = {0.2, 0.5, 0.9}, w[3] = {0.3, 0.3, 0.4};
  double b[4] = {};
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 4; ++j) b[j] += w[k] * std::pow(z[k], j + 1);
  const TwoDepths t = two_depths(b[0], b[1], b[2]);
  double fourth = 0;
  for (int j = 0; j < 3; ++j)
    EXPECT_NEAR(
        t.weight[0] * std::pow(t.depth[0], j + 1) + t.weight[1] * std::pow(t.depth[1], j + 1), b[j],
        1e-12);
  for (int k = 0; k < 2; ++k) fourth += t.weight[k] * std::pow(t.depth[k], 4);
  EXPECT_GT(std::abs(fourth - b[3]), 1e-4);
}

TEST(TechniquesMomentResample, OneDepthAndNearlyOneDepthStayInPlace) {
  for (const double z : {0.0, 0.3, 0.999, 1.0}) {
    const TwoDepths t = two_depths(z, z * z, z * z * z);
    EXPECT_EQ(t.depth[0], z);
    EXPECT_EQ(t.depth[1], z);
    EXPECT_EQ(t.weight[0], 1);
    EXPECT_EQ(t.weight[1], 0);
  }
  // Variances about kMinResampleVariance: merged or split, the distribution Algorithm 1 returns
  // lies within a transport (Wasserstein-1) distance of 1e-5 of the depth range of the true one
  // (moment_resample.h).
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> unit(0, 1), weight(0.001, 0.999), spread(-13, -8);
  double worst = 0;
  for (int i = 0; i < 20000; ++i) {
    const double z2 = unit(rng), w3 = weight(rng);
    const double z3 = z2 + std::sqrt(std::pow(10.0, spread(rng)) / ((1 - w3) * w3));
    double b[3];
    power3(z2, z3, w3, b);
    const TwoDepths t = two_depths(b[0], b[1], b[2]);
    worst =
        std::max(worst, transport_distance({{z2, 1 - w3}, {z3, w3}},
                                           {{t.depth[0], t.weight[0]}, {t.depth[1], t.weight[1]}}));
  }
  std::printf("Algorithm 1 near the variance threshold: transport distance up to %.3g\n", worst);
  EXPECT_LT(worst, 1.01e-5);
}

// A light map whose left half holds depth 0.25 and right half 0.75 (a step between texels 3 and
// 4 of 8), with one empty texel.
struct StepMap {
  LightViewDesc view;
  std::unique_ptr<LightFrame> frame;
  std::unique_ptr<LightDepthMap> light;
  StepMap() {
    view.resolution = 8;
    const std::vector<Eigen::Vector3d> box{{-1, -1, -1}, {1, 1, 1}};
    frame = std::make_unique<LightFrame>(view, box);
    LayerStack stack;
    stack.width = stack.height = 8;
    stack.offsets.assign(65, 0);
    light = std::make_unique<LightDepthMap>(*frame, stack);
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x) light->depth[size_t(y * 8 + x)] = x < 4 ? 0.25 : 0.75;
    light->depth[63] = std::numeric_limits<double>::infinity();
  }
};

TEST(TechniquesMomentResample, TheMomentMapSamplesAStepBilinearlyAndItsMipsByMeans) {
  const StepMap s;
  const LightMomentMap map(*s.light);
  ASSERT_EQ(map.levels(), 4);  // 8, 4, 2, 1
  double b[3];
  // Level 0, between texel centres 3.5 and 4.5 at x = 3.8: 70 % of 0.25 and 30 % of 0.75.
  map.sample(3.8, 2.5, 1, b);
  const TwoDepths t = two_depths(b[0], b[1], b[2]);
  EXPECT_NEAR(t.depth[0], 0.25, 1e-12);
  EXPECT_NEAR(t.depth[1], 0.75, 1e-12);
  EXPECT_NEAR(t.weight[1], 0.3, 1e-12);
  // Inside one half the sample holds one depth.
  map.sample(1.7, 1.2, 1, b);
  EXPECT_NEAR(b[0], 0.25, 1e-15);
  EXPECT_NEAR(b[1], 0.0625, 1e-15);
  EXPECT_EQ(two_depths(b[0], b[1], b[2]).weight[1], 0);
  // A footprint of 8 texels reads the top level, the mean of the whole map, blended bilinearly
  // with the empty outside: at its centre the plain mean (one texel empty, depth 1).
  map.sample(4, 4, 8, b);
  EXPECT_NEAR(b[0], (32 * 0.25 + 31 * 0.75 + 1) / 64, 1e-15);
  // At x = 3.5: level 1 (footprint 2) blends its texels 1 (0.25) and 2 (0.75) as 3 : 1, level 2
  // (footprint 4) its texels 0 (0.25) and 1 (0.75) as 5 : 3; a footprint of 2 sqrt 2 lies halfway.
  double one[3], two[3], half[3];
  map.sample(3.5, 2, 2, one);
  map.sample(3.5, 2, 4, two);
  map.sample(3.5, 2, 2 * std::sqrt(2.0), half);
  EXPECT_NEAR(one[0], 0.375, 1e-15);
  EXPECT_NEAR(two[0], 0.4375, 1e-15);
  for (int j = 0; j < 3; ++j) EXPECT_NEAR(half[j], 0.5 * (one[j] + two[j]), 1e-14);
  // Outside the map every texel is empty.
  map.sample(-5, 3, 1, b);
  EXPECT_EQ(b[0], 1);
  EXPECT_EQ(b[2], 1);
}

// A plane facing the light over a light map of one constant depth (everything else of
// techniques_rectified_map_test.cpp's setting): away from the map's edge, where the filter's
// support stays inside, the filtered rectified map is the point-sampled one.
TEST(TechniquesMomentResample, AConstantDepthLightMapGivesThePointSampledMap) {
  LightViewDesc view;
  view.azimuth_deg = 30, view.elevation_deg = 55, view.resolution = 96, view.margin = 0;
  std::vector<Eigen::Vector3d> cube;
  for (int i = 0; i < 8; ++i) cube.emplace_back(i & 1 ? 5 : -5, i & 2 ? 5 : -5, i & 4 ? 5 : -5);
  const LightFrame frame(view, cube);
  LayerStack stack;
  stack.width = stack.height = 96;
  stack.offsets.assign(96 * 96 + 1, 0);
  LightDepthMap light(frame, stack);
  for (double& d : light.depth) d = 0.4;
  const Eigen::Vector3d centre = frame.to_world({48, 48, 0.4});
  const Eigen::Vector3d side = frame.to_light().cross(Eigen::Vector3d::UnitY()).normalized();
  CameraDesc camera;
  camera.position = centre + 3 * frame.to_light() + 4 * side;
  camera.target = centre - 2 * side;
  camera.fov_deg = 40, camera.width = 40, camera.height = 30;
  const RectifiedMap point(light, camera, 0.3, {64, 3, Resample::Point});
  const RectifiedMap filtered(light, camera, 0.3, {64, 3, Resample::Filtered});
  ASSERT_TRUE(filtered.filtered());
  ASSERT_FALSE(point.filtered());
  const double dphi = point.azimuth(1) - point.azimuth(0);
  int compared = 0, unclamped = 0;
  for (int v = 0; v < point.height(); ++v)
    for (int u = 0; u < point.width(); ++u) {
      const double r = point.radius(u), phi = point.azimuth(v);
      const Eigen::Vector3d q = frame.to_raster(
          camera.position + r * (std::cos(phi) * point.axis(0) + std::sin(phi) * point.axis(1)));
      const double footprint = std::max(point.texel_width(), r * dphi) / frame.world_per_texel();
      const double margin = 4 * std::max(footprint, 1.0) + 2;
      if (!(q.x() > margin && q.y() > margin && q.x() < 96 - margin && q.y() < 96 - margin))
        continue;
      const TwoDepths t = filtered.texel(u, v);
      EXPECT_EQ(t.weight[1], 0) << u << " " << v;
      EXPECT_NEAR(t.depth[0], point.depth(u, v), 1e-12) << u << " " << v;
      ++compared;
      unclamped += point.depth(u, v) > 0 && point.depth(u, v) < 1;
    }
  EXPECT_GT(compared, 64 * 64 / 8);
  EXPECT_GT(unclamped, 64);
}

}  // namespace
}  // namespace mb
