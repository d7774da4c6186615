#pragma once
// The basis factorisation: B^-1 from LU, FTRAN (B^-1 a), BTRAN (B^-T c_B), product-form updates.
#include "lp/fast/simplex.h"

namespace mb::lp::fast {

// Point j of I (Problem::point without its vectors' bookkeeping, and selects, not a branch).
template <int K>
inline double FastSimplex<K>::point(int j) const {
  const bool on_grid = j < g_;
  return (on_grid ? grid_points_ : extra_points_)[on_grid ? j : j - g_];
}

template <int K>
inline bool FastSimplex<K>::is_artificial(int j) const {
  return j >= n_ && j < n_ + k_;
}

// The inverse of the mapped basis from `factors` (its previous LP's) by a product-form update per
// column that changed, instead of a factorisation: with the same atoms mapped to the same depths,
// most columns come back unchanged (grid points and kernel depths; z_f's and the composite's
// are new). False (the caller factorises) when too many changed or an update would be (nearly)
// singular. x_B from the new moments.
template <int K>
inline bool FastSimplex<K>::update_factors(const BasisState& factors) {
  double a[kMaxRows][kMaxRows];
  int changed[kMaxRows], count = 0;
  for (int i = 0; i < k_; ++i) {
    load_column(basis_[i], a[i]);
    if (!lanes::same_row<K>(a[i], factors.basic[i])) changed[count++] = i;
  }
  if (count > settings_.changed_columns || factors.updates + count > refactor_interval())
    return false;
  for (int i = 0; i < k_; ++i) {
    lanes::copy_row<K>(factors.binv[i], binv_[i]);
    lanes::copy_row<K>(factors.basic[i], basic_[i]);
  }
  updates_ = factors.updates;
  fresh_.basis_changed();
  for (int c = 0; c < count; ++c) {
    const int i = changed[c];
    double u[kMaxRows] = {};  // (GCC cannot see that ftran fills k_ <= kMaxRows)
    ftran(a[i], u);
    if (!stable_pivot(u, i)) return false;
    pivot(i, basis_[i], u);
  }
  ftran(p_->rhs.data(), x_);
  return true;
}

template <int K>
inline void FastSimplex<K>::save_basis(BasisState& to) const {
  std::copy(basis_, basis_ + k_, to.basis);
  lanes::copy_row<K>(x_, to.x);
  for (int i = 0; i < k_; ++i) {
    lanes::copy_row<K>(binv_[i], to.binv[i]);
    lanes::copy_row<K>(basic_[i], to.basic[i]);
  }
  to.updates = updates_;
}

template <int K>
inline void FastSimplex<K>::restore_basis(const BasisState& from) {
  std::copy(from.basis, from.basis + k_, basis_);
  lanes::copy_row<K>(from.x, x_);
  for (int i = 0; i < k_; ++i) {
    lanes::copy_row<K>(from.binv[i], binv_[i]);
    lanes::copy_row<K>(from.basic[i], basic_[i]);
  }
  updates_ = from.updates;
  fresh_.basis_changed();
}

template <int K>
inline double FastSimplex<K>::column_entry(int j, int r) const {
  if (j < n_) return p_->at(r, j);
  if (j == composite_) return p_->rhs[r];
  return r == j - n_ ? artificial_sign_[r] : 0.0;
}

// values[0..n) when they are all the same (bit for bit), else NaN.
template <int K>
inline double FastSimplex<K>::constant_first_row(const double* values, int n) {
  for (int j = 1; j < n; ++j)
    if (std::bit_cast<uint64_t>(values[j]) != std::bit_cast<uint64_t>(values[0]))
      return std::numeric_limits<double>::quiet_NaN();
  return n > 0 ? values[0] : std::numeric_limits<double>::quiet_NaN();
}

// Column j's k entries, with the block decided once.
template <int K>
inline void FastSimplex<K>::load_column(int j, double* a) const {
  if (j < g_) {
    const double* v = p_->grid->values.data() + j;
    for (int r = 0; r < k_; ++r) a[r] = v[size_t(r) * g_];
  } else if (j < n_) {
    const double* v = p_->extra.values.data() + (j - g_);
    for (int r = 0; r < k_; ++r) a[r] = v[size_t(r) * e_];
  } else {
    for (int r = 0; r < k_; ++r) a[r] = column_entry(j, r);
  }
}

template <int K>
inline double FastSimplex<K>::cost(int j) const {
  if (phase_ == 1) return is_artificial(j) ? 1.0 : 0.0;
  if (j < n_) return cost_[j];
  return j == composite_ ? composite_cost() : 0.0;
}

template <int K>
inline bool FastSimplex<K>::refactor() {
  double b[kMaxRows][kMaxRows], inv[kMaxRows][kMaxRows];
  for (int i = 0; i < k_; ++i) {
    load_column(basis_[i], basic_[i]);
    for (int r = 0; r < k_; ++r) b[r][i] = basic_[i][r];
  }
  // Partial pivoting; a pivot below 1e-13 of the largest entry means rank loss (the merely
  // ill-conditioned bases of tiny-valued columns, z^6 near 0, must still pass).
  if (!invert_fixed<double, K>(b, inv, 1e-13)) return false;
  for (int i = 0; i < k_; ++i) std::copy(inv[i], inv[i] + k_, binv_[i]);
  ftran(p_->rhs.data(), x_);
  updates_ = 0;
  fresh_.basis_changed();
  return true;
}

template <int K>
inline void FastSimplex<K>::btran(double* y) const {
  double basic_cost[kMaxRows], misfit[kMaxRows];
  for (int i = 0; i < k_; ++i) basic_cost[i] = cost(basis_[i]);
  for (int r = 0; r < k_; ++r) {
    double v = 0;
    for (int i = 0; i < k_; ++i) v += basic_cost[i] * binv_[i][r];
    y[r] = v;
  }
  for (int i = 0; i < k_; ++i) {  // c_B - B^T y
    double v = basic_cost[i];
    for (int r = 0; r < k_; ++r) v -= basic_[i][r] * y[r];
    misfit[i] = v;
  }
  for (int r = 0; r < k_; ++r) {
    double v = 0;
    for (int i = 0; i < k_; ++i) v += misfit[i] * binv_[i][r];
    y[r] += v;
  }
}

template <int K>
inline bool FastSimplex<K>::is_basic(int j) const {
  return basic_position(j) >= 0;
}

// The position of column j among basis_[0..among), or -1. Selects, no early exit: k is fixed,
// and std::find is a call.
template <int K>
inline int FastSimplex<K>::basic_position(int j, int among) const {
  int at = -1;
  for (int i = 0; i < among; ++i) at = basis_[i] == j ? i : at;
  return at;
}

// u = B^{-1} a_j, the entering column in basis coordinates.
template <int K>
inline void FastSimplex<K>::ftran_column(int j, double* u) const {
  double a[kMaxRows];
  load_column(j, a);
  ftran(a, u);
}

// u = B^{-1} a for any k-vector a (a column, a residual, the moments).
template <int K>
inline void FastSimplex<K>::ftran(const double* a, double* u) const {
  for (int i = 0; i < k_; ++i) {
    double v = 0;
    for (int r = 0; r < k_; ++r) v += binv_[i][r] * a[r];
    u[i] = v;
  }
}

// Whether u_i (u = B^{-1} a) is large enough, against the largest |u_q|, for a to replace basic
// column i without a (nearly) singular basis (exchange, update_factors).
template <int K>
inline bool FastSimplex<K>::stable_pivot(const double* u, int i) const {
  double largest = 0;
  for (int q = 0; q < k_; ++q) largest = std::max(largest, std::abs(u[q]));
  return std::abs(u[i]) > 1e-7 * largest;
}

// Product-form update of the explicit inverse: column `entering` replaces basis row `leave`.
template <int K>
inline void FastSimplex<K>::pivot(int leave, int entering, const double* u) {
  const double reciprocal = 1 / u[leave];  // one division, not k (8.8 exchanges and pivots an LP)
  lanes::update_inverse<K>(binv_, leave, u, reciprocal);
  basis_[leave] = entering;
  load_column(entering, basic_[leave]);
  ++updates_;
  fresh_.basis_changed();
}

// |a_rj| <= column_bound() for every column.
template <int K>
inline double FastSimplex<K>::column_bound() const {
  return std::max(p_->grid->max_abs, p_->extra.max_abs);
}

template <int K>
inline double FastSimplex<K>::composite_cost() const {
  if (composite_cost_ != composite_cost_) {
    double sum = 0;
    for (size_t t = 0; t < p_->start_support.size(); ++t)
      sum += p_->start_weights[t] * cost_[p_->start_support[t]];
    composite_cost_ = sum;
  }
  return composite_cost_;
}

template <int K>
inline int FastSimplex<K>::refactor_interval() const {
  return retrying_ ? settings_.careful_refactor_interval : settings_.refactor_interval;
}

}  // namespace mb::lp::fast
