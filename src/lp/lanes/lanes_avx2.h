#pragma once
// The AVX2 paths of the lane kernels (lanes.h), for builds without AVX-512: four doubles a
// vector and a scalar tail. Each returns exactly what its scalar reference (lanes_scalar.h)
// returns, bit for bit. Kernels without an AVX2 path use the scalar reference in such builds.
#if defined(__AVX2__) && defined(__FMA__)
#include "lp/lanes/lanes_scalar.h"
#include "util/simd_intrinsics.h"

namespace mb::lp::fast::lanes::avx2 {

using scalar::kNone;

// Eight independent lanes, so that the minimum is not one chain of dependent minsd. (GCC turns
// `a < b ? a : b` into minpd only under -ffinite-math-only; min_pd(d, low) is exactly that.)
inline double smallest_of(const double* d, int n) {
  double lane[8];
  int j = 0;
  __m256d low = _mm256_setzero_pd(), high = _mm256_setzero_pd();
  for (; j + 8 <= n; j += 8) {
    low = _mm256_min_pd(_mm256_loadu_pd(d + j), low);
    high = _mm256_min_pd(_mm256_loadu_pd(d + j + 4), high);
  }
  _mm256_storeu_pd(lane, low);
  _mm256_storeu_pd(lane + 4, high);
  double smallest = 0;
  for (; j < n; ++j) smallest = d[j] < smallest ? d[j] : smallest;
  for (int q = 0; q < 8; ++q) smallest = lane[q] < smallest ? lane[q] : smallest;
  return smallest;
}

inline int first_holding(const double* d, int n, double value) {
  const __m256d target = _mm256_set1_pd(value);
  int j = 0;
  for (; j + 8 <= n; j += 8) {
    const __m256d a = _mm256_cmp_pd(_mm256_loadu_pd(d + j), target, _CMP_EQ_OQ);
    const __m256d b = _mm256_cmp_pd(_mm256_loadu_pd(d + j + 4), target, _CMP_EQ_OQ);
    if (_mm256_movemask_pd(_mm256_or_pd(a, b))) break;
  }
  for (; j < n; ++j)
    if (d[j] == value) return j;
  return -1;
}

template <class F>
void for_each_below(const double* d, int n, double threshold, F&& f) {
  const __m256d below = _mm256_set1_pd(threshold);
  int j = 0;
  for (; j + 4 <= n; j += 4) {
    int mask = _mm256_movemask_pd(_mm256_cmp_pd(_mm256_loadu_pd(d + j), below, _CMP_NGE_UQ));
    for (; mask; mask &= mask - 1) f(j + __builtin_ctz(mask));
  }
  for (; j < n; ++j)
    if (!(d[j] >= threshold)) f(j);
}

template <int K>
double combine(const double* w, const double* values, size_t stride, const double* base,
               double* out, int n,
               double /*first_row*/ = std::numeric_limits<double>::quiet_NaN()) {
  __m256d weights[K];
  for (int r = 0; r < K; ++r) weights[r] = _mm256_set1_pd(w[r]);
  __m256d low = _mm256_setzero_pd();
  int j = 0;
  for (; j + 4 <= n; j += 4) {
    __m256d v = base ? _mm256_loadu_pd(base + j) : _mm256_setzero_pd();
    for (int r = 0; r < K; ++r)
      v = _mm256_fnmadd_pd(weights[r], _mm256_loadu_pd(values + r * stride + j), v);
    _mm256_storeu_pd(out + j, v);
    low = _mm256_min_pd(v, low);  // NaN keeps the minimum so far, as in the reference
  }
  double lane[4];
  _mm256_storeu_pd(lane, low);
  double smallest = 0;
  for (double v : lane) smallest = v < smallest ? v : smallest;
  const double tail =
      scalar::combine<K>(w, values + j, stride, base ? base + j : nullptr, out + j, n - j);
  return tail < smallest ? tail : smallest;
}

// Per query the smallest positive (p - from) * direction in four lanes, then a second pass for
// the first index holding it.
template <int Q>
void nearest_beyond_each(const double (&from)[Q], const double (&direction)[Q],
                         const double (&distance)[Q], const double* points, int n, int (&out)[Q]) {
  double nearest[Q];
  for (int q = 0; q < Q; ++q) nearest[q] = kNone;
  int e = 0;
  {
    __m256d origin[Q], sign[Q], low[Q];
    const __m256d none = _mm256_set1_pd(kNone), zero = _mm256_setzero_pd();
    for (int q = 0; q < Q; ++q)
      origin[q] = _mm256_set1_pd(from[q]), sign[q] = _mm256_set1_pd(direction[q]), low[q] = none;
    for (; e + 4 <= n; e += 4) {
      const __m256d p = _mm256_loadu_pd(points + e);
      for (int q = 0; q < Q; ++q) {
        const __m256d d = _mm256_mul_pd(_mm256_sub_pd(p, origin[q]), sign[q]);
        low[q] =
            _mm256_min_pd(_mm256_blendv_pd(none, d, _mm256_cmp_pd(d, zero, _CMP_GT_OQ)), low[q]);
      }
    }
    for (int q = 0; q < Q; ++q) {
      double lane[4];
      _mm256_storeu_pd(lane, low[q]);
      for (double v : lane) nearest[q] = v < nearest[q] ? v : nearest[q];
    }
  }
  for (; e < n; ++e)
    for (int q = 0; q < Q; ++q) {
      const double d = (points[e] - from[q]) * direction[q];
      if (d > 0 && d < nearest[q]) nearest[q] = d;
    }
  int open = 0;
  bool wanted[Q];
  for (int q = 0; q < Q; ++q) open += wanted[q] = nearest[q] < distance[q];
  e = 0;
  for (; open > 0 && e + 4 <= n; e += 4) {
    const __m256d p = _mm256_loadu_pd(points + e);
    for (int q = 0; q < Q; ++q) {
      if (!wanted[q]) continue;
      const __m256d d =
          _mm256_mul_pd(_mm256_sub_pd(p, _mm256_set1_pd(from[q])), _mm256_set1_pd(direction[q]));
      const int mask = _mm256_movemask_pd(_mm256_cmp_pd(d, _mm256_set1_pd(nearest[q]), _CMP_EQ_OQ));
      if (mask) out[q] = e + __builtin_ctz(mask), wanted[q] = false, --open;
    }
  }
  for (; open > 0 && e < n; ++e)
    for (int q = 0; q < Q; ++q)
      if (wanted[q] && (points[e] - from[q]) * direction[q] == nearest[q])
        out[q] = e, wanted[q] = false, --open;
}

}  // namespace mb::lp::fast::lanes::avx2
#endif
