// Problem 1 with moments known to a tolerance (src/lp/moment_box.h, REFERENCE.md §2): a boundary
// moment vector pushed just outside the moment cone by rounding is answered within its box, a
// vector far outside is infeasible with its distance from the cone, and on many boundary vectors
// of few atoms the box's G never exceeds the atoms' own mass in front of z_f (the atoms are one of
// the distributions the box admits).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "lp/moment_box.h"
#include "lp/problem.h"
#include "lp/solution.h"
#include "moments/basis.h"

namespace mb::lp {
namespace {

std::vector<double> moments_of(const Basis& basis, const std::vector<double>& z,
                               const std::vector<double>& w) {
  std::vector<double> m(basis.size(), 0.0);
  for (size_t j = 0; j < basis.size(); ++j)
    for (size_t i = 0; i < z.size(); ++i) m[j] += w[i] * basis[j](z[i]);
  return m;
}

TEST(MomentBox, ABoundaryVectorJustOutsideIsAnsweredAndOneFarOutsideIsNot) {
  const Basis basis = Basis::parse({"power4"});
  const ProblemFactory factory(basis, Discretization{0, 1, 129, false});
  // Two atoms on grid points: the moment vector lies on the cone's boundary.
  std::vector<double> b = moments_of(basis, {0.25, 0.75}, {1.0 / 3, 2.0 / 3});
  b[3] = std::nextafter(std::nextafter(b[3], 0.0), 0.0);  // two ulps outside
  const Problem just_outside = factory.from_moments(b, 0.5);
  // The exact LP (as `solve` runs it) has no answer there.
  const Solution exact = make_backend("fast")->solve(just_outside);
  EXPECT_NE(exact.status, ProblemStatus::Optimal) << "G " << exact.G;
  const MomentBoxAnswer boxed =
      solve_moment_box(factory, just_outside, ulp_box(factory, just_outside, 8));
  ASSERT_EQ(boxed.status, ProblemStatus::Optimal);
  EXPECT_NEAR(boxed.G, 1.0 / 3, 1e-6);  // two atoms determine the distribution

  b[3] -= 1e-3;
  const Problem far = factory.from_moments(b, 0.5);
  const MomentBoxAnswer outside = solve_moment_box(factory, far, ulp_box(factory, far, 8));
  ASSERT_EQ(outside.status, ProblemStatus::Infeasible);
  // The nearest admissible vector differs by ~1e-3 in b_4 (relative ~6e-3) or less elsewhere.
  EXPECT_GT(outside.relative_distance, 1e-5);
  EXPECT_LT(outside.relative_distance, 1e-2);
}

TEST(MomentBox, BoundaryVectorsOfFewAtomsAreAnsweredAsLowerBounds) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> point(0, 128);
  std::uniform_real_distribution<double> weight(0.05, 1);
  int answered = 0, total = 0;
  for (const char* set : {"power4", "trig4"}) {
    const Basis basis = Basis::parse({set});
    const ProblemFactory factory(basis, Discretization{0, 1, 129, false});
    for (int i = 0; i < 60; ++i, ++total) {
      const int atoms = 1 + i % 4;
      std::vector<double> z, w;
      double sum = 0;
      for (int a = 0; a < atoms; ++a) z.push_back(point(rng) / 128.0), w.push_back(weight(rng));
      for (double x : w) sum += x;
      for (double& x : w) x /= sum;
      const double zf = (point(rng) + 0.5) / 128.0;
      const Problem p = factory.from_moments(moments_of(basis, z, w), zf);
      const MomentBoxAnswer box = solve_moment_box(factory, p, ulp_box(factory, p, 4));
      if (box.status != ProblemStatus::Optimal) continue;
      ++answered;
      double below = 0;
      for (int a = 0; a < atoms; ++a) below += z[a] < zf ? w[a] : 0;
      EXPECT_LE(box.G, below + 1e-7) << set << " instance " << i;
    }
  }
  EXPECT_GE(answered, total - 2);
}

}  // namespace
}  // namespace mb::lp
