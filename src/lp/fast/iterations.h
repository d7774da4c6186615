#pragma once
// Simplex iterations: the primal loop (pricing, ratio test, update) and dual simplex steps.
#include "lp/fast/simplex.h"

namespace mb::lp::fast {

// The basis position of the most negative weight (the first, on ties).
template <int K>
inline int FastSimplex<K>::most_negative() const {
  int worst = 0;
  double least = x_[0];
  for (int i = 1; i < k_; ++i) {  // selects, not branches (they mispredict)
    const bool less = x_[i] < least;
    least = less ? x_[i] : least;
    worst = less ? i : worst;
  }
  return worst;
}

// One simplex run to optimality for the current phase. False on numerical failure.
template <int K>
inline bool FastSimplex<K>::iterate(Solution& s) {
  int degenerate = 0;
  // A node slides when the last two pivots left the same basis position, or the last one entered
  // an end of the grid, where Dantzig's steepest column often lies and from where a node of small
  // weight then walks back (slide_entering; the ends as a trigger: 0.94 -> 0.90 pivots an LP,
  // power4, 256).
  bool sliding = false;
  int previous_leave = -1;
  const int limit = std::min(20 * (n_ + k_), settings_.max_iterations);
  for (int guard = 0; guard < limit; ++guard) {
    if (updates_ >= refactor_interval() && !refactor()) return false;
    bool bland = degenerate >= settings_.degenerate_before_bland;
    // The extra columns first (phase 2 only, after the first iteration: see enter_among_extras):
    // only when none of them may enter does a full pass decide, so every run still ends with one,
    // and optimality is never judged on the extras alone.
    btran(y_);  // once per iteration, for the extras and the full pass alike
    fresh_.duals_computed();
    const bool partial = phase_ == 2 && !bland && !retrying_;
    int entering = partial && guard > 0 && !sliding ? enter_from_extras() : -1;
    if (entering < 0) {
      // Duals too large for the double certificate (|y| ~ 1e8: narrow kernels) are refined in
      // double-double before the full pass, so that the precise certificate finds the reduced
      // costs of its duals in place; refining them there would mean a second
      // pricing pass, and most LPs that need it end after this pass.
      if (phase_ == 2 && pricing_rounding(y_) > 0.1 * kCertifyBound) refine_duals_for_certificate();
      reduced_costs();
      // (Only when some column may enter at all: most warm LPs are optimal, and their smallest
      // reduced cost is rounding, below zero but inside the tolerance.)
      if (partial && guard == 0 && fresh_.smallest_reduced < -entering_tolerance())
        entering = enter_among_extras();
      if (entering < 0 && sliding && partial) entering = slide_entering();  // (not run's retry)
      if (entering < 0) entering = choose_entering(bland);
    }
    if (entering < 0) return true;
    double u[kMaxRows];
    ftran_column(entering, u);
    const double theta = ratio_test_step(entering, u, bland, s);
    if (!(theta >= 0)) return false;
    // Near-zero steps count as degenerate too: Harris steps of 1e-18 can cycle as well.
    degenerate = theta < 1e-12 ? degenerate + 1 : 0;
    const int left = basic_position(entering);  // the position the step's leaving column held
    sliding = left == previous_leave || entering == 0 || entering == g_ - 1;
    previous_leave = left;
  }
  iteration_limit_ = true;
  return false;
}

// One primal simplex step: `entering` (u = B^{-1} a_entering) comes in, the ratio test picks the
// leaving row. The step length, or -1 when no row may leave (numerical failure).
template <int K>
inline double FastSimplex<K>::ratio_test_step(int entering, const double* u, bool bland,
                                              Solution& s) {
  int leave = -1;
  if (!bland) {
    // Harris ratio test: a relaxed bound first, then the largest pivot within it.
    // Selects, not branches (which rows block varies from pivot to pivot).
    double theta_max = std::numeric_limits<double>::infinity();
    for (int i = 0; i < k_; ++i) {
      const double ratio = (x_[i] + settings_.feasibility_tolerance) / u[i];
      theta_max = u[i] > settings_.pivot_tolerance && ratio < theta_max ? ratio : theta_max;
    }
    if (!std::isfinite(theta_max)) return -1;  // unbounded: impossible with sum w = 1
    const double limit = std::max(theta_max, 0.0);
    double best_pivot = 0;
    for (int i = 0; i < k_; ++i) {
      const bool better =
          u[i] > settings_.pivot_tolerance && !(x_[i] / u[i] > limit) && u[i] > best_pivot;
      leave = better ? i : leave;
      best_pivot = better ? u[i] : best_pivot;
    }
  } else {
    // Bland's rule needs the textbook ratio test (Harris' relaxation can cycle): the minimum
    // ratio, ties to the smallest column index.
    double best_ratio = std::numeric_limits<double>::infinity();
    for (int i = 0; i < k_; ++i) {
      if (u[i] <= settings_.pivot_tolerance) continue;
      double ratio = std::max(x_[i], 0.0) / u[i];
      if (ratio < best_ratio || (ratio == best_ratio && leave >= 0 && basis_[i] < basis_[leave]))
        leave = i, best_ratio = ratio;
    }
  }
  if (leave < 0) return -1;
  const double theta = std::max(x_[leave], 0.0) / u[leave];
  move_along(leave, entering, u, theta);
  ++s.iterations;
  return theta;
}

// x_B moves by theta along -u (u = B^-1 a_entering) and column `entering` takes basis position
// `leave` with weight theta: the basis update of a primal or dual simplex step.
template <int K>
inline void FastSimplex<K>::move_along(int leave, int entering, const double* u, double theta) {
  for (int i = 0; i < k_; ++i) x_[i] -= theta * u[i];
  x_[leave] = theta;
  pivot(leave, entering, u);
}

// Dual simplex steps from a dual feasible but slightly primal infeasible basis, which
// ill-conditioned instances (z^3, z^6 near z = 0) can end the primal phase with: the most
// negative basic variable leaves, the entering column keeps every reduced cost >= 0. Every step
// starts from a fresh inverse, since x_B is judged at 1e-12.
template <int K>
inline bool FastSimplex<K>::dual_simplex(Solution& s) {
  alpha_.resize(n_);
  for (int step = 0; step < 4 * k_ + 16; ++step) {
    if (!refactor()) return false;
    // x_B refined with double-double residuals, so that a weight the certificate found negative
    // (it refines the same way) leaves here too: in double, cond(B) ~ 1e8 hides -1e-12.
    refine_weights();
    const int leave = most_negative();
    if (!(x_[leave] < -settings_.negligible_weight)) return true;
    price();
    // alpha_j = (B^{-1} A)_{leave, j}, stored negated: -alpha_j = 0 - row_leave . a_j.
    subtract_row_combination(binv_[leave], nullptr, alpha_.data());
    for (int i = 0; i < k_; ++i)
      if (basis_[i] < n_) alpha_[basis_[i]] = 0;  // basic columns cannot enter
    // Dual Harris ratio test: a relaxed bound on the step in the duals, then the largest
    // |alpha| within it, so that the new basis stays well conditioned.
    double alpha_max = 0;
#pragma omp simd reduction(max : alpha_max)
    for (int j = 0; j < n_; ++j) alpha_max = std::max(alpha_max, alpha_[j]);
    const double pivot_floor = std::max(settings_.pivot_tolerance, 1e-7 * alpha_max);
    double bound = std::numeric_limits<double>::infinity();
    for (int j = 0; j < n_; ++j)
      if (alpha_[j] > pivot_floor)
        bound = std::min(bound, (reduced_[j] + settings_.optimality_tolerance) / alpha_[j]);
    int entering = -1;
    double best_alpha = 0;
    for (int j = 0; j < n_; ++j)
      if (alpha_[j] > pivot_floor && reduced_[j] / alpha_[j] <= bound && alpha_[j] > best_alpha)
        entering = j, best_alpha = alpha_[j];
    if (entering < 0) return false;
    double u[kMaxRows];
    ftran_column(entering, u);
    move_along(leave, entering, u, x_[leave] / u[leave]);
    ++s.iterations;
  }
  return false;
}

// One step of iterative refinement of x_B with a double-double residual (rhs - B x_B), rounded
// back to double.
template <int K>
inline void FastSimplex<K>::refine_weights() {
  DoubleDouble x[kMaxRows];
  for (int i = 0; i < k_; ++i) x[i] = {x_[i], 0};
  refine_precisely<false>(x, p_->rhs.data(), binv_);
  for (int i = 0; i < k_; ++i) x_[i] = x[i].value();
}

}  // namespace mb::lp::fast
