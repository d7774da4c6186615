// The rectified map of the prefiltered rows (docs/scattering.md §3.1): a plane facing the light
// gives each light ray's inclination in closed form, view rays land on their row at their depth,
// the camera's rays fill each row's range but the guard band, and the prefix sums equal direct
// sums.
#include <gtest/gtest.h>

#include <cmath>

#include "raster/render_view.h"
#include "techniques/scatter/rectified_map.h"

namespace mb {
namespace {

constexpr int kLightRes = 96, kMapRes = 64;
constexpr double kGuard = 3, kSigma = 0.3;

// A plane facing the light (constant light depth) over the whole light map, a floor hidden behind
// it (so that the map has a depth range), and a camera upstream of the plane looking at it
// obliquely, so that no view ray runs along the light's axis.
struct FacingPlane {
  LightViewDesc view;
  Scene scene;
  std::unique_ptr<LightFrame> frame;
  LayerStack stack;
  CameraDesc camera;
  Eigen::Vector3d plane_point;

  FacingPlane() {
    view.azimuth_deg = 30, view.elevation_deg = 55, view.resolution = kLightRes, view.margin = 0;
    std::vector<Eigen::Vector3d> cube;
    for (int i = 0; i < 8; ++i) cube.emplace_back(i & 1 ? 5 : -5, i & 2 ? 5 : -5, i & 4 ? 5 : -5);
    const LightFrame fit(view, cube);
    const auto at = [&](double x, double y, double z) { return fit.to_world({x, y, z}); };
    const auto quad = [&](double z) {
      scene.mesh.add_quad(at(0, 0, z), at(kLightRes, 0, z), at(kLightRes, kLightRes, z),
                          at(0, kLightRes, z));
    };
    quad(0.1), quad(0.9);
    scene.name = "plane";
    scene.two_sided.assign(scene.mesh.triangles.size(), 1);
    scene.part.assign(scene.mesh.triangles.size(), 0);
    scene.opacity.resize(1), scene.color.push_back(Eigen::Vector3d::Constant(0.8));
    frame = std::make_unique<LightFrame>(view, scene.mesh.vertices);
    stack = render_view(scene, view, 1);
    plane_point = at(kLightRes / 2.0, kLightRes / 2.0, 0.1);
    const Eigen::Vector3d to_light = frame->to_light();
    const Eigen::Vector3d side = to_light.cross(Eigen::Vector3d::UnitY()).normalized();
    camera.position = plane_point + 3 * to_light + 4 * side;
    camera.target = plane_point - 2 * side;
    camera.fov_deg = 40, camera.width = 40, camera.height = 30;
  }
};

TEST(TechniquesRectifiedMap, APlaneFacingTheLightGivesItsInclination) {
  const FacingPlane s;
  const LightDepthMap light(*s.frame, s.stack);
  const RectifiedMap map(light, s.camera, kSigma, {kMapRes, kGuard});
  ASSERT_EQ(map.width(), kMapRes);
  const Eigen::Vector3d p = s.camera.position;
  // Every light ray meets the plane at the same distance along the axis from the camera's plane.
  const double lambda = (s.plane_point - p).dot(map.axis(2));
  ASSERT_GT(lambda, 0);
  int surfaces = 0, unclamped = 0;
  for (int v = 0; v < map.height(); ++v)
    for (int u = 0; u < map.width(); ++u) {
      const double r = map.radius(u), phi = map.azimuth(v);
      const Eigen::Vector3d q =
          s.frame->to_raster(p + r * (std::cos(phi) * map.axis(0) + std::sin(phi) * map.axis(1)));
      const bool inside = q.x() >= 0 && q.y() >= 0 && q.x() < kLightRes && q.y() < kLightRes;
      const double theta = std::atan2(r, lambda);
      const double want = inside ? std::clamp(map.normalise(v, theta), 0.0, 1.0) : 1.0;
      EXPECT_NEAR(map.depth(u, v), want, 1e-9) << u << " " << v;
      surfaces += inside;
      unclamped += inside && want > 0 && want < 1;
    }
  EXPECT_GT(surfaces, kMapRes * kMapRes / 4);
  EXPECT_GT(unclamped, kMapRes);  // the plane's inclinations reach into the rows' ranges
}

TEST(TechniquesRectifiedMap, ViewRaysLandOnTheirRowAtTheirDepthInsideTheGuardBand) {
  const FacingPlane s;
  const LightDepthMap light(*s.frame, s.stack);
  const RectifiedMap map(light, s.camera, kSigma, {kMapRes, kGuard});
  const Eigen::Vector3d p = s.camera.position;
  const double lambda = (s.plane_point - p).dot(map.axis(2));
  // A point on texel (u, v)'s light ray: its view ray reads row v up to x = u + 1/2; beyond the
  // plane it is shadowed (deeper than the texel), in front of it lit.
  int ordered = 0;
  for (int v = 0; v < map.height(); v += 7)
    for (int u = 0; u < map.width(); u += 5)
      for (const double step : {-0.5, 0.5}) {
        const double phi = map.azimuth(v), r = map.radius(u);
        const Eigen::Vector3d x = p +
                                  r * (std::cos(phi) * map.axis(0) + std::sin(phi) * map.axis(1)) +
                                  (lambda + step) * map.axis(2);
        const RectifiedRay ray = map.locate((x - p).normalized(), (x - p).norm());
        EXPECT_EQ(ray.row, v);
        EXPECT_NEAR(ray.x, u + 0.5, 1e-9);
        const double depth = map.normalise(v, std::atan2(r, lambda + step));
        EXPECT_NEAR(ray.depth, std::clamp(depth, 0.0, 1.0), 1e-12);
        const double texel = map.depth(u, v);
        if (depth > 0 && depth < 1 && texel > 0 && texel < 1) {
          EXPECT_EQ(ray.depth > texel, step > 0) << u << " " << v;
          ++ordered;
        }
      }
  EXPECT_GT(ordered, 10);
  // The camera's own rays lie in [g / n, 1 - g / n]; some reach either end (a row's extremes).
  const CameraFrame frame(s.camera);
  const double lo = kGuard / kMapRes, hi = 1 - kGuard / kMapRes;
  double least = 1, most = 0;
  for (int y = 0; y < frame.height(); ++y)
    for (int x = 0; x < frame.width(); ++x) {
      const double depth = map.locate(frame.ray(x, y), 1).depth;
      EXPECT_GE(depth, lo - 1e-12);
      EXPECT_LE(depth, hi + 1e-12);
      least = std::min(least, depth), most = std::max(most, depth);
    }
  EXPECT_NEAR(least, lo, 1e-9);
  EXPECT_NEAR(most, hi, 1e-9);
}

TEST(TechniquesRectifiedMap, PrefixSumsEqualDirectSums) {
  const FacingPlane s;
  const LightDepthMap light(*s.frame, s.stack);
  const RectifiedMap map(light, s.camera, kSigma, {kMapRes, kGuard});
  const auto power = [](double z, double* out) {
    for (int j = 0; j < 4; ++j) out[j] = std::pow(z, j + 1);
  };
  const RowPrefixSums sums(map, 4, power);
  for (int v = 0; v < map.height(); v += 9) {
    const double delta = map.delta(v);
    long double weight = 0, moment[4] = {};
    for (int k = 1; k <= map.width(); ++k) {
      const double d = map.depth(k - 1, v);
      const long double w = (std::exp(-(long double)kSigma * (k - 1) * delta) -
                             std::exp(-(long double)kSigma * k * delta)) /
                            kSigma;
      weight += w;
      for (int j = 0; j < 4; ++j) moment[j] += w * std::pow((long double)d, j + 1);
      // Σ w_{i,v} is the integral of exp(-sigma t) over the first k texels.
      EXPECT_NEAR(map.prefix_weight(v, k), (1 - std::exp(-kSigma * k * delta)) / kSigma,
                  1e-12 / kSigma);
      for (int j = 0; j < 4; ++j)
        EXPECT_NEAR(sums.at(v, k)[size_t(j)], double(moment[j] / weight), 1e-13) << v << " " << k;
    }
    // A ray ending inside a texel, and one beyond the map, against its own weighted atoms.
    std::vector<double> depths, weights;
    for (const double x : {0.25, 17.6, map.width() + 30.5}) {
      const RectifiedRay ray{v, x, 0.5};
      ray_distribution(map, ray, depths, weights);
      long double total = 0, direct[4] = {};
      for (size_t i = 0; i < depths.size(); ++i) {
        total += weights[i];
        for (int j = 0; j < 4; ++j)
          direct[j] += weights[i] * std::pow((long double)depths[i], j + 1);
      }
      EXPECT_NEAR(double(total), map.weight_sum(v, x), 1e-13 / kSigma);
      double mean[4];
      sums.mean(ray, mean);
      for (int j = 0; j < 4; ++j) EXPECT_NEAR(mean[j], double(direct[j] / total), 1e-13);
    }
  }
}

}  // namespace
}  // namespace mb
