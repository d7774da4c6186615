#include "moments/hamburger.h"

#include <Eigen/Dense>
#include <algorithm>

#include "moments/canonical.h"

namespace mb {

namespace {

// G = the mass of the canonical distribution strictly below z_f: node 0 is z_f itself.
template <class Real>
void finish_bound(MsmBound<Real>& r, const Real* moments, Real zf) {
  for (int i = 0; i < r.node_count; ++i) r.weights[i] = node_weight(moments, r.nodes, r.node_count, i);
  Real lower = 0;
  for (int i = 1; i < r.node_count; ++i)
    if (r.nodes[i] < zf) lower += r.weights[i];
  r.lower = std::clamp(lower, Real(0), Real(1));
  r.at_zf = std::clamp(r.weights[0], Real(0), Real(1));
}

}  // namespace

template <class Real>
MsmBound<Real> hamburger4(const Real* b, Real zf) {
  const Real b1 = b[0], b2 = b[1], b3 = b[2], b4 = b[3];
  // Step 1: B c = (1, z_f, z_f^2) by LDL^T of the Hankel matrix [[1,b1,b2],[b1,b2,b3],[b2,b3,b4]].
  const Real d11 = b2 - b1 * b1;
  const Real l21 = (b3 - b1 * b2) / d11;
  const Real d22 = (b4 - b2 * b2) - l21 * (b3 - b1 * b2);
  Real y1 = zf - b1;
  Real y2 = zf * zf - b2 - l21 * y1;
  y1 /= d11;
  y2 /= d22;
  const Real c2 = y2, c1 = y1 - l21 * c2, c0 = 1 - b1 * c1 - b2 * c2;
  // Step 2: the other two nodes of the canonical distribution.
  MsmBound<Real> r;
  r.node_count = 3;
  r.nodes[0] = zf;
  quadratic_roots(c2, c1, c0, r.nodes[1], r.nodes[2]);
  // Step 3: weights reproducing 1, b1, b2 on {z_f, z2, z3} (Lagrange, written out: this is the
  // hot path of eval), then the mass strictly below z_f.
  const Real z2 = r.nodes[1], z3 = r.nodes[2];
  r.weights[0] = (z2 * z3 - b1 * (z2 + z3) + b2) / ((zf - z2) * (zf - z3));
  r.weights[1] = (zf * z3 - b1 * (zf + z3) + b2) / ((z2 - zf) * (z2 - z3));
  // Not 1 - w1 - w2: a far node's tiny weight would lose its relative precision.
  r.weights[2] = (zf * z2 - b1 * (zf + z2) + b2) / ((z3 - zf) * (z3 - z2));
  const Real lower = zf <= z2 ? Real(0) : zf <= z3 ? r.weights[1] : 1 - r.weights[0];
  r.lower = std::clamp(lower, Real(0), Real(1));
  r.at_zf = std::clamp(r.weights[0], Real(0), Real(1));
  return r;
}

void hamburger4_lower_batch(const double* b, const double* zf_in, double* lower, size_t count, double alpha) {
#pragma omp simd
  for (size_t k = 0; k < count; ++k) {
    const double b1 = (1 - alpha) * b[4 * k] + alpha * 0.5, b2 = (1 - alpha) * b[4 * k + 1] + alpha * 0.5;
    const double b3 = (1 - alpha) * b[4 * k + 2] + alpha * 0.5, b4 = (1 - alpha) * b[4 * k + 3] + alpha * 0.5;
    const double zf = zf_in[k];
    const double d11 = b2 - b1 * b1, e = b3 - b1 * b2;
    const double l21 = e / d11, d22 = (b4 - b2 * b2) - l21 * e;
    const double y1 = (zf - b1) / d11;
    const double c2 = (zf * zf - b2 - l21 * (zf - b1)) / d22, c1 = y1 - l21 * c2, c0 = 1 - b1 * c1 - b2 * c2;
    const double root = std::sqrt(std::max(0.0, c1 * c1 - 4 * c2 * c0));
    const double q = -(c1 + std::copysign(root, c1)) / 2;
    const double r1 = q / c2, r2 = c0 / q;
    const double z2 = std::min(r1, r2), z3 = std::max(r1, r2);
    const double w_zf = (z2 * z3 - b1 * (z2 + z3) + b2) / ((zf - z2) * (zf - z3));
    const double w2 = (zf * z3 - b1 * (zf + z3) + b2) / ((z2 - zf) * (z2 - z3));
    const double g = zf <= z2 ? 0.0 : zf <= z3 ? w2 : 1 - w_zf;
    lower[k] = std::min(1.0, std::max(0.0, g));
  }
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
  return r;
}

template MsmBound<float> hamburger4<float>(const float*, float);
template MsmBound<double> hamburger4<double>(const double*, double);

}  // namespace mb
