// Sharp bounds on the mean blocker depth (soft/blocker_bounds.h, docs/soft-shadows.md §3).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "lp/blocker_bounds.h"

namespace mb {
namespace {

lp::ProblemFactory factory_of(const Basis& basis) {
  lp::Discretization d;
  d.grid = 256;
  return lp::ProblemFactory(basis, d);
}

std::vector<double> grid_with(const std::vector<double>& depths) {
  std::vector<double> points;
  for (int i = 0; i < 256; ++i) points.push_back(i / 255.0);
  points.insert(points.end(), depths.begin(), depths.end());
  return points;
}

std::vector<double> moments_of(const Basis& basis, const std::vector<double>& z,
                               const std::vector<double>& w) {
  std::vector<double> b(basis.size(), 0.0);
  for (size_t i = 0; i < z.size(); ++i)
    for (size_t k = 0; k < basis.size(); ++k) b[k] += w[i] * basis[k](z[i]);
  return b;
}

// A search region of 25 texels on two to four surfaces (each jittered by 0.01), random weights
// summing to 1, and a search depth z_s.
struct Region {
  std::vector<double> z, w;
  double zs = 0;
};
Region random_region(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.05, 0.95), jitter(-0.01, 0.01), weight(0.2, 1);
  Region r;
  const int surfaces = 2 + int(rng() % 3);
  std::vector<double> centres;
  for (int s = 0; s < surfaces; ++s) centres.push_back(u(rng));
  double total = 0;
  for (int i = 0; i < 25; ++i) {
    r.z.push_back(std::clamp(centres[i % surfaces] + jitter(rng), 0.0, 1.0));
    r.w.push_back(weight(rng));
    total += r.w.back();
  }
  for (double& v : r.w) v /= total;
  r.zs = u(rng);
  return r;
}

// The region's own blockers are one of the distributions the bounds range over: their mean depth
// lies inside, for power and trigonometric moments, on regions of two to four surfaces.
TEST(BlockerBounds, TheRegionsOwnMeanLiesInside) {
  std::mt19937_64 rng(44);
  int checked = 0;
  for (const char* name : {"power4", "trig4"}) {
    const Basis basis = Basis::parse({name});
    const lp::ProblemFactory factory = factory_of(basis);
    for (int n = 0; n < 60; ++n) {
      const Region region = random_region(rng);
      const std::vector<double>&z = region.z, &w = region.w;
      const double zs = region.zs;
      double mass = 0, sum = 0;
      for (size_t i = 0; i < z.size(); ++i)
        if (z[i] < zs) mass += w[i], sum += w[i] * z[i];
      if (mass == 0) continue;
      const BlockerBounds b = blocker_bounds(factory, grid_with(z), moments_of(basis, z, w), zs);
      ASSERT_TRUE(b.feasible) << name << " " << n;
      EXPECT_LE(b.lo, sum / mass + 1e-7) << name << " " << n;
      EXPECT_GE(b.hi, sum / mass - 1e-7) << name << " " << n;
      EXPECT_LE(b.hi, zs);
      ++checked;
    }
  }
  EXPECT_GT(checked, 80);
}

// Two atoms have moments on the boundary of power4's moment cone, which only they represent: the
// interval closes on the blocker atom's depth.
TEST(BlockerBounds, TwoAtomsCloseTheInterval) {
  const Basis basis = Basis::parse({"power4"});
  const lp::ProblemFactory factory = factory_of(basis);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.05, 0.95), weight(0.1, 0.9);
  double widest = 0;
  for (int n = 0; n < 50; ++n) {
    double a = u(rng), c = u(rng);
    if (std::abs(a - c) < 0.05) continue;
    if (a > c) std::swap(a, c);
    const double wa = weight(rng), zs = (a + c) / 2;
    const BlockerBounds b =
        blocker_bounds(factory, grid_with({a, c}), moments_of(basis, {a, c}, {wa, 1 - wa}), zs);
    ASSERT_TRUE(b.feasible) << n << " a " << a << " c " << c << " wa " << wa;
    EXPECT_NEAR(b.lo, a, 1e-6) << n;
    EXPECT_NEAR(b.hi, a, 1e-6) << n;
    widest = std::max(widest, b.hi - b.lo);
  }
  std::printf("two atoms: widest interval %.3g\n", widest);
}

// Without mass in front of z_s no distribution has blockers.
TEST(BlockerBounds, NoBlockersNoBounds) {
  const Basis basis = Basis::parse({"power4"});
  const BlockerBounds b =
      blocker_bounds(factory_of(basis), grid_with({0.6}), moments_of(basis, {0.6}, {1.0}), 0.3);
  EXPECT_FALSE(b.feasible);
}

// Two independent solutions of the same linear-fractional program: Charnes and Cooper's LP by
// GLPK, and Dinkelbach's steps on our engine, on the same points (the grid, the region's depths
// and z_s), for power and trigonometric moments.
TEST(BlockerBounds, DinkelbachOnOurEngineAgreesWithCharnesCooper) {
  std::mt19937_64 rng(45);
  const auto backend = lp::make_backend("fast");
  int checked = 0, steps = 0;
  double worst = 0;
  for (const char* name : {"power4", "trig4"}) {
    const Basis basis = Basis::parse({name});
    const lp::ProblemFactory factory = factory_of(basis);
    for (int n = 0; n < 60; ++n) {
      const Region region = random_region(rng);
      const std::vector<double>&z = region.z, &w = region.w;
      const double zs = region.zs;
      std::vector<double> points = grid_with(z);
      points.push_back(zs);
      const BlockerBounds glpk = blocker_bounds(factory, points, moments_of(basis, z, w), zs);
      const BlockerBounds ours = blocker_bounds_dinkelbach(factory, z, w, zs, *backend);
      ASSERT_TRUE(glpk.solved && ours.solved) << name << " " << n;
      ASSERT_EQ(glpk.feasible, ours.feasible) << name << " " << n;
      if (!ours.feasible) continue;
      EXPECT_LE(ours.lo, ours.hi);
      EXPECT_NEAR(ours.lo, glpk.lo, 1e-7) << name << " " << n << " zs " << zs;
      EXPECT_NEAR(ours.hi, glpk.hi, 1e-7) << name << " " << n << " zs " << zs;
      worst = std::max({worst, std::abs(ours.lo - glpk.lo), std::abs(ours.hi - glpk.hi)});
      steps += ours.lps;
      ++checked;
    }
  }
  EXPECT_GT(checked, 80);
  std::printf("Dinkelbach vs Charnes-Cooper: %d regions, worst difference %.3g, %.2f LPs each\n",
              checked, worst, double(steps) / checked);
}

// A region with no blocker of its own whose moments another distribution also has, with mass in
// front of z_s: the first distribution comes from the LP of most blocker mass.
TEST(BlockerBounds, DinkelbachFindsBlockersTheRegionLacks) {
  const Basis basis = Basis::parse({"power4"});
  const lp::ProblemFactory factory = factory_of(basis);
  const auto backend = lp::make_backend("fast");
  const std::vector<double> z = {0.5, 0.6, 0.7}, w = {0.3, 0.4, 0.3};
  const double zs = 0.49;
  std::vector<double> points = grid_with(z);
  points.push_back(zs);
  const BlockerBounds glpk = blocker_bounds(factory, points, moments_of(basis, z, w), zs);
  const BlockerBounds ours = blocker_bounds_dinkelbach(factory, z, w, zs, *backend);
  ASSERT_TRUE(glpk.feasible);
  ASSERT_TRUE(ours.feasible);
  EXPECT_LT(ours.hi, zs);
  EXPECT_NEAR(ours.lo, glpk.lo, 1e-7);
  EXPECT_NEAR(ours.hi, glpk.hi, 1e-7);
  const BlockerBounds single = blocker_bounds_dinkelbach(factory, {{0.6}}, {{1.0}}, 0.3, *backend);
  EXPECT_TRUE(single.solved);
  EXPECT_FALSE(single.feasible);
}

// Our engine's interval closes on two atoms as the LP's does.
TEST(BlockerBounds, DinkelbachClosesOnTwoAtoms) {
  const Basis basis = Basis::parse({"power4"});
  const lp::ProblemFactory factory = factory_of(basis);
  const auto backend = lp::make_backend("fast");
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> u(0.05, 0.95), weight(0.1, 0.9);
  for (int n = 0; n < 50; ++n) {
    double a = u(rng), c = u(rng);
    if (std::abs(a - c) < 0.05) continue;
    if (a > c) std::swap(a, c);
    const double wa = weight(rng), zs = (a + c) / 2;
    const BlockerBounds b =
        blocker_bounds_dinkelbach(factory, {{a, c}}, {{wa, 1 - wa}}, zs, *backend);
    ASSERT_TRUE(b.feasible) << n;
    EXPECT_NEAR(b.lo, a, 1e-6) << n;
    EXPECT_NEAR(b.hi, a, 1e-6) << n;
  }
}

}  // namespace
}  // namespace mb
