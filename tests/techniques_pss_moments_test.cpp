// The prefiltered moment rows (docs/scattering.md §3.2) on the scattering_tiny house: pss_msm4 at
// alpha 0 lies between the LP's bounds on the same prefix sums over an interval holding
// Hamburger's nodes, and pss_csm's truncation error falls as its terms grow.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "eval/evaluation.h"
#include "moments/hamburger.h"
#include "raster/render_view.h"
#include "techniques/lp_fragment_solver.h"
#include "techniques/registry.h"
#include "techniques/scatter/rectified_map.h"

namespace mb {
namespace {

constexpr int kRes = 128;
constexpr double kGuard = 4;

struct House {
  Scene scene;
  MediumDesc medium;
  LightViewDesc view;
  std::unique_ptr<LightFrame> frame;
  LayerStack stack;
  std::unique_ptr<LightDepthMap> light;
  House() {
    const DatasetDesc dataset = load_dataset("scattering_tiny");
    scene = build_dataset_scenes(dataset).at(0);
    medium = *dataset.medium;
    view = scene.views.at(0);
    view.resolution = kRes;
    stack = render_view(scene, view, 1);
    frame = std::make_unique<LightFrame>(view, scene.mesh.vertices);
    light = std::make_unique<LightDepthMap>(*frame, stack);
  }
  ScatterSetup setup() const {
    const CameraDesc& camera = scene.cameras.at(0);
    return {light.get(), &scene, &view, &camera, camera.position, medium.extinction, light.get()};
  }
};

ScatterParams params(double beta) {
  ScatterParams p;
  p.light_resolution = kRes, p.guard_band = kGuard, p.beta = beta;
  return p;
}

// The shadowed fraction a row answers for a ray: one minus its lit share.
double shadowed(const ScatterTechnique& t, const Eigen::Vector3d& w, double length, double sigma) {
  return 1 - t.lit_length({w, length, 0}) / transmittance_integral(0, length, sigma);
}

// Hamburger's canonical distribution through the ray's depth attains Problem 1's bounds on all of
// R; once its nodes join the LP's admissible set (the ray's own texels and a grid on [-4, 5]), the
// LP's lower and upper bounds are Hamburger's, and pss_msm4's blend lies between them.
TEST(TechniquesPssMoments, Msm4AtAlphaZeroLiesBetweenTheLpBoundsOnItsNodes) {
  const House house;
  const ScatterSetup setup = house.setup();
  ScatterParams p = params(0.5);
  p.technique.set("pss_msm4.alpha", 0);
  const auto msm = make_scatter_technique("pss_msm4", p);
  msm->prepare(setup);
  const RectifiedMap map(*house.light, *setup.camera_desc, setup.extinction, {kRes, kGuard});
  const RowPrefixSums sums(map, 4, [](double z, double* out) {
    for (int j = 0; j < 4; ++j) out[j] = std::pow(z, j + 1);
  });
  const Basis basis = Basis::parse({"power4"});
  lp::Discretization disc;
  disc.lo = -4, disc.hi = 5, disc.grid = 256;
  const lp::ProblemFactory factory(basis, disc);
  TechniqueParams lower, upper;
  upper.lp_beta = 1;
  LpFragmentSolver lower_lp(basis, factory, lower), upper_lp(basis, factory, upper);
  const CameraFrame camera(*setup.camera_desc);
  std::vector<double> depths, weights;
  int checked = 0, open = 0;
  for (int y = 0; y < camera.height(); y += 3)
    for (int x = 0; x < camera.width(); x += 3)
      for (const double length : {3.0, 9.0, 30.0}) {
        const Eigen::Vector3d w = camera.ray(x, y);
        const RectifiedRay ray = map.locate(w, length);
        ray_distribution(map, ray, depths, weights);
        double total = 0;
        for (double v : weights) total += v;
        for (double& v : weights) v /= total;
        double b[4];
        sums.mean(ray, b);
        const MsmBound<double> r = hamburger4(b, ray.depth);
        std::vector<double> nodes(r.nodes + 1, r.nodes + r.node_count);
        if (!std::isfinite(r.lower) || !std::isfinite(r.at_zf)) continue;
        bool inside = true;
        for (double z : nodes) inside = inside && std::isfinite(z) && z > disc.lo && z < disc.hi;
        if (!inside) continue;
        lp::Problem problem = factory.from_distribution(depths, weights, ray.depth);
        factory.add_points(problem, nodes);
        const lp::Solution& lo = lower_lp.solve(problem, depths, weights, ray.depth);
        ASSERT_EQ(lo.status, lp::ProblemStatus::Optimal);
        const double g_lo = lo.G;
        const lp::Solution& hi = upper_lp.solve(problem, depths, weights, ray.depth);
        ASSERT_EQ(hi.status, lp::ProblemStatus::Optimal);
        const double g_hi = hi.G;
        const double f = shadowed(*msm, w, length, setup.extinction);
        EXPECT_GE(f, g_lo - 1e-6) << x << " " << y << " " << length;
        EXPECT_LE(f, g_hi + 1e-6) << x << " " << y << " " << length;
        EXPECT_NEAR(std::clamp(r.lower + 0.5 * r.at_zf, 0.0, 1.0), f, 1e-9);
        ++checked;
        open += g_hi - g_lo > 1e-3;
      }
  std::printf("pss_msm4 against the LP's bounds: %d rays, %d with bounds 1e-3 apart\n", checked,
              open);
  EXPECT_GT(checked, 300);
  EXPECT_GT(open, 30);
}

// The Fourier series of the shadow test converges in the mean: more terms, less error against the
// row's own visibility (pss_exact), without damping.
TEST(TechniquesPssMoments, CsmApproachesPssExactAsItsTermsGrow) {
  const House house;
  const ScatterSetup setup = house.setup();
  const auto exact = make_scatter_technique("pss_exact", params(0.5));
  exact->prepare(setup);
  const CameraFrame camera(*setup.camera_desc);
  double previous = 1;
  for (const int terms : {2, 8, 32}) {
    ScatterParams p = params(0.5);
    p.technique.set("scatter.csm_terms", terms);
    p.technique.set("scatter.csm_damping", 0);
    const auto csm = make_scatter_technique("pss_csm", p);
    csm->prepare(setup);
    double error = 0;
    int rays = 0;
    for (int y = 0; y < camera.height(); ++y)
      for (int x = 0; x < camera.width(); ++x, ++rays) {
        const Eigen::Vector3d w = camera.ray(x, y);
        error += std::abs(shadowed(*csm, w, 12, setup.extinction) -
                          shadowed(*exact, w, 12, setup.extinction));
      }
    error /= rays;
    std::printf("pss_csm with %d terms: mean |F - F_pss_exact| = %.4g\n", terms, error);
    EXPECT_LT(error, previous) << terms;
    previous = error;
  }
}

}  // namespace
}  // namespace mb
