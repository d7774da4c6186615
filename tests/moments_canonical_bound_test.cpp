// The canonical representation through a point for any number of power or trigonometric moments
// (moments/canonical_bound.h): it reproduces the moments it came from, and for four and six power
// moments it is the distribution the closed forms of moments/hamburger.h build.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <random>

#include "moments/canonical.h"
#include "moments/canonical_bound.h"
#include "moments/hamburger.h"

namespace mb {
namespace {

struct Atoms {
  std::vector<double> x, w;
};

Atoms random_atoms(std::mt19937_64& rng, int count) {
  std::uniform_real_distribution<double> unit(0, 1);
  Atoms a;
  double total = 0;
  for (int i = 0; i < count; ++i) a.x.push_back(2 * unit(rng) - 1), a.w.push_back(0.05 + unit(rng));
  for (double v : a.w) total += v;
  for (double& v : a.w) v /= total;
  return a;
}

void power_moments(const Atoms& a, int m, double* b) {
  for (int j = 0; j < m; ++j) {
    b[j] = 0;
    for (size_t i = 0; i < a.x.size(); ++i) b[j] += a.w[i] * std::pow(a.x[i], j + 1);
  }
}

TEST(CanonicalBound, PowerAgreesWithHamburgersClosedForms) {
  std::mt19937_64 rng(71);
  static constexpr double kStar6[6] = {0, 0.48, 0, 0.451, 0, 0.45};
  double worst4 = 0, worst6 = 0;
  for (int n = 0; n < 300; ++n) {
    const Atoms a = random_atoms(rng, 2 + n % 9);
    double b[6];
    power_moments(a, 6, b);
    bias_moments(b, 6, 1e-6, kStar6);  // the same moments for both methods, positive definite
    const double xf = 2 * std::uniform_real_distribution<double>(0, 1)(rng) - 1;
    for (int order : {2, 3}) {
      CanonicalNodes c;
      ASSERT_TRUE(canonical_power(b, order, xf, c)) << n;
      double lower = 0;
      for (int k = 1; k < c.count; ++k) lower += c.nodes[k] < xf ? c.weights[k] : 0;
      const MsmBound<double> r = order == 2 ? hamburger4(b, xf) : hamburger6(b, xf);
      EXPECT_NEAR(lower, r.lower, 1e-7) << "order " << order << " case " << n;
      EXPECT_NEAR(c.weights[0], r.at_zf, 1e-7) << "order " << order << " case " << n;
      (order == 2 ? worst4 : worst6) =
          std::max(order == 2 ? worst4 : worst6, std::abs(lower - r.lower));
    }
  }
  std::printf("canonical vs closed form: |dG| up to %.2e (4 moments), %.2e (6 moments)\n", worst4,
              worst6);
}

TEST(CanonicalBound, EightPowerMomentsAreReproduced) {
  std::mt19937_64 rng(72);
  static constexpr double kStar8[8] = {0, 0.75, 0, 0.676666667, 0, 0.63, 0, 0.6003030303};
  for (int n = 0; n < 200; ++n) {
    const Atoms a = random_atoms(rng, 2 + n % 12);
    double b[8];
    power_moments(a, 8, b);
    bias_moments(b, 8, 1e-5, kStar8);
    const double xf = 2 * std::uniform_real_distribution<double>(0, 1)(rng) - 1;
    CanonicalNodes c;
    ASSERT_TRUE(canonical_power(b, 4, xf, c)) << n;
    ASSERT_EQ(c.count, 5) << n;
    EXPECT_EQ(c.nodes[0], xf);
    for (int j = 0; j <= 8; ++j) {
      double moment = 0;
      for (int k = 0; k < c.count; ++k) moment += c.weights[k] * std::pow(c.nodes[k], j);
      EXPECT_NEAR(moment, j == 0 ? 1.0 : b[j - 1], 1e-7) << "moment " << j << " case " << n;
    }
    for (int k = 0; k < c.count; ++k) EXPECT_GT(c.weights[k], 0) << n;
  }
}

TEST(CanonicalBound, TrigonometricMomentsAreReproduced) {
  std::mt19937_64 rng(73);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int n = 0; n < 300; ++n) {
    const int order = 2 + n % 3;
    const Atoms a = random_atoms(rng, 1 + n % 10);
    std::complex<double> c[kMaxCanonicalOrder];
    for (int k = 1; k <= order; ++k) {
      c[k - 1] = 0;
      for (size_t i = 0; i < a.x.size(); ++i)
        c[k - 1] += a.w[i] * std::polar(1.0, k * std::numbers::pi * (a.x[i] + 1));
      c[k - 1] *= 1 - 1e-6;  // towards the uniform distribution: positive definite
    }
    const double phi = 2 * std::numbers::pi * unit(rng);
    CanonicalNodes r;
    ASSERT_TRUE(canonical_trigonometric(c, order, phi, r)) << n;
    ASSERT_EQ(r.count, order + 1) << n;
    EXPECT_NEAR(r.nodes[0], phi, 1e-12);
    for (int j = 0; j <= order; ++j) {
      std::complex<double> moment = 0;
      for (int k = 0; k < r.count; ++k) moment += r.weights[k] * std::polar(1.0, j * r.nodes[k]);
      const std::complex<double> expected = j == 0 ? 1.0 : c[j - 1];
      EXPECT_NEAR(std::abs(moment - expected), 0, 1e-7) << "moment " << j << " case " << n;
    }
    for (int k = 0; k < r.count; ++k) EXPECT_GT(r.weights[k], 0) << n;
  }
}

}  // namespace
}  // namespace mb
