// Every SIMD path of the fast simplex's lane kernels against its scalar reference, bit for bit
// (src/lp/lanes/lanes.h): random inputs with ties, NaNs, signed zeros and every tail length, for
// each path this build has (AVX-512 builds test the AVX2 paths too). A path that drifted by one
// rounding, or chose another index on a tie, would make answers depend on the instruction set.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "lp/lanes/lanes.h"

namespace mb::lp::fast::lanes {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool same_bits(double a, double b) {
  return std::bit_cast<uint64_t>(a) == std::bit_cast<uint64_t>(b);
}
::testing::AssertionResult same_bits(const double* a, const double* b, int n) {
  for (int i = 0; i < n; ++i)
    if (!same_bits(a[i], b[i]))
      return ::testing::AssertionFailure() << "entry " << i << ": " << a[i] << " vs " << b[i];
  return ::testing::AssertionSuccess();
}

// Values from a small set (ties are common), sometimes NaN or -0, sometimes continuous.
struct Inputs {
  std::mt19937_64 rng{12345};
  double value() {
    std::uniform_int_distribution<int> kind(0, 9);
    std::uniform_real_distribution<double> real(-2, 2);
    switch (kind(rng)) {
      case 0:
        return kNaN;
      case 1:
        return -0.0;
      case 2:
      case 3:
        return double(std::uniform_int_distribution<int>(-3, 3)(rng)) / 4;
      default:
        return real(rng);
    }
  }
  std::vector<double> values(int n) {
    std::vector<double> v(size_t(n) + 8, kNaN);  // padding: a path must not read what it masks
    for (int i = 0; i < n; ++i) v[i] = value();
    return v;
  }
  std::vector<double> finite(int n) {
    std::vector<double> v = values(n);
    for (int i = 0; i < n; ++i)
      if (v[i] != v[i]) v[i] = 0.5;
    return v;
  }
};

constexpr int kRounds = 300;

#define FOR_EACH_PATH(CHECK) \
  AVX2_PATH(CHECK)           \
  AVX512_PATH(CHECK)
#if defined(__AVX2__) && defined(__FMA__)
#define AVX2_PATH(CHECK) CHECK(avx2)
#else
#define AVX2_PATH(CHECK)
#endif
#ifdef __AVX512F__
#define AVX512_PATH(CHECK) CHECK(avx512)
#else
#define AVX512_PATH(CHECK)
#endif

TEST(LpLanes, ReductionsAndSearches) {
  Inputs in;
  for (int round = 0; round < kRounds; ++round) {
    const int n = round % 41;
    const auto d = in.values(n);
    const double threshold = in.finite(1)[0];
    const double target = n > 0 && round % 3 ? d[round % n] : in.finite(1)[0];
    const double smallest = scalar::smallest_of(d.data(), n);
    const int first = scalar::first_holding(d.data(), n, target);
    const bool below = scalar::any_below(d.data(), n, threshold);
    std::vector<int> visited;
    scalar::for_each_below(d.data(), n, threshold, [&](int j) { visited.push_back(j); });
#define CHECK(path)                                                                          \
  {                                                                                          \
    EXPECT_TRUE(same_bits(path::smallest_of(d.data(), n), smallest)) << #path << " n " << n; \
    EXPECT_EQ(path::first_holding(d.data(), n, target), first) << #path << " n " << n;       \
    std::vector<int> seen;                                                                   \
    path::for_each_below(d.data(), n, threshold, [&](int j) { seen.push_back(j); });         \
    EXPECT_EQ(seen, visited) << #path;                                                       \
  }
    FOR_EACH_PATH(CHECK)
#undef CHECK
#ifdef __AVX512F__
    EXPECT_EQ(avx512::any_below(d.data(), n, threshold), below);
#endif
  }
}

template <int K>
void check_combine(Inputs& in) {
  for (int round = 0; round < kRounds; ++round) {
    const int n = round % 37;
    const auto values = in.finite(K * n + 8), base = in.finite(n), w = in.finite(K);
    const bool with_base = round % 2;
    std::vector<double> expected(n + 8, kNaN), got(n + 8, kNaN);
    const double smallest = scalar::combine<K>(
        w.data(), values.data(), size_t(n), with_base ? base.data() : nullptr, expected.data(), n);
#define CHECK(path)                                                                      \
  {                                                                                      \
    std::fill(got.begin(), got.end(), kNaN);                                             \
    const double s = path::combine<K>(w.data(), values.data(), size_t(n),                \
                                      with_base ? base.data() : nullptr, got.data(), n); \
    EXPECT_TRUE(same_bits(s, smallest)) << #path;                                        \
    EXPECT_TRUE(same_bits(got.data(), expected.data(), n + 8))                           \
        << #path << " K " << K << " n " << n;                                            \
  }
    FOR_EACH_PATH(CHECK)
#undef CHECK
#ifdef __AVX512F__
    // Row 0 constant: read from a register, the same bits.
    std::vector<double> constant = values;
    for (int j = 0; j < n; ++j) constant[j] = values[0];
    scalar::combine<K>(w.data(), constant.data(), size_t(n), nullptr, expected.data(), n);
    avx512::combine<K>(w.data(), constant.data(), size_t(n), nullptr, got.data(), n, values[0]);
    EXPECT_TRUE(same_bits(got.data(), expected.data(), n));
#endif
  }
}

TEST(LpLanes, PricingCombination) {
  Inputs in;
  check_combine<1>(in);
  check_combine<3>(in);
  check_combine<5>(in);
  check_combine<8>(in);
}

template <int K>
void check_basis_kernels(Inputs& in) {
  for (int round = 0; round < kRounds; ++round) {
    double binv[kMaxRows][kMaxRows], expected[kMaxRows][kMaxRows];
    for (auto& row : binv)
      for (double& v : row) v = in.finite(1)[0];
    const auto u = in.finite(kMaxRows);
    std::vector<double> uu(u.begin(), u.end());
    if (round % 3 == 0) uu[round % K] = 0;  // rows with u_i = 0 stay
    const int leave = round % K;
    if (uu[leave] == 0) uu[leave] = 0.75;
    std::memcpy(expected, binv, sizeof binv);
    scalar::update_inverse<K>(expected, leave, uu.data(), 1 / uu[leave]);
#ifdef __AVX512F__
    double got[kMaxRows][kMaxRows];
    std::memcpy(got, binv, sizeof binv);
    avx512::update_inverse<K>(got, leave, uu.data(), 1 / uu[leave]);
    EXPECT_TRUE(same_bits(&got[0][0], &expected[0][0], kMaxRows * kMaxRows)) << "K " << K;
    EXPECT_EQ(avx512::same_row<K>(binv[0], binv[0]), scalar::same_row<K>(binv[0], binv[0]));
    EXPECT_EQ(avx512::same_row<K>(binv[0], binv[1]), scalar::same_row<K>(binv[0], binv[1]));
#endif
    // Basic points: grid, extra and other (composite, artificial) columns.
    const int g = 20, n = 30;
    const auto grid = in.finite(g), extra = in.finite(n - g);
    int basis[kMaxRows];
    for (int i = 0; i < kMaxRows; ++i) basis[i] = int((in.rng() % 40));
    double points[kMaxRows];
    scalar::basic_points<K>(basis, g, n, grid.data(), extra.data(), points);
    // Partner and limit searches on those points (NaN: no point).
    const double z = in.finite(1)[0], direction = round % 2 ? 1.0 : -1.0;
    const int skip = round % K;
    const int partner = scalar::nearest_other<K>(points, z, skip);
    const unsigned mask = 1u << skip | (partner >= 0 ? 1u << partner : 0u);
    const double limit = scalar::nearest_beyond<K>(points, z, direction, mask);
    // misfit in double-double, both orientations.
    DoubleDouble v[kMaxRows];
    for (auto& x : v) x = {in.finite(1)[0], in.finite(1)[0] * 1e-17};
    const auto target = in.finite(kMaxRows);
    double plain[kMaxRows], transposed[kMaxRows];
    scalar::misfit<K, false>(binv, v, target.data(), plain);
    scalar::misfit<K, true>(binv, v, target.data(), transposed);
#ifdef __AVX512F__
    double got_points[kMaxRows];
    avx512::basic_points<K>(basis, g, n, grid.data(), extra.data(), got_points);
    EXPECT_TRUE(same_bits(got_points, points, K));
    EXPECT_EQ(avx512::nearest_other<K>(points, z, skip), partner);
    EXPECT_TRUE(same_bits(avx512::nearest_beyond<K>(points, z, direction, mask), limit))
        << avx512::nearest_beyond<K>(points, z, direction, mask) << " vs " << limit;
    double got_plain[kMaxRows], got_transposed[kMaxRows];
    avx512::misfit<K, false>(binv, v, target.data(), got_plain);
    avx512::misfit<K, true>(binv, v, target.data(), got_transposed);
    EXPECT_TRUE(same_bits(got_plain, plain, K));
    EXPECT_TRUE(same_bits(got_transposed, transposed, K));
#else
    (void)partner, (void)limit, (void)plain, (void)transposed;
#endif
  }
}

TEST(LpLanes, BasisKernels) {
  Inputs in;
  check_basis_kernels<2>(in);
  check_basis_kernels<5>(in);
  check_basis_kernels<8>(in);
}

template <int K>
void check_walks(Inputs& in) {
  for (int round = 0; round < kRounds; ++round) {
    const int n = 1 + round % 40;
    // An ascending grid with phi changing sign somewhere, and extra points with ties.
    std::vector<double> grid(n + 8, kNaN);
    for (int i = 0; i < n; ++i) grid[i] = double(i) / n;
    const auto values = in.finite(K * n + 8), v = in.finite(K);
    const int step = round % 2 ? 1 : -1, start = int(in.rng() % n);
    const double limit = step * (round % 5 == 0 ? 0.5 : std::numeric_limits<double>::infinity());
    const int walk =
        scalar::first_sign_change<K>(v.data(), grid.data(), values.data(), n, start, step, limit);
    auto points = in.finite(n);
    for (int i = 0; i < n; ++i) points[i] = std::round(points[i] * 8) / 8;  // ties
    const double lo = -0.5, hi = 0.75, previous = 0.125;
    int near, far;
    scalar::bracket_extras<K>(v.data(), points.data(), values.data(), n, lo, hi, previous, near,
                              far);
    const double from[3] = {0.0, 0.25, -0.25}, direction[3] = {1, -1, 1};
    const double distance[3] = {0.3, std::numeric_limits<double>::infinity(), 0.125};
    int beyond[3] = {-7, -7, -7};
    scalar::nearest_beyond_each<3>(from, direction, distance, points.data(), n, beyond);
#ifdef __AVX512F__
    EXPECT_EQ(
        avx512::first_sign_change<K>(v.data(), grid.data(), values.data(), n, start, step, limit),
        walk)
        << "n " << n << " start " << start << " step " << step;
    int got_near, got_far;
    avx512::bracket_extras<K>(v.data(), points.data(), values.data(), n, lo, hi, previous, got_near,
                              got_far);
    EXPECT_EQ(got_near, near);
    EXPECT_EQ(got_far, far);
#else
    (void)walk, (void)near, (void)far;
#endif
#define CHECK(path)                                                                  \
  {                                                                                  \
    int got[3] = {-7, -7, -7};                                                       \
    path::nearest_beyond_each<3>(from, direction, distance, points.data(), n, got);  \
    for (int q = 0; q < 3; ++q) EXPECT_EQ(got[q], beyond[q]) << #path << " q " << q; \
  }
    FOR_EACH_PATH(CHECK)
#undef CHECK
  }
}

TEST(LpLanes, BracketWalks) {
  Inputs in;
  check_walks<2>(in);
  check_walks<5>(in);
  check_walks<8>(in);
}

template <int K>
void check_greatest_decrease(Inputs& in) {
  for (int round = 0; round < kRounds; ++round) {
    const int n = round % 35;
    double binv[kMaxRows][kMaxRows];
    for (auto& row : binv)
      for (double& v : row) v = in.finite(1)[0];
    const auto weight = in.finite(kMaxRows), values = in.finite(K * n + 8);
    auto d = in.finite(n);
    for (double& x : d) x = -std::abs(x);
    double best = round % 4 ? 0.0 : -0.1;
    int column = -1;
    scalar::greatest_decrease<K>(binv, weight.data(), values.data(), size_t(n), d.data(), 3, n,
                                 1e-11, 1e-9, best, column);
#ifdef __AVX512F__
    double got_best = round % 4 ? 0.0 : -0.1;
    int got_column = -1;
    avx512::greatest_decrease<K>(binv, weight.data(), values.data(), size_t(n), d.data(), 3, n,
                                 1e-11, 1e-9, got_best, got_column);
    EXPECT_EQ(got_column, column) << "n " << n;
    EXPECT_TRUE(same_bits(got_best, best));
#else
    (void)column;
#endif
  }
}

TEST(LpLanes, GreatestDecrease) {
  Inputs in;
  check_greatest_decrease<3>(in);
  check_greatest_decrease<5>(in);
}

TEST(LpLanes, WarmOffers) {
  Inputs in;
  for (int round = 0; round < kRounds; ++round) {
    double distance[24], expected[24];
    int usable = 0;
    for (int b = 0; b < 3; ++b) {
      auto zf = in.values(8);
      const bool none = round % 7 == b;
      usable += scalar::offer_distances(none ? nullptr : zf.data(), 0.25, expected + 8 * b);
#ifdef __AVX512F__
      EXPECT_EQ(avx512::offer_distances(none ? nullptr : zf.data(), 0.25, distance + 8 * b),
                scalar::offer_distances(none ? nullptr : zf.data(), 0.25, expected + 8 * b));
#endif
    }
#ifdef __AVX512F__
    EXPECT_TRUE(same_bits(distance, expected, 24));
    if (usable > 0) {
      EXPECT_EQ(avx512::closest(expected, 24), scalar::closest(expected, 24));
    }
#else
    (void)distance;
#endif
  }
}

TEST(LpLanes, FrontCosts) {
  Inputs in;
  for (int round = 0; round < kRounds; ++round) {
    const int n = round % 29;
    const auto points = in.values(n);
    std::vector<double> expected(n + 8, -1), got(n + 8, -1);
    scalar::front_costs(points.data(), n, 0.1, expected.data());
#ifdef __AVX512F__
    avx512::front_costs(points.data(), n, 0.1, got.data());
    EXPECT_TRUE(same_bits(got.data(), expected.data(), n + 8));
#endif
  }
}

TEST(LpLanes, BuildPathIsNamed) {
  // The path the solver uses in this build (recorded with benchmark tables).
  const std::string path = kPath;
  EXPECT_TRUE(path == "avx512" || path == "avx2" || path == "scalar") << path;
}

}  // namespace
}  // namespace mb::lp::fast::lanes
