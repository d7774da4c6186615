#pragma once
// The canonical representation through a point, for any number of power moments on R (Hankel)
// or trigonometric moments on the circle (Toeplitz): the n + 1 point distribution with the given
// moments that has a node at the query point (docs/transparency.md §5). Its mass in front of the
// point is Hamburger's sharp lower bound for power moments (as hamburger4/6 compute in closed
// form) and MBOIT's reconstruction for both kinds.
#include <complex>

namespace mb {

constexpr int kMaxCanonicalOrder = 4;  // n: up to 8 power or 4 trigonometric moments

struct CanonicalNodes {
  int count = 0;  // n + 1 nodes normally; fewer where the kernel polynomial loses degree
  // Power: positions on R; trigonometric: angles in [0, 2 pi). Node 0 is the query point.
  double nodes[kMaxCanonicalOrder + 1] = {};
  double weights[kMaxCanonicalOrder + 1] = {};
};

// b = (b_1, .., b_2n) power moments of a probability distribution on R (positive definite Hankel
// matrix, e.g. after a bias); false where the Hankel matrix is not numerically positive definite.
bool canonical_power(const double* b, int n, double xf, CanonicalNodes& out);

// c = (c_1, .., c_n), c_k = E[e^{i k phi}] of a probability distribution on the circle (positive
// definite Toeplitz matrix); the query angle phi_f. False as above.
bool canonical_trigonometric(const std::complex<double>* c, int n, double phi_f,
                             CanonicalNodes& out);

}  // namespace mb
