// k-bit unorm storage with any affine transform (moments/storage.h, docs/reference.md §8): a
// texel's round trip stays within half a step mapped back through the inverse transform, a
// filtered map's stored values within storage_tolerance of the exact moments', and the format
// refuses bit depths and transforms a map cannot hold.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "basis/basis.h"
#include "moments/quantization_transform.h"
#include "moments/storage.h"
#include "scene/procedural.h"
#include "util/eigen.h"
#include "util/error.h"

namespace mb {
namespace {

// A random admissible transform for `basis`: random row directions, each row shifted and scaled
// onto its range over [0, 1] (dense samples widened by 1 %, so the curve stays inside [0, 1]^m).
MomentStorage random_storage(const Basis& basis, int bits, SeededRandom& rng) {
  const int m = int(basis.size());
  Eigen::MatrixXd a(m, m);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) a(i, j) = rng.uniform(-1, 1);
  Eigen::VectorXd c(m);
  for (int i = 0; i < m; ++i) {
    double lo = INFINITY, hi = -INFINITY;
    for (int k = 0; k <= 4096; ++k) {
      double v = 0;
      for (int j = 0; j < m; ++j) v += a(i, j) * basis[j](k / 4096.0);
      lo = std::min(lo, v), hi = std::max(hi, v);
    }
    const double pad = 0.01 * (hi - lo), scale = 1 / (hi - lo + 2 * pad);
    a.row(i) *= scale;
    c(i) = -(lo - pad) * scale;
  }
  return unorm_storage(bits, a, c);
}

TEST(MomentStorage, UnormRoundTripWithAnyTransformStaysWithinHalfAStep) {
  SeededRandom rng(61);
  for (const char* set : {"power2", "power4", "power6", "trig4"}) {
    const Basis basis = Basis::parse({set});
    const int m = int(basis.size());
    for (int bits : unorm_bit_depths()) {
      const MomentStorage storage = random_storage(basis, bits, rng);
      EXPECT_EQ(storage.name(), "unorm" + std::to_string(bits));
      const double step = 0.5 / (std::ldexp(1.0, bits) - 1);
      const double bound =
          storage.transform.inverse().cwiseAbs().rowwise().sum().maxCoeff() * step * (1 + 1e-6);
      for (int trial = 0; trial < 2000; ++trial) {
        const double z = rng.uniform(0, 1);
        std::vector<double> b(m), q(m);
        for (int j = 0; j < m; ++j) b[j] = q[j] = basis[j](z);
        const std::vector<double> exact = stored_values(storage, b);
        store_moments(storage, q);
        for (int i = 0; i < m; ++i) {
          ASSERT_TRUE(q[i] >= 0 && q[i] <= 1) << set << " " << bits;
          ASSERT_LE(std::abs(q[i] - exact[i]), step * (1 + 1e-9)) << set << " " << bits;
          // On the format's grid of 2^k values.
          const double steps = q[i] * (std::ldexp(1.0, bits) - 1);
          ASSERT_NEAR(steps, std::round(steps), 1e-6);
        }
        load_moments(storage, q);
        for (int j = 0; j < m; ++j)
          ASSERT_LE(std::abs(q[j] - b[j]), bound) << set << " " << bits << " z " << z;
      }
    }
  }
}

// A filtered map's stored values (each texel rounded, then averaged) lie within storage_tolerance
// of the stored values of the kernel's exact moments: what lp.moment_box relies on.
TEST(MomentStorage, FilteredStoredValuesLieWithinTheTolerance) {
  SeededRandom rng(62);
  const Basis basis = Basis::parse({"power6"});
  for (int bits : unorm_bit_depths()) {
    const MomentStorage storage = random_storage(basis, bits, rng);
    const std::vector<double> tolerance = storage_tolerance(storage, basis);
    for (int trial = 0; trial < 500; ++trial) {
      std::vector<double> depths, weights, moments(6, 0.0);
      double total = 0;
      for (int t = 0; t < 1 + trial % 9; ++t) {
        depths.push_back(rng.uniform(0, 1));
        weights.push_back(rng.uniform(0.05, 1));
        total += weights.back();
      }
      for (double& w : weights) w /= total;
      for (size_t t = 0; t < depths.size(); ++t)
        for (int j = 0; j < 6; ++j) moments[j] += weights[t] * basis[j](depths[t]);
      const std::vector<double> filtered = filtered_stored_values(storage, basis, depths, weights);
      const std::vector<double> exact = stored_values(storage, moments);
      for (int i = 0; i < 6; ++i) ASSERT_LE(std::abs(filtered[i] - exact[i]), tolerance[i]);
    }
  }
}

TEST(MomentStorage, ToleranceIsHalfAStepOfTheBitDepth) {
  const Basis basis = Basis::parse({"power4"});
  const MomentStorage ten =
      unorm_storage(10, Eigen::MatrixXd::Identity(4, 4), Eigen::VectorXd::Zero(4));
  // Half a step plus 8 ulps of (1 + m sum_i |A_ji| max |b_i|): the rounding of q = A b + c
  // itself (max |z^i| = 1 on [0, 1], proven from above within a hundredth).
  const double ulps = 8 * std::numeric_limits<double>::epsilon();
  const auto expect_tolerance = [&](const MomentStorage& s, double half_step) {
    const std::vector<double> eps = storage_tolerance(s, basis);
    for (size_t j = 0; j < eps.size(); ++j) {
      const double row = s.transform.row(Eigen::Index(j)).cwiseAbs().sum();
      EXPECT_GE(eps[j], half_step + ulps * (1 + 4 * row)) << j;
      EXPECT_LE(eps[j], half_step + ulps * (1 + 4 * row * 1.01)) << j;
    }
  };
  expect_tolerance(ten, 0.5 / 1023);
  expect_tolerance(unorm16_power4_storage(), 0.5 / 65535);
  // Rounding to 10 bits: values just above and below half a step.
  std::vector<double> q{0.51 / 1023, 0.49 / 1023, 1.2, -0.1};
  round_stored(ten, q);
  EXPECT_DOUBLE_EQ(q[0], 1.0 / 1023);
  EXPECT_DOUBLE_EQ(q[1], 0.0);
  EXPECT_DOUBLE_EQ(q[2], 1.0);  // clamped: outside an admissible transform's range
  EXPECT_DOUBLE_EQ(q[3], 0.0);
}

TEST(MomentStorage, RefusesBitDepthsAndTransformsNoMapHolds) {
  const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(2, 2);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(2);
  for (int bits : {0, 1, 12, 24, 32}) {
    try {
      unorm_storage(bits, identity, zero, "lp.moment_box");
      FAIL() << bits << " bits accepted";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("lp.moment_box"), std::string::npos) << what;
      EXPECT_NE(what.find(std::to_string(bits) + " bits"), std::string::npos) << what;
      EXPECT_NE(what.find("8, 10, 16"), std::string::npos) << what;
    }
  }
  EXPECT_THROW(unorm_storage(16, Eigen::MatrixXd::Identity(2, 3), zero), InputError);
  EXPECT_THROW(unorm_storage(16, identity, Eigen::VectorXd::Zero(3)), InputError);
  Eigen::MatrixXd singular(2, 2);
  singular << 1, 2, 2, 4;
  EXPECT_THROW(unorm_storage(16, singular, zero), InputError);
}

}  // namespace
}  // namespace mb

namespace mb {
namespace {

// theta_6 (seed 004 §2.5 stores six moments at 10 bits with a transform it does not print): this
// project's keeps the curve inside [0, 1]^6 by its rows' certified ranges and gains at least seed
// 004's 30.5 bits over the raw powers.
TEST(MomentStorage, Theta6IsAdmissibleAndGainsSeed004sBits) {
  const Basis basis = Basis::parse({"power6"});
  const MomentStorage storage = unorm10_power6_storage();
  EXPECT_EQ(storage.name(), "unorm10");
  const QuantizationTransform t{storage.transform, storage.offset};
  EXPECT_LE(admissibility_violation(basis, t), 1e-9);
  EXPECT_GT(entropy_gain_bits(basis, t), 30.5);
}

}  // namespace
}  // namespace mb
