// Summed-area tables and the soft techniques (shadow/summed_area.h, techniques/soft/,
// docs/soft-shadows.md §2).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "raster/render_view.h"
#include "scene/scene.h"
#include "shadow/summed_area.h"
#include "soft_test_scenes.h"
#include "techniques/soft/soft_technique.h"
#include "test_support.h"

namespace mb {
namespace {

struct Map {
  int width = 37, height = 29, channels = 2;
  std::vector<double> values;
  Map() {
    std::mt19937_64 rng(44);
    std::uniform_real_distribution<double> u(0, 1);
    values.resize(size_t(width) * height * channels);
    for (double& v : values) v = u(rng);
  }
  double at(int x, int y, int c, const std::vector<double>& outside) const {
    if (x < 0 || y < 0 || x >= width || y >= height) return outside[c];
    return values[(size_t(y) * width + x) * channels + c];
  }
};

// Exact: a box query is the direct sum of the same texels' integers (2^53 times each value,
// rounded), bit for bit, also where the box leaves the map for the outside value.
TEST(SummedAreaTable, ExactBoxEqualsTheDirectSumBitForBit) {
  const Map m;
  const std::vector<double> outside{1.0, 0.25};
  const SummedAreaTable sat(m.values, m.width, m.height, 2, outside, 8, 30 * 30,
                            SatPrecision::Exact);
  std::mt19937_64 rng(1);
  for (int q = 0; q < 500; ++q) {
    const int x0 = int(rng() % 30) - 6, y0 = int(rng() % 22) - 6;  // within the pad
    const int x1 = x0 + 1 + int(rng() % 14), y1 = y0 + 1 + int(rng() % 14);
    double mean[2];
    sat.box_mean(x0, y0, x1, y1, mean);
    for (int c = 0; c < 2; ++c) {
      unsigned __int128 sum = 0;
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x)
          sum += static_cast<unsigned __int128>(std::nearbyint(m.at(x, y, c, outside) * 0x1p53));
      const double direct = double(sum) / 0x1p53 / (double(x1 - x0) * (y1 - y0));
      ASSERT_EQ(mean[c], direct) << "box " << x0 << "," << y0 << " - " << x1 << "," << y1;
    }
  }
}

// Fixed32 (seed 004 §3.2): the prefix sums wrap modulo 2^32 many times over the map, yet every box
// of at most N texels comes out within the rounding of its texels, half a unit of 1/scale each.
TEST(SummedAreaTable, FixedPointBoxesOfUpToNTexelsWithinTheirRounding) {
  const Map m;
  const std::vector<double> outside{1.0, 1.0};
  const int64_t n = 12 * 12;
  const SummedAreaTable sat(m.values, m.width, m.height, 2, outside, 8, n, SatPrecision::Fixed32);
  EXPECT_EQ(sat.scale(), std::floor(4294967295.0 / 144));
  std::mt19937_64 rng(2);
  double worst = 0;
  for (int q = 0; q < 500; ++q) {
    const int w = 1 + int(rng() % 12), h = 1 + int(rng() % 12);
    const int x0 = int(rng() % 30) - 4, y0 = int(rng() % 22) - 4;  // within the pad
    double mean[2];
    sat.box_mean(x0, y0, x0 + w, y0 + h, mean);
    for (int c = 0; c < 2; ++c) {
      double direct = 0;
      for (int y = y0; y < y0 + h; ++y)
        for (int x = x0; x < x0 + w; ++x) direct += m.at(x, y, c, outside);
      direct /= w * h;
      worst = std::max(worst, std::abs(mean[c] - direct));
      ASSERT_LE(std::abs(mean[c] - direct), 0.5 / sat.scale() + 1e-15);
    }
  }
  std::printf("fixed32, N = 144: worst |SAT - direct| %.3g (bound %.3g)\n", worst,
              0.5 / sat.scale());
}

// A fractional rectangle is the area-weighted mean of the texels it overlaps.
TEST(SummedAreaTable, FractionalRectangleIsTheAreaWeightedMean) {
  const Map m;
  const std::vector<double> outside{1.0, 0.5};
  const SummedAreaTable sat(m.values, m.width, m.height, 2, outside, 10, 40 * 40,
                            SatPrecision::Exact);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> ux(-5, 28), uy(-5, 21), len(0.05, 17);
  for (int q = 0; q < 300; ++q) {  // within the pad of 10
    const double ax = ux(rng), ay = uy(rng), bx = ax + len(rng), by = ay + len(rng);
    double mean[2];
    sat.rect_mean(ax, ay, bx, by, mean);
    for (int c = 0; c < 2; ++c) {
      double sum = 0;
      for (int y = int(std::floor(ay)); y < int(std::ceil(by)); ++y)
        for (int x = int(std::floor(ax)); x < int(std::ceil(bx)); ++x) {
          const double wx = std::min(bx, x + 1.0) - std::max(ax, double(x));
          const double wy = std::min(by, y + 1.0) - std::max(ay, double(y));
          sum += wx * wy * sat.stored(x, y, c);
        }
      ASSERT_NEAR(mean[c], sum / ((bx - ax) * (by - ay)), 1e-13) << q;
    }
  }
}

struct Slab {
  Scene scene;
  LayerStack stack;
  Fragments fragments;
  ShadowMap map;
  SoftReceivers soft;
  LightFrame frame;
};

// The half-plane of the area light test (shadow_area_light_test.cpp), lit by a 20-degree light.
Slab slab() {
  Scene scene = testing_support::slab_scene(256, 0.02);
  const LightViewDesc view = scene.views.at(0);
  LayerStack stack = render_view(scene, view, 2);
  const GaussianKernel kernel = make_gaussian_kernel(1, 1);
  Fragments fragments = collect_receivers(stack, kernel, BiasParams{}, 2);
  SoftReceivers soft =
      light_receivers(scene, view, stack, fragments, kernel, BiasParams{}, AreaLight{20, 16}, 2);
  ShadowMap map = layer0_shadow_map(stack);
  LightFrame frame(view, scene.mesh.vertices);
  return {std::move(scene), std::move(stack), std::move(fragments),
          std::move(map),   std::move(soft),  frame};
}

// PCSS's premise holds exactly for a blocker parallel to the receiver: every blocker found lies at
// the slab's depth, the penumbra is 2 h tan(theta / 2) wide, and the box filter of a step is the
// linear ramp across it. pcss_exact gives that ramp wherever its search region reaches the edge.
TEST(SoftTechniques, ExactPcssOfAHalfPlaneIsTheLinearRamp) {
  const Slab s = slab();
  SoftParams params;
  params.min_filter = 1;
  const GaussianKernel kernel = make_gaussian_kernel(1, 1);
  const std::vector<double> shadow =
      soft_shadow("pcss_exact", s.map, s.fragments, s.soft, kernel, BiasParams{}, params, 2).shadow;
  const double radius_texels =
      1.01 * std::tan(10 * std::numbers::pi / 180) / s.frame.world_per_texel();
  int checked = 0;
  double worst = 0;
  for (size_t k = 0; k < s.fragments.size(); ++k) {
    const size_t t = s.fragments.texel[k];
    const Eigen::Vector3d world = s.frame.to_world(
        {double(t % s.stack.width) + 0.5, double(t / s.stack.width) + 0.5, s.fragments.zf[k]});
    if (std::abs(world.y()) > 1e-6 || std::abs(world.z()) > 1.5 || world.x() < -3) continue;
    const double d = world.x() / s.frame.world_per_texel();  // texels outside the edge
    if (std::abs(d) > params.pcss_search / 2 - 1) continue;  // the search must reach the slab
    const double ramp = std::clamp(0.5 - d / (2 * radius_texels), 0.0, 1.0);
    worst = std::max(worst, std::abs(shadow[k] - ramp));
    ++checked;
  }
  std::printf("pcss_exact on a half-plane: %d receivers, worst |G - ramp| %.4f\n", checked, worst);
  EXPECT_GT(checked, 1000);
  EXPECT_LT(worst, 0.05);  // half a texel of the rasterised edge over a 5.6-texel ramp's half
}

// Every receiver is answered on its own: 1 and 3 threads give the same bits.
// The slab lit from 60 degrees: ground and slab slope in light space, so a filter that tested
// them against one depth would need a bias that grows with its width.
struct TiltedSlab {
  LayerStack stack;
  Fragments fragments;
  ShadowMap map;
  SoftReceivers soft;
};
TiltedSlab tilted_slab(const AreaLight& light, const GaussianKernel& kernel,
                       double elevation = 60) {
  const Scene scene = testing_support::slab_scene(256, 0.02, elevation);
  const LightViewDesc view = scene.views.at(0);
  TiltedSlab s{render_view(scene, view, 2)};
  s.fragments = collect_receivers(s.stack, kernel, BiasParams{}, 2);
  s.soft = light_receivers(scene, view, s.stack, s.fragments, kernel, BiasParams{}, light, 2);
  s.map = layer0_shadow_map(s.stack);
  return s;
}

TiltedSlab tilted_slab_flat(const AreaLight& light, const GaussianKernel& kernel) {
  return tilted_slab(light, kernel, 90);
}

// A light of next to no extent leaves pcss_exact nothing but the protocol's kernel at the
// protocol's bias: the hard reference, to the rounding of a sum in another order, on sloped
// receivers too (docs/soft-shadows.md §2).
TEST(SoftTechniques, ExactPcssOfAPointLikeLightIsTheProtocolsPcf) {
  const GaussianKernel kernel = make_gaussian_kernel(9, 2.4);
  const TiltedSlab s = tilted_slab(AreaLight{1e-9, 1}, kernel);
  const std::vector<double> shadow =
      soft_shadow("pcss_exact", s.map, s.fragments, s.soft, kernel, BiasParams{}, SoftParams{}, 2)
          .shadow;
  double worst = 0;
  int penumbra = 0;
  for (size_t k = 0; k < shadow.size(); ++k) {
    worst = std::max(worst, std::abs(shadow[k] - s.soft.hard[k]));
    penumbra += s.soft.hard[k] > 0.01 && s.soft.hard[k] < 0.99;
  }
  std::printf(
      "pcss_exact at 1e-9 degrees: %zu receivers, %d in the kernel's penumbra, worst "
      "|G - pcf| %.3g\n",
      shadow.size(), penumbra, worst);
  EXPECT_GT(penumbra, 200);
  EXPECT_LT(worst, 1e-12);
}

// Where PCSS's premise holds (one blocker depth), PCSS must be nearer the area light than the hard
// shadow is, also on sloped receivers and under the protocol's 9x9 kernel; the sampled PCSS too.
TEST(SoftTechniques, PcssOfAHalfPlaneIsNearerTheAreaLightThanTheHardShadow) {
  const GaussianKernel kernel = make_gaussian_kernel(9, 2.4);
  const TiltedSlab s = tilted_slab(AreaLight{20, 64}, kernel);
  double hard = 0;
  for (size_t k = 0; k < s.fragments.size(); ++k)
    hard += std::abs(s.soft.hard[k] - s.fragments.pcf[k]);
  hard /= double(s.fragments.size());
  for (const std::string name : {"pcss_exact", "pcss"}) {
    const std::vector<double> shadow =
        soft_shadow(name, s.map, s.fragments, s.soft, kernel, BiasParams{}, SoftParams{}, 2).shadow;
    double error = 0;
    for (size_t k = 0; k < shadow.size(); ++k) error += std::abs(shadow[k] - s.fragments.pcf[k]);
    error /= double(shadow.size());
    std::printf("%s on a tilted half-plane at 20 degrees: mean error %.5f, hard shadow %.5f\n",
                name.c_str(), error, hard);
    EXPECT_LT(error, 0.5 * hard) << name;
  }
}

// Seed 001's CSM shadow for one occluder depth z at receiver depth d: 1 - saturate(2 f), f the
// step's Fourier series to M terms, term k attenuated by exp(-alpha (k / M)^2).
double csm_shadow(double z, double d, const TechniqueParams& p) {
  const int terms = p.integer("soft.csm_terms");
  double f = 0.5;
  for (int k = 1; k <= terms; ++k) {
    const double ck = (2 * k - 1) * std::numbers::pi;
    f += 2 * std::exp(-p.number("soft.csm_absorption") * k * k / double(terms * terms)) *
         std::sin(ck * (z - d)) / ck;
  }
  return 1 - std::clamp(2 * f, 0.0, 1.0);
}

// Every technique's two plain cases on the half-plane: ground deep under the slab is in its
// umbra, ground far from it is lit (the filterable variants' tables, exact and fixed point).
TEST(SoftTechniques, UmbraUnderTheSlabAndLightFarFromIt) {
  const Slab s = slab();
  const GaussianKernel kernel = make_gaussian_kernel(9, 2.4);
  std::vector<std::string> names = soft_technique_names();
  names.push_back("msm_soft:lp:power4");
  for (const std::string& name : names)
    for (const std::string sat : {"fixed32", "exact"}) {
      SoftParams params;
      params.sat = sat;
      const std::vector<double> shadow =
          soft_shadow(name, s.map, s.fragments, s.soft, kernel, BiasParams{}, params, 2).shadow;
      int umbra = 0, lit = 0;
      for (size_t k = 0; k < shadow.size(); ++k) {
        const size_t t = s.fragments.texel[k];
        const Eigen::Vector3d world = s.frame.to_world(
            {double(t % s.stack.width) + 0.5, double(t / s.stack.width) + 0.5, s.fragments.zf[k]});
        if (std::abs(world.y()) > 1e-6 || std::abs(world.z()) > 1.5) continue;  // ground only
        if (world.x() < -1.5 && world.x() > -3) {
          // CSM's series is periodic in z - d with period 2: the slab lies 0.96 in front of the
          // ground, near the series' jump at -1, where it reads seed 001's truncated series (with
          // its attenuation), computed here term by term, not the step.
          const double expected =
              name == "pcss_csm"
                  ? csm_shadow(s.map.at(int(t % s.stack.width), int(t / s.stack.width)),
                               s.fragments.zf[k] - BiasParams{}.constant, TechniqueParams{})
                  : 1.0;
          EXPECT_GT(shadow[k], expected - 0.1) << name << " " << sat << " at x " << world.x();
          if (name == "pcss_csm") {
            EXPECT_NEAR(shadow[k], expected, 1e-4) << sat;
          }
          ++umbra;
        } else if (world.x() > 1.5 && world.x() < 3) {
          EXPECT_LT(shadow[k], 0.02) << name << " " << sat << " at x " << world.x();
          ++lit;
        }
      }
      EXPECT_GT(umbra, 500) << name;
      EXPECT_GT(lit, 500) << name;
    }
}

// msm_soft:lp:power4 keeps msm_soft's blocker search and box and solves Problem 1 on the box's
// moments over the grid and the box's own depths, a subset of the distributions on the reals
// Hamburger's bound ranges over: never below msm_soft's last step at a vanishing alpha, on exact
// tables. Where a box holds two depths (the flat slab and the ground) four power moments admit one
// distribution, and the two agree.
TEST(SoftTechniques, LpFinalStepIsAtLeastHamburgersBoundAndEqualOnTwoDepths) {
  SoftParams params;
  params.sat = "exact";
  TechniqueParams technique;
  technique.set("soft.msm_alpha", 1e-9);
  const GaussianKernel kernel = make_gaussian_kernel(9, 2.4);
  for (const bool tilted : {false, true}) {
    const TiltedSlab s = tilted ? tilted_slab(AreaLight{20, 16}, kernel)
                                : tilted_slab_flat(AreaLight{20, 16}, kernel);
    const SoftResult hamburger = soft_shadow("msm_soft", s.map, s.fragments, s.soft, kernel,
                                             BiasParams{}, params, 2, technique);
    const SoftResult lp = soft_shadow("msm_soft:lp:power4", s.map, s.fragments, s.soft, kernel,
                                      BiasParams{}, params, 2, technique);
    ASSERT_EQ(lp.failures, 0u);
    double below = 0, apart = 0;
    int penumbra = 0;
    for (size_t k = 0; k < lp.shadow.size(); ++k) {
      below = std::max(below, hamburger.shadow[k] - lp.shadow[k]);
      apart = std::max(apart, std::abs(hamburger.shadow[k] - lp.shadow[k]));
      penumbra += lp.shadow[k] > 0.01 && lp.shadow[k] < 0.99;
    }
    std::printf("%s: %zu receivers, %d in penumbrae; Hamburger above the LP by %.3g, apart %.3g\n",
                tilted ? "tilted" : "flat", lp.shadow.size(), penumbra, below, apart);
    EXPECT_GT(penumbra, 200);
    // Within the LP's certified 1e-9 and alpha's pull.
    EXPECT_LT(below, 1e-8);
    if (tilted)
      EXPECT_GT(apart, 1e-3);  // on a sloped receiver the box's interval is worth it
    else
      EXPECT_LT(apart, 1e-7);
  }
}

// The LP's answer is a lower bound for the box's own distribution, which it ranges over: with the
// box fixed at 9 texels (min_filter = max_filter = 9, so the box is x - 4 .. x + 4 whatever the
// blocker search finds) and no umbra skip, msm_soft:lp:power4 never exceeds the box filter at its
// test depth z_f - (c + s 4.5 (|dz/dx| + |dz/dy|)), computed here texel by texel; on sloped
// receivers, whose boxes hold many depths, it lies below it where the moments leave room.
TEST(SoftTechniques, LpFinalStepNeverExceedsTheBoxFilterItBounds) {
  const GaussianKernel kernel = make_gaussian_kernel(9, 2.4);
  const TiltedSlab s = tilted_slab(AreaLight{8, 16}, kernel);
  SoftParams params;
  params.sat = "exact";
  params.min_filter = 9;
  params.max_filter = 9;
  TechniqueParams technique;
  technique.set("soft.umbra_epsilon", 0);
  const BiasParams bias;
  const SoftResult lp = soft_shadow("msm_soft:lp:power4", s.map, s.fragments, s.soft, kernel, bias,
                                    params, 2, technique);
  ASSERT_EQ(lp.failures, 0u);
  double worst = -1;
  int below = 0;
  for (size_t k = 0; k < lp.shadow.size(); ++k) {
    const int x = int(s.fragments.texel[k] % s.map.width),
              y = int(s.fragments.texel[k] / s.map.width);
    const double z =
        s.fragments.zf[k] -
        (bias.constant + bias.slope * 4.5 * (std::abs(s.soft.gx[k]) + std::abs(s.soft.gy[k])));
    int in_front = 0;
    for (int j = y - 4; j <= y + 4; ++j)
      for (int i = x - 4; i <= x + 4; ++i) in_front += s.map.at(i, j) < z;
    const double box = in_front / 81.0;
    worst = std::max(worst, lp.shadow[k] - box);
    below += lp.shadow[k] < box - 1e-3;
  }
  std::printf(
      "msm_soft:lp:power4 on a 9-texel box: %zu receivers, largest excess over the box "
      "filter %.3g, %d more than 1e-3 below it\n",
      lp.shadow.size(), worst, below);
  EXPECT_LE(worst, 1e-9);
  EXPECT_GT(below, 100);
}

TEST(SoftTechniques, BitIdenticalForAnyThreadCount) {
  const Slab s = slab();
  const GaussianKernel kernel = make_gaussian_kernel(9, 2.4);
  std::vector<std::string> names = soft_technique_names();
  names.push_back("msm_soft:lp:trig4");
  for (const std::string& name : names)
    for (const std::string sat : {"fixed32", "exact"}) {
      SoftParams params;
      params.sat = sat;
      const SoftResult one =
          soft_shadow(name, s.map, s.fragments, s.soft, kernel, BiasParams{}, params, 1);
      const SoftResult three =
          soft_shadow(name, s.map, s.fragments, s.soft, kernel, BiasParams{}, params, 3);
      EXPECT_EQ(one.failures, 0u) << name << " " << sat;
      ASSERT_EQ(one.shadow, three.shadow) << name << " " << sat;
    }
}

// The audit's bounds range over every distribution with the region's moments, the region's own
// among them: its mean blocker depth lies inside on every audited receiver. Where the region holds
// two depths (the slab and the ground) its power moments admit no other distribution, and the
// interval closes on the slab's depth.
TEST(SoftTechniques, BlockerAuditBoundsHoldTheRegionsOwnMean) {
  const Slab s = slab();
  SoftParams params;
  params.audit = 400;
  const auto rows = blocker_audit(s.map, s.fragments, s.soft, make_gaussian_kernel(9, 2.4),
                                  BiasParams{}, params, TechniqueParams{}, 2);
  int two_depths = 0, outside = 0;
  for (const BlockerAuditRow& row : rows) {
    EXPECT_LE(row.lo, row.exact + 1e-7) << row.receiver;
    EXPECT_GE(row.hi, row.exact - 1e-7) << row.receiver;
    EXPECT_LE(row.penumbra_lo, row.penumbra_hi);
    outside += row.outside();
    const size_t t = s.fragments.texel[row.receiver];
    const int x = int(t % s.map.width), y = int(t / s.map.width), half = params.sat_search / 2;
    std::vector<double> depths;
    for (int j = y - half; j <= y + half; ++j)
      for (int i = x - half; i <= x + half; ++i) depths.push_back(s.map.at(i, j));
    // Surfaces: depths more than 1e-9 apart (one plane's texels differ in their last bits).
    std::sort(depths.begin(), depths.end());
    int surfaces = 1;
    for (size_t i = 1; i < depths.size(); ++i) surfaces += depths[i] - depths[i - 1] > 1e-9;
    if (surfaces != 2) continue;
    EXPECT_NEAR(row.hi - row.lo, 0, 1e-6) << row.receiver;
    ++two_depths;
  }
  std::printf(
      "blocker audit on the slab: %zu receivers with blockers, %d of two depths, "
      "msm_soft's estimate outside the bounds on %d\n",
      rows.size(), two_depths, outside);
  EXPECT_GT(rows.size(), 20u);
  EXPECT_GT(two_depths, 10);
}

// A light without extent has no penumbra to estimate: a named error, not hard shadows.
TEST(SoftTechniques, RefuseAHardLight) {
  const Slab s = slab();
  SoftReceivers hard = s.soft;
  hard.angle_deg = 0;
  const std::string message = testing_support::input_error_of([&] {
    soft_shadow("pcss", s.map, s.fragments, hard, make_gaussian_kernel(9, 2.4), BiasParams{},
                SoftParams{}, 1);
  });
  EXPECT_NE(message.find("light.angle > 0"), std::string::npos) << message;
}

}  // namespace
}  // namespace mb
