#pragma once
// Double-double numbers (a + b, |b| <= ulp(a) / 2, ~106 bits) from error-free transformations
// (Knuth's two-sum, an FMA for the product's rounding error), for the fast backend's certificate
// (REFERENCE.md §2: G to 1e-9 needs reduced costs y.a accurate to ~1e-11 while |y| reaches 1e8).
// Unlike x87 long double (64 bits) they live in SSE registers and pipeline like plain doubles.
// Needs IEEE double arithmetic: no -ffast-math (reassociation would cancel the error terms).
#include <cmath>

namespace mb::lp {

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

// acc += b c for a double-double b and a double c. The low-order products are added in double:
// their rounding is ~2^-106 of the terms, far below what the certificate needs.
inline void add_product(DoubleDouble& acc, DoubleDouble b, double c) {
  const double p = b.hi * c, e = std::fma(b.hi, c, -p) + b.lo * c;
  const DoubleDouble s = two_sum(acc.hi, p);
  acc = fast_two_sum(s.hi, s.lo + acc.lo + e);
}
inline void add_product(DoubleDouble& acc, double b, double c) { add_product(acc, DoubleDouble{b, 0}, c); }

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
inline long double to_long_double(DoubleDouble v) { return (long double)v.hi + v.lo; }

}  // namespace mb::lp
