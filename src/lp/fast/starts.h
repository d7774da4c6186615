#pragma once
// Cold starts: artificial columns for phase 1 and their removal, and the composite column.
#include "lp/fast/simplex.h"

namespace mb::lp::fast {

template <int K>
inline void FastSimplex<K>::start_with_artificials() {
  for (int r = 0; r < k_; ++r) {
    artificial_sign_[r] = p_->rhs[r] >= 0 ? 1.0 : -1.0;
    basis_[r] = n_ + r;
    x_[r] = std::abs(p_->rhs[r]);
  }
  for (int i = 0; i < k_; ++i) {
    load_column(basis_[i], basic_[i]);
    for (int r = 0; r < k_; ++r) binv_[i][r] = i == r ? artificial_sign_[r] : 0.0;
  }
  updates_ = 0;
  fresh_.basis_changed();
}

// The known distribution as one composite column (its moment vector, which is the rhs, at its
// cost F_Z(z_f)): a convex combination of columns, so adding it leaves the optimum unchanged,
// and with weight 1 it is a feasible basic solution. The other k - 1 basic columns are grid
// columns spread over I, at level zero. No phase 1, no Carathéodory reduction.
template <int K>
inline bool FastSimplex<K>::start_from_distribution() {
  // Where the mass and z_f are, on the grid: the optimal support lies around them, so the start
  // columns do too (spread over all of I, narrow kernels took ~100 pivots instead of ~10).
  double lo = p_->zf, hi = p_->zf;
  for (int j : p_->start_support) lo = std::min(lo, point(j)), hi = std::max(hi, point(j));
  const auto& grid = p_->grid->points;
  int first = grid_bound(grid, lo, false, cell_scale_) - 1;
  int last = grid_bound(grid, hi, false, cell_scale_) + 1;
  for (int widen = 0; widen < 6; ++widen) {
    first = std::max(0, first - widen * (k_ - 1));
    last = std::min(g_ - 1, last + widen * (k_ - 1));
    if (last - first + 1 < k_ - 1) continue;
    basis_[0] = composite_;
    for (int i = 1; i < k_; ++i)  // k - 1 columns spread evenly over [first, last]
      basis_[i] = k_ == 2 ? (first + last) / 2
                          : first + int(std::lround(double(i - 1) * (last - first) / (k_ - 2)));
    if (refactor()) {
      for (int i = 0; i < k_; ++i) x_[i] = i == 0 ? 1.0 : 0.0;  // exact: B e_1 = rhs
      return true;
    }
  }
  return false;
}

// After phase 1 every artificial left in the basis sits at zero; pivot each out on the
// structural column with the largest entry in its row of B^{-1} A.
template <int K>
inline bool FastSimplex<K>::drive_out_artificials() {
  for (int i = 0; i < k_; ++i) {
    if (!is_artificial(basis_[i])) continue;
    int best = -1;
    double best_value = 1e-7;
    for (int j = 0; j < n_; ++j) {
      if (std::find(basis_, basis_ + k_, j) != basis_ + k_) continue;
      double v = 0;
      for (int r = 0; r < k_; ++r) v += binv_[i][r] * p_->at(r, j);
      if (std::abs(v) > best_value) best = j, best_value = std::abs(v);
    }
    if (best < 0) return false;
    basis_[i] = best;
    if (!refactor()) return false;
  }
  return refactor();
}

}  // namespace mb::lp::fast
