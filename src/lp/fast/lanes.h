#pragma once
// Lane kernels: the loops over columns, rows or basis positions that run in SIMD lanes.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#ifdef __AVX__
#include <immintrin.h>
#endif

#include "lp/fast_backend.h"

namespace mb::lp::fast {

#ifdef __AVX512F__
// One lane a row or basis position of a k-row basis.
template <int K>
constexpr __mmask8 lane_mask() {
  return __mmask8((1u << K) - 1);
}
#endif

#ifdef __AVX512F__
// The lanes of the block of eight starting at index j that lie below n: all eight but in the last
// block (the AVX-512 loops load, compare and store with it, so they need no scalar tail).
inline __mmask8 lanes_below(int n, int j) {
  return n - j >= 8 ? __mmask8(0xff) : __mmask8((1u << (n - j)) - 1);
}
// min(start, the smallest lane of low).
inline double smallest_lane(__m512d low, double start = 0) {
  // Three shuffle-and-minimum steps, not a store and eight dependent scalar ones. (The masked
  // forms with every lane set: GCC 12's unmasked ones, and _mm512_reduce_min_pd, warn of an
  // uninitialised variable.) No lane is NaN: every caller's masked minimum keeps its previous
  // value for NaN inputs.
  low = _mm512_mask_min_pd(low, 0xff, low, _mm512_mask_shuffle_f64x2(low, 0xff, low, low, 0x4e));
  low = _mm512_mask_min_pd(low, 0xff, low, _mm512_mask_shuffle_f64x2(low, 0xff, low, low, 0xb1));
  low = _mm512_mask_min_pd(low, 0xff, low, _mm512_mask_permute_pd(low, 0xff, low, 0x55));
  const double smallest = _mm512_cvtsd_f64(low);
  return smallest < start ? smallest : start;
}
#endif

// k entries of a row of B, B^-1 or x_B: one masked vector move with AVX-512 (the element loops
// of k = 5 were a 32- and an 8-byte move each).
template <int K>
void copy_row(const double* from, double* to) {
#ifdef __AVX512F__
  _mm512_mask_storeu_pd(to, lane_mask<K>(), _mm512_maskz_loadu_pd(lane_mask<K>(), from));
#else
  std::copy(from, from + K, to);
#endif
}

// Whether the k entries of two rows are equal (==: NaN never is).
template <int K>
bool same_row(const double* a, const double* b) {
#ifdef __AVX512F__
  return _mm512_mask_cmp_pd_mask(lane_mask<K>(), _mm512_maskz_loadu_pd(lane_mask<K>(), a),
                                 _mm512_maskz_loadu_pd(lane_mask<K>(), b),
                                 _CMP_EQ_OQ) == lane_mask<K>();
#else
  bool same = true;
  for (int r = 0; r < K; ++r) same &= a[r] == b[r];
  return same;
#endif
}

#ifdef __AVX512F__
// out_j = base_j - sum_r w_r A_rj (base 0 when null) for the n columns of one block whose rows
// lie `stride` apart, eight lanes masked at the end (no scalar tail), each value folded into the
// running minimum `low` (NaN keeps the minimum so far). The same fused chains as combine_block.
// `first_row`: the block's row 0 when it is one constant (the orthonormalised constant function,
// problem.h; the grid's, grid_first_row_), else NaN: then row 0 comes from a register instead of
// loaded, the same chain and bits. 1.01x (power4) and 1.02x (trig4) on lp_bench's warm runs at
// grid 256 (scripts/bench_best.sh, 80 runs each); a blend of two precomputed first steps instead,
// without the cost's load either, was 0.97x (its mask operations cost more than the loads saved).
template <int K>
void combine_masked(const __m512d* weight, const double* values, size_t stride, const double* base,
                    double* out, int n, __m512d& low,
                    double first_row = std::numeric_limits<double>::quiet_NaN()) {
  const bool constant_first_row = !std::isnan(first_row);
  const __m512d first_row_values = _mm512_set1_pd(first_row);
  for (int j = 0; j < n; j += 8) {
    const __mmask8 live = lanes_below(n, j);
    __m512d v = base ? _mm512_maskz_loadu_pd(live, base + j) : _mm512_setzero_pd();
    v = _mm512_fnmadd_pd(
        weight[0], constant_first_row ? first_row_values : _mm512_maskz_loadu_pd(live, values + j),
        v);
    for (int r = 1; r < K; ++r)
      v = _mm512_fnmadd_pd(weight[r], _mm512_maskz_loadu_pd(live, values + r * stride + j), v);
    _mm512_mask_storeu_pd(out + j, live, v);
    low = _mm512_mask_min_pd(low, live, v, low);
  }
}
#endif

#ifdef __AVX512F__
// The index of the least of the lanes that hold one (index >= 0; each lane keeps its first strict
// best, so the lowest index among the lanes holding the least is the first overall), or -1.
inline int first_least_lane(__m512d best, __m512i index) {
  const __mmask8 improved = _mm512_cmp_epi64_mask(index, _mm512_set1_epi64(-1), _MM_CMPINT_NE);
  if (!improved) return -1;
  constexpr double kNone = std::numeric_limits<double>::infinity();
  const __m512d held = _mm512_mask_mov_pd(_mm512_set1_pd(kNone), improved, best);
  const double least = smallest_lane(held, kNone);
  const __mmask8 holding = improved & _mm512_cmp_pd_mask(best, _mm512_set1_pd(least), _CMP_EQ_OQ);
  // The least index as smallest_lane finds the least value (GCC 12's _mm512_reduce_min_epi64
  // warns likewise); a store and a scalar minimum of eight were ~2 % of the solver's samples.
  const __m512i none = _mm512_set1_epi64(std::numeric_limits<int64_t>::max());
  __m512i low = _mm512_mask_mov_epi64(none, holding, index);
  low = _mm512_mask_min_epi64(low, 0xff, low, _mm512_mask_shuffle_i64x2(low, 0xff, low, low, 0x4e));
  low = _mm512_mask_min_epi64(low, 0xff, low, _mm512_mask_shuffle_i64x2(low, 0xff, low, low, 0xb1));
  low = _mm512_mask_min_epi64(low, 0xff, low, _mm512_mask_permutex_epi64(low, 0xff, low, 0xb1));
  return _mm512_cvtsi512_si32(low);  // a column index: its low half
}
#endif

// Each out_j is the chain base_j - w_0 a_0j - w_1 a_1j - ... in fused multiply-adds, as the
// compiler contracts the scalar loop, so both paths give the same bits.
template <int K>
double combine_block(const double* w, const double* const* rows, const double* base, double* out,
                     int n) {
  double weight[K];
  for (int r = 0; r < K; ++r) weight[r] = w[r];
  double smallest = 0;
  int j = 0;
#if defined(__AVX__) && defined(__FMA__)
  {
    __m256d weights[K];
    for (int r = 0; r < K; ++r) weights[r] = _mm256_set1_pd(weight[r]);
    __m256d low = _mm256_setzero_pd();
    for (; j + 4 <= n; j += 4) {
      __m256d v = base ? _mm256_loadu_pd(base + j) : _mm256_setzero_pd();
      for (int r = 0; r < K; ++r) v = _mm256_fnmadd_pd(weights[r], _mm256_loadu_pd(rows[r] + j), v);
      _mm256_storeu_pd(out + j, v);
      low = _mm256_min_pd(v, low);  // NaN keeps the minimum so far, as in smallest_of
    }
    double lane[4];
    _mm256_storeu_pd(lane, low);
    for (double v : lane) smallest = v < smallest ? v : smallest;
  }
#endif
  for (; j < n; ++j) {
    double v = base ? base[j] : 0.0;
    for (int r = 0; r < K; ++r) v = std::fma(-weight[r], rows[r][j], v);
    out[j] = v;
    smallest = v < smallest ? v : smallest;
  }
  return smallest;
}

// The smallest of d[0..n) (at most 0), eight independent lanes so that it vectorises (a single
// running minimum is a chain of dependent minsd, 4 cycles a column).
inline double smallest_of(const double* d, int n) {
#ifdef __AVX512F__
  {
    __m512d low = _mm512_setzero_pd();
    for (int j = 0; j < n; j += 8) {
      const __mmask8 live = lanes_below(n, j);
      low = _mm512_mask_min_pd(low, live, _mm512_maskz_loadu_pd(live, d + j), low);
    }
    return smallest_lane(low);
  }
#endif
  double lane[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  int j = 0;
#ifdef __AVX__
  // GCC turns `a < b ? a : b` into minpd only under -ffinite-math-only; say it directly.
  __m256d low = _mm256_setzero_pd(), high = _mm256_setzero_pd();
  for (; j + 8 <= n; j += 8) {
    low = _mm256_min_pd(_mm256_loadu_pd(d + j), low);
    high = _mm256_min_pd(_mm256_loadu_pd(d + j + 4), high);
  }
  _mm256_storeu_pd(lane, low);
  _mm256_storeu_pd(lane + 4, high);
#else
  for (; j + 8 <= n; j += 8)
    for (int q = 0; q < 8; ++q) lane[q] = d[j + q] < lane[q] ? d[j + q] : lane[q];
#endif
  double smallest = 0;
  for (; j < n; ++j) smallest = d[j] < smallest ? d[j] : smallest;
  for (int q = 0; q < 8; ++q) smallest = lane[q] < smallest ? lane[q] : smallest;
  return smallest;
}

// Whether some d[0..n) is below `threshold` or NaN, in one branch-free pass.
inline bool any_below(const double* d, int n, double threshold) {
  int j = 0;
#ifdef __AVX512F__
  const __m512d limit = _mm512_set1_pd(threshold);
  __mmask8 below = 0;
  for (; j < n; j += 8) {
    const __mmask8 live = lanes_below(n, j);
    below |= _mm512_mask_cmp_pd_mask(live, _mm512_maskz_loadu_pd(live, d + j), limit, _CMP_NGE_UQ);
  }
  return below != 0;
#endif
  bool found = false;
  for (; j < n; ++j) found |= !(d[j] >= threshold);
  return found;
}

// The first index j < n with d[j] == value, eight at a time (a scalar search was 40 % of a
// pivot), or -1.
inline int first_holding(const double* d, int n, double value) {
  int j = 0;
#ifdef __AVX512F__
  // Eight lanes, masked at the end: the compare's mask is the answer, no scalar tail.
  const __m512d target = _mm512_set1_pd(value);
  for (; j < n; j += 8) {
    const __mmask8 live = lanes_below(n, j);
    const unsigned hit =
        _mm512_mask_cmp_pd_mask(live, _mm512_maskz_loadu_pd(live, d + j), target, _CMP_EQ_OQ);
    if (hit) return j + __builtin_ctz(hit);
  }
  return -1;
#elif defined(__AVX__)
  const __m256d target = _mm256_set1_pd(value);
  for (; j + 8 <= n; j += 8) {
    const __m256d a = _mm256_cmp_pd(_mm256_loadu_pd(d + j), target, _CMP_EQ_OQ);
    const __m256d b = _mm256_cmp_pd(_mm256_loadu_pd(d + j + 4), target, _CMP_EQ_OQ);
    if (_mm256_movemask_pd(_mm256_or_pd(a, b))) break;
  }
#else
  for (; j + 8 <= n; j += 8) {
    bool hit = false;
    for (int q = 0; q < 8; ++q) hit |= d[j + q] == value;
    if (hit) break;
  }
#endif
  for (; j < n; ++j)
    if (d[j] == value) return j;
  return -1;
}

}  // namespace mb::lp::fast
