// Quantization transforms (docs/reference.md §8; seed 000 §4.3, seed 004 §2.5): exact ranges,
// the seed's gains, the hull-volume bounds, the search and theta_6.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "basis/basis.h"
#include "moments/quantization_transform.h"
#include "moments/storage.h"
#include "util/error.h"

namespace mb {
namespace {

Basis power(int m) {
  std::vector<std::string> names;
  for (int k = 1; k <= m; ++k) names.push_back(k == 1 ? "z" : "z^" + std::to_string(k));
  return Basis::parse(names);
}

// Every sample of theta(b(z)) on a dense grid lies in [0, 1]^m, and so do the certified ranges.
void expect_admissible(const Basis& basis, const QuantizationTransform& t) {
  EXPECT_LE(admissibility_violation(basis, t), 0.0);
  const int m = int(basis.size());
  Eigen::VectorXd b(m);
  for (int k = 0; k <= 20000; ++k) {
    for (int j = 0; j < m; ++j) b(j) = basis[j](k / 20000.0);
    const Eigen::VectorXd q = t.A * b + t.c;
    ASSERT_GE(q.minCoeff(), 0.0) << "z = " << k / 20000.0;
    ASSERT_LE(q.maxCoeff(), 1.0) << "z = " << k / 20000.0;
  }
}

// log2 |det A| - sum_i log2 (exact range of row i): the gain of A's row directions.
double gain_from_ranges(const Basis& basis, const Eigen::MatrixXd& A) {
  double bits = std::log2(std::abs(A.determinant()));
  for (Eigen::Index i = 0; i < A.rows(); ++i)
    bits -= std::log2(row_range(basis, A.row(i).transpose()).width());
  return bits;
}

TEST(QuantizationTransform, ExactRangeEnclosesADenseSample) {
  // Rows with cancellation (Chebyshev-like) and random ones, on a power and a trigonometric basis.
  std::mt19937_64 rng(61);
  std::normal_distribution<double> normal;
  for (const Basis& basis :
       {power(4), Basis::parse({"sin(pi z)", "cos(2 pi z)", "exp(-4z)", "1/(1+z)"})}) {
    for (int trial = 0; trial < 6; ++trial) {
      Eigen::VectorXd a(4);
      for (int j = 0; j < 4; ++j) a(j) = (trial == 0 ? 30 : 1) * normal(rng);
      const RowRange r = row_range(basis, a);
      double lo = INFINITY, hi = -INFINITY;
      const int n = 100000;
      for (int k = 0; k <= n; ++k) {
        double f = 0;
        for (int j = 0; j < 4; ++j) f += a(j) * basis[j](double(k) / n);
        lo = std::min(lo, f), hi = std::max(hi, f);
      }
      const double width = hi - lo, slack = 1e-12 * width;
      // Attained values are values of f (within rounding), the bounds enclose every sample.
      EXPECT_GE(r.max + slack, hi);
      EXPECT_LE(r.min - slack, lo);
      EXPECT_GE(r.max_upper, hi);
      EXPECT_LE(r.min_lower, lo);
      // A sample spacing of 1e-5 misses at most |f''| h^2 / 8 of an extremum: close.
      EXPECT_LT(r.max_upper - hi, 1e-8 * width);
      EXPECT_LT(lo - r.min_lower, 1e-8 * width);
    }
  }
}

TEST(QuantizationTransform, SeedTransformsGainTwoAndTwelvePointThreeBits) {
  // Seed 000 §4.3: theta_2 gains 2 bits, theta_4 12.3, both over the identity (canonical) storage.
  const QuantizationTransform t2 = quantization_transform(power(2), "seed");
  EXPECT_NEAR(entropy_gain_bits(power(2), t2), 2.0, 1e-9);
  EXPECT_NEAR(gain_from_ranges(power(2), t2.A), 2.0, 1e-9);
  expect_admissible(power(2), t2);
  const QuantizationTransform t4 = quantization_transform(power(4), "seed");
  const double bits = entropy_gain_bits(power(4), t4);
  EXPECT_NEAR(bits, 12.2783, 1e-3);
  EXPECT_NEAR(std::round(bits * 10) / 10, 12.3, 1e-12);
  expect_admissible(power(4), t4);
  // As printed (moments/storage.h, what the 16-bit map stores), theta_4's third row dips 6.5e-8
  // below 0: far below a 16-bit step, and the store clamps; refitted, it dips nowhere.
  const MomentStorage printed = unorm16_power4_storage();
  const double dip = admissibility_violation(power(4), {printed.transform, printed.offset});
  EXPECT_GT(dip, 6.4e-8);
  EXPECT_LT(dip, 6.6e-8);
  // The canonical transform of power moments is the identity.
  const QuantizationTransform c4 = quantization_transform(power(4), "canonical");
  EXPECT_LT((c4.A - Eigen::MatrixXd::Identity(4, 4)).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT(c4.c.cwiseAbs().maxCoeff(), 1e-12);
  expect_admissible(power(4), c4);
}

TEST(QuantizationTransform, PowerMomentHullVolumesAreKarlinShapleys) {
  // vol(hull of (z, ..., z^m)) = prod_{k <= m} B(k, k): 1/6, 1/180, 1/25200. The sampled hull is
  // inside the true one; its missing volume shrinks like n^-2 with n samples (a chord of a smooth
  // curve cuts off O(h^2)), which the tolerances allow for n = 4096, 1500, 300 with a margin.
  const double exact[] = {0, 0, 1.0 / 6, 1.0 / 180, 1.0 / 25200};
  const double tolerance[] = {0, 0, 1e-5, 1e-4, 1e-3};
  for (int m : {2, 3, 4}) {
    const GainBounds g = gain_bounds(power(m));
    EXPECT_LE(g.hull_volume, exact[m] * (1 + 1e-12)) << "m = " << m;
    EXPECT_GE(g.hull_volume, exact[m] * (1 - tolerance[m])) << "m = " << m;
    // Brunn-Minkowski: vol(H - H) >= 2^m vol(H), so the difference bound is the tighter one.
    EXPECT_GE(g.difference_volume, std::ldexp(g.hull_volume, m) * (1 - 1e-9));
    EXPECT_LE(g.difference_bound_bits, g.hull_bound_bits + 1e-9);
    // m = 2 has the angle grid's bound besides, far tighter than either volume's.
    EXPECT_EQ(g.best_bits(), m == 2 ? g.angle_grid_bits : g.difference_bound_bits);
  }
}

TEST(QuantizationTransform, OptimizedTwoIsExhaustiveAndFindsTheta2) {
  const OptimizedTransform o = optimize_transform(power(2));
  EXPECT_TRUE(o.exhaustive);
  EXPECT_NEAR(o.gain_bits, 2.0, 1e-6);
  EXPECT_LE(o.gain_bits, gain_bounds(power(2)).best_bits());
  expect_admissible(power(2), o.transform);
}

TEST(QuantizationTransform, AngleGridCertifiesTheTwoFunctionOptimum) {
  // The search's answer against the certified bound over both row angles: a wrong search (a
  // missed optimum) or a wrong bound (below an admissible transform's gain) fails one side.
  for (const Basis& basis :
       {power(2), Basis::parse({"cos(pi z)", "exp(-z)"}), Basis::parse({"sin(4 pi z)", "log(1+z)"}),
        Basis::parse({"z^5", "z^6"})}) {
    const OptimizedTransform o = optimize_transform(basis);
    const GainBounds g = gain_bounds(basis);
    EXPECT_LE(o.gain_bits, g.angle_grid_bits) << basis[0].name() << ", " << basis[1].name();
    EXPECT_LT(g.angle_grid_bits - o.gain_bits, 5e-3) << basis[0].name() << ", " << basis[1].name();
    EXPECT_LT(g.angle_grid_bits, g.difference_bound_bits);
    // A coarse grid is a valid bound too, only looser.
    const double coarse = two_row_gain_bound_bits(basis, 64);
    EXPECT_GE(coarse, o.gain_bits);
    EXPECT_GT(coarse, g.angle_grid_bits);
  }
  // Seed 000's theta_2 is within the bound, and VSM's optimum is 2 bits, certified to 1e-3.
  EXPECT_LE(entropy_gain_bits(power(2), quantization_transform(power(2), "seed")),
            gain_bounds(power(2)).angle_grid_bits);
  EXPECT_LT(gain_bounds(power(2)).angle_grid_bits, 2.001);
  EXPECT_THROW(two_row_gain_bound_bits(power(3), 4096), InputError);
}

TEST(QuantizationTransform, OptimizedThreeMatchesFigure5) {
  // Seed 000 Figure 5: 6.2 bits; transformed hull volume 0.41, 73.9 times the original one.
  const Basis basis = power(3);
  const OptimizedTransform o = optimize_transform(basis);
  EXPECT_NEAR(o.gain_bits, 6.2075, 2e-3);
  const GainBounds g = gain_bounds(basis);
  EXPECT_LE(o.gain_bits, g.best_bits());
  const double ratio = std::abs(o.transform.A.determinant());
  EXPECT_NEAR(ratio, 73.9, 0.05);
  EXPECT_NEAR(ratio * g.hull_volume, 0.41, 0.005);
  expect_admissible(basis, o.transform);
  // Deterministic: a second search gives the same matrix bit for bit.
  const OptimizedTransform again = optimize_transform(basis);
  EXPECT_EQ(again.transform.A, o.transform.A);
  EXPECT_EQ(again.transform.c, o.transform.c);
}

TEST(QuantizationTransform, OptimizedBeatsCanonicalOnCatalogCandidates) {
  for (const Basis& basis :
       {power(4), Basis::parse({"exp(-4z)", "sin(pi z)", "cos(2 pi z)", "log(1+4z)"}),
        Basis::parse({"z", "exp(2z)", "1/(1+z)"}),
        // Nearly dependent on [0, 1]: a thin hull, which Qhull sees in whitened coordinates.
        Basis::parse({"z^3", "z^4", "z^5", "z^6"})}) {
    const OptimizedTransform o = optimize_transform(basis);
    const GainBounds g = gain_bounds(basis);
    EXPECT_GT(o.gain_bits, 0.0);  // canonical is 0 by definition
    EXPECT_LE(o.gain_bits, g.best_bits());
    // Over the canonical rows (each function alone), both measured with exact ranges.
    const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(basis.size(), basis.size());
    EXPECT_NEAR(o.gain_bits,
                gain_from_ranges(basis, o.transform.A) - gain_from_ranges(basis, identity), 1e-6);
    expect_admissible(basis, o.transform);
    expect_admissible(basis, quantization_transform(basis, "canonical"));
  }
  // Four power moments: the search reaches seed 000's theta_4.
  EXPECT_GE(optimize_transform(power(4)).gain_bits,
            entropy_gain_bits(power(4), quantization_transform(power(4), "seed")) - 1e-4);
}

TEST(QuantizationTransform, JoggledHullBoundsTheSampledHullFromBelow) {
  // Qhull's joggle ("QJ", gain_bounds's fallback) moves the points; the margin subtracted keeps the
  // volume below the exact hull of the same samples, which "Qt" computes here.
  std::vector<double> points;
  for (int k = 0; k < 300; ++k) {
    const double z = 0.5 - 0.5 * std::cos(M_PI * k / 299);
    for (int j = 1; j <= 4; ++j) points.push_back(std::pow(z, j));
  }
  const double exact = sampled_hull_volume(points, 4, false);
  const double joggled = sampled_hull_volume(points, 4, true);
  EXPECT_NEAR(exact, 1.0 / 25200, 1e-3 / 25200);
  EXPECT_LT(joggled, exact);
  EXPECT_GT(joggled, exact * (1 - 1e-3));
}

TEST(QuantizationTransform, EightTrigonometricMomentsHaveBounds) {
  // Eight moments (MBOIT's trig4 information on [0, 1]): 28 curve samples in 8 dimensions, and a
  // difference body of enough samples to span them (the differences of n points span n - 1). The
  // same 28 Chebyshev depths' hull by scipy.spatial.ConvexHull ("Qt", Qhull 2019.1, whitened as
  // here) has volume 1.7238517529588445e-05 in the functions' own coordinates.
  const Basis basis = Basis::parse({"cos(pi z)", "cos(2 pi z)", "cos(3 pi z)", "cos(4 pi z)",
                                    "sin(pi z)", "sin(2 pi z)", "sin(3 pi z)", "sin(4 pi z)"});
  const GainBounds g = gain_bounds(basis);
  EXPECT_NEAR(g.hull_volume, 1.7238517529588445e-05, 1e-9 * 1.7238517529588445e-05);
  EXPECT_GT(g.difference_volume, 0.0);
  EXPECT_LE(g.difference_bound_bits, g.hull_bound_bits);
}

TEST(QuantizationTransform, Theta6GainsBeyondSeed004) {
  // Seed 004 §2.5: 30.5 bits for six moments; this project's theta_6 re-derived from exact ranges.
  const Basis basis = power(6);
  const QuantizationTransform t = power6_optimized_transform();
  const double bits = gain_from_ranges(basis, t.A);
  EXPECT_NEAR(bits, 30.587, 1e-3);
  EXPECT_NEAR(entropy_gain_bits(basis, t), bits, 1e-6);
  EXPECT_LE(bits, gain_bounds(basis).best_bits());
  expect_admissible(basis, t);
}

TEST(QuantizationTransform, RefusesWhatItCannotCertify) {
  EXPECT_THROW(quantization_transform(power(3), "seed"), InputError);
  EXPECT_THROW(quantization_transform(Basis::parse({"z", "exp(z)"}), "seed"), InputError);
  EXPECT_THROW(quantization_transform(power(2), "best"), InputError);
  // Expressions have no closed-form derivatives, so no certified range.
  EXPECT_THROW(quantization_transform(Basis::parse({"z", "z^2*exp(-z)"}), "canonical"), InputError);
  EXPECT_THROW(quantization_transform(Basis::parse({"z", "z^2", "z"}), "optimized"), InputError);
  EXPECT_THROW(fit_rows(power(2), Eigen::MatrixXd::Ones(2, 2)), InputError);
}

}  // namespace
}  // namespace mb
