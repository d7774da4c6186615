// The double-double sums behind the fast backend's precise certificate (src/lp/double_double.h):
// exact where the answer is known exactly, and far more accurate than double where double is not.
#include <gtest/gtest.h>

#include <random>

#include "lp/double_double.h"

namespace mb::lp {
namespace {

TEST(DoubleDouble, TwoSumIsExact) {
  // 1 + 2^-60 is not a double; the pair keeps both parts.
  const DoubleDouble s = two_sum(1.0, std::ldexp(1.0, -60));
  EXPECT_EQ(s.hi, 1.0);
  EXPECT_EQ(s.lo, std::ldexp(1.0, -60));
  const DoubleDouble t = two_sum(std::ldexp(1.0, -60), 1.0);
  EXPECT_EQ(t.hi, 1.0);
  EXPECT_EQ(t.lo, std::ldexp(1.0, -60));
}

// Dot products of integers below 2^30: products reach 2^60, beyond double's 53 bits (exact only
// through the FMA's error term), the sums 2^63; the exact answer comes from 128-bit integers.
TEST(DoubleDouble, DotProductsOfLargeIntegersAreExact) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int64_t> digit(-(int64_t(1) << 30), int64_t(1) << 30);
  int double_wrong = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    DoubleDouble sum;
    double naive = 0;
    __int128 exact = 0;
    for (int term = 0; term < 9; ++term) {
      const int64_t a = digit(rng), b = digit(rng);
      add_product(sum, double(a), double(b));
      naive += double(a) * double(b);
      exact += __int128(a) * b;
    }
    EXPECT_EQ(__int128(sum.hi) + __int128(sum.lo), exact) << "trial " << trial;
    double_wrong += __int128(naive) != exact;
  }
  EXPECT_GT(double_wrong, 1900);  // plain double arithmetic would fail this test
}

// A reduced cost as the certificate computes it: 1 - y.a with |y| ~ 1e8 and a near-cancelling a.
// Double loses ~1e-8; the double-double value agrees with a quad-precision reference (GCC's
// __float128) to ~1e-22, and so is far inside the certificate's 1e-11 budget.
TEST(DoubleDouble, ReducedCostsWithLargeDualsMatchQuadPrecision) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> normal;
  double worst_double = 0, worst_pair = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    double y_hi[5], a[5];
    DoubleDouble y[5];
    __float128 reference = 1;
    for (int r = 0; r < 5; ++r) {
      y_hi[r] = 1e8 * normal(rng);
      y[r] = two_sum(y_hi[r], 1e-9 * normal(rng));  // duals refined beyond double
      a[r] = normal(rng);
    }
    // Make y.a nearly 1 so that the reduced cost is small (a basic or near-basic column).
    long double partial = 0;
    for (int r = 0; r < 4; ++r) partial += to_long_double(y[r]) * a[r];
    a[4] = double((1 - partial) / to_long_double(y[4]));
    DoubleDouble d{1, 0};
    double naive = 1;
    for (int r = 0; r < 5; ++r) {
      add_product(d, y[r], -a[r]);
      naive -= y[r].hi * a[r];
      reference -= ((__float128)y[r].hi + y[r].lo) * a[r];
    }
    const __float128 pair_error = ((__float128)d.hi + d.lo) - reference,
                     double_error = naive - reference;
    worst_pair = std::max(worst_pair, std::abs(double(pair_error)));
    worst_double = std::max(worst_double, std::abs(double(double_error)));
  }
  EXPECT_LT(worst_pair, 1e-20);
  EXPECT_GT(worst_double, 1e-9);  // what the certificate could not have certified in double
}

}  // namespace
}  // namespace mb::lp
