#include "moments/canonical_bound.h"

#include <cmath>
#include <numbers>

#include "moments/canonical.h"
#include "util/eigen.h"

namespace mb {

namespace {

using Complex = std::complex<double>;
// At most (n + 1) x (n + 1): fixed maximum sizes keep every matrix on the stack.
constexpr int kMax = kMaxCanonicalOrder + 1;
using ComplexMatrix =
    Eigen::Matrix<std::complex<double>, Eigen::Dynamic, Eigen::Dynamic, 0, kMax, kMax>;
using ComplexVector = Eigen::Matrix<std::complex<double>, Eigen::Dynamic, 1, 0, kMax, 1>;

// The roots of sum_j a_j x^j (a_0 .. a_degree, complex) as the eigenvalues of the companion
// matrix; leading coefficients that vanish against the largest are dropped first (a node that
// went to infinity).
int polynomial_roots(const ComplexVector& a, Complex* roots) {
  int degree = int(a.size()) - 1;
  const double scale = a.cwiseAbs().maxCoeff();
  while (degree > 0 && std::abs(a[degree]) <= 1e-13 * scale) --degree;
  if (degree == 0) return 0;
  if (degree == 2) {  // the quadratic formula without cancellation
    const Complex b = a[1] / a[2], c = a[0] / a[2], root = std::sqrt(b * b - 4.0 * c);
    const Complex q = -0.5 * (std::real(std::conj(b) * root) >= 0 ? b + root : b - root);
    roots[0] = q;
    roots[1] = q != Complex(0) ? c / q : -b - q;
    return 2;
  }
  ComplexMatrix companion = ComplexMatrix::Zero(degree, degree);
  for (int i = 1; i < degree; ++i) companion(i, i - 1) = 1;
  for (int i = 0; i < degree; ++i) companion(i, degree - 1) = -a[i] / a[degree];
  Eigen::ComplexEigenSolver<ComplexMatrix> solver(companion, false);
  if (solver.info() != Eigen::Success) return -1;
  for (int i = 0; i < degree; ++i) roots[i] = solver.eigenvalues()[i];
  return degree;
}

// The canonical representation of a positive definite moment matrix M = E[v(x) v(x)^H] through
// x_f (docs/transparency.md §5): the polynomial v(x)^H M^{-1} v(x_f) (the minimiser of the
// Christoffel function at x_f, up to a factor) vanishes at the other nodes, and each node's weight
// is the Christoffel function 1 / (v^H M^{-1} v) there.
// `project` puts a computed root back on the set it lies on in exact arithmetic (R or the unit
// circle); `position` gives the node's coordinate.
template <class V>
bool canonical(const ComplexMatrix& moments, Complex query, V v, CanonicalNodes& out,
               Complex (*project)(Complex), double (*position)(Complex),
               int (*roots_of)(const ComplexVector&, Complex*)) {
  Eigen::LLT<ComplexMatrix> llt(moments);
  if (llt.info() != Eigen::Success) return false;
  const ComplexVector a = llt.solve(v(query));
  // p(x) = sum_j conj(a_j) x^j.
  Complex roots[kMaxCanonicalOrder];
  const int found = roots_of(a.conjugate(), roots);
  if (found < 0) return false;
  out.count = 0;
  const auto add = [&](Complex root) {
    const Complex x = project(root);
    const ComplexVector vx = v(x);
    const double k = std::real(vx.dot(llt.solve(vx)));  // v^H M^{-1} v
    if (!(k > 0) || !std::isfinite(k)) return false;
    out.nodes[out.count] = position(x);
    out.weights[out.count++] = 1 / k;
    return true;
  };
  if (!add(query)) return false;
  for (int i = 0; i < found; ++i)
    if (!add(roots[i])) return false;
  return true;
}

// A real polynomial's n <= 4 roots, all real for a positive definite Hankel matrix: by the closed
// forms of moments/canonical.h (Ferrari for four), else (fewer real roots found, from rounding)
// by the companion matrix.
int real_polynomial_roots(const ComplexVector& a, Complex* roots) {
  const int degree = int(a.size()) - 1;
  double c[kMax], found[kMaxCanonicalOrder];
  for (int j = 0; j <= degree; ++j) c[j] = a[j].real();
  int count = 0;
  if (degree == 4) count = quartic_roots(c[4], c[3], c[2], c[1], c[0], found);
  if (degree == 3) count = cubic_roots(c[3], c[2], c[1], c[0], found);
  if (degree == 2 && c[2] != 0) quadratic_roots(c[2], c[1], c[0], found[0], found[1]), count = 2;
  if (count != degree || !std::isfinite(found[0])) return polynomial_roots(a, roots);
  for (int i = 0; i < count; ++i) roots[i] = found[i];
  return count;
}

}  // namespace

bool canonical_power(const double* b, int n, double xf, CanonicalNodes& out) {
  if (n < 1 || n > kMaxCanonicalOrder) return false;
  ComplexMatrix hankel(n + 1, n + 1);
  for (int j = 0; j <= n; ++j)
    for (int k = 0; k <= n; ++k) hankel(j, k) = j + k == 0 ? 1.0 : b[j + k - 1];
  const auto v = [n](Complex x) {
    ComplexVector out(n + 1);
    Complex power = 1;
    for (int j = 0; j <= n; ++j, power *= x) out[j] = power;
    return out;
  };
  // The roots are real for a positive definite Hankel matrix; rounding leaves tiny imaginary parts.
  return canonical(
      hankel, Complex(xf), v, out, [](Complex x) { return Complex(x.real()); },
      [](Complex x) { return x.real(); }, real_polynomial_roots);
}

bool canonical_trigonometric(const std::complex<double>* c, int n, double phi_f,
                             CanonicalNodes& out) {
  if (n < 1 || n > kMaxCanonicalOrder) return false;
  // M_jk = E[z^j conj(z)^k] = c_{j-k}, c_{-k} = conj(c_k).
  ComplexMatrix toeplitz(n + 1, n + 1);
  for (int j = 0; j <= n; ++j)
    for (int k = 0; k <= n; ++k) {
      const int d = j - k;
      toeplitz(j, k) = d == 0 ? Complex(1) : d > 0 ? c[d - 1] : std::conj(c[-d - 1]);
    }
  const auto v = [n](Complex z) {
    ComplexVector out(n + 1);
    Complex power = 1;
    for (int j = 0; j <= n; ++j, power *= z) out[j] = power;
    return out;
  };
  // The roots lie on the unit circle for a positive definite Toeplitz matrix (the kernel
  // polynomial at a point of the circle is para-orthogonal); the angle is what counts.
  const auto angle = [](Complex z) {
    const double a = std::arg(z);
    return a < 0 ? a + 2 * std::numbers::pi : a;
  };
  return canonical(
      toeplitz, std::polar(1.0, phi_f), v, out, [](Complex z) { return z / std::abs(z); }, angle,
      polynomial_roots);
}

}  // namespace mb
