#include "moments/canonical.h"

#include <limits>
#include <numbers>

namespace mb {

int cubic_roots(double c3, double c2, double c1, double c0, double* roots) {
  const double a = c2 / c3, b = c1 / c3, c = c0 / c3;
  // z = t - a/3: t^3 + p t + q = 0.
  const double p = b - a * a / 3, q = 2 * a * a * a / 27 - a * b / 3 + c;
  int count = 0;
  if (p < 0) {
    const double r = 2 * std::sqrt(-p / 3);
    const double argument = std::clamp(3 * q / (p * r), -1.0, 1.0);
    const double phi = std::acos(argument) / 3;
    for (int k = 0; k < 3; ++k)
      roots[count++] = r * std::cos(phi - 2 * std::numbers::pi * k / 3) - a / 3;
  } else {
    roots[count++] = std::cbrt(-q) - a / 3;  // one real root (only from rounding here)
  }
  for (int k = 0; k < count; ++k)
    for (int step = 0; step < 2; ++step) {
      double z = roots[k];
      double f = ((z + a) * z + b) * z + c, df = (3 * z + 2 * a) * z + b;
      if (df != 0) roots[k] = z - f / df;
    }
  std::sort(roots, roots + count);
  return count;
}

namespace {

// The largest real root of m^3 + a m^2 + b m + c (Cardano with one real root, the trigonometric
// form with three).
template <class Real>
Real largest_cubic_root(Real a, Real b, Real c) {
  const Real p = b - a * a / 3, q = 2 * a * a * a / 27 - a * b / 3 + c;
  const Real disc = q * q / 4 + p * p * p / 27;
  Real t;
  if (disc > 0) {
    const Real r = std::sqrt(disc);
    t = std::cbrt(-q / 2 + r) + std::cbrt(-q / 2 - r);
  } else if (p < 0) {
    const Real r = 2 * std::sqrt(-p / 3);
    t = r * std::cos(std::acos(std::clamp(3 * q / (p * r), Real(-1), Real(1))) / 3);
  } else {
    t = std::cbrt(-q);
  }
  return t - a / 3;
}

// Appends the real roots of t^2 + b t + c (cancellation-free), shifted by `shift`.
template <class Real>
void append_quadratic_roots(Real b, Real c, Real shift, Real* roots, int& count) {
  const Real disc = b * b - 4 * c;
  if (disc < 0) return;
  const Real q = -(b + std::copysign(std::sqrt(disc), b)) / 2;
  roots[count++] = q + shift;
  roots[count++] = (q != 0 ? c / q : q) + shift;
}

}  // namespace

template <class Real>
int quartic_roots(Real c4, Real c3, Real c2, Real c1, Real c0, Real* roots) {
  const Real scale = std::max({std::abs(c3), std::abs(c2), std::abs(c1), std::abs(c0)});
  if (!(std::abs(c4) > scale * std::numeric_limits<Real>::epsilon() * 16)) {
    if (!(std::abs(c3) > scale * std::numeric_limits<Real>::epsilon() * 16)) {
      int count = 0;
      if (c2 != 0) append_quadratic_roots(c1 / c2, c0 / c2, Real(0), roots, count);
      std::sort(roots, roots + count);
      return count;
    }
    double r[3];
    const int count = cubic_roots(double(c3), double(c2), double(c1), double(c0), r);
    for (int k = 0; k < count; ++k) roots[k] = Real(r[k]);
    return count;
  }
  const Real A = c3 / c4, B = c2 / c4, C = c1 / c4, D = c0 / c4;
  // z = t - A/4: t^4 + p t^2 + q t + r.
  const Real p = B - 3 * A * A / 8, q = C - A * B / 2 + A * A * A / 8,
             r = D - A * C / 4 + A * A * B / 16 - 3 * A * A * A * A / 256;
  // (t^2 + m)^2 = (2m - p) t^2 - q t + m^2 - r is a square when 8m^3 - 4p m^2 - 8r m + 4pr - q^2
  // = 0; its largest root has 2m >= p (the cubic is -q^2 <= 0 at m = p/2).
  const Real m = largest_cubic_root(-p / 2, -r, (4 * p * r - q * q) / 8);
  const Real sigma2 = 2 * m - p, shift = -A / 4;
  int count = 0;
  if (sigma2 > std::numeric_limits<Real>::epsilon() * (std::abs(p) + std::abs(m))) {
    const Real sigma = std::sqrt(sigma2);
    append_quadratic_roots(-sigma, m + q / (2 * sigma), shift, roots, count);
    append_quadratic_roots(sigma, m - q / (2 * sigma), shift, roots, count);
  } else {  // q ~ 0: biquadratic t^4 + p t^2 + r
    Real squares[2];
    int n = 0;
    append_quadratic_roots(p, r, Real(0), squares, n);
    for (int k = 0; k < n; ++k)
      if (squares[k] >= 0) {
        roots[count++] = std::sqrt(squares[k]) + shift;
        roots[count++] = -std::sqrt(squares[k]) + shift;
      }
  }
  for (int k = 0; k < count; ++k)
    for (int step = 0; step < 2; ++step) {
      const Real z = roots[k];
      const Real f = (((z + A) * z + B) * z + C) * z + D,
                 df = ((4 * z + 3 * A) * z + 2 * B) * z + C;
      if (df != 0 && std::isfinite(f / df)) roots[k] = z - f / df;
    }
  std::sort(roots, roots + count);
  return count;
}

template int quartic_roots<float>(float, float, float, float, float, float*);
template int quartic_roots<double>(double, double, double, double, double, double*);

}  // namespace mb
