#pragma once
// Iterative refinement of x_B and y with double-double residuals (lp/double_double.h).
#include "lp/fast/simplex.h"

namespace mb::lp::fast {

// One step of iterative refinement of v in B v = target (Transposed: B^T v = target; x_B from the
// moments, y from the basic costs) with a double-double residual and the given inverse of B
// (double or long double): each step gains the digits that cond(B) times the inverse's precision
// leaves.
template <int K>
template <bool Transposed, class Inverse>
inline void FastSimplex<K>::refine_precisely(DoubleDouble* v, const double* target,
                                             const Inverse& inverse) const {
  double misfit[kMaxRows];
  misfit_of<Transposed>(v, target, misfit);
  correct_precisely<Transposed>(v, misfit, inverse);
}

// v += B^{-1} misfit (Transposed: B^{-T} misfit): refine_precisely's step from its residual.
template <int K>
template <bool Transposed, class Inverse>
inline void FastSimplex<K>::correct_precisely(DoubleDouble* v, const double* misfit,
                                              const Inverse& inverse) const {
  using Real = std::remove_cvref_t<decltype(inverse[0][0])>;
  for (int i = 0; i < k_; ++i) {
    Real correction = 0;
    for (int r = 0; r < k_; ++r)
      correction += misfit[r] * (Transposed ? inverse[r][i] : inverse[i][r]);
    add(v[i], double(correction));
  }
}

// misfit = target - B v (Transposed: target - B^T v), summed in double-double and rounded: the
// refinements' residuals, the certificate's residual of the clamped x_B, and its basic columns'
// reduced costs (c_B - B^T y). The k sums side by side: one at a time, each double-double sum is
// a chain of dependent adds, and latency dominated.
template <int K>
template <bool Transposed>
inline void FastSimplex<K>::misfit_of(const DoubleDouble* v, const double* target,
                                      double* misfit) const {
  lanes::misfit<K, Transposed>(basic_, v, target, misfit);
}

}  // namespace mb::lp::fast
