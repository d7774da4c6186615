#pragma once
// Problem 1 on the continuous interval [lo, hi] (docs/reference.md §2, "The grid is an
// approximation"): a semi-infinite LP, solved by an exchange method over the finite LP. Solve on
// the finite set (grid ∪ the fragment's points), find where the dual function
// phi(z) = y . T (1, b(z)) rises above the step [z < z_f] on [lo, z_f) and on [z_f, hi], add those
// points, solve again. It ends with a certificate: phi <= step + eps on all of [lo, hi], proven
// cell by cell from Taylor models of phi (the catalog functions' closed-form derivatives and
// bounds of the next derivative, basis/basis_derivatives.h). Weak duality then makes
// E[phi] - eps a lower bound of the continuous infimum, and the finite optimum is an upper one.
//
// What is proven: for catalog bases, the bound on phi - step over every cell, in long double with
// an allowance for rounding (libm's long-double functions assumed accurate to a few ulps). For
// user expressions nothing is proven: phi is sampled (8 points per grid cell, violations refined
// by golden section) and `proven` is false.
#include <limits>
#include <span>
#include <vector>

#include "lp/problem.h"
#include "lp/solution.h"

namespace mb::lp {

struct ContinuousSettings {
  int max_rounds = 60;
  // The exchange stops once upper - lower is within this (docs/reference.md §2: the bracket's
  // width).
  double target_width = 1e-9;
  // A cell passes when phi's bound over it is within this of the step: most of target_width is
  // left to the finite LP's own certified error.
  double cell_tolerance = 1e-10;
  // A point is added when phi exceeds the step there by more than this.
  double add_tolerance = 1e-11;
  int max_depth = 48;        // bisections of one initial cell
  long max_cells = 200000;   // cells per certificate pass
  int points_per_round = 0;  // 0: 2 (m + 1)
};

struct ContinuousSolution {
  Solution finite;       // the last finite LP's answer (its support indexes the extended problem)
  double upper = 0;      // its optimum: a distribution on I with the given moments
  double lower = 0;      // E[phi] - violation (proven when `proven`)
  double violation = 0;  // the bound of max over I of phi - delta (1 + z^n) - step (>= 0)
  // Infinite tails (DualCertificate::delta): the certified function is phi - delta (1 + z^n), n =
  // the domain's even degree, so a lower bound from phi on other moments m subtracts
  // delta (1 + m_n) as well; 0 where no tail needed it.
  long double delta = 0;
  bool proven = false;  // the basis has closed-form derivatives and every cell was bounded
  int rounds = 0, points_added = 0;
  bool stalled = false;  // a later round's finite LP failed: the bracket is the last round's
  long cells = 0;        // cells bounded in the last certificate pass
  // phi = c_0 + sum_j c_j b_j(z) of the last round (the factory's basis): G's first-order
  // sensitivity to the moments (dG/db_j = c_j where G is differentiable).
  std::vector<long double> coefficients;
  double width() const { return upper - lower; }
  bool ok() const {
    return finite.call == CallStatus::Ok && finite.status == ProblemStatus::Optimal;
  }
};

// Where Problem 1's depths may lie: [lo, hi], and tails beyond it to tail_lo <= lo and
// tail_hi >= hi (infinite: I = R, which only a polynomial basis can certify). The certificate
// bounds phi on the tails from its Taylor coefficients at the interval's ends.
struct ContinuousDomain {
  double lo = 0, hi = 1;
  double tail_lo = 0, tail_hi = 1;
  int even_degree = 0;  // the basis is z, .., z^n with n even (infinite tails need it)
  // How far out (|z|) the exchange may add points (the certificate's cells reach there; beyond,
  // only the tail bound).
  double probe_limit = std::numeric_limits<double>::infinity();
  static ContinuousDomain interval(double lo, double hi) { return {lo, hi, lo, hi}; }
};

// The certificate of one dual function phi = c_0 + sum_j c_j b_j on a domain: a bound of
// phi - step over all of it, and where phi rises above the step (the exchange's next points).
struct DualCertificate {
  long double violation = 0;  // bound of max over I of phi - delta (1 + z^n) - step (>= 0)
  // Infinite tails: phi - delta (1 + z^n) is what is bounded (see continuous.cpp, tail_bound);
  // a lower bound built from phi subtracts delta (1 + E[z^n]).
  long double delta = 0;
  bool proven = true;  // the basis has closed-form derivatives and every cell was bounded
  long cells = 0;
  std::vector<double> violators;  // points where phi exceeds the step, the largest excess first
  // The rounding allowance of phi at a point, per unit of sum_j |c_j b_j(z)|.
  static long double rounding();
};

// `points`: points of I known to matter (the finite LP's), the cells start between them; points
// beyond the cells are checked one by one.
DualCertificate certify_dual(const Basis& basis, const std::vector<long double>& coefficients,
                             double zf, std::span<const double> points,
                             const ContinuousDomain& domain, const ContinuousSettings& settings);

class ContinuousSolver {
 public:
  explicit ContinuousSolver(const ProblemFactory& factory, ContinuousSettings settings = {})
      : factory_(factory),
        settings_(settings),
        domain_(
            ContinuousDomain::interval(factory.discretization().lo, factory.discretization().hi)) {}
  // The continuous interval, when it is not the factory's grid interval (a seed grid may cover
  // only part of it; its ends must then be among the problem's points).
  void set_interval(double lo, double hi) { domain_ = ContinuousDomain::interval(lo, hi); }
  // Tails of I beyond the interval (see ContinuousDomain).
  void set_tails(double tail_lo, double tail_hi, int even_degree = 0,
                 double probe_limit = std::numeric_limits<double>::infinity()) {
    domain_.tail_lo = tail_lo, domain_.tail_hi = tail_hi, domain_.even_degree = even_degree;
    domain_.probe_limit = probe_limit;
  }
  // Solves `problem` (built by the factory; the exchange appends its points to the problem's
  // extra columns) on the factory's interval [lo, hi] plus any of the problem's points beyond it.
  // `depths` and `weights`: the distribution the problem was built from, if any; the lower bound
  // is then E_S[phi] from its atoms in long double, not y . b from moments rounded to double.
  ContinuousSolution solve(Problem& problem, Backend& backend, std::span<const double> depths = {},
                           std::span<const double> weights = {}) const;

 private:
  const ProblemFactory& factory_;
  ContinuousSettings settings_;
  ContinuousDomain domain_;
};

}  // namespace mb::lp
