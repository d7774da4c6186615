// Problem 1 with moments known to a tolerance (src/continuous/moment_box.h, docs/reference.md §2):
// a boundary moment vector pushed just outside the moment cone by rounding is answered within its
// box, a vector far outside is infeasible with its distance from the cone, and on many boundary
// vectors of few atoms the box's G never exceeds the atoms' own mass in front of z_f (the atoms are
// one of the distributions the box admits) nor falls below it at the box's other end, 1 minus its
// least mass behind z_f.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "basis/basis.h"
#include "continuous/local_power.h"
#include "continuous/moment_box.h"
#include "lp/problem.h"
#include "lp/solution.h"
#include "moments/storage.h"

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
  // The box's largest G from above: 1 minus its least mass strictly behind z_f, here 2/3.
  Problem behind = just_outside;
  behind.behind = true;
  const MomentBoxAnswer upper =
      solve_moment_box(factory, behind, ulp_box(factory, just_outside, 8));
  ASSERT_EQ(upper.status, ProblemStatus::Optimal);
  EXPECT_NEAR(upper.G, 2.0 / 3, 1e-6);

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
      // The atoms lie in the box, so their G lies within its range: at most 1 minus the box's
      // least mass strictly behind z_f (solve's `range`, docs/reference.md §2).
      Problem behind = p;
      behind.behind = true;
      const MomentBoxAnswer upper = solve_moment_box(factory, behind, ulp_box(factory, p, 4));
      ASSERT_EQ(upper.status, ProblemStatus::Optimal) << set << " instance " << i;
      EXPECT_GE(1 - upper.G, below - 1e-7) << set << " instance " << i;
      EXPECT_GE(1 - upper.G, box.G - 1e-7) << set << " instance " << i;
    }
  }
  EXPECT_GE(answered, total - 2);
}

constexpr double kInf = std::numeric_limits<double>::infinity();

// VSM's box on R has a closed answer: the box problem is the least of Cantelli's bound
// (z_f - mu)^2 / (m_2 - 2 mu z_f + z_f^2) (0 where z_f <= mu) over the box's (mu, m_2) with
// m_2 >= mu^2. A dense search of the box is the independent reference.
TEST(MomentBoxContinuous, VsmOnRMatchesCantellisBoundMinimisedOverTheBox) {
  const Basis basis = Basis::parse({"power2"});
  ContinuousDomain r = ContinuousDomain::interval(-1, 2);
  r.tail_lo = -kInf, r.tail_hi = kInf, r.even_degree = 2, r.probe_limit = 1e4;
  struct Case {
    double mu, variance, zf, eps;
  };
  for (const Case& k : {Case{0.4, 0.01, 0.5, 1e-4}, Case{0.4, 0.01, 0.45, 1e-3},
                        Case{0.3, 0.002, 0.32, 5e-5}, Case{0.6, 0.05, 0.9, 1e-3}}) {
    const double m2 = k.variance + k.mu * k.mu;
    const MomentBox box = MomentBox::of_moments({k.mu, m2}, {k.eps, k.eps});
    // The seed must admit a distribution in the box: mu -+ sigma, the two-atom one.
    const double sigma = std::sqrt(k.variance);
    const std::vector<double> seeds{0, k.mu - sigma, k.mu + sigma, 1};
    const ContinuousBoxAnswer a = solve_moment_box_continuous(basis, box, k.zf, r, seeds);
    ASSERT_TRUE(a.ok()) << k.mu << " " << k.zf;
    EXPECT_TRUE(a.proven);
    EXPECT_LE(a.width(), 1e-8);
    double least = 1;
    constexpr int kSteps = 2000;
    for (int i = 0; i <= kSteps; ++i)
      for (int j = 0; j <= kSteps; ++j) {
        const double mu = k.mu - k.eps + 2 * k.eps * i / kSteps;
        const double second = m2 - k.eps + 2 * k.eps * j / kSteps;
        if (second < mu * mu) continue;
        const double g =
            k.zf > mu ? (k.zf - mu) * (k.zf - mu) / (second - 2 * mu * k.zf + k.zf * k.zf) : 0;
        least = std::min(least, g);
      }
    // The search's own resolution: G moves by at most ~|grad G| eps / kSteps between samples.
    EXPECT_NEAR(a.upper, least, 2e-6) << "mu " << k.mu << " zf " << k.zf;
    EXPECT_LE(a.lower, least + 1e-9);
    // The exact moments' G (eps = 0) is never below the box's.
    const double exact =
        (k.zf - k.mu) * (k.zf - k.mu) / (k.variance + (k.zf - k.mu) * (k.zf - k.mu));
    EXPECT_LE(a.lower, exact + 1e-12);
  }
}

// A zero box is Problem 1 itself: against the exact continuous LP in local coordinates (Hausdorff
// on [0, 1] and Hamburger on R); and G never rises as the box widens.
TEST(MomentBoxContinuous, AZeroBoxIsProblemOneAndWideningNeverRaisesG) {
  const Basis basis = Basis::parse({"power4"});
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> depth(0.05, 0.95), weight(0.1, 1);
  auto fast = make_backend("fast");
  for (int i = 0; i < 12; ++i) {
    std::vector<double> z, w;
    double total = 0;
    for (int a = 0; a < 6; ++a)
      z.push_back(depth(rng)), w.push_back(weight(rng)), total += w.back();
    for (double& x : w) x /= total;
    const double zf = depth(rng);
    const bool on_r = i % 2;
    ContinuousDomain domain = ContinuousDomain::interval(0, 1);
    if (on_r) domain = {-1, 2, -kInf, kInf, 4, 100};
    const LocalPowerSolution exact =
        solve_power_locally({4, on_r ? -kInf : 0.0, on_r ? kInf : 1.0, 64}, z, w, zf, *fast);
    ASSERT_TRUE(exact.solution.ok());
    const std::vector<double> b = moments_of(basis, z, w);
    double previous = kInf;
    for (double eps : {0.0, 1e-9, 1e-7, 1e-5, 1e-3}) {
      const ContinuousBoxAnswer a = solve_moment_box_continuous(
          basis, MomentBox::of_moments(b, std::vector<double>(4, eps)), zf, domain, z);
      ASSERT_TRUE(a.ok()) << "instance " << i << " eps " << eps;
      EXPECT_LE(a.width(), 1e-7) << "instance " << i << " eps " << eps;
      if (eps == 0) {
        EXPECT_NEAR(a.upper, exact.solution.upper, 1e-7) << "instance " << i;
      }
      EXPECT_LE(a.lower, previous + 1e-9) << "instance " << i << " eps " << eps;
      previous = a.upper;
    }
  }
}

// The 16-bit map's box lives in theta_4's coordinates: the stored values of a distribution are
// within the format's tolerance of the exact ones, so the box admits the distribution and its G
// lies below the exact G (and below the mass in front of z_f).
TEST(MomentBoxContinuous, TheSixteenBitBoxAdmitsTheDistributionThatWasStored) {
  const Basis basis = Basis::parse({"power4"});
  const MomentStorage storage = unorm16_power4_storage();
  const std::vector<double> eps = storage_tolerance(storage, basis);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> depth(0.02, 0.98), weight(0.1, 1);
  ContinuousDomain r = {-1, 2, -kInf, kInf, 4, 100};
  for (int i = 0; i < 10; ++i) {
    std::vector<double> z, w, q(4, 0.0);
    double total = 0;
    for (int a = 0; a < 5; ++a)
      z.push_back(depth(rng)), w.push_back(weight(rng)), total += w.back();
    for (double& x : w) x /= total;
    std::vector<double> exact_q(4, 0.0);
    for (int a = 0; a < 5; ++a) {
      std::vector<double> column(4), stored(4);
      for (int j = 0; j < 4; ++j) column[j] = basis[j](z[a]);
      const std::vector<double> s = stored_values(storage, column);
      stored = column;
      store_moments(storage, stored);
      for (int j = 0; j < 4; ++j) q[j] += w[a] * stored[j], exact_q[j] += w[a] * s[j];
    }
    for (int j = 0; j < 4; ++j) EXPECT_LE(std::abs(q[j] - exact_q[j]), eps[j]);
    const double zf = depth(rng);
    double below = 0;
    for (int a = 0; a < 5; ++a) below += z[a] < zf ? w[a] : 0;
    const MomentBox box{q, eps, storage.transform, storage.offset};
    const ContinuousBoxAnswer a = solve_moment_box_continuous(basis, box, zf, r, z);
    ASSERT_TRUE(a.ok()) << "instance " << i;
    EXPECT_LE(a.lower, below + 1e-9);
    EXPECT_LE(a.width(), 1e-6);
  }
}

}  // namespace
}  // namespace mb::lp
