// The area light's shadow (soft/area_light.h, docs/soft-shadows.md §1): the hard reference at
// angle 0 bit for bit, the analytic penumbra of a half-plane, convergence in N.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "raster/render_view.h"
#include "scene/dataset.h"
#include "scene/scene.h"
#include "shadow/area_light.h"
#include "soft_test_scenes.h"
#include "test_support.h"

namespace mb {
namespace {

struct Lit {
  LayerStack stack;
  Fragments fragments;
};

Lit lit(const Scene& scene, const LightViewDesc& view, const GaussianKernel& kernel,
        const BiasParams& bias) {
  Lit out{render_view(scene, view, 2), {}};
  out.fragments = collect_receivers(out.stack, kernel, bias, 2);
  return out;
}

// The area light's shadow of a view's own receivers, their planes read from its stack.
AreaLightShadow area_light_shadow(const Scene& scene, const LightViewDesc& view, const Lit& l,
                                  const GaussianKernel& kernel, const BiasParams& bias,
                                  const AreaLight& light) {
  std::vector<double> gx, gy;
  for (size_t k = 0; k < l.fragments.size(); ++k) {
    const uint64_t i = l.stack.offsets[l.fragments.texel[k]] + l.fragments.layer[k];
    gx.push_back(l.stack.dz_dx[i]);
    gy.push_back(l.stack.dz_dy[i]);
  }
  return area_light_shadow(scene, view, l.fragments, gx, gy, kernel, bias, light, 2);
}

Scene blocks() {
  const DatasetDesc tiny = load_dataset("tiny");
  return build_scene(parse_scene(tiny.scene_files.at(0)));
}

// With no extent the light has one direction, the view itself: the same test at the same texel,
// depth and gradient as the hard reference, for both references of the protocol.
TEST(AreaLight, AngleZeroIsTheHardReferenceBitForBit) {
  const Scene scene = blocks();
  const GaussianKernel kernel = make_gaussian_kernel(9, 2.4);
  for (Reference reference : {Reference::Biased, Reference::ReceiverPlane}) {
    BiasParams bias;
    bias.reference = reference;
    for (const LightViewDesc& view : scene.views) {
      LightViewDesc v = view;
      v.resolution = 96;
      const Lit l = lit(scene, v, kernel, bias);
      const AreaLightShadow area = area_light_shadow(scene, v, l, kernel, bias, {0, 16});
      ASSERT_EQ(area.shadow.size(), l.fragments.size());
      for (size_t k = 0; k < l.fragments.size(); ++k) {
        ASSERT_EQ(area.shadow[k], l.fragments.pcf[k]) << view.name << " receiver " << k;
        ASSERT_EQ(area.covered_taps[k], l.fragments.covered_taps[k]);
      }
    }
  }
}

// The fraction of a disk of radius 1 beyond a chord at signed distance d from its centre, towards
// the side d points away from: what a half-plane occluder hides of the light from a receiver d
// light radii outside its hard shadow's edge.
double hidden_fraction(double d) {
  if (d >= 1) return 0;
  if (d <= -1) return 1;
  if (d < 0) return 1 - hidden_fraction(-d);
  return (std::acos(d) - d * std::sqrt(1 - d * d)) / std::numbers::pi;
}

// A thin square slab 1.01 above a plane, the light straight down with an angular diameter of 20
// degrees: across the slab's edge the plane's shadow follows the disk-segment profile over a
// penumbra of 2 h tan(10 deg), here 22 texels (one tap, so the kernel does not blur it).
TEST(AreaLight, HalfPlanePenumbraFollowsTheDiskSegment) {
  const Scene scene = testing_support::slab_scene(512, 0);
  const GaussianKernel kernel = make_gaussian_kernel(1, 1);
  const BiasParams bias;
  const LightViewDesc& view = scene.views.at(0);
  const Lit l = lit(scene, view, kernel, bias);
  const AreaLight light{20, 64};
  const AreaLightShadow area = area_light_shadow(scene, view, l, kernel, bias, light);
  const LightFrame frame(view, scene.mesh.vertices);
  const double radius_world = 1.01 * std::tan(10 * std::numbers::pi / 180);
  const double radius_texels = radius_world / frame.world_per_texel();
  EXPECT_NEAR(
      rim_shear(frame, 20) * (frame.to_raster({0, 0, 0}).z() - frame.to_raster({0, 1.01, 0}).z()),
      radius_texels, 1e-9);
  double sum_sq = 0, worst = 0, penumbra_lo = 1e9, penumbra_hi = -1e9;
  int count = 0;
  for (size_t k = 0; k < l.fragments.size(); ++k) {
    const size_t t = l.fragments.texel[k];
    const Eigen::Vector3d world = frame.to_world(
        {double(t % l.stack.width) + 0.5, double(t / l.stack.width) + 0.5, l.fragments.zf[k]});
    // The plane, away from the slab's other edges (at z = +-2 and x = -4).
    if (std::abs(world.y()) > 1e-6 || std::abs(world.z()) > 1.5 || world.x() < -3) continue;
    const double expected = hidden_fraction(world.x() / radius_world);
    const double got = area.shadow[k];
    sum_sq += (got - expected) * (got - expected);
    worst = std::max(worst, std::abs(got - expected));
    ++count;
    if (got > 0 && got < 1)
      penumbra_lo = std::min(penumbra_lo, world.x()),
      penumbra_hi = std::max(penumbra_hi, world.x());
  }
  const double rms = std::sqrt(sum_sq / count);
  std::printf(
      "half-plane: %d receivers, rms %.4f, worst %.4f, penumbra [%.4f, %.4f] world, "
      "expected +-%.4f\n",
      count, rms, worst, penumbra_lo, penumbra_hi, radius_world);
  EXPECT_GT(count, 10000);
  EXPECT_LT(rms, 0.01);
  EXPECT_LT(worst, 0.06);  // a texel's quantisation at the steepest slope, plus N's sampling
  // The penumbra spans the light's directions that reach past the edge: of N directions, the
  // outermost along raster x (world x here), which lie within the rim by N's sampling error.
  const double rim = rim_shear(frame, 20);
  double reach_minus = 0, reach_plus = 0;
  for (const auto& s : light_shears(frame, light))
    reach_minus = std::max(reach_minus, -s.x() / rim),
    reach_plus = std::max(reach_plus, s.x() / rim);
  std::printf("outermost directions at %.4f and %.4f of the rim\n", reach_minus, reach_plus);
  EXPECT_GT(std::min(reach_minus, reach_plus), 0.8);
  const double texel = frame.world_per_texel();
  EXPECT_NEAR(penumbra_lo, -reach_plus * radius_world, 1.6 * texel);
  EXPECT_NEAR(penumbra_hi, reach_minus * radius_world, 1.6 * texel);
}

// The mean |G_N - G_4N| over the receivers falls at least as 1/sqrt(N) (by half per quadrupling,
// with a margin for the few receivers a map resolves).
TEST(AreaLight, ConvergesAtLeastAsOneOverSqrtN) {
  const Scene scene = blocks();
  const GaussianKernel kernel = make_gaussian_kernel(9, 2.4);
  const BiasParams bias;
  LightViewDesc view = scene.views.at(0);
  view.resolution = 128;
  const Lit l = lit(scene, view, kernel, bias);
  std::vector<std::vector<double>> shadows;
  for (int n : {4, 16, 64, 256})
    shadows.push_back(area_light_shadow(scene, view, l, kernel, bias, {8, n}).shadow);
  std::vector<double> error;
  for (size_t i = 0; i + 1 < shadows.size(); ++i) {
    double sum = 0;
    for (size_t k = 0; k < l.fragments.size(); ++k)
      sum += std::abs(shadows[i][k] - shadows[i + 1][k]);
    error.push_back(sum / l.fragments.size());
  }
  std::printf("mean |G_N - G_4N|: N=4 %.3g, N=16 %.3g, N=64 %.3g\n", error[0], error[1], error[2]);
  ASSERT_GT(error[0], 0);
  for (size_t i = 0; i + 1 < error.size(); ++i) EXPECT_LE(error[i + 1], 0.6 * error[i]) << i;
}

}  // namespace
}  // namespace mb
