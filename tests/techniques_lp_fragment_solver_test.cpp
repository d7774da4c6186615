// The one LP fragment solver (techniques/lp_fragment_solver.h): its grid, continuous and moment-box
// paths answer the same fragment consistently, lp.beta's maximum on the continuous interval (by
// reflection) is Hamburger's upper bound for power moments and bounds every grid's for any basis,
// the moment box refuses lp.beta, and a warm start gives the cold answer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>

#include "moments/hamburger.h"
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

std::string scientific(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
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

// lp.beta's maximum is solved on the grid and (by reflection) on the continuous interval; the
// moment box refuses a beta above 0 instead of answering the lower bound as if it were the blend.
TEST(LpFragmentSolver, BetaRefusesOnlyTheMomentBox) {
  const Basis basis = Basis::parse({"power4"});
  TechniqueParams p;
  p.lp = lp::Discretization{-1, 2, 129, false};
  p.lp_beta = 0.5;
  p.lp_moment_box = "double";
  const lp::ProblemFactory grid(basis, p.lp);
  std::string m = testing_support::input_error_of([&] { LpFragmentSolver{basis, grid, p}; });
  EXPECT_NE(m.find("lp.beta: 0.5"), std::string::npos) << m;
  EXPECT_NE(m.find("with a moment box (here: double, from lp.moment_box"), std::string::npos) << m;
  // At beta 0 the box answers the sharp lower bound, as before; without a box, both
  // discretisations take any beta.
  p.lp_beta = 0;
  EXPECT_EQ(testing_support::input_error_of([&] { LpFragmentSolver{basis, grid, p}; }), "");
  p.lp_beta = 0.5;
  p.lp_moment_box = "none";
  EXPECT_EQ(testing_support::input_error_of([&] { LpFragmentSolver{basis, grid, p}; }), "");
  p.lp.continuous = true;
  const lp::ProblemFactory continuous(basis, p.lp);
  EXPECT_EQ(testing_support::input_error_of([&] { LpFragmentSolver{basis, continuous, p}; }), "");
}

// Kernels of 3 to 7 atoms in (0.05, 0.95): for four power moments their Hankel matrix is regular,
// so Hamburger's canonical distribution through z_f exists.
std::vector<Fragment> regular_fragments(int count, uint64_t seed) {
  std::vector<Fragment> out = fragments(count, seed);
  SeededRandom rng(seed + 1);
  for (Fragment& f : out)
    while (f.depths.size() < 3) {
      f.depths.push_back(rng.uniform(0.05, 0.95));
      f.weights.push_back(f.weights.front() / 2);
      f.weights.front() /= 2;
    }
  return out;
}

// The continuous maximum by reflection (docs/reference.md §2, "The maximum") for power4: on an
// interval holding Hamburger's canonical nodes it is Hamburger's upper bound G + w_1 (the
// supremum over R, attained there); every finite grid of the interval ranges over fewer
// distributions, so its maximum lies below, and a fine grid's close.
TEST(LpFragmentSolver, ContinuousMaximumOfPowerMomentsIsHamburgersUpperBound) {
  const Basis basis = Basis::parse({"power4"});
  TechniqueParams p;
  p.lp = lp::Discretization{-2, 3, 4097, false};
  p.lp_beta = 1;
  const lp::ProblemFactory grid_factory(basis, p.lp);
  LpFragmentSolver on_grid(basis, grid_factory, p);
  p.lp.continuous = true;
  const lp::ProblemFactory continuous_factory(basis, p.lp);
  LpFragmentSolver on_interval(basis, continuous_factory, p);
  int compared = 0;
  double largest = 0, largest_gap = 0, largest_w = 0;
  for (const Fragment& f : regular_fragments(60, 23)) {
    double b[4] = {};
    for (size_t t = 0; t < f.depths.size(); ++t)
      for (int k = 0; k < 4; ++k) b[k] += f.weights[t] * std::pow(f.depths[t], k + 1);
    const MsmBound<double> h = hamburger4(b, f.zf);
    bool inside = h.node_count > 0;
    for (int i = 0; i < h.node_count; ++i) inside &= h.nodes[i] > -2 && h.nodes[i] < 3;
    if (!inside) continue;
    ++compared;
    const double upper = std::min(1.0, h.lower + h.at_zf);
    const double c = answer(on_interval, continuous_factory, f);
    const double g = answer(on_grid, grid_factory, f);
    ASSERT_FALSE(std::isnan(c) || std::isnan(g));
    EXPECT_NEAR(c, upper, 1e-6) << "z_f " << f.zf;
    EXPECT_LE(g, c + 1e-9);
    largest = std::max(largest, std::abs(c - upper));
    largest_gap = std::max(largest_gap, c - g);
    largest_w = std::max(largest_w, h.at_zf);
  }
  EXPECT_GE(compared, 50);
  EXPECT_GT(largest_w, 0.1);     // the maximum lies well above the minimum on some kernels
  EXPECT_LT(largest_gap, 2e-3);  // a grid step of 1.2e-3: the grid's maximum comes close
  RecordProperty("largest_difference_from_hamburger", scientific(largest));
  RecordProperty("largest_gap_to_the_grid", scientific(largest_gap));
}

// A catalog basis that is not the power basis (the reflected basis's own exchange, certified):
// the continuous maximum lies above every grid's (a grid is a subset of the interval) and within
// a small tolerance of a very fine grid's; at beta 0.5 the solver answers the midpoint of its
// beta 0 and beta 1 answers.
TEST(LpFragmentSolver, ContinuousMaximumOfAnyBasisBoundsEveryGridsAndBlends) {
  const std::vector<std::vector<std::string>> sets = {{"trig4"}, {"exp(z)", "exp(-2z)", "exp(4z)"}};
  for (const auto& names : sets) {
    const Basis basis = Basis::parse(names);
    const std::string set = names.front();
    TechniqueParams p;
    p.lp = lp::Discretization{0, 1, 129, false};
    p.lp.continuous = true;
    const lp::ProblemFactory continuous_factory(basis, p.lp);
    LpFragmentSolver lower(basis, continuous_factory, p);
    p.lp_beta = 0.5;
    LpFragmentSolver half(basis, continuous_factory, p);
    p.lp_beta = 1;
    LpFragmentSolver upper(basis, continuous_factory, p);
    p.lp.continuous = false;
    std::vector<std::unique_ptr<lp::ProblemFactory>> grid_factories;
    std::vector<std::unique_ptr<LpFragmentSolver>> grids;
    for (int n : {33, 257, 16385}) {
      p.lp.grid = n;
      grid_factories.push_back(std::make_unique<lp::ProblemFactory>(basis, p.lp));
      grids.push_back(std::make_unique<LpFragmentSolver>(basis, *grid_factories.back(), p));
    }
    double largest_gap = 0, largest_spread = 0;
    for (const Fragment& f : fragments(30, 31)) {
      const double g = answer(lower, continuous_factory, f);
      const double g_plus = answer(upper, continuous_factory, f);
      ASSERT_FALSE(std::isnan(g) || std::isnan(g_plus)) << set;
      EXPECT_NEAR(answer(half, continuous_factory, f), g + 0.5 * (g_plus - g), 1e-12) << set;
      largest_spread = std::max(largest_spread, g_plus - g);
      for (size_t i = 0; i < grids.size(); ++i) {
        const double on_grid = answer(*grids[i], *grid_factories[i], f);
        ASSERT_FALSE(std::isnan(on_grid)) << set;
        EXPECT_LE(on_grid, g_plus + 1e-9) << set << " grid " << grid_factories[i]->grid()->size();
        if (i + 1 == grids.size()) {
          EXPECT_NEAR(on_grid, g_plus, 1e-6) << set << " z_f " << f.zf;
          largest_gap = std::max(largest_gap, g_plus - on_grid);
        }
      }
    }
    EXPECT_GT(largest_spread, 0.1) << set;  // the maximum is not the minimum
    RecordProperty("largest_gap_to_fine_grid " + set, scientific(largest_gap));
  }
}

}  // namespace
}  // namespace mb
