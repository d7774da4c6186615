#include "moments/hamburger.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "moments/canonical.h"
#include "util/eigen.h"

namespace mb {

namespace {

// G = the mass of the canonical distribution strictly below z_f: node 0 is z_f itself.
template <class Real>
void finish_bound(MsmBound<Real>& r, const Real* moments, Real zf) {
  for (int i = 0; i < r.node_count; ++i)
    r.weights[i] = node_weight(moments, r.nodes, r.node_count, i);
  Real lower = 0;
  for (int i = 1; i < r.node_count; ++i)
    if (r.nodes[i] < zf) lower += r.weights[i];
  r.lower = std::clamp(lower, Real(0), Real(1));
  r.at_zf = std::clamp(r.weights[0], Real(0), Real(1));
}

// Steps 1-3 of Algorithm 3 for one fragment, shared by the scalar solver and the stream form
// (which inlines it to vectorise): the nodes z2 <= z3 of the canonical distribution with a node
// at z_f, its weights at z_f and at z2, and the lower bound.
template <class Real>
struct Hamburger4Core {
  Real z2, z3, w_zf, w2, lower;
};

template <class Real>
inline Hamburger4Core<Real> hamburger4_core(Real b1, Real b2, Real b3, Real b4, Real zf) {
  // Step 1: B c = (1, z_f, z_f^2) by LDL^T of the Hankel matrix [[1,b1,b2],[b1,b2,b3],[b2,b3,b4]].
  const Real d11 = b2 - b1 * b1;
  const Real l21 = (b3 - b1 * b2) / d11;
  const Real d22 = (b4 - b2 * b2) - l21 * (b3 - b1 * b2);
  Real y1 = zf - b1;
  Real y2 = zf * zf - b2 - l21 * y1;
  y1 /= d11;
  y2 /= d22;
  const Real c2 = y2, c1 = y1 - l21 * c2, c0 = 1 - b1 * c1 - b2 * c2;
  // Step 2: the other two nodes.
  Hamburger4Core<Real> r;
  quadratic_roots(c2, c1, c0, r.z2, r.z3);
  // Step 3: weights reproducing 1, b1, b2 on {z_f, z2, z3} (Lagrange, written out: this is the
  // hot path of eval), then the mass strictly below z_f.
  r.w_zf = (r.z2 * r.z3 - b1 * (r.z2 + r.z3) + b2) / ((zf - r.z2) * (zf - r.z3));
  r.w2 = (zf * r.z3 - b1 * (zf + r.z3) + b2) / ((r.z2 - zf) * (r.z2 - r.z3));
  r.lower = zf <= r.z2 ? Real(0) : zf <= r.z3 ? r.w2 : 1 - r.w_zf;
  return r;
}

}  // namespace

template <class Real>
MsmBound<Real> hamburger4(const Real* b, Real zf) {
  const Hamburger4Core<Real> c = hamburger4_core(b[0], b[1], b[2], b[3], zf);
  MsmBound<Real> r;
  r.node_count = 3;
  r.nodes[0] = zf;
  r.nodes[1] = c.z2;
  r.nodes[2] = c.z3;
  r.weights[0] = c.w_zf;
  r.weights[1] = c.w2;
  // Not 1 - w1 - w2: a far node's tiny weight would lose its relative precision.
  r.weights[2] = (zf * c.z2 - b[0] * (zf + c.z2) + b[1]) / ((c.z3 - zf) * (c.z3 - c.z2));
  r.lower = std::clamp(c.lower, Real(0), Real(1));
  r.at_zf = std::clamp(c.w_zf, Real(0), Real(1));
  return r;
}

void hamburger4_lower_batch(const double* b, const double* zf, double* lower, size_t count,
                            double alpha) {
#pragma omp simd
  for (size_t k = 0; k < count; ++k) {
    const double* m = b + 4 * k;
    const double g =
        hamburger4_core((1 - alpha) * m[0] + alpha * 0.5, (1 - alpha) * m[1] + alpha * 0.5,
                        (1 - alpha) * m[2] + alpha * 0.5, (1 - alpha) * m[3] + alpha * 0.5, zf[k])
            .lower;
    lower[k] = std::min(1.0, std::max(0.0, g));
  }
}

void hamburger4_blend_batch(const double* b, const double* zf, size_t count, double beta,
                            double* out) {
  const double b1 = b[0], b2 = b[1], b3 = b[2], b4 = b[3];
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
#pragma omp simd
  for (size_t k = 0; k < count; ++k) {
    const Hamburger4Core<double> c = hamburger4_core(b1, b2, b3, b4, zf[k]);
    // std::clamp's results, NaN kept (hamburger4 returns it; the caller counts it).
    const bool finite = c.lower == c.lower && c.w_zf == c.w_zf;
    const double g = std::min(1.0, std::max(0.0, c.lower));
    const double w = std::min(1.0, std::max(0.0, c.w_zf));
    const double a = g + beta * w;
    out[k] = finite ? std::min(1.0, std::max(0.0, a)) : kNaN;
  }
}

// Moments whose Hankel matrix is singular lie on the boundary of the moment space: only a
// distribution with fewer atoms than the matrix's size has them, and it is unique
// (docs/reference.md §2), so G is its mass strictly below z_f. Its r atoms are the roots of the
// monic polynomial z^r + a_{r-1} z^{r-1} + .. + a_0 with H_r a = -(m_r, .., m_{2r-1}), for the
// largest r whose r x r Hankel matrix is regular. Used where the regular path gives no number
// (alpha = 0 on 1-3 atoms); node_count = 0 when no r fits.
MsmBound<double> determinate_bound(const double* m, double zf, bool must_reproduce) {
  MsmBound<double> r;
  for (int size = 3; size >= 1; --size) {
    Eigen::Matrix3d h = Eigen::Matrix3d::Identity();
    Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
    for (int i = 0; i < size; ++i) {
      for (int j = 0; j < size; ++j) h(i, j) = m[i + j];
      rhs(i) = -m[size + i];
    }
    Eigen::FullPivLU<Eigen::Matrix3d> lu(h);
    lu.setThreshold(1e-10);
    if (lu.rank() < 3)
      continue;  // the identity pads: rank 3 means the size x size block is regular
    const Eigen::Vector3d a = lu.solve(rhs);
    double nodes[3];
    int count = size;
    if (size == 1) {
      nodes[0] = -a(0);
    } else if (size == 2) {
      quadratic_roots(1.0, a(1), a(0), nodes[0], nodes[1]);
    } else {
      count = cubic_roots(1.0, a(2), a(1), a(0), nodes);
      if (count != 3) continue;
    }
    double lower = 0;
    bool valid = true;
    for (int i = 0; i < count; ++i) {
      const double w = node_weight(m, nodes, count, i);
      valid = valid && std::isfinite(w) && w > -1e-9;
      if (nodes[i] < zf) lower += w;
    }
    // Near-singular but regular matrices (4 atoms, two of them close) also reach here: the
    // determinate reading is taken only if its atoms reproduce all seven moments to rounding.
    for (int k = 0; valid && must_reproduce && k <= 6; ++k) {
      double moment = 0;
      for (int i = 0; i < count; ++i)
        moment += node_weight(m, nodes, count, i) * std::pow(nodes[i], k);
      valid = std::abs(moment - m[k]) <= 1e-11 * std::max(1.0, std::abs(m[k]));
    }
    if (!valid) continue;
    r.node_count = count;
    for (int i = 0; i < count; ++i) r.nodes[i] = nodes[i];
    r.lower = std::clamp(lower, 0.0, 1.0);
    return r;
  }
  return r;
}

namespace {

// The three roots of c3 z^3 + c2 z^2 + c1 z + c0 (ascending) in closed form, then one Newton step
// each (seed 004 §2.5): the trigonometric form of the depressed cubic t^3 + p t + q, its angle by
// atan2 rather than acos, which keeps its digits where two roots nearly coincide. A positive
// discriminant (one real root; for a positive definite Hankel matrix only from rounding) is
// clamped to a double root.
void cubic_roots_once_polished(double c3, double c2, double c1, double c0, double* roots) {
  const double a = c2 / c3, b = c1 / c3, c = c0 / c3;
  const double p = b - a * a / 3, q = (2 * a * a / 27 - b / 3) * a + c;
  // t = 2 sqrt(-p/3) cos((theta - 2 pi k) / 3), cos(theta) = -q/2 / sqrt(-p^3/27).
  const double half_q = q / 2, minus_p3 = std::max(0.0, -p / 3);
  const double sine = std::sqrt(std::max(0.0, minus_p3 * minus_p3 * minus_p3 - half_q * half_q));
  const double theta = std::atan2(sine, -half_q) / 3, radius = 2 * std::sqrt(minus_p3);
  for (int k = 0; k < 3; ++k) {
    const double z = radius * std::cos(theta - 2 * std::numbers::pi * k / 3) - a / 3;
    const double f = ((z + a) * z + b) * z + c, df = (3 * z + 2 * a) * z + b;
    roots[k] = df != 0 && std::isfinite(f / df) ? z - f / df : z;
  }
  std::sort(roots, roots + 3);
}

// E[p(Z)] for the cubic p with p(x_i) = f_i at the four nodes x: its Newton form from divided
// differences, expanded into powers (Horner) and applied to m_0 .. m_3, which every distribution
// on the nodes with these moments integrates exactly. Seed 004 §2.5: the weighted sum of the
// canonical distribution's weights without the weights themselves.
double newton_weight_sum(const double* m, const double* x, const double* values) {
  double d[4] = {values[0], values[1], values[2], values[3]};
  for (int order = 1; order < 4; ++order)
    for (int i = 3; i >= order; --i) {
      // A double root (clamped discriminant) carries equal values: the flat interpolant there.
      const double dx = x[i] - x[i - order];
      d[i] = dx != 0 ? (d[i] - d[i - 1]) / dx : 0;
    }
  // p = d0 + (z - x0)(d1 + (z - x1)(d2 + (z - x2) d3)), expanded from the inside out.
  double poly[4] = {d[3], 0, 0, 0};
  for (int i = 2, degree = 0; i >= 0; --i, ++degree) {
    for (int k = degree + 1; k > 0; --k) poly[k] = poly[k - 1] - x[i] * poly[k];
    poly[0] = d[i] - x[i] * poly[0];
  }
  return ((poly[3] * m[3] + poly[2] * m[2]) + poly[1] * m[1]) + poly[0] * m[0];
}

// Seed 004 §2.5 for one fragment (docs/reference.md §4, "Six moments, stably"). `flip` is 1, or -1
// for the test that shows verify failing a closed form with one sign flipped.
MsmBound<double> hamburger6_steps(const double* b, double zf, double flip) {
  const double b1 = b[0], b2 = b[1], b3 = b[2], b4 = b[3], b5 = b[4], b6 = b[5];
  // Step 1: LDL^T (Cholesky) of B = [[1,b1,b2,b3],[b1,b2,b3,b4],[b2,b3,b4,b5],[b3,b4,b5,b6]],
  // keeping the products L_ij D_j that the updates reuse.
  const double d1 = b2 - b1 * b1;
  const double l21d1 = b3 - b1 * b2, l31d1 = b4 - b1 * b3;
  const double l21 = l21d1 / d1, l31 = l31d1 / d1;
  const double d2 = (b4 - b2 * b2) - l21d1 * l21;
  const double l32d2 = (b5 - b2 * b3) - l21d1 * l31;
  const double l32 = l32d2 / d2;
  const double d3 = (b6 - b3 * b3) - l31d1 * l31 - l32d2 * l32;
  // B c = (1, z_f, z_f^2, z_f^3): forward substitution, scaling by D, back substitution.
  double y1 = zf - b1;
  double y2 = zf * zf - b2 - l21 * y1;
  double y3 = zf * zf * zf - b3 - l31 * y1 - flip * l32 * y2;
  y1 /= d1, y2 /= d2, y3 /= d3;
  const double c3 = y3, c2 = y2 - l32 * c3, c1 = y1 - l21 * c2 - l31 * c3;
  const double c0 = 1 - b1 * c1 - b2 * c2 - b3 * c3;
  // Step 2: the other three nodes, the roots of sum_k c_k z^k.
  MsmBound<double> r;
  r.node_count = 4;
  r.nodes[0] = zf;
  cubic_roots_once_polished(c3, c2, c1, c0, r.nodes + 1);
  // Step 3: G is the canonical distribution's mass at the nodes below z_f (1 there, 0 at z_f and
  // behind it), its weight at z_f the upper bound's addend; both through one Newton polynomial.
  const double m[4] = {1, b1, b2, b3};
  double below[4] = {0}, at[4] = {1, 0, 0, 0};
  for (int i = 1; i < 4; ++i) below[i] = r.nodes[i] < zf ? 1 : 0;
  r.lower = std::clamp(newton_weight_sum(m, r.nodes, below), 0.0, 1.0);
  r.at_zf = std::clamp(newton_weight_sum(m, r.nodes, at), 0.0, 1.0);
  // The weights themselves (Lagrange) only for tests and hamburger6's consistency check, which
  // they make sharper than the Newton form's own weights would: those reproduce 1, b1, b2, b3 by
  // construction, and passed garbage from singular matrices that Lagrange's rounding exposes
  // (over-darkening 4e-5 against 7e-8 on the default dataset).
  for (int i = 0; i < 4; ++i) r.weights[i] = node_weight(m, r.nodes, 4, i);
  return r;
}

// Where the regular path gives no number, or a canonical distribution that does not reproduce
// the seven moments (a singular matrix's garbage: G ~ 1e-48 where the atoms' mass is 1), the
// moments are read as a determinate distribution of fewer atoms. Near-singular matrices of narrow
// kernels (81 atoms spanning 0.01) keep the regular answer: it reproduces them, where 3 atoms
// would also fit to 1e-13.
MsmBound<double> hamburger6_checked(const double* b, double zf, double flip) {
  const MsmBound<double> r = hamburger6_steps(b, zf, flip);
  const double m[7] = {1, b[0], b[1], b[2], b[3], b[4], b[5]};
  bool consistent = std::isfinite(r.lower) && std::isfinite(r.at_zf);
  for (int k = 0; consistent && k <= 6; ++k) {
    double moment = 0;
    for (int i = 0; i < r.node_count; ++i) moment += r.weights[i] * std::pow(r.nodes[i], k);
    consistent = std::abs(moment - m[k]) <= 1e-6 * std::max(1.0, std::abs(m[k]));
  }
  if (!consistent) {
    const MsmBound<double> determinate = determinate_bound(m, zf, true);
    if (determinate.node_count > 0) return determinate;
  }
  return r;
}

}  // namespace

MsmBound<double> hamburger6(const double* b, double zf) {
  return hamburger6_checked(b, zf, 1);
}

MsmBound<double> hamburger6_sign_flipped(const double* b, double zf) {
  return hamburger6_checked(b, zf, -1);
}

template MsmBound<float> hamburger4<float>(const float*, float);
template MsmBound<double> hamburger4<double>(const double*, double);

}  // namespace mb
