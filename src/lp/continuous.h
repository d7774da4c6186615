#pragma once
// Problem 1 on the continuous interval [lo, hi] (REFERENCE.md §2, "The grid is an
// approximation"): a semi-infinite LP, solved by an exchange method over the finite LP. Solve on
// the finite set (grid ∪ the fragment's points), find where the dual function
// phi(z) = y . T (1, b(z)) rises above the step [z < z_f] on [lo, z_f) and on [z_f, hi], add those
// points, solve again. It ends with a certificate: phi <= step + eps on all of [lo, hi], proven
// cell by cell from Taylor models of phi (the catalog functions' closed-form derivatives and
// bounds of the next derivative, moments/basis_derivatives.h). Weak duality then makes
// E[phi] - eps a lower bound of the continuous infimum, and the finite optimum is an upper one.
//
// What is proven: for catalog bases, the bound on phi - step over every cell, in long double with
// an allowance for rounding (libm's long-double functions assumed accurate to a few ulps). For
// user expressions nothing is proven: phi is sampled (8 points per grid cell, violations refined
// by golden section) and `proven` is false.
#include <limits>
#include <span>

#include "lp/problem.h"
#include "lp/solution.h"

namespace mb::lp {

struct ContinuousSettings {
  int max_rounds = 60;
  // The exchange stops once upper - lower is within this (REFERENCE.md §2: the bracket's width).
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
  double violation = 0;  // the bound of max over I of phi - step (>= 0)
  bool proven = false;   // the basis has closed-form derivatives and every cell was bounded
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

class ContinuousSolver {
 public:
  explicit ContinuousSolver(const ProblemFactory& factory, ContinuousSettings settings = {})
      : factory_(factory),
        settings_(settings),
        lo_(factory.discretization().lo),
        hi_(factory.discretization().hi),
        tail_lo_(lo_),
        tail_hi_(hi_) {}
  // The continuous interval, when it is not the factory's grid interval (a seed grid may cover
  // only part of it; its ends must then be among the problem's points).
  void set_interval(double lo, double hi) { lo_ = tail_lo_ = lo, hi_ = tail_hi_ = hi; }
  // Tails of I beyond the interval, to tail_lo <= lo and tail_hi >= hi (infinite: I = R, which
  // only a polynomial basis can certify): the certificate bounds phi there from its Taylor
  // coefficients at the interval's ends.
  // `even_degree`: the basis is z, .., z^n with n even (infinite tails need it).
  // `probe_limit`: how far out (|z|) the exchange may add points (the certificate's cells reach
  // there; beyond, only the tail bound).
  void set_tails(double tail_lo, double tail_hi, int even_degree = 0,
                 double probe_limit = std::numeric_limits<double>::infinity()) {
    tail_lo_ = tail_lo, tail_hi_ = tail_hi, even_degree_ = even_degree, probe_limit_ = probe_limit;
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
  double lo_, hi_;
  double tail_lo_ = 0, tail_hi_ = 0;
  int even_degree_ = 0;
  double probe_limit_ = std::numeric_limits<double>::infinity();
};

}  // namespace mb::lp
