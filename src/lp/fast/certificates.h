#pragma once
// Certificates: every optimal answer is proven within 1e-9 of the optimum before it is returned.
#include "lp/fast/simplex.h"

namespace mb::lp::fast {

// A bound on the rounding error of any reduced cost the double pass computes with duals y:
// gamma (1 + |y|_1 max |a_rj|), gamma = (k + 2) eps.
template <int K>
inline double FastSimplex<K>::pricing_rounding(const double* y) const {
  double y_norm = 0;
  for (int r = 0; r < k_; ++r) y_norm += std::abs(y[r]);
  return (k_ + 2) * std::numeric_limits<double>::epsilon() * (1 + y_norm * column_bound());
}

// The certificate, in double when that is provably enough, else in double-double.
template <int K>
inline bool FastSimplex<K>::certify(Solution& s) {
  certificate_entering_ = -1;
  return certify_in_double(s) || certify_precisely(s);
}

// Most bases have moderate duals, and then double arithmetic certifies them with room to spare:
// the same first-order bound as below, with the true residual B x - rhs (double x_B is only
// cond(B) eps accurate) and every computed term widened by its rounding error bound
// gamma (|terms|), gamma = (k + 2) eps. Narrow kernels (|y| ~ 1e8) fail this on rounding alone
// and go to double-double. Every bound term is computed from the data (true residuals, reduced
// costs of the y used), so the inverse need not be fresh: the product-form one, with one step of
// refinement for y as for x_B, serves as well, and saves a factorisation per LP.
template <int K>
inline bool FastSimplex<K>::certify_in_double(Solution& s) {
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  const double gamma = (k_ + 2) * kEps;
  double y[kMaxRows] = {};  // (GCC cannot see that the copy fills k_ <= kMaxRows)
  if (fresh_.duals)  // the iterations' last duals, of this very basis and inverse: the same bits
    std::copy(y_, y_ + k_, y);
  else
    btran(y);
  const double reduced_cost_error = pricing_rounding(y);
  if (reduced_cost_error > 0.1 * kCertifyBound) return false;
  // One step of iterative refinement: x_B from the double inverse misses rhs by ~cond(B) eps;
  // after it the residual is at the level of its own rounding (backward stable).
  double correction[kMaxRows], misfit[kMaxRows];
  for (int r = 0; r < k_; ++r) {
    double v = p_->rhs[r];
    for (int i = 0; i < k_; ++i) v -= basic_[i][r] * x_[i];
    misfit[r] = v;
  }
  ftran(misfit, correction);
  for (int i = 0; i < k_; ++i) x_[i] += correction[i];
  // A weight below what double-double would call zero is for the precise pass (and then the
  // dual simplex) to judge: the bound's terms would not notice it (settings_.certify_residual; a
  // clamped weight of ~-1e-12 passed here with G = 1.41e-8 where the optimum, a basis primal and
  // dual feasible in __float128, is 2.50e-8).
  double clamped[kMaxRows];
  for (int i = 0; i < k_; ++i) {
    if (!(x_[i] >= -settings_.negligible_weight)) return false;
    clamped[i] = std::max(x_[i], 0.0);
  }
  double bound = 0;
  for (int r = 0; r < k_; ++r) {
    double residual = -p_->rhs[r], size = std::abs(p_->rhs[r]);
    for (int i = 0; i < k_; ++i) {
      const double term = basic_[i][r] * clamped[i];
      residual += term;
      size += std::abs(term);
    }
    // The reported support must reproduce the moments as accurately as long double's does
    // (the KKT checker and the users' own checks look at the residual alone).
    if (!(std::abs(residual) + gamma * size <= settings_.certify_residual)) return false;
    bound += std::abs(y[r]) * (std::abs(residual) + gamma * size);
  }
  const bool priced = priced_with(y);
  for (int r = 0; r < k_; ++r) y_[r] = y[r];
  if (!priced) reduced_costs();
  auto reduced_cost = [&](int j) { return std::abs(reduced_[j]) + reduced_cost_error; };
  for (int i = 0; i < k_; ++i) {
    if (clamped[i] <= 0) continue;
    if (basis_[i] < n_) bound += clamped[i] * reduced_cost(basis_[i]);
    if (basis_[i] == composite_)
      for (size_t t = 0; t < p_->start_support.size(); ++t)
        bound += clamped[i] * p_->start_weights[t] * reduced_cost(p_->start_support[t]);
  }
  // Weak duality with sum w = 1: no distribution beats y.(1, b) by more than -min_j d_j.
  bound += std::max(0.0, reduced_cost_error - fresh_.smallest_reduced);  // reduced_ is y's (above)
  if (!(bound <= kCertifyBound)) return false;
  double objective = 0;
  for (int i = 0; i < k_; ++i) objective += cost(basis_[i]) * clamped[i];
  report(s, objective, clamped, y);
  return true;
}

// weights: x_B clamped at 0; y: the duals, double or double-double (Solution keeps long double).
template <int K>
template <class Dual>
inline void FastSimplex<K>::report(Solution& s, double objective, const double* weights,
                                   const Dual* y) const {
  s.status = ProblemStatus::Optimal;
  s.support.clear();
  s.weights.clear();
  if (is_basic(composite_)) {
    s.support.reserve(k_);  // one allocation each, not one per doubling
    s.weights.reserve(k_);
    for (int i = 0; i < k_; ++i) {
      const double w = weights[i];
      if (w <= 0) continue;
      if (basis_[i] == composite_) {
        // The composite column stands for the known distribution: report its atoms.
        for (size_t t = 0; t < p_->start_support.size(); ++t)
          add_support(s, p_->start_support[t], w * p_->start_weights[t]);
      } else {
        add_support(s, basis_[i], w);
      }
    }
  } else {
    // Distinct basic columns: no atom to merge, so no search.
    s.support.resize(k_);
    s.weights.resize(k_);
    int count = 0;
    for (int i = 0; i < k_; ++i) {
      s.support[count] = basis_[i];
      s.weights[count] = weights[i];
      count += weights[i] > 0;
    }
    s.support.resize(count);
    s.weights.resize(count);
  }
  s.G = objective;
  s.duals.resize(k_);
  for (int r = 0; r < k_; ++r) s.duals[r] = to_long_double(y[r]);
}

// The precise certificate, in double-double: x_B and y refined from the double inverse first
// (two steps with double-double residuals reach well past long double accuracy for cond(B) up to
// ~1e8, at a fraction of a factorisation's cost; most bases need one), then, if that does not
// certify, with B inverted afresh in long double. On that failure the accurate inverse and x_B
// are kept, so the caller resumes from them. (Double-double lives in SSE registers and
// pipelines; x87 long double does neither.)
template <int K>
inline bool FastSimplex<K>::certify_precisely(Solution& s) {
  DoubleDouble x[kMaxRows], y[kMaxRows];
  double basic_cost[kMaxRows];
  const bool refined = fresh_.duals && fresh_.precise_duals;  // y_ refined by iterate already
  for (int i = 0; i < k_; ++i) {
    basic_cost[i] = cost(basis_[i]);
    x[i] = {x_[i], 0};
    y[i] = refined ? precise_y_[i] : DoubleDouble{y_[i], 0};
  }
  auto refine = [&](const auto& inverse, int steps) {
    for (int step = 0; step < steps; ++step) {
      refine_precisely<false>(x, p_->rhs.data(), inverse);
      refine_precisely<true>(y, basic_cost, inverse);
    }
  };
  // x_B: one step, then its residual, which the bound needs anyway, decides whether a second
  // step is taken (a third of the bounds fail on |y| times the residual one step leaves); the
  // second starts from that residual, so no residual is computed twice.
  refine_precisely<false>(x, p_->rhs.data(), binv_);
  double residual[kMaxRows];
  misfit_of<false>(x, p_->rhs.data(), residual);
  if (!refined) refine_precisely<true>(y, basic_cost, binv_);
  if (precise_bound(x, y, s, residual)) return true;
  correct_precisely<false>(x, residual, binv_);
  if (precise_bound(x, y, s)) return true;
  refine(binv_, 1);
  if (precise_bound(x, y, s)) return true;
  long double factors[kMaxRows][kMaxRows], inv[kMaxRows][kMaxRows];
  for (int r = 0; r < k_; ++r)
    for (int i = 0; i < k_; ++i) factors[r][i] = basic_[i][r];
  if (!invert_fixed<long double, K>(factors, inv, 1e-14L)) return false;
  for (int i = 0; i < k_; ++i) {
    long double v = 0;
    for (int r = 0; r < k_; ++r) v += inv[i][r] * (long double)p_->rhs[r];
    x[i] = to_double_double(v);
    for (int r = 0; r < k_; ++r) binv_[i][r] = double(inv[i][r]);
  }
  updates_ = 0;
  fresh_.basis_changed();
  for (int r = 0; r < k_; ++r) {
    long double v = 0;
    for (int i = 0; i < k_; ++i) v += basic_cost[i] * inv[i][r];
    y[r] = to_double_double(v);
  }
  // The solve alone leaves a residual of ~cond(B) long double epsilons, which |y| ~ 1e8 would
  // turn into a failed bound: refine with the long double inverse.
  refine(inv, 2);
  for (int i = 0; i < k_; ++i) x_[i] = x[i].value();
  return precise_bound(x, y, s);
}

// y_ (btran's duals of the current basis) refined by one double-double step into precise_y_, and
// rounded back into y_ (iterate, for certify_precisely).
template <int K>
inline void FastSimplex<K>::refine_duals_for_certificate() {
  double basic_cost[kMaxRows];
  for (int i = 0; i < k_; ++i) basic_cost[i] = cost(basis_[i]), precise_y_[i] = {y_[i], 0};
  refine_precisely<true>(precise_y_, basic_cost, binv_);
  for (int i = 0; i < k_; ++i) y_[i] = precise_y_[i].value();
  fresh_.precise_duals = true;
}

// d_j = c_j - y.a_j in double-double.
template <int K>
inline double FastSimplex<K>::precise_reduced_cost(int j, const DoubleDouble* y) const {
  double a[kMaxRows];
  load_column(j, a);
  DoubleDouble d{cost_[j], 0};
  for (int r = 0; r < k_; ++r) add_product(d, y[r], -a[r]);
  return d.value();
}

// Accepts x_B and y when the same first-order bound on |G - G*| as the KKT checker's (|y| times
// the residual of the clamped x_B, plus complementarity, plus dual infeasibility) is <= 1e-9,
// every term from double-double sums (the bound's own double rounding is ~1e-16 of it).
// `residual_of_x`: rhs - B x when known (used when no weight is clamped).
template <int K>
inline bool FastSimplex<K>::precise_bound(const DoubleDouble* x, const DoubleDouble* y, Solution& s,
                                          const double* residual_of_x) {
  DoubleDouble clamped[kMaxRows];
  bool unclamped = true;
  for (int i = 0; i < k_; ++i) {
    if (!(x[i].value() >= -settings_.negligible_weight)) return false;
    clamped[i] = x[i].hi > 0 ? x[i] : DoubleDouble{};
    unclamped &= x[i].hi > 0 || (x[i].hi == 0 && x[i].lo == 0);
  }
  // rhs - B max(x, 0): only its size counts below.
  double residual[kMaxRows];
  if (residual_of_x && unclamped)
    std::copy(residual_of_x, residual_of_x + k_, residual);
  else
    misfit_of<false>(clamped, p_->rhs.data(), residual);
  // Its part of the bound first: when it alone is too large (refinement needs another step), the
  // rest is not computed.
  double bound = 0;
  for (int r = 0; r < k_; ++r) {
    if (!(std::abs(residual[r]) <= settings_.certify_residual)) return false;  // x_B not feasible
    bound += std::abs(y[r].value() * residual[r]);
  }
  if (!(bound <= kCertifyBound)) return false;
  // Complementarity as the KKT checker sees it: basic reduced costs, zero in exact arithmetic,
  // are |y| times rounding in practice. Computed for every basic column, since each is also a
  // suspect below (so that none is judged twice).
  // (Read for the structural columns only: the composite's atoms count instead.)
  double basic_cost[kMaxRows], basic_reduced[kMaxRows];
  for (int i = 0; i < k_; ++i) basic_cost[i] = basis_[i] < n_ ? cost_[basis_[i]] : 0.0;
  misfit_of<true>(y, basic_cost, basic_reduced);
  for (int i = 0; i < k_; ++i) {
    const double w = clamped[i].value();
    if (w <= 0) continue;
    if (basis_[i] < n_) bound += w * std::abs(basic_reduced[i]);
    if (basis_[i] == composite_)  // reported as its atoms, so their reduced costs count
      for (size_t t = 0; t < p_->start_support.size(); ++t)
        bound += w * p_->start_weights[t] * std::abs(precise_reduced_cost(p_->start_support[t], y));
  }
  if (!(bound <= kCertifyBound)) return false;
  // Double pricing with the rounded duals finds the suspects, double-double judges them: a
  // column whose double reduced cost is at least its rounding bound (that of the pass plus the
  // rounding of y) cannot be negative.
  double rounding = 0;
  for (int r = 0; r < k_; ++r) {
    y_[r] = y[r].value();
    rounding += std::abs((y[r].hi - y_[r]) + y[r].lo);
  }
  if (!priced_with(y_)) reduced_costs();
  const double suspect_below = (pricing_rounding(y_) + rounding * column_bound()) * (1 + 1e-6);
  // Weak duality with sum w = 1: no distribution beats y.(1, b) by more than -min_j d_j, so the
  // most negative reduced cost counts, once (as in the KKT checker).
  // (The first column holding it on ties, as a scan in column order would find it.)
  double infeasibility = 0;
  int most_negative_column = -1;
  auto judge = [&](int j, double d) {
    if (-d > infeasibility || (-d == infeasibility && -d > 0 && j < most_negative_column))
      infeasibility = -d, most_negative_column = j;
  };
  // The basic columns, suspects by their rounding alone, are judged by their double-double
  // values, then hidden (read +inf), so that one branch-free pass nearly always shows that no
  // other column is a suspect, without a branch per block.
  for (int i = 0; i < k_; ++i)
    if (basis_[i] < n_) judge(basis_[i], basic_reduced[i]);
  const BasicColumnsHidden hidden(*this, std::numeric_limits<double>::infinity());
  const double* reduced = reduced_.data();
  auto judge_precisely = [&](int column) { judge(column, precise_reduced_cost(column, y)); };
  if (lanes::any_below(reduced, n_, suspect_below))
    lanes::for_each_below(reduced, n_, suspect_below, judge_precisely);
  if (!(bound + infeasibility <= kCertifyBound)) {
    // Dual infeasible beyond the budget: the most negative column, unless basic (rounding).
    if (infeasibility > 0 && !is_basic(most_negative_column))
      certificate_entering_ = most_negative_column;
    return false;
  }
  // G and the weights from double-double sums, rounded once.
  DoubleDouble objective;
  double weights[kMaxRows];
  for (int i = 0; i < k_; ++i) {
    weights[i] = clamped[i].value();
    add_product(objective, clamped[i], cost(basis_[i]));
    x_[i] = x[i].value();
  }
  report(s, objective.value(), weights, y);
  return true;
}

template <int K>
inline void FastSimplex<K>::add_support(Solution& s, int j, double w) {
  for (size_t t = 0; t < s.support.size(); ++t)
    if (s.support[t] == j) {
      s.weights[t] += w;
      return;
    }
  s.support.push_back(j);
  s.weights.push_back(w);
}

}  // namespace mb::lp::fast
