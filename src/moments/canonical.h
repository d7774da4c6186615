#pragma once
// Small pieces shared by the closed-form solvers (docs/reference.md §4): moment bias, the weights
// of a distribution on given nodes that reproduces given power moments, and real polynomial roots.
#include <algorithm>
#include <cmath>

namespace mb {

// b <- (1 - alpha) b + alpha b* (docs/reference.md §4), for m values.
template <class Real>
void bias_moments(Real* b, int m, Real alpha, const Real* b_star) {
  for (int j = 0; j < m; ++j) b[j] = (1 - alpha) * b[j] + alpha * b_star[j];
}

// Weight at nodes[i] of the distribution on `count` distinct nodes whose power moments
// 1, b1, .., b_{count-1} equal `moments` (moments[0] = 1): Lagrange interpolation,
// w_i = E[prod_{q != i} (Z - z_q)] / prod_{q != i} (z_i - z_q).
template <class Real>
Real node_weight(const Real* moments, const Real* nodes, int count, int i) {
  Real poly[8] = {1};  // coefficients of prod (z - z_q), lowest first
  int degree = 0;
  Real denominator = 1;
  for (int q = 0; q < count; ++q) {
    if (q == i) continue;
    for (int d = degree + 1; d > 0; --d) poly[d] = poly[d - 1] - nodes[q] * poly[d];
    poly[0] = -nodes[q] * poly[0];
    ++degree;
    denominator *= nodes[i] - nodes[q];
  }
  Real numerator = 0;
  for (int d = 0; d <= degree; ++d) numerator += poly[d] * moments[d];
  return numerator / denominator;
}

// Real roots of c2 z^2 + c1 z + c0 in ascending order, by the cancellation-free formula
// (q = -(c1 + sign(c1) sqrt(disc)) / 2, roots q / c2 and c0 / q); a negative discriminant (only
// from rounding, for a positive definite Hankel matrix) is clamped to a double root.
template <class Real>
void quadratic_roots(Real c2, Real c1, Real c0, Real& low, Real& high) {
  const Real root = std::sqrt(std::max(Real(0), c1 * c1 - 4 * c2 * c0));
  const Real q = -(c1 + std::copysign(root, c1)) / 2;
  Real a = q / c2, b = q != 0 ? c0 / q : a;
  low = std::min(a, b);
  high = std::max(a, b);
}

// The three real roots of c3 z^3 + c2 z^2 + c1 z + c0 (ascending), by the trigonometric method for
// a depressed cubic, each polished by two Newton steps. Returns the number of roots found.
int cubic_roots(double c3, double c2, double c1, double c0, double* roots);

// The real roots of c4 z^4 + c3 z^3 + c2 z^2 + c1 z + c0 (ascending; 0, 2 or 4 of them, a
// double root counted twice), by Ferrari's method: the largest root of the resolvent cubic
// splits the depressed quartic into two quadratics; each root is then polished by two Newton
// steps on the quartic. Falls back to the cubic when c4 is negligible. Real = float or double.
template <class Real>
int quartic_roots(Real c4, Real c3, Real c2, Real c1, Real c0, Real* roots);

}  // namespace mb
