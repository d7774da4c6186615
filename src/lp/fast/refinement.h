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
void FastSimplex<K>::refine_precisely(DoubleDouble* v, const double* target,
                                      const Inverse& inverse) const {
  double misfit[kMaxRows];
  misfit_of<Transposed>(v, target, misfit);
  correct_precisely<Transposed>(v, misfit, inverse);
}

// v += B^{-1} misfit (Transposed: B^{-T} misfit): refine_precisely's step from its residual.
template <int K>
template <bool Transposed, class Inverse>
void FastSimplex<K>::correct_precisely(DoubleDouble* v, const double* misfit,
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
void FastSimplex<K>::misfit_of(const DoubleDouble* v, const double* target, double* misfit) const {
#ifdef __AVX512F__
  // As the lanes of one vector: rows of B v from B's columns (basic_[i]), or positions of B^T v
  // from its rows.
  DoubleDouble8 sum{_mm512_maskz_loadu_pd(kLanes, target)};
  if constexpr (Transposed) {
    __m512d row[K];
    basic_rows(row);
    for (int r = 0; r < K; ++r) add_product(sum, v[r], negated(row[r]));
  } else {
    for (int i = 0; i < K; ++i)
      add_product(sum, v[i], negated(_mm512_maskz_loadu_pd(kLanes, basic_[i])));
  }
  _mm512_mask_storeu_pd(misfit, kLanes, value(sum));
#else
  DoubleDouble sum[kMaxRows];
  for (int q = 0; q < k_; ++q) sum[q] = {target[q], 0};
  if constexpr (Transposed) {
    for (int r = 0; r < k_; ++r)
      for (int i = 0; i < k_; ++i) add_product(sum[i], v[r], -basic_[i][r]);
  } else {
    for (int i = 0; i < k_; ++i)
      for (int r = 0; r < k_; ++r) add_product(sum[r], v[i], -basic_[i][r]);
  }
  for (int q = 0; q < k_; ++q) misfit[q] = sum[q].value();
#endif
}

#ifdef __AVX512F__
// row[r] = (basic_[0][r], ..., basic_[k-1][r]): row r of B, one lane a basis position.
template <int K>
void FastSimplex<K>::basic_rows(__m512d (&row)[K]) const {
  static_assert(kMaxRows == 8, "basic_[i][r] lies 8 doubles after basic_[i - 1][r]");
  const __m512i position = _mm512_set_epi64(56, 48, 40, 32, 24, 16, 8, 0);
  for (int r = 0; r < K; ++r)
    row[r] = _mm512_mask_i64gather_pd(_mm512_setzero_pd(), kLanes, position, &basic_[0][r], 8);
}
#endif

#ifdef __AVX512F__
// -v exactly (the sign bit flipped, as the scalar unary minus).
template <int K>
__m512d FastSimplex<K>::negated(__m512d v) {
  return _mm512_castsi512_pd(
      _mm512_xor_si512(_mm512_castpd_si512(v), _mm512_set1_epi64(int64_t(1) << 63)));
}
#endif

}  // namespace mb::lp::fast
