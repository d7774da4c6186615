// The one LP fragment solver (techniques/lp_fragment_solver.h): its grid, continuous and moment-box
// paths answer the same fragment consistently, lp.beta's maximum fails the fragment it cannot
// answer, and a warm start gives the cold answer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "scene/procedural.h"
#include "techniques/lp_fragment_solver.h"
#include "test_support.h"

namespace mb {
namespace {

struct Fragment {
  std::vector<double> depths, weights;
  double zf = 0;
};

std::vector<Fragment> fragments(int count, uint64_t seed) {
  SeededRandom rng(seed);
  std::vector<Fragment> out(count);
  for (int i = 0; i < count; ++i) {
    const int atoms = 2 + i % 5;
    double total = 0;
    for (int a = 0; a < atoms; ++a) {
      out[i].depths.push_back(rng.uniform(0.05, 0.95));
      out[i].weights.push_back(rng.uniform(0.1, 1));
      total += out[i].weights.back();
    }
    for (double& w : out[i].weights) w /= total;
    out[i].zf = rng.uniform(0.1, 0.9);
  }
  return out;
}

double answer(LpFragmentSolver& solver, const lp::ProblemFactory& factory, const Fragment& f,
              const lp::WarmStart* warm = nullptr) {
  lp::Problem p = factory.from_distribution(f.depths, f.weights, f.zf);
  const lp::Solution& s = solver.solve(p, f.depths, f.weights, f.zf, warm);
  if (s.call != lp::CallStatus::Ok || s.status != lp::ProblemStatus::Optimal)
    return std::numeric_limits<double>::quiet_NaN();  // no answer: the caller counts it
  return std::clamp(s.G, 0.0, 1.0);
}

// The continuous answer ranges over more distributions than the grid's (all of [0, 1]), the
// double moment box over more than the exact moments: neither lies above the grid's answer, and
// both lie within the certified tolerance of it where the grid already holds the extremal points.
TEST(LpFragmentSolver, ContinuousAndBoxNeverAboveTheGrid) {
  const Basis basis = Basis::parse({"power4"});
  TechniqueParams grid;
  grid.lp = lp::Discretization{0, 1, 257, false};
  TechniqueParams continuous = grid, box = grid;
  continuous.lp.continuous = true;
  box.lp_moment_box = "double";
  const lp::ProblemFactory grid_factory(basis, grid.lp), continuous_factory(basis, continuous.lp);
  LpFragmentSolver on_grid(basis, grid_factory, grid),
      on_interval(basis, continuous_factory, continuous), in_box(basis, grid_factory, box);
  EXPECT_FALSE(in_box.reads_problem());
  double largest_gap = 0;
  int answered = 0, below = 0;
  for (const Fragment& f : fragments(60, 11)) {
    const double g = answer(on_grid, grid_factory, f);
    const double c = answer(on_interval, continuous_factory, f);
    const double b = answer(in_box, grid_factory, f);
    ASSERT_FALSE(std::isnan(g));
    ASSERT_FALSE(std::isnan(c));
    // The box's LP (GLPK, no certificate) may give no answer; where it does, it is a minimum over
    // more distributions.
    if (std::isnan(b)) continue;
    ++answered;
    EXPECT_LE(c, g + 1e-9);
    EXPECT_LE(b, g + 1e-9);
    largest_gap = std::max(largest_gap, g - c);
    below += g - c > 1e-7;
  }
  EXPECT_GE(answered, 50);
  EXPECT_GT(below, 0);           // the interval's points beyond the grid do move some answers
  EXPECT_LT(largest_gap, 1e-2);  // a 257-point grid: the interval's answer is close
}

// lp.beta: the blend lies between the minimum and the maximum the same solver finds at beta 0 and
// 1, and warm-starting the minimum from its own previous basis changes no answer.
TEST(LpFragmentSolver, BetaBlendsBetweenTheBoundsAndWarmStartsAgree) {
  const Basis basis = Basis::parse({"trig4"});
  TechniqueParams p;
  p.lp = lp::Discretization{0, 1, 129, false};
  const lp::ProblemFactory factory(basis, p.lp);
  LpFragmentSolver lower(basis, factory, p);
  p.lp_beta = 1;
  LpFragmentSolver upper(basis, factory, p);
  p.lp_beta = 0.5;
  LpFragmentSolver half(basis, factory, p);
  const lp::WarmStart warm{};
  for (const Fragment& f : fragments(40, 5)) {
    const double g = answer(lower, factory, f), g_plus = answer(upper, factory, f);
    ASSERT_FALSE(std::isnan(g) || std::isnan(g_plus));
    EXPECT_LE(g, g_plus + 1e-12);
    EXPECT_NEAR(answer(half, factory, f), g + 0.5 * (g_plus - g), 1e-12);
    EXPECT_NEAR(answer(lower, factory, f, &warm), g, 1e-9);
  }
}

// lp.beta's maximum is solved on the grid only: the continuous interval and the moment box refuse
// a beta above 0 instead of answering the lower bound as if it were the blend.
TEST(LpFragmentSolver, BetaNeedsTheGrid) {
  const Basis basis = Basis::parse({"power4"});
  TechniqueParams p;
  p.lp = lp::Discretization{-1, 2, 129, false};
  p.lp.continuous = true;
  p.lp_beta = 0.5;
  const lp::ProblemFactory continuous(basis, p.lp);
  std::string m = testing_support::input_error_of([&] { LpFragmentSolver{basis, continuous, p}; });
  EXPECT_NE(m.find("lp.beta: 0.5"), std::string::npos) << m;
  EXPECT_NE(m.find("lp.discretization = continuous (here: continuous)"), std::string::npos) << m;
  p.lp.continuous = false;
  p.lp_moment_box = "double";
  const lp::ProblemFactory grid(basis, p.lp);
  m = testing_support::input_error_of([&] { LpFragmentSolver{basis, grid, p}; });
  EXPECT_NE(m.find("lp.moment_box (here: double)"), std::string::npos) << m;
  // At beta 0 both answer the sharp lower bound, as before.
  p.lp_beta = 0;
  EXPECT_EQ(testing_support::input_error_of([&] { LpFragmentSolver{basis, grid, p}; }), "");
  p.lp_moment_box = "none";
  p.lp.continuous = true;
  EXPECT_EQ(testing_support::input_error_of([&] { LpFragmentSolver{basis, continuous, p}; }), "");
}

}  // namespace
}  // namespace mb
