#pragma once
// Double-double numbers (a + b, |b| <= ulp(a) / 2, ~106 bits) from error-free transformations
// (Knuth's two-sum, an FMA for the product's rounding error), for the fast backend's certificate
// (docs/reference.md §2: G to 1e-9 needs reduced costs y.a accurate to ~1e-11 while |y| reaches
// 1e8). Unlike x87 long double (64 bits) they live in SSE registers and pipeline like plain
// doubles. Needs IEEE double arithmetic: no -ffast-math (reassociation would cancel the error
// terms).
#include <cmath>

#ifdef __AVX512F__
#include "util/simd_intrinsics.h"
#endif

namespace mb::lp {

// Normalised (|lo| <= ulp(hi) / 2) from two_sum, fast_two_sum, add and to_double_double; a sum that
// add_product accumulated is not, and is read with value().
struct DoubleDouble {
  double hi = 0, lo = 0;
  double value() const { return hi + lo; }
};

// a + b exactly, as a rounded sum and its error.
inline DoubleDouble two_sum(double a, double b) {
  const double s = a + b, bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}

// Renormalised a + b where |a| >= |b| (or a = 0).
inline DoubleDouble fast_two_sum(double a, double b) {
  const double s = a + b;
  return {s, b - (s - a)};
}

// acc += b c for a double-double b and a double c, as in Ogita, Rump and Oishi's Dot2: hi is the
// running double sum, and every rounding error (of the product, from an FMA, and of the sum, from
// two_sum) goes into lo in double, without renormalising the pair each step; read the sum with
// value(). The result is as accurate as a renormalised double-double sum for these few terms
// (error ~eps |sum| + ~eps^2 sum |terms|), and the chain from one term to the next is one add
// where a two-sum and a renormalisation were ~7 dependent ones (the precise certificate's residuals
// are such chains).
inline void add_product(DoubleDouble& acc, DoubleDouble b, double c) {
  // (Both FMAs explicit: the same bits whether or not the compiler contracts, as the lanes do.)
  const double p = b.hi * c, e = std::fma(b.lo, c, std::fma(b.hi, c, -p));
  const DoubleDouble s = two_sum(acc.hi, p);
  acc = {s.hi, s.lo + acc.lo + e};
}
inline void add_product(DoubleDouble& acc, double b, double c) {
  add_product(acc, DoubleDouble{b, 0}, c);
}

// acc += v.
inline void add(DoubleDouble& acc, double v) {
  const DoubleDouble s = two_sum(acc.hi, v);
  acc = fast_two_sum(s.hi, s.lo + acc.lo);
}

// A long double's value as a double-double (exact: 64 bits fit in two doubles).
inline DoubleDouble to_double_double(long double v) {
  const double hi = double(v);
  return {hi, double(v - hi)};
}
inline long double to_long_double(DoubleDouble v) {
  return (long double)v.hi + v.lo;
}
inline long double to_long_double(double v) {
  return v;
}

#ifdef __AVX512F__
// Eight double-doubles side by side, one a lane: the certificate's k <= 8 sums (rows of B x, or
// positions of B^T y) at once. Every lane runs exactly the scalar functions' operations in their
// order, FMAs included, so each lane's result has the
// same bits as the scalar one: one sum at a time, the dependent chains of the two-sums were most
// of the certificate's time.
struct DoubleDouble8 {
  __m512d hi = _mm512_setzero_pd(), lo = _mm512_setzero_pd();
};

inline DoubleDouble8 two_sum(__m512d a, __m512d b) {
  const __m512d s = _mm512_add_pd(a, b), bb = _mm512_sub_pd(s, a);
  return {s, _mm512_add_pd(_mm512_sub_pd(a, _mm512_sub_pd(s, bb)), _mm512_sub_pd(b, bb))};
}
// acc += b c, lane by lane, for one double-double b (broadcast) and eight doubles c (Dot2, as the
// scalar add_product).
inline void add_product(DoubleDouble8& acc, DoubleDouble b, __m512d c) {
  const __m512d high = _mm512_set1_pd(b.hi), p = _mm512_mul_pd(high, c);
  const __m512d e = _mm512_fmadd_pd(_mm512_set1_pd(b.lo), c, _mm512_fmsub_pd(high, c, p));
  const DoubleDouble8 s = two_sum(acc.hi, p);
  acc = {s.hi, _mm512_add_pd(_mm512_add_pd(s.lo, acc.lo), e)};
}
inline __m512d value(const DoubleDouble8& v) {
  return _mm512_add_pd(v.hi, v.lo);
}
#endif

}  // namespace mb::lp
