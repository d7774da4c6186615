#include "moments/hamburger.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

MsmBound<double> hamburger6(const double* b, double zf) {
  Eigen::Matrix4d hankel;
  const double m[7] = {1, b[0], b[1], b[2], b[3], b[4], b[5]};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) hankel(i, j) = m[i + j];
  const Eigen::Vector4d c = hankel.ldlt().solve(Eigen::Vector4d(1, zf, zf * zf, zf * zf * zf));
  MsmBound<double> r;
  r.nodes[0] = zf;
  r.node_count = 1 + cubic_roots(c(3), c(2), c(1), c(0), r.nodes + 1);
  finish_bound(r, m, zf);
  // Where the regular path gives no number, or a canonical distribution that does not reproduce
  // the seven moments (a singular matrix's garbage: G ~ 1e-48 where the atoms' mass is 1), the
  // moments are read as a determinate distribution of fewer atoms. Near-singular matrices of
  // narrow kernels (81 atoms spanning 0.01) keep the regular answer: it reproduces them, and is
  // within 3.5e-4 of 60-digit arithmetic there, where 3 atoms would also fit to 1e-13.
  bool consistent = std::isfinite(r.lower) && std::isfinite(r.at_zf) && c.allFinite();
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

template MsmBound<float> hamburger4<float>(const float*, float);
template MsmBound<double> hamburger4<double>(const double*, double);

}  // namespace mb
