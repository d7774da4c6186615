// The closed-form solvers of docs/reference.md §4 against facts that hold whatever the
// implementation: the Cantelli and Markov formulas evaluated from the distribution itself, G <=
// F_Z, Hamburger <= Hausdorff, Proposition 4 (seed 000), the canonical distribution's moments,
// float vs double.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "moments/canonical.h"
#include "moments/chebyshev.h"
#include "moments/hamburger.h"
#include "moments/hausdorff.h"
#include "moments/storage.h"
#include "scene/procedural.h"
#include "test_distribution.h"
#include "util/eigen.h"

namespace mb {
namespace {

using testing_support::Distribution;

Distribution random_distribution(SeededRandom& rng, int atoms) {
  Distribution d;
  double total = 0;
  for (int i = 0; i < atoms; ++i) {
    d.z.push_back(rng.uniform(0.02, 0.98));
    d.w.push_back(rng.uniform(0.05, 1.0));
    total += d.w.back();
  }
  for (double& w : d.w) w /= total;
  return d;
}

TEST(ClosedForms, VsmEqualsCantelliFromTheDistribution) {
  SeededRandom rng(11);
  for (int trial = 0; trial < 2000; ++trial) {
    Distribution d = random_distribution(rng, 1 + trial % 6);
    auto b = d.power_moments(2);
    double mean = 0, variance = 0;
    for (size_t i = 0; i < d.z.size(); ++i) mean += d.w[i] * d.z[i];
    for (size_t i = 0; i < d.z.size(); ++i) variance += d.w[i] * (d.z[i] - mean) * (d.z[i] - mean);
    const double zf = rng.uniform(0, 1);
    const double cantelli =
        zf <= mean ? 0 : (zf - mean) * (zf - mean) / (variance + (zf - mean) * (zf - mean));
    const double g = vsm_bound(b.data(), zf, 0);
    EXPECT_NEAR(g, cantelli, 1e-9);
    EXPECT_LE(g, d.cdf(zf) + 1e-12);
  }
}

TEST(ClosedForms, EsmEqualsMarkovFromTheDistribution) {
  SeededRandom rng(12);
  const double c = 80;
  for (int trial = 0; trial < 2000; ++trial) {
    Distribution d = random_distribution(rng, 1 + trial % 6);
    double expectation = 0, markov_tail = 0;
    const double zf = rng.uniform(0, 1);
    for (size_t i = 0; i < d.z.size(); ++i) {
      expectation += d.w[i] * std::exp(c * d.z[i]);
      markov_tail += d.w[i] * std::exp(c * (d.z[i] - zf));  // E[e^{c(Z - z_f)}] >= P(Z >= z_f)
    }
    const double g = esm_bound(expectation, zf, c);
    EXPECT_NEAR(g, std::max(0.0, 1 - markov_tail), 1e-9 * std::max(1.0, markov_tail));
    EXPECT_LE(g, d.cdf(zf) + 1e-12);
  }
}

TEST(ClosedForms, HamburgerIsAtMostHausdorffAndBothAtMostTheTrueCdf) {
  SeededRandom rng(13);
  int strictly_sharper = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    Distribution d = random_distribution(rng, 3 + trial % 6);
    auto b = d.power_moments(4);
    const double zf = rng.uniform(0, 1);
    const double hamburger = hamburger4(b.data(), zf).lower,
                 hausdorff = hausdorff4(b.data(), zf).lower;
    ASSERT_LE(hamburger, hausdorff + 1e-9) << "trial " << trial;
    ASSERT_LE(hausdorff, d.cdf(zf) + 1e-9) << "trial " << trial;
    ASSERT_GE(hamburger, 0);
    strictly_sharper += hausdorff > hamburger + 1e-6;
  }
  EXPECT_GT(strictly_sharper, 100);  // [0, 1] really is a smaller admissible set
}

TEST(ClosedForms, CanonicalThreePointDistributionReproducesAllFiveMoments) {
  SeededRandom rng(14);
  for (int trial = 0; trial < 5000; ++trial) {
    Distribution d = random_distribution(rng, 3 + trial % 5);
    auto b = d.power_moments(4);
    auto r = hamburger4(b.data(), rng.uniform(0, 1));
    ASSERT_EQ(r.node_count, 3);
    // Rounding in the LDL^T grows with the Hankel matrix's condition number (close atoms).
    Eigen::Matrix3d hankel;
    const double m[5] = {1, b[0], b[1], b[2], b[3]};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) hankel(i, j) = m[i + j];
    // The Hankel matrix is symmetric: its singular values are its eigenvalues' magnitudes.
    const Eigen::Vector3d eigenvalues =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(hankel, Eigen::EigenvaluesOnly)
            .eigenvalues()
            .cwiseAbs();
    // A far node with a tiny weight (z = 43, w = 2e-9 happens) amplifies both by z^power.
    double magnitude = 0;
    for (int i = 0; i < 3; ++i)
      magnitude += std::abs(r.weights[i]) * std::pow(std::max(1.0, std::abs(r.nodes[i])), 4);
    const double tolerance =
        std::max(1e-12, 1e-13 * magnitude * eigenvalues.maxCoeff() / eigenvalues.minCoeff());
    for (int power = 0; power <= 4; ++power) {
      double moment = 0;
      for (int i = 0; i < 3; ++i) moment += r.weights[i] * std::pow(r.nodes[i], power);
      ASSERT_NEAR(moment, power == 0 ? 1.0 : b[power - 1], tolerance)
          << "trial " << trial << " power " << power << " nodes " << r.nodes[0] << " " << r.nodes[1]
          << " " << r.nodes[2] << " w " << r.weights[0] << " " << r.weights[1] << " "
          << r.weights[2];
    }
  }
}

std::vector<double> b_with_one(const std::vector<double>& b) {
  std::vector<double> m{1.0};
  m.insert(m.end(), b.begin(), b.end());
  return m;
}

TEST(ClosedForms, SixMomentsReproduceSevenMomentsAndAreSharperThanFour) {
  SeededRandom rng(15);
  for (int trial = 0; trial < 5000; ++trial) {
    Distribution d = random_distribution(rng, 4 + trial % 5);
    auto b = d.power_moments(6);
    const double zf = rng.uniform(0.05, 0.95);
    auto r6 = hamburger6(b.data(), zf);
    // 4 nodes through z_f; 3 where the moments are those of 3 atoms to rounding (a tiny weight),
    // which then determine the distribution.
    ASSERT_GE(r6.node_count, 3);
    if (r6.node_count == 3)
      for (int i = 0; i < 3; ++i) r6.weights[i] = node_weight(b_with_one(b).data(), r6.nodes, 3, i);
    for (int power = 0; power <= 6; ++power) {
      double moment = 0;
      for (int i = 0; i < r6.node_count; ++i)
        moment += r6.weights[i] * std::pow(r6.nodes[i], power);
      ASSERT_NEAR(moment, power == 0 ? 1.0 : b[power - 1], 1e-6)
          << "trial " << trial << " power " << power;
    }
    ASSERT_GE(r6.lower, hamburger4(b.data(), zf).lower - 1e-7) << "trial " << trial;
    ASSERT_LE(r6.lower, d.cdf(zf) + 1e-7) << "trial " << trial;
  }
}

// One to three atoms make the 4x4 Hankel matrix of six moments singular: the moments determine the
// distribution (docs/reference.md §2), and hamburger6 returns its mass strictly below z_f (at alpha
// = 0, where the canonical representation through z_f does not exist), never no number.
TEST(ClosedForms, SixMomentsOfFewAtomsGiveTheDeterminateDistributionsMass) {
  SeededRandom rng(17);
  int checked = 0;
  for (int trial = 0; trial < 600; ++trial) {
    Distribution d = random_distribution(rng, 1 + trial % 3);
    const auto b = d.power_moments(6);
    for (double zf : {0.03, 0.31, 0.5, 0.77, 0.97}) {
      const auto r = hamburger6(b.data(), zf);
      ASSERT_TRUE(std::isfinite(r.lower) && std::isfinite(r.at_zf)) << "trial " << trial;
      // Atoms closer than ~1e-3 leave the moments too near a smaller rank for any method in double.
      double gap = 1;
      for (size_t i = 0; i < d.z.size(); ++i)
        for (size_t k = i + 1; k < d.z.size(); ++k) gap = std::min(gap, std::abs(d.z[i] - d.z[k]));
      double nearest = 1;
      for (double z : d.z) nearest = std::min(nearest, std::abs(z - zf));
      if (gap < 1e-2 || nearest < 1e-3) continue;
      EXPECT_NEAR(r.lower, d.cdf(zf), 1e-6) << "trial " << trial << " zf " << zf;
      ++checked;
    }
  }
  EXPECT_GT(checked, 2000);
}

// Seed 000, Proposition 4: a kernel covering at most two depths has a singular moment matrix, and
// the bias alpha -> 0 makes Hamburger 4MSM converge to F_Z; with three depths and alpha = 0 it
// never exceeds F_Z.
TEST(ClosedForms, Proposition4TwoDepthsConvergeToTheCdfAsAlphaVanishes) {
  SeededRandom rng(16);
  const double star[4] = {0.5, 0.5, 0.5, 0.5};
  for (int trial = 0; trial < 200; ++trial) {
    Distribution d;
    d.z = {rng.uniform(0.1, 0.45), rng.uniform(0.55, 0.9)};
    double w = rng.uniform(0.1, 0.9);
    d.w = {w, 1 - w};
    auto b = d.power_moments(4);
    Eigen::Matrix3d hankel;
    const double m[5] = {1, b[0], b[1], b[2], b[3]};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) hankel(i, j) = m[i + j];
    ASSERT_LT(std::abs(hankel.determinant()), 1e-15);
    // z_f away from both depths (by at least 0.05).
    for (double zf : {d.z[0] - 0.05, 0.5 * (d.z[0] + d.z[1]), d.z[1] + 0.05}) {
      double previous = 1;
      for (double alpha : {1e-4, 1e-6, 1e-8, 1e-10}) {
        double biased[4] = {b[0], b[1], b[2], b[3]};
        bias_moments(biased, 4, alpha, star);
        double error = std::abs(hamburger4(biased, zf).lower - d.cdf(zf));
        ASSERT_LE(error, previous + 1e-12) << "alpha " << alpha;
        previous = error;
      }
      ASSERT_LT(previous, 1e-6) << "trial " << trial << " zf " << zf;
    }
  }
  for (int trial = 0; trial < 2000; ++trial) {
    Distribution d = random_distribution(rng, 3);
    auto b = d.power_moments(4);
    double zf = rng.uniform(0, 1);
    ASSERT_LE(hamburger4(b.data(), zf).lower, d.cdf(zf) + 1e-9);
  }
}

// float32 against double on the same biased moments, in digits (-log10 of the absolute error of
// G, which lives in [0, 1]). Reported, and bounded where float must still be useful.
TEST(ClosedForms, Float32AgreesWithDoubleToAFewDigits) {
  SeededRandom rng(17);
  const double alpha = 5e-6;
  const double star[4] = {0.5, 0.5, 0.5, 0.5};
  std::vector<double> digits;
  for (int trial = 0; trial < 20000; ++trial) {
    Distribution d = random_distribution(rng, 1 + trial % 8);
    auto b = d.power_moments(4);
    double biased[4] = {b[0], b[1], b[2], b[3]};
    bias_moments(biased, 4, alpha, star);
    float biased_float[4];
    for (int j = 0; j < 4; ++j) biased_float[j] = float(biased[j]);
    const double zf = rng.uniform(0, 1);
    double g = hamburger4(biased, zf).lower;
    float gf = hamburger4(biased_float, float(zf)).lower;
    ASSERT_TRUE(std::isfinite(gf));
    digits.push_back(-std::log10(std::max(std::abs(double(gf) - g), 1e-17)));
  }
  std::sort(digits.begin(), digits.end());
  const double median = digits[digits.size() / 2], worst_percent = digits[digits.size() / 100];
  std::printf(
      "float32 vs double, Hamburger 4MSM, alpha %g: median %.1f digits, 1st percentile %.1f, worst "
      "%.1f\n",
      alpha, median, worst_percent, digits.front());
  EXPECT_GT(median, 4.0);
  EXPECT_GT(worst_percent, 1.5);
}

// 16-bit storage: the error of store + load of one texel is bounded by the rounding (half a unit
// in the last place, 0.5 / 65535 per channel) mapped back through the inverse transform.
TEST(ClosedForms, Unorm16RoundTripStaysWithinTheTransformBound) {
  for (const auto& storage : {unorm16_power4_storage(), unorm16_power2_storage()}) {
    const int m = int(storage.transform.rows());
    const Eigen::MatrixXd inverse = storage.transform.inverse();
    const double bound = inverse.cwiseAbs().rowwise().sum().maxCoeff() * 0.5 / 65535 * (1 + 1e-9);
    SeededRandom rng(18);
    for (int trial = 0; trial < 20000; ++trial) {
      const double z = rng.uniform(0, 1);
      std::vector<double> b(m), q(m);
      for (int j = 0; j < m; ++j) b[j] = q[j] = std::pow(z, j + 1);
      store_moments(storage, q);
      for (double v : q) ASSERT_TRUE(v >= 0 && v <= 1);  // the transform maps [0,1] into [0,1]^m
      load_moments(storage, q);
      for (int j = 0; j < m; ++j)
        ASSERT_LE(std::abs(q[j] - b[j]), bound) << "z " << z << " channel " << j;
    }
  }
}

}  // namespace
}  // namespace mb

namespace mb {
namespace {

// The vectorised stream form computes the same bound as the scalar solver.
TEST(ClosedForms, BatchHamburgerMatchesTheScalarSolver) {
  SeededRandom rng(19);
  const int n = 4096;
  const double alpha = 3e-5, star[4] = {0.5, 0.5, 0.5, 0.5};
  std::vector<double> b, zf, batch(n);
  for (int k = 0; k < n; ++k) {
    Distribution d = random_distribution(rng, 1 + k % 8);
    for (double v : d.power_moments(4)) b.push_back(v);
    zf.push_back(rng.uniform(0, 1));
  }
  hamburger4_lower_batch(b.data(), zf.data(), batch.data(), n, alpha);
  for (int k = 0; k < n; ++k) {
    double biased[4] = {b[4 * k], b[4 * k + 1], b[4 * k + 2], b[4 * k + 3]};
    bias_moments(biased, 4, alpha, star);
    ASSERT_NEAR(batch[k], hamburger4(biased, zf[k]).lower, 1e-9) << "fragment " << k;
  }
}

// MBOIT's four-moment blend for one pixel's moments and many fragments (the resolve pass) equals
// the scalar solver's G + beta w, and keeps a NaN of degenerate moments for the caller to count.
TEST(ClosedForms, BatchBlendMatchesTheScalarSolver) {
  SeededRandom rng(43);
  const double star[4] = {0, 0.375, 0, 0.375};
  int compared = 0;
  for (int pixel = 0; pixel < 300; ++pixel) {
    Distribution d = random_distribution(rng, 1 + pixel % 12);
    for (double& z : d.z) z = 2 * z - 1;  // MBOIT's t = 2u - 1
    std::vector<double> b = d.power_moments(4);
    bias_moments(b.data(), 4, 1e-10, star);
    std::vector<double> zf(d.z), out(d.z.size());
    zf.push_back(rng.uniform(-1, 1));
    out.resize(zf.size());
    const double beta = pixel % 3 == 0 ? 0.0 : 0.25;
    hamburger4_blend_batch(b.data(), zf.data(), zf.size(), beta, out.data());
    for (size_t k = 0; k < zf.size(); ++k) {
      const MsmBound<double> r = hamburger4(b.data(), zf[k]);
      ASSERT_NEAR(out[k], std::clamp(r.lower + beta * r.at_zf, 0.0, 1.0), 1e-12)
          << "pixel " << pixel << " fragment " << k;
      ++compared;
    }
  }
  EXPECT_GT(compared, 1500);
  // A zero variance (every moment of one atom, no bias): the Hankel matrix is singular.
  const double atom[4] = {0.5, 0.25, 0.125, 0.0625}, zf = 0.2;
  double out = 0;
  hamburger4_blend_batch(atom, &zf, 1, 0.25, &out);
  EXPECT_TRUE(std::isnan(out));
}

}  // namespace
}  // namespace mb
