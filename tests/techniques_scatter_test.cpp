// The single-scattering rows (docs/scattering.md §2-3): the exact reference against an analytic
// answer, and ray marching converging to it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "raster/render_view.h"
#include "scene/procedural.h"
#include "techniques/registry.h"
#include "techniques/scatter/scatter_technique.h"
#include "util/error.h"

namespace mb {
namespace {

constexpr int kRes = 64;
// The window's texel lines (raster x in [kA, kB], y in [kC, kD]).
constexpr double kA = 21, kB = 37, kC = 17, kD = 45;

// A wall facing the light (raster depth 0) with a rectangular window whose edges lie on texel
// lines, over a floor (depth 1), both filling the map (margin 0): built in the raster space of a
// frame fitted to a cube, whose lateral square the floor spans exactly, so that the scene's own
// frame is that frame again.
struct WindowScene {
  LightViewDesc view;
  Scene scene;
  std::unique_ptr<LightFrame> frame;
  LayerStack stack;
  double wall_depth = 0, floor_depth = 0;

  WindowScene() {
    view.azimuth_deg = 30, view.elevation_deg = 55, view.resolution = kRes, view.margin = 0;
    std::vector<Eigen::Vector3d> cube;
    for (int i = 0; i < 8; ++i) cube.emplace_back(i & 1 ? 5 : -5, i & 2 ? 5 : -5, i & 4 ? 5 : -5);
    const LightFrame fit(view, cube);
    const auto at = [&](double x, double y, double z) { return fit.to_world({x, y, z}); };
    // A quad of raster rectangle [x0, x1] x [y0, y1] at raster depth z.
    const auto rect = [&](TriangleMesh& m, double x0, double x1, double y0, double y1, double z) {
      m.add_quad(at(x0, y0, z), at(x1, y0, z), at(x1, y1, z), at(x0, y1, z));
    };
    TriangleMesh& m = scene.mesh;
    rect(m, 0, kRes, 0, kRes, 0.9);  // floor
    rect(m, 0, kA, 0, kRes, 0.1);    // the wall around the window
    rect(m, kB, kRes, 0, kRes, 0.1);
    rect(m, kA, kB, 0, kC, 0.1);
    rect(m, kA, kB, kD, kRes, 0.1);
    scene.name = "window";
    scene.two_sided.assign(m.triangles.size(), 1);
    scene.part.assign(m.triangles.size(), 0);
    scene.opacity.resize(1), scene.color.push_back(Eigen::Vector3d::Constant(0.8));
    frame = std::make_unique<LightFrame>(view, m.vertices);
    stack = render_view(scene, view, 1);
    wall_depth = frame->to_raster(at(kA, kC, 0.1)).z();
    floor_depth = frame->to_raster(at(0, 0, 0.9)).z();
  }
};

// The parameter interval where the ray's raster point lies in the box [lo, hi] (per axis), or an
// empty one (first > second).
std::pair<double, double> box_interval(const Eigen::Vector3d& r0, const Eigen::Vector3d& dr,
                                       const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  double a = -1e300, b = 1e300;
  for (int k = 0; k < 3; ++k) {
    if (dr[k] == 0) {
      if (r0[k] < lo[k] || r0[k] > hi[k]) return {1, 0};
      continue;
    }
    double t0 = (lo[k] - r0[k]) / dr[k], t1 = (hi[k] - r0[k]) / dr[k];
    if (t0 > t1) std::swap(t0, t1);
    a = std::max(a, t0), b = std::min(b, t1);
  }
  return {a, b};
}

// The analytic answer: the shadowed set is a union of boxes in raster space (the four wall pieces
// beyond the wall's depth, the floor's square beyond its depth); the lit set is the rest of
// [0, s], integrated in closed form.
double analytic_lit_length(const WindowScene& w, const Eigen::Vector3d& p, const Eigen::Vector3d& d,
                           double s, double sigma) {
  const Eigen::Vector3d r0 = w.frame->to_raster(p), dr = w.frame->to_raster(p + d) - r0;
  const double big = 1e300, zw = w.wall_depth, zf = w.floor_depth;
  const Eigen::Vector3d boxes[5][2] = {{{0, 0, zw}, {kA, kRes, big}},
                                       {{kB, 0, zw}, {kRes, kRes, big}},
                                       {{kA, 0, zw}, {kB, kC, big}},
                                       {{kA, kD, zw}, {kB, kRes, big}},
                                       {{0, 0, zf}, {kRes, kRes, big}}};
  std::vector<std::pair<double, double>> shadow;
  for (const auto& box : boxes) {
    auto [a, b] = box_interval(r0, dr, box[0], box[1]);
    a = std::max(a, 0.0), b = std::min(b, s);
    if (a < b) shadow.push_back({a, b});
  }
  std::sort(shadow.begin(), shadow.end());
  double lit = 0, t = 0;
  for (const auto& [a, b] : shadow) {
    if (a > t) lit += transmittance_integral(t, a, sigma);
    t = std::max(t, b);
  }
  if (s > t) lit += transmittance_integral(t, s, sigma);
  return lit;
}

struct RandomRay {
  Eigen::Vector3d origin, direction;
  double length;
};

std::vector<RandomRay> random_rays(const LightFrame& frame, int count, uint64_t seed) {
  SeededRandom random(seed);
  std::vector<RandomRay> rays;
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector3d o =
        frame.to_world({random.uniform(-16, kRes + 16), random.uniform(-16, kRes + 16),
                        random.uniform(-0.4, 1.4)});
    Eigen::Vector3d d;
    do d = {random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1)};
    while (d.norm() > 1 || d.norm() < 0.1);
    rays.push_back({o, d.normalized(), random.uniform(0.1, 25)});
  }
  return rays;
}

TEST(TechniquesScatter, ExactMatchesTheAnalyticWindowTo1e9) {
  const WindowScene w;
  ASSERT_EQ(w.stack.width, kRes);
  ASSERT_NEAR(w.wall_depth, 0, 1e-12);
  ASSERT_NEAR(w.floor_depth, 1, 1e-12);
  const LightDepthMap map(*w.frame, w.stack);
  // The texel lines are where the scene put them: the window's texels hold the floor.
  EXPECT_NEAR(map.at(kA + 0.5, kC + 0.5), 1, 1e-12);
  EXPECT_NEAR(map.at(kA - 0.5, kC + 0.5), 0, 1e-12);
  const auto exact = make_scatter_technique("exact", {});
  double worst = 0, shadowed = 0;
  for (double sigma : {0.02, 0.3, 2.0}) {
    for (const RandomRay& ray : random_rays(*w.frame, 4000, 7)) {
      ScatterSetup setup{&map, nullptr, nullptr, nullptr, ray.origin, sigma};
      exact->prepare(setup);
      const double got = exact->lit_length({ray.direction, ray.length, 0});
      const double want = analytic_lit_length(w, ray.origin, ray.direction, ray.length, sigma);
      worst = std::max(worst, std::abs(got - want));
      shadowed += transmittance_integral(0, ray.length, sigma) - want;
    }
  }
  std::printf("window test: worst |exact - analytic| = %.3g\n", worst);
  EXPECT_GT(shadowed, 100);  // the rays do cross shadow
  EXPECT_LT(worst, 1e-9);
}

// Ray marching's error against the exact answer, averaged over rays, falls as N grows (the
// jittered estimate's mean error like 1/N, docs/scattering.md §3).
TEST(TechniquesScatter, RayMarchingConvergesToTheExactAnswer) {
  const WindowScene w;
  const LightDepthMap map(*w.frame, w.stack);
  const auto exact = make_scatter_technique("exact", {});
  const std::vector<RandomRay> rays = random_rays(*w.frame, 2000, 11);
  double previous = 1e300;
  ScatterParams seeded;
  seeded.technique.set("scatter.seed", 3);
  for (int n : {8, 64, 512, 4096}) {
    const auto march = make_scatter_technique("raymarch:" + std::to_string(n), seeded);
    double error = 0;
    for (size_t i = 0; i < rays.size(); ++i) {
      const ScatterSetup setup{&map, nullptr, nullptr, nullptr, rays[i].origin, 0.3};
      exact->prepare(setup), march->prepare(setup);
      const ScatterRay ray{rays[i].direction, rays[i].length, i};
      error += std::abs(march->lit_length(ray) - exact->lit_length(ray));
    }
    error /= double(rays.size());
    EXPECT_LT(error, previous * 0.5) << "N = " << n;
    previous = error;
  }
  EXPECT_LT(previous, 1e-3);
}

TEST(TechniquesScatter, RowsAndBadNames) {
  EXPECT_EQ(technique_row("exact", TechniqueFamily::Scattering).role, RowRole::Reference);
  EXPECT_EQ(technique_row("raymarch:32", TechniqueFamily::Scattering).display_name(),
            "raymarch:<N>");
  EXPECT_THROW(make_scatter_technique("raymarch:0", {}), InputError);
  EXPECT_THROW(make_scatter_technique("raymarch:x", {}), InputError);
  EXPECT_THROW(make_scatter_technique("raymarch:", {}), InputError);
  EXPECT_THROW(make_scatter_technique("pcf", {}), InputError);
}

}  // namespace
}  // namespace mb
