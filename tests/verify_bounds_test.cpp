// Bound curves (the seed paper's Figure 3): the m-series of one kernel obey the invariants of
// Problem 1 and agree with independent answers.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "moments/tmsm.h"
#include "test_support.h"
#include "verify/bound_curves.h"

namespace mb {
namespace {

using testing_support::input_error_of;

BoundCurveRequest six_atoms() {
  BoundCurveRequest r;
  r.depths = {0.12, 0.3, 0.31, 0.55, 0.7, 0.93};
  r.weights = {0.1, 0.25, 0.05, 0.3, 0.2, 0.1};
  r.samples = 101;
  r.lp.grid = 512;
  r.threads = 2;
  return r;
}

// Prefixes are nested bases: more functions, fewer admissible distributions, so
// 0 <= G_2 <= G_3 <= G_4 <= F_Z at every z_f (docs/reference.md §2, the true kernel is feasible).
TEST(BoundCurves, NestedBasesGiveOrderedBoundsBelowTheCdf) {
  BoundCurveRequest r = six_atoms();
  r.bases = {"power4", "trig4", "exp(-4z); 1/(1+z); sin(pi z); z^3"};
  const BoundCurves c = compute_bound_curves(r);
  ASSERT_EQ(c.series.size(), 9u);
  ASSERT_EQ(c.zf.size(), 101u);
  int gaps = 0;
  for (size_t b = 0; b < 3; ++b)
    for (size_t i = 0; i < c.zf.size(); ++i) {
      const double g2 = c.series[3 * b].lower[i], g3 = c.series[3 * b + 1].lower[i],
                   g4 = c.series[3 * b + 2].lower[i];
      ASSERT_FALSE(std::isnan(g2) || std::isnan(g3) || std::isnan(g4))
          << c.series[3 * b].basis << " at " << c.zf[i];
      EXPECT_GE(g2, 0);
      EXPECT_LE(g2, g3 + 1e-9) << c.series[3 * b].basis << " z_f " << c.zf[i];
      EXPECT_LE(g3, g4 + 1e-9) << c.series[3 * b].basis << " z_f " << c.zf[i];
      EXPECT_LE(g4, c.cdf[i] + 1e-9) << c.series[3 * b].basis << " z_f " << c.zf[i];
      gaps += g4 < c.cdf[i] - 1e-3;
    }
  EXPECT_GT(gaps, 10);  // six atoms are not determined by four moments: the bound is not trivial
  for (const auto& s : c.series) EXPECT_EQ(s.failures, 0u) << s.basis << " m=" << s.m;
  // The series summaries: four functions leave a smaller area between CDF and bound than two.
  for (size_t b = 0; b < 3; ++b) EXPECT_LT(c.series[3 * b + 2].mean_gap, c.series[3 * b].mean_gap);
}

// Proposition 4: at most two depths and the power basis with m = 4 determine the distribution,
// so the bound is the CDF itself; one depth already with m = 2.
TEST(BoundCurves, FewDepthsAreReproducedExactly) {
  BoundCurveRequest r;
  r.depths = {0.3, 0.72};
  r.weights = {0.4, 0.6};
  r.bases = {"power4"};
  r.sizes = {4};
  r.samples = 61;
  const BoundCurves two = compute_bound_curves(r);
  for (size_t i = 0; i < two.zf.size(); ++i)
    EXPECT_NEAR(two.series[0].lower[i], two.cdf[i], 1e-7) << two.zf[i];
  r.depths = {0.45};
  r.weights = {1};
  r.sizes = {2};
  const BoundCurves one = compute_bound_curves(r);
  for (size_t i = 0; i < one.zf.size(); ++i)
    EXPECT_NEAR(one.series[0].lower[i], one.cdf[i], 1e-7) << one.zf[i];
}

// The trigonometric m = 4 series against the closed form of Problem 1 for that basis (TMSM on the
// continuous [0, 1]): the LP on a finite I can only be higher, by a grid-limited amount.
TEST(BoundCurves, TrigonometricSeriesMatchesTmsm) {
  BoundCurveRequest r = six_atoms();
  r.lp.grid = 2048;
  r.bases = {"trig4"};
  r.sizes = {4};
  const BoundCurves c = compute_bound_curves(r);
  double b[4] = {};
  for (size_t t = 0; t < r.depths.size(); ++t) {
    const double phi = 2 * std::numbers::pi * r.depths[t];
    b[0] += r.weights[t] * std::sin(phi), b[1] += r.weights[t] * std::cos(phi);
    b[2] += r.weights[t] * std::sin(2 * phi), b[3] += r.weights[t] * std::cos(2 * phi);
  }
  double largest = 0;
  for (size_t i = 1; i + 1 < c.zf.size(); ++i) {
    const double closed = tmsm(b, c.zf[i], false).lower;
    EXPECT_LE(closed, c.series[0].lower[i] + 1e-7) << c.zf[i];
    largest = std::max(largest, std::abs(closed - c.series[0].lower[i]));
  }
  EXPECT_LT(largest, 2e-3);
}

TEST(BoundCurves, SameCurvesForAnyThreadCount) {
  BoundCurveRequest r = six_atoms();
  r.bases = {"power4"};
  r.threads = 1;
  const BoundCurves one = compute_bound_curves(r);
  r.threads = 2;
  const BoundCurves two = compute_bound_curves(r);
  for (size_t s = 0; s < one.series.size(); ++s)
    EXPECT_EQ(one.series[s].lower, two.series[s].lower);
}

TEST(BoundCurves, BadRequestsNameWhatIsWrong) {
  BoundCurveRequest r = six_atoms();
  r.bases = {"power4"};
  r.sizes = {5};
  EXPECT_NE(input_error_of([&] {
              compute_bound_curves(r);
            }).find("m = 5 needs 5 functions, but basis 'power4' has 4"),
            std::string::npos);
  r = six_atoms();
  r.bases = {"power4"};
  r.weights.pop_back();
  EXPECT_NE(input_error_of([&] { compute_bound_curves(r); }).find("one weight per depth"),
            std::string::npos);
  r = six_atoms();
  r.bases = {"power4"};
  r.depths[2] = 1.5;
  EXPECT_NE(input_error_of([&] { compute_bound_curves(r); }).find("outside the LP interval"),
            std::string::npos);
  r = six_atoms();
  r.bases = {"z; 2*z"};
  r.sizes = {2};
  EXPECT_NE(input_error_of([&] { compute_bound_curves(r); }).find("linearly dependent"),
            std::string::npos);
}

}  // namespace
}  // namespace mb
