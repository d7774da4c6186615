#include "moments/tmsm.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "moments/canonical.h"

namespace mb {

namespace {

// The moments of tmsm.md §2: T_i = E[sin^(4-i)(πz) cos^i(πz)] from the trigonometric moments.
template <class Real>
void half_angle_moments(const Real* b, Real* t) {
  const Real s1 = b[0], c1 = b[1], s2 = b[2], c2 = b[3];
  t[0] = (3 - 4 * c1 + c2) / 8;
  t[1] = (2 * s1 - s2) / 8;
  t[2] = (1 - c2) / 8;
  t[3] = (2 * s1 + s2) / 8;
  t[4] = (3 + 4 * c1 + c2) / 8;
}

// One member of the family {cut, z_f, a, c} of tmsm.md §3, in x = -cot(πz) (cut at infinity).
// Left uninitialised on purpose: every field is written before it is read (have_best_ guards
// best_), and zeroing it per fragment was ~8 % of the solver's time (perf: rep stos).
template <class Real>
struct Candidate {
  Real x[2];          // the free points a, c
  Real w[4];          // probabilities at z_f, a, c, cut
  Real lower;         // mass with x < x_f
  Real worst_weight;  // the most negative weight, less its rounding allowance
};

template <class Real>
class TmsmSolver {
 public:
  // Which family member the free points a, c belong to: (b) has no mass at the cut and (c) none
  // at z_f by construction, so those weights are 0 rather than rounding noise.
  enum class Kind { NoCut, NoZf, Stationary };

  TmsmSolver(const Real* b, Real zf) : zf_(zf) {
    Real t[5];
    half_angle_moments(b, t);
    // M_k = 8 E[x^k / (1 + x^2)^2] = 8 (-1)^k T_k; the cut enters M_4 only.
    for (int k = 0; k < 5; ++k) m_[k] = (k % 2 ? -8 : 8) * t[k];
    xf_ = -1 / std::tan(std::numbers::pi_v<Real> * zf);
    for (int k = 0; k < 4; ++k) e_[k] = m_[k + 1] - xf_ * m_[k];  // E_k = E_nu[(x - x_f) x^k]
  }

  MsmBound<Real> solve(bool with_support) {
    const Real *m = m_, *e = e_;
    // (b) no mass at the cut: s E1 - p E0 = E2, s E2 - p E1 = E3.
    const Real d = e[0] * e[2] - e[1] * e[1];
    consider_pair((e[0] * e[3] - e[1] * e[2]) / d, (e[1] * e[3] - e[2] * e[2]) / d, Kind::NoCut);
    // (c) no mass at z_f: s M1 - p M0 = M2, s M2 - p M1 = M3.
    const Real d0 = m[0] * m[2] - m[1] * m[1];
    consider_pair((m[0] * m[3] - m[1] * m[2]) / d0, (m[1] * m[3] - m[2] * m[2]) / d0, Kind::NoZf);
    // (d) both free points in A: (x_f - a)(x_f - c) = 1 + x_f^2 and the annihilating condition.
    const Real sum = (e[2] + e[0]) / (e[1] - xf_ * e[0]);
    consider_pair(sum, 1 + sum * xf_, Kind::Stationary);
    // An admissible distribution without mass in front of z_f is optimal (G >= 0): the quartic
    // could only offer another one at G = 0 up to rounding.
    if (best_admissible_ && best_.lower <= 0) return finish(with_support);
    // (a) the stationary points of w_a: the quartic of tmsm.md §3.
    Real roots[4];
    const Real x = xf_;
    const int count =
        quartic_roots(e[0], -(4 * e[1] + 2 * x * e[0]), 3 * e[2] + 6 * x * e[1] - 3 * e[0],
                      4 * e[1] + 2 * x * e[0] - 4 * x * e[2], -(e[2] + 2 * x * e[1]), roots);
    for (int k = 0; k < count; ++k) {
      const Real a = roots[k];
      consider(a, (e[2] - a * e[1]) / (e[1] - a * e[0]), Kind::Stationary);
    }
    return finish(with_support);
  }

 private:
  static Real square_plus_one_squared(Real x) { return (1 + x * x) * (1 + x * x); }

  void consider_pair(Real sum, Real product, Kind kind) {
    const Real disc = sum * sum - 4 * product;
    if (!(disc >= 0)) return;
    Real a, c;
    quadratic_roots(Real(1), -sum, product, a, c);
    consider(a, c, kind);
  }

  // Weights of {z_f, a, c, cut} reproducing M_0..M_4 (Lagrange on the finite points with
  // M_0..M_2, the cut takes the rest of M_4), then keeps the candidate if it is the best
  // admissible one (or the least infeasible while none is admissible).
  void consider(Real a, Real c, Kind kind) {
    if (!std::isfinite(a) || !std::isfinite(c) || a == c) return;
    const Real *m = m_, *e = e_, xf = xf_;
    if (kind != Kind::NoZf && (a == xf || c == xf)) return;
    Candidate<Real> k;
    k.x[0] = a;
    k.x[1] = c;
    // The weights at a and c first: they alone give the candidate's bound, and a candidate that
    // cannot beat an admissible best needs nothing more (the choice is the same as without this
    // shortcut: ties keep the earlier candidate either way).
    Real v[3];
    const bool no_zf = kind == Kind::NoZf;
    const Real base = no_zf ? m[1] : e[1], slope = no_zf ? m[0] : e[0];
    const Real den1 = no_zf ? a - c : (a - xf) * (a - c), den2 = no_zf ? c - a : (c - xf) * (c - a);
    v[1] = (base - c * slope) / den1;
    v[2] = (base - a * slope) / den2;
    const Real scale[3] = {square_plus_one_squared(xf) / 8, square_plus_one_squared(a) / 8,
                           square_plus_one_squared(c) / 8};
    k.w[1] = v[1] * scale[1];
    k.w[2] = v[2] * scale[2];
    k.lower = (a < xf ? k.w[1] : Real(0)) + (c < xf ? k.w[2] : Real(0));
    if (!std::isfinite(k.lower) || (best_admissible_ && !(k.lower < best_.lower))) return;
    v[0] = no_zf ? Real(0) : (m[2] - (a + c) * m[1] + a * c * m[0]) / ((xf - a) * (xf - c));
    k.w[0] = v[0] * scale[0];
    const Real xf2 = xf * xf, a2 = a * a, c2 = c * c;
    const Real finite4 = v[0] * xf2 * xf2 + v[1] * a2 * a2 + v[2] * c2 * c2;
    k.w[3] = kind == Kind::NoCut ? Real(0) : (m[4] - finite4) / 8;
    if (k.w[0] >= 0 && k.w[1] >= 0 && k.w[2] >= 0 && k.w[3] >= 0) {
      k.worst_weight =
          std::min({k.w[0], k.w[1], k.w[2], k.w[3]});  // admissible: no allowance needed
    } else {
      // Each weight with the size of the terms it comes from, so that admissibility allows for its
      // own rounding error ((1 + x^2)^2 magnifies both far from z = 1/2).
      Real size[4];
      size[0] = no_zf ? Real(0)
                      : (std::abs(m[2]) + std::abs((a + c) * m[1]) + std::abs(a * c * m[0])) /
                            std::abs((xf - a) * (xf - c));
      size[1] = (std::abs(base) + std::abs(c * slope)) / std::abs(den1);
      size[2] = (std::abs(base) + std::abs(a * slope)) / std::abs(den2);
      for (int i = 0; i < 3; ++i) size[i] *= scale[i];
      size[3] = (std::abs(m[4]) + std::abs(v[0]) * xf2 * xf2 + std::abs(v[1]) * a2 * a2 +
                 std::abs(v[2]) * c2 * c2) /
                8;
      // A weight is negative for real unless it is within a few roundings of its terms.
      constexpr Real kRounding = 8 * std::numeric_limits<Real>::epsilon();
      k.worst_weight = std::numeric_limits<Real>::infinity();
      for (int i = 0; i < 4; ++i)
        k.worst_weight = std::min(k.worst_weight, k.w[i] + kRounding * size[i]);
    }
    if (!std::isfinite(k.worst_weight)) return;
    const Real tolerance = std::is_same_v<Real, float> ? Real(1e-6) : Real(1e-12);
    const bool admissible = k.worst_weight >= -tolerance;
    if (admissible ? (!best_admissible_ || k.lower < best_.lower)
                   : (!best_admissible_ && (!have_best_ || k.worst_weight > best_.worst_weight))) {
      best_ = k;
      best_admissible_ = admissible;
      have_best_ = true;
    }
  }

  MsmBound<Real> finish(bool with_support) const {
    MsmBound<Real> r;
    if (!have_best_) {  // every formula failed: not a moment vector this solver can read
      r.lower = std::numeric_limits<Real>::quiet_NaN();
      return r;
    }
    r.lower = std::clamp(best_.lower, Real(0), Real(1));
    r.at_zf = std::clamp(best_.w[0], Real(0), Real(1));
    if (!with_support) return r;  // the depths cost two atan2, as much as the rest
    r.node_count = 4;
    r.nodes[0] = zf_;
    r.nodes[1] = depth_of(best_.x[0]);
    r.nodes[2] = depth_of(best_.x[1]);
    r.nodes[3] = 1;
    for (int i = 0; i < 4; ++i) r.weights[i] = best_.w[i];
    return r;
  }

  // x = -cot(πz)  <=>  πz = atan2(1, -x) in (0, π).
  static Real depth_of(Real x) { return std::atan2(Real(1), -x) / std::numbers::pi_v<Real>; }

  Real zf_, xf_;
  Real m_[5], e_[4];
  Candidate<Real> best_;
  bool best_admissible_ = false, have_best_ = false;
};

// z_f = 1 (tmsm.md §5): 1 - the largest mass at the cut, a Schur complement of the Hankel
// matrix of m_k = (-1)^k T_k.
template <class Real>
Real lower_at_one(const Real* b) {
  Real t[5];
  half_angle_moments(b, t);
  const Real m0 = t[0], m1 = -t[1], m2 = t[2], m3 = -t[3], m4 = t[4];
  const Real det2 = m0 * m2 - m1 * m1;
  const Real det3 = m0 * (m2 * m4 - m3 * m3) - m1 * (m1 * m4 - m3 * m2) + m2 * (m1 * m3 - m2 * m2);
  // Fewer than two finite points: the representation is unique and the cut holds what the
  // finite point (if any, m2^2 / m0 of m4) does not.
  const Real cut = det2 > 0 ? det3 / det2 : m0 > 0 ? m4 - m2 * m2 / m0 : m4;
  return std::clamp(1 - cut, Real(0), Real(1));
}

}  // namespace

template <class Real>
MsmBound<Real> tmsm(const Real* b, Real zf, bool with_support) {
  MsmBound<Real> r;
  if (!(zf > 0)) return r;  // A = (0, z_f) is empty
  if (zf >= 1) {
    r.lower = zf > 1 ? Real(1) : lower_at_one(b);
    return r;
  }
  return TmsmSolver<Real>(b, zf).solve(with_support);
}

template MsmBound<float> tmsm<float>(const float*, float, bool);
template MsmBound<double> tmsm<double>(const double*, double, bool);

}  // namespace mb
