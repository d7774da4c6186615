// The LP's maximum G+ (docs/reference.md §2, "The maximum"): G <= F_Z <= G+ for the kernel's own
// distribution, both backends agreeing, the reflection identity with the minimum, Hamburger's
// upper bound G + w_1 equal to the LP's maximum on R, and lp.beta's blend.
#include <gtest/gtest.h>

#include <algorithm>

#include "lp/kkt_checker.h"
#include "lp/problem.h"
#include "lp/solution.h"
#include "moments/hamburger.h"
#include "scene/procedural.h"
#include "techniques/technique.h"
#include "test_support.h"

namespace mb::lp {
namespace {

struct Instance {
  std::vector<double> depths, weights;
  double zf = 0;
};

// 1..6 atoms on [0.02, 0.98]; z_f half the time on an atom (where G+ and F_Z differ by its mass).
std::vector<Instance> instances(int count, uint64_t seed) {
  SeededRandom rng(seed);
  std::vector<Instance> out(count);
  for (int i = 0; i < count; ++i) {
    Instance& inst = out[i];
    const int atoms = 1 + i % 6;
    double total = 0;
    for (int a = 0; a < atoms; ++a) {
      inst.depths.push_back(rng.uniform(0.02, 0.98));
      inst.weights.push_back(rng.uniform(0.05, 1));
      total += inst.weights.back();
    }
    for (double& w : inst.weights) w /= total;
    inst.zf = i % 2 ? inst.depths[i % atoms] : rng.uniform(0.01, 0.99);
  }
  return out;
}

// Z(z < zf) and Z(z <= zf).
std::pair<double, double> cdfs(const Instance& inst) {
  double front = 0, at_or_front = 0;
  for (size_t a = 0; a < inst.depths.size(); ++a) {
    front += inst.depths[a] < inst.zf ? inst.weights[a] : 0;
    at_or_front += inst.depths[a] <= inst.zf ? inst.weights[a] : 0;
  }
  return {front, at_or_front};
}

Solution maximum(Backend& backend, Problem p) {
  p.behind = true;
  return backend.solve(p);
}

TEST(LpMaximum, BracketsTheCdfAndBothBackendsAgree) {
  auto fast = make_backend("fast"), glpk = make_backend("glpk");
  const std::vector<std::vector<std::string>> bases = {
      {"power4"}, {"trig4"}, {"z", "exp(3*z)", "sin(5*z)"}};
  for (const auto& names : bases) {
    const std::string functions = names.front() + (names.size() > 1 ? "..." : "");
    const Basis basis = Basis::parse(names);
    const ProblemFactory factory(basis, Discretization{0, 1, 129, false});
    int compared = 0;
    for (const Instance& inst : instances(300, 42)) {
      const Problem p = factory.from_distribution(inst.depths, inst.weights, inst.zf);
      const Solution lower = fast->solve(p), upper = maximum(*fast, p);
      ASSERT_EQ(lower.status, ProblemStatus::Optimal);
      ASSERT_EQ(upper.status, ProblemStatus::Optimal) << functions;
      Problem behind = p;
      behind.behind = true;
      EXPECT_TRUE(check_kkt(behind, upper).ok) << check_kkt(behind, upper).describe();
      const auto [front, at_or_front] = cdfs(inst);
      const double g_plus = 1 - upper.G;
      EXPECT_LE(lower.G, front + 1e-9) << functions;
      EXPECT_GE(g_plus, at_or_front - 1e-9) << functions << " zf " << inst.zf;
      const Solution reference = maximum(*glpk, p);
      if (reference.status != ProblemStatus::Optimal) continue;
      EXPECT_NEAR(upper.G, reference.G, 1e-7) << functions << " zf " << inst.zf;
      ++compared;
    }
    EXPECT_GT(compared, 250) << functions;
  }
}

TEST(LpMaximum, DeterminateDistributionsGiveTheCdfAtOrInFront) {
  // One atom is determined by two moments, two atoms by four power moments (seed 000, Prop. 4):
  // the maximum is then Z(z <= z_f) itself.
  auto fast = make_backend("fast");
  const Discretization disc{0, 1, 101, false};
  const std::vector<double> two = {0.2, 0.7}, two_weights = {0.4, 0.6};
  for (double zf : {0.1, 0.2, 0.45, 0.7, 0.8}) {
    const Problem p =
        make_problem_from_distribution(Basis::parse({"power4"}), disc, two, two_weights, zf);
    const double expected = (zf >= 0.2 ? 0.4 : 0) + (zf >= 0.7 ? 0.6 : 0);
    EXPECT_NEAR(1 - maximum(*fast, p).G, expected, 1e-9) << "zf " << zf;
    const Problem one = make_problem_from_distribution(
        Basis::parse({"z", "z^2"}), disc, std::vector<double>{0.3}, std::vector<double>{1.0}, zf);
    EXPECT_NEAR(1 - maximum(*fast, one).G, zf >= 0.3 ? 1.0 : 0.0, 1e-9) << "zf " << zf;
  }
}

TEST(LpMaximum, EqualsOneMinusTheMinimumOfTheReflectedDistribution) {
  // Z' = 1 - Z has the power moments of a linear map of Z's, the span of 1, z..z^4 is closed
  // under z -> 1 - z, and a symmetric grid maps onto itself: the most mass at or in front of z_f
  // is one less the least mass of Z' strictly in front of 1 - z_f, by the minimum's own path.
  auto fast = make_backend("fast");
  const ProblemFactory factory(Basis::parse({"power4"}), Discretization{0, 1, 257, false});
  for (const Instance& inst : instances(200, 7)) {
    Instance mirrored = inst;
    for (double& z : mirrored.depths) z = 1 - z;
    mirrored.zf = 1 - inst.zf;
    const Solution upper =
        maximum(*fast, factory.from_distribution(inst.depths, inst.weights, inst.zf));
    const Solution lower =
        fast->solve(factory.from_distribution(mirrored.depths, mirrored.weights, mirrored.zf));
    ASSERT_EQ(upper.status, ProblemStatus::Optimal);
    ASSERT_EQ(lower.status, ProblemStatus::Optimal);
    EXPECT_NEAR(1 - upper.G, 1 - lower.G, 1e-7) << "zf " << inst.zf;
  }
}

TEST(LpMaximum, HamburgerUpperBoundIsTheMaximumOnR) {
  // G + w_1 is the supremum over R; with the canonical nodes among the LP's points the LP's
  // maximum on a wide grid reaches it and cannot exceed it.
  auto fast = make_backend("fast"), glpk = make_backend("glpk");
  const ProblemFactory factory(Basis::parse({"power4"}), Discretization{-4, 5, 2049, false});
  int compared = 0;
  for (const Instance& inst : instances(300, 11)) {
    if (inst.depths.size() < 3) continue;  // fewer atoms: Hankel singular, no canonical form
    double b[4] = {};
    for (size_t a = 0; a < inst.depths.size(); ++a)
      for (int j = 0; j < 4; ++j) b[j] += inst.weights[a] * std::pow(inst.depths[a], j + 1);
    const MsmBound<double> r = hamburger4(b, inst.zf);
    Problem p = factory.from_distribution(inst.depths, inst.weights, inst.zf);
    std::vector<double> nodes;
    for (int n = 0; n < r.node_count; ++n)
      if (r.weights[n] > 0 && std::abs(r.nodes[n]) < 40) nodes.push_back(r.nodes[n]);
    if (nodes.size() < size_t(r.node_count)) continue;
    factory.add_points(p, nodes);
    Solution s = maximum(*fast, p);
    if (s.status != ProblemStatus::Optimal) s = maximum(*glpk, p);
    ASSERT_EQ(s.status, ProblemStatus::Optimal);
    EXPECT_NEAR(r.lower + r.at_zf, 1 - s.G, 1e-6) << "zf " << inst.zf;
    ++compared;
  }
  EXPECT_GT(compared, 150);
}

TEST(LpMaximum, BetaBlendsTheLpTechniqueBetweenItsBounds) {
  TechniqueParams params;
  params.lp = Discretization{0, 1, 129, false};
  const auto lower = make_technique("lp:power4", params);
  params.lp_beta = 1;
  const auto upper = make_technique("lp:power4", params);
  params.lp_beta = 0.25;
  const auto blend = make_technique("lp:power4", params);
  EXPECT_EQ(lower->darkening_bound(), 1e-9);
  EXPECT_TRUE(std::isinf(blend->darkening_bound()));
  int strictly_between = 0;
  for (const Instance& inst : instances(120, 3)) {
    FragmentInput in;
    in.zf = inst.zf;
    in.kernel_depths = inst.depths;
    in.kernel_weights = inst.weights;
    const double g = lower->shadow(in), g_plus = upper->shadow(in), b = blend->shadow(in);
    const auto [front, at_or_front] = cdfs(inst);
    EXPECT_LE(g, front + 1e-9);
    EXPECT_GE(g_plus, at_or_front - 1e-9);
    EXPECT_NEAR(b, g + 0.25 * (g_plus - g), 1e-9);
    strictly_between += g_plus - g > 1e-3;
  }
  EXPECT_EQ(lower->failures() + upper->failures() + blend->failures(), 0u);
  EXPECT_GT(strictly_between, 30);  // the moments leave room: the blend is not the bound itself
}

}  // namespace
}  // namespace mb::lp
