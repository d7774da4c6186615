#pragma once
// The AVX-512 paths of the lane kernels (lanes.h): eight doubles a vector, the last block of a
// loop masked (no scalar tail). Each returns exactly what its scalar reference (lanes_scalar.h)
// returns, bit for bit: the same fused chains in the same order, the same first index on ties.
// (Masked forms with every lane set appear where GCC 12's unmasked ones warn of an uninitialised
// variable.)
#ifdef __AVX512F__
#include <cstdint>
#include <limits>

#include "lp/double_double.h"
#include "lp/lanes/lanes_scalar.h"
#include "util/simd_intrinsics.h"

namespace mb::lp::fast::lanes::avx512 {

using scalar::kNone;

// The lanes of the block of eight starting at index j that lie below n.
inline __mmask8 lanes_below(int n, int j) {
  return n - j >= 8 ? __mmask8(0xff) : __mmask8((1u << (n - j)) - 1);
}
// One lane a row or basis position of a k-row basis.
template <int K>
constexpr __mmask8 lane_mask() {
  return __mmask8((1u << K) - 1);
}

// min(start, the smallest lane of low), in three shuffle-and-minimum steps. No lane is NaN: every
// caller's masked minimum keeps its previous value for NaN inputs.
inline double smallest_lane(__m512d low, double start = 0) {
  low = _mm512_mask_min_pd(low, 0xff, low, _mm512_mask_shuffle_f64x2(low, 0xff, low, low, 0x4e));
  low = _mm512_mask_min_pd(low, 0xff, low, _mm512_mask_shuffle_f64x2(low, 0xff, low, low, 0xb1));
  low = _mm512_mask_min_pd(low, 0xff, low, _mm512_mask_permute_pd(low, 0xff, low, 0x55));
  const double smallest = _mm512_cvtsd_f64(low);
  return smallest < start ? smallest : start;
}

// The index of the least of the lanes that hold one (index >= 0; each lane keeps its first strict
// best, so the lowest index among the lanes holding the least is the first overall), or -1.
inline int first_least_lane(__m512d best, __m512i index) {
  const __mmask8 improved = _mm512_cmp_epi64_mask(index, _mm512_set1_epi64(-1), _MM_CMPINT_NE);
  if (!improved) return -1;
  const __m512d held = _mm512_mask_mov_pd(_mm512_set1_pd(kNone), improved, best);
  const double least = smallest_lane(held, kNone);
  const __mmask8 holding = improved & _mm512_cmp_pd_mask(best, _mm512_set1_pd(least), _CMP_EQ_OQ);
  const __m512i none = _mm512_set1_epi64(std::numeric_limits<int64_t>::max());
  __m512i low = _mm512_mask_mov_epi64(none, holding, index);
  low = _mm512_mask_min_epi64(low, 0xff, low, _mm512_mask_shuffle_i64x2(low, 0xff, low, low, 0x4e));
  low = _mm512_mask_min_epi64(low, 0xff, low, _mm512_mask_shuffle_i64x2(low, 0xff, low, low, 0xb1));
  low = _mm512_mask_min_epi64(low, 0xff, low, _mm512_mask_permutex_epi64(low, 0xff, low, 0xb1));
  return _mm512_cvtsi512_si32(low);  // an index: its low half
}

// -v exactly (the sign bit flipped, as the scalar unary minus).
inline __m512d negated(__m512d v) {
  return _mm512_castsi512_pd(
      _mm512_xor_si512(_mm512_castpd_si512(v), _mm512_set1_epi64(int64_t(1) << 63)));
}

// One masked vector move or compare.
template <int K>
void copy_row(const double* from, double* to) {
  _mm512_mask_storeu_pd(to, lane_mask<K>(), _mm512_maskz_loadu_pd(lane_mask<K>(), from));
}
template <int K>
bool same_row(const double* a, const double* b) {
  return _mm512_mask_cmp_pd_mask(lane_mask<K>(), _mm512_maskz_loadu_pd(lane_mask<K>(), a),
                                 _mm512_maskz_loadu_pd(lane_mask<K>(), b),
                                 _CMP_EQ_OQ) == lane_mask<K>();
}

inline double smallest_of(const double* d, int n) {
  __m512d low = _mm512_setzero_pd();
  for (int j = 0; j < n; j += 8) {
    const __mmask8 live = lanes_below(n, j);
    low = _mm512_mask_min_pd(low, live, _mm512_maskz_loadu_pd(live, d + j), low);
  }
  return smallest_lane(low);
}

inline bool any_below(const double* d, int n, double threshold) {
  const __m512d limit = _mm512_set1_pd(threshold);
  __mmask8 below = 0;
  for (int j = 0; j < n; j += 8) {
    const __mmask8 live = lanes_below(n, j);
    below |= _mm512_mask_cmp_pd_mask(live, _mm512_maskz_loadu_pd(live, d + j), limit, _CMP_NGE_UQ);
  }
  return below != 0;
}

inline int first_holding(const double* d, int n, double value) {
  const __m512d target = _mm512_set1_pd(value);
  for (int j = 0; j < n; j += 8) {
    const __mmask8 live = lanes_below(n, j);
    const unsigned hit =
        _mm512_mask_cmp_pd_mask(live, _mm512_maskz_loadu_pd(live, d + j), target, _CMP_EQ_OQ);
    if (hit) return j + __builtin_ctz(hit);
  }
  return -1;
}

template <class F>
void for_each_below(const double* d, int n, double threshold, F&& f) {
  const __m512d limit = _mm512_set1_pd(threshold);
  for (int j = 0; j < n; j += 8) {
    const __mmask8 live = lanes_below(n, j);
    unsigned mask =
        _mm512_mask_cmp_pd_mask(live, _mm512_maskz_loadu_pd(live, d + j), limit, _CMP_NGE_UQ);
    for (; mask; mask &= mask - 1) f(j + __builtin_ctz(mask));
  }
}

// `first_row`: the block's row 0 when every entry of it is this value (the orthonormalised
// constant function of the grid, problem.h), else NaN; then row 0 comes from a register instead of
// memory, the same chain and bits.
template <int K>
double combine(const double* w, const double* values, size_t stride, const double* base,
               double* out, int n, double first_row = std::numeric_limits<double>::quiet_NaN()) {
  __m512d weight[K], low = _mm512_setzero_pd();
  for (int r = 0; r < K; ++r) weight[r] = _mm512_set1_pd(w[r]);
  const bool constant_first_row = first_row == first_row;
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
  return smallest_lane(low);
}

inline void front_costs(const double* points, int n, double zf, double* cost) {
  const __m512d z = _mm512_set1_pd(zf), one = _mm512_set1_pd(1.0), zero = _mm512_setzero_pd();
  for (int e = 0; e < n; e += 8) {
    const __mmask8 live = lanes_below(n, e);
    const __mmask8 front =
        _mm512_mask_cmp_pd_mask(live, _mm512_maskz_loadu_pd(live, points + e), z, _CMP_LT_OQ);
    _mm512_mask_storeu_pd(cost + e, live, _mm512_mask_blend_pd(front, zero, one));
  }
}

// A row of B^-1 a vector: one multiply-add a row, rows left alone by mask, not by a branch.
template <int K>
void update_inverse(double (*binv)[kMaxRows], int leave, const double* u, double reciprocal) {
  constexpr __mmask8 kLanes = lane_mask<K>();
  const __m512d pivot_row =
      _mm512_mul_pd(_mm512_maskz_loadu_pd(kLanes, binv[leave]), _mm512_set1_pd(reciprocal));
  _mm512_mask_storeu_pd(binv[leave], kLanes, pivot_row);
  for (int i = 0; i < K; ++i) {
    const __mmask8 update = i == leave || u[i] == 0 ? 0 : kLanes;
    const __m512d row = _mm512_maskz_loadu_pd(kLanes, binv[i]);
    _mm512_mask_storeu_pd(binv[i], update, _mm512_fnmadd_pd(_mm512_set1_pd(u[i]), pivot_row, row));
  }
}

// Two gathers (AVX-512F alone: the column indices widened to 64-bit lanes; `basis` holds kMaxRows
// entries, set or not).
template <int K>
void basic_points(const int* basis, int g, int n, const double* grid, const double* extra,
                  double* out) {
  constexpr __mmask8 kLanes = lane_mask<K>();
  const __m512i j = _mm512_maskz_cvtepi32_epi64(
      kLanes, _mm256_loadu_si256(reinterpret_cast<const __m256i*>(basis)));
  const __mmask8 on_grid = _mm512_mask_cmplt_epi64_mask(kLanes, j, _mm512_set1_epi64(g));
  const __mmask8 on_extra =
      _mm512_mask_cmplt_epi64_mask(kLanes, j, _mm512_set1_epi64(n)) & ~on_grid;
  const __m512d none = _mm512_set1_pd(std::numeric_limits<double>::quiet_NaN());
  const __m512d grid_points = _mm512_mask_i64gather_pd(none, on_grid, j, grid, 8);
  _mm512_storeu_pd(out,
                   _mm512_mask_i64gather_pd(grid_points, on_extra,
                                            _mm512_sub_epi64(j, _mm512_set1_epi64(g)), extra, 8));
}

template <int K>
int nearest_other(const double* points, double z, int skip) {
  const __m512d gaps = _mm512_abs_pd(_mm512_sub_pd(_mm512_loadu_pd(points), _mm512_set1_pd(z)));
  const __mmask8 others =
      _mm512_mask_cmp_pd_mask(lane_mask<K>() & ~(1u << skip), gaps, gaps, _CMP_ORD_Q);
  const double least =
      smallest_lane(_mm512_mask_mov_pd(_mm512_set1_pd(kNone), others, gaps), kNone);
  const unsigned holding = _mm512_mask_cmp_pd_mask(others, gaps, _mm512_set1_pd(least), _CMP_EQ_OQ);
  return least < kNone && holding ? __builtin_ctz(holding) : -1;
}

template <int K>
double nearest_beyond(const double* points, double from, double direction, unsigned skip) {
  const __m512d basic = _mm512_loadu_pd(points), sign = _mm512_set1_pd(direction);
  const __mmask8 beyond = _mm512_mask_cmp_pd_mask(
      lane_mask<K>() & ~skip, _mm512_mul_pd(_mm512_sub_pd(basic, _mm512_set1_pd(from)), sign),
      _mm512_setzero_pd(), _CMP_GT_OQ);
  const double nearest = smallest_lane(
      _mm512_mask_mov_pd(_mm512_set1_pd(kNone), beyond, _mm512_mul_pd(basic, sign)), kNone);
  return direction * nearest + 0.0;  // (z direction) direction = z exactly; +0 as the reference
}

// Each lane keeps its first strict best, so the first index of the best overall wins; phi in
// lanes is fused_dot's chain.
template <int K>
void bracket_extras(const double* v, const double* points, const double* values, int n, double lo,
                    double hi, double previous, int& near, int& far) {
  const __m512d low = _mm512_set1_pd(lo), high = _mm512_set1_pd(hi);
  const __m512d from_point = _mm512_set1_pd(previous), zero = _mm512_setzero_pd();
  __m512d weight[K];
  for (int r = 0; r < K; ++r) weight[r] = _mm512_set1_pd(v[r]);
  __m512d near_best = _mm512_setzero_pd(), far_best = _mm512_set1_pd(hi - lo);
  __m512i near_index = _mm512_set1_epi64(-1), far_index = _mm512_set1_epi64(-1);
  const __m512i lane_index = _mm512_set_epi64(7, 6, 5, 4, 3, 2, 1, 0);
  for (int e = 0; e < n; e += 8) {
    const __mmask8 live = lanes_below(n, e);
    const __m512d p = _mm512_maskz_loadu_pd(live, points + e);
    const __mmask8 above = _mm512_mask_cmp_pd_mask(live, p, low, _CMP_GT_OQ);
    const __mmask8 inside = _mm512_mask_cmp_pd_mask(above, p, high, _CMP_LT_OQ);
    if (!inside) continue;
    __m512d sum = zero;
    for (int r = 0; r < K; ++r)
      sum = _mm512_fmadd_pd(weight[r], _mm512_maskz_loadu_pd(inside, values + size_t(r) * n + e),
                            sum);
    const __mmask8 positive = _mm512_mask_cmp_pd_mask(inside, sum, zero, _CMP_GT_OQ);
    const __m512d progress = _mm512_abs_pd(_mm512_sub_pd(p, from_point));
    const __m512i index = _mm512_add_epi64(_mm512_set1_epi64(e), lane_index);
    const __mmask8 nearer = _mm512_mask_cmp_pd_mask(positive, progress, near_best, _CMP_GT_OQ);
    near_best = _mm512_mask_mov_pd(near_best, nearer, progress);
    near_index = _mm512_mask_mov_epi64(near_index, nearer, index);
    const __mmask8 closer =
        _mm512_mask_cmp_pd_mask(inside & ~positive, progress, far_best, _CMP_LT_OQ);
    far_best = _mm512_mask_mov_pd(far_best, closer, progress);
    far_index = _mm512_mask_mov_epi64(far_index, closer, index);
  }
  near = first_least_lane(negated(near_best), near_index);
  far = first_least_lane(far_best, far_index);
}

// Eight grid points at a time (walks at grid 1024 are ~4x longer than at 256).
template <int K>
int first_sign_change(const double* v, const double* grid, const double* values, int n, int g,
                      int step, double limit) {
  __m512d weight[K];
  for (int r = 0; r < K; ++r) weight[r] = _mm512_set1_pd(v[r]);
  const __m512d bound = _mm512_set1_pd(limit), zero = _mm512_setzero_pd();
  for (; g >= 0 && g < n; g += 8 * step) {
    const int start = step > 0 ? g : std::max(0, g - 7);
    const __mmask8 live = step > 0 ? lanes_below(n, g) : __mmask8((1u << (g - start + 1)) - 1);
    __m512d sum = zero;
    for (int r = 0; r < K; ++r)
      sum = _mm512_fmadd_pd(weight[r], _mm512_maskz_loadu_pd(live, values + size_t(r) * n + start),
                            sum);
    const __m512d points = _mm512_maskz_loadu_pd(live, grid + start);
    const unsigned beyond = step > 0 ? _mm512_mask_cmp_pd_mask(live, points, bound, _CMP_GE_OQ)
                                     : _mm512_mask_cmp_pd_mask(live, points, bound, _CMP_LE_OQ);
    const unsigned stop = beyond | _mm512_mask_cmp_pd_mask(live, sum, zero, _CMP_LE_OQ);
    if (!stop) continue;
    const int lane = step > 0 ? __builtin_ctz(stop) : 31 - __builtin_clz(stop);
    return beyond >> lane & 1 ? -1 : start + lane;
  }
  return -1;
}

// One pass for all queries: each lane keeps its nearest distance and the first index holding it.
template <int Q>
void nearest_beyond_each(const double (&from)[Q], const double (&direction)[Q],
                         const double (&distance)[Q], const double* points, int n, int (&out)[Q]) {
  __m512d origin[Q], sign[Q], low[Q];
  __m512i where[Q];
  const __m512d zero = _mm512_setzero_pd();
  const __m512i step = _mm512_set1_epi64(8);
  __m512i index = _mm512_set_epi64(7, 6, 5, 4, 3, 2, 1, 0);
  for (int q = 0; q < Q; ++q) {
    origin[q] = _mm512_set1_pd(from[q]), sign[q] = _mm512_set1_pd(direction[q]);
    low[q] = _mm512_set1_pd(kNone), where[q] = _mm512_setzero_si512();
  }
  for (int e = 0; e < n; e += 8, index = _mm512_add_epi64(index, step)) {
    const __mmask8 live = lanes_below(n, e);
    const __m512d p = _mm512_maskz_loadu_pd(live, points + e);
    for (int q = 0; q < Q; ++q) {
      const __m512d d = _mm512_mul_pd(_mm512_sub_pd(p, origin[q]), sign[q]);
      const __mmask8 nearer = _mm512_mask_cmp_pd_mask(
          _mm512_mask_cmp_pd_mask(live, d, zero, _CMP_GT_OQ), d, low[q], _CMP_LT_OQ);
      low[q] = _mm512_mask_mov_pd(low[q], nearer, d);
      where[q] = _mm512_mask_mov_epi64(where[q], nearer, index);
    }
  }
  for (int q = 0; q < Q; ++q) {
    const double least = smallest_lane(low[q], kNone);
    if (!(least < distance[q])) continue;  // the grid point is as near (or none beyond)
    const __mmask8 holding = _mm512_cmp_pd_mask(low[q], _mm512_set1_pd(least), _CMP_EQ_OQ);
    int64_t index_of[8];
    _mm512_storeu_si512(index_of, _mm512_mask_mov_epi64(_mm512_set1_epi64(n), holding, where[q]));
    int64_t first = n;
    for (int64_t v : index_of) first = v < first ? v : first;
    out[q] = int(first);
  }
}

// Eight columns at a time in blocking_step's chains.
template <int K>
void greatest_decrease(const double (*binv)[kMaxRows], const double* weights, const double* values,
                       size_t stride, const double* d, int offset, int n, double tolerance,
                       double pivot_tolerance, __m512d& best, __m512i& index) {
  const __m512d limit = _mm512_set1_pd(-tolerance);
  const __m512d pivot_floor = _mm512_set1_pd(pivot_tolerance);
  const __m512d infinity = _mm512_set1_pd(kNone);
  __m512d weight[K];
  for (int i = 0; i < K; ++i) weight[i] = _mm512_set1_pd(weights[i]);
  const __m512i lane = _mm512_set_epi64(7, 6, 5, 4, 3, 2, 1, 0);
  for (int j = 0; j < n; j += 8) {
    const __mmask8 live = lanes_below(n, j);
    const __m512d dj = _mm512_maskz_loadu_pd(live, d + j);
    const __mmask8 entering = _mm512_mask_cmp_pd_mask(live, dj, limit, _CMP_LT_OQ);
    if (!entering) continue;
    __m512d a[K];
    for (int r = 0; r < K; ++r) a[r] = _mm512_maskz_loadu_pd(entering, values + r * stride + j);
    __m512d num = infinity, den = _mm512_set1_pd(1);
    for (int i = 0; i < K; ++i) {
      __m512d u = _mm512_setzero_pd();
      for (int r = 0; r < K; ++r) u = _mm512_fmadd_pd(_mm512_set1_pd(binv[i][r]), a[r], u);
      const __mmask8 blocks = _mm512_mask_cmp_pd_mask(entering, u, pivot_floor, _CMP_GT_OQ);
      const __m512d candidate = _mm512_mul_pd(weight[i], den), current = _mm512_mul_pd(num, u);
      const __mmask8 less = _mm512_mask_cmp_pd_mask(blocks, candidate, current, _CMP_LT_OQ);
      num = _mm512_mask_mov_pd(num, less, weight[i]);
      den = _mm512_mask_mov_pd(den, less, u);
    }
    const __m512d theta = _mm512_maskz_div_pd(entering, num, den);
    const __mmask8 finite = _mm512_mask_cmp_pd_mask(entering, theta, infinity, _CMP_LT_OQ);
    const __m512d decrease = _mm512_mul_pd(dj, theta);
    const __mmask8 better = _mm512_mask_cmp_pd_mask(finite, decrease, best, _CMP_LT_OQ);
    best = _mm512_mask_mov_pd(best, better, decrease);
    index =
        _mm512_mask_mov_epi64(index, better, _mm512_add_epi64(_mm512_set1_epi64(offset + j), lane));
  }
}
// Both blocks' search as the scalar reference's interface: best and column in and out.
template <int K>
void greatest_decrease(const double (*binv)[kMaxRows], const double* weights, const double* values,
                       size_t stride, const double* d, int offset, int n, double tolerance,
                       double pivot_tolerance, double& best, int& column) {
  __m512d lanes_best = _mm512_set1_pd(best);
  __m512i lanes_index = _mm512_set1_epi64(-1);
  greatest_decrease<K>(binv, weights, values, stride, d, offset, n, tolerance, pivot_tolerance,
                       lanes_best, lanes_index);
  const int chosen = first_least_lane(lanes_best, lanes_index);
  if (chosen >= 0) best = smallest_lane(lanes_best, kNone), column = chosen;
}

// As the lanes of one vector: rows of B v from B's columns, or positions of B^T v from its rows.
template <int K, bool Transposed>
void misfit(const double (*basic)[kMaxRows], const DoubleDouble* v, const double* target,
            double* out) {
  constexpr __mmask8 kLanes = lane_mask<K>();
  DoubleDouble8 sum{_mm512_maskz_loadu_pd(kLanes, target)};
  if constexpr (Transposed) {
    static_assert(kMaxRows == 8, "basic[i][r] lies 8 doubles after basic[i - 1][r]");
    const __m512i position = _mm512_set_epi64(56, 48, 40, 32, 24, 16, 8, 0);
    for (int r = 0; r < K; ++r) {
      const __m512d row =
          _mm512_mask_i64gather_pd(_mm512_setzero_pd(), kLanes, position, &basic[0][r], 8);
      add_product(sum, v[r], negated(row));
    }
  } else {
    for (int i = 0; i < K; ++i)
      add_product(sum, v[i], negated(_mm512_maskz_loadu_pd(kLanes, basic[i])));
  }
  _mm512_mask_storeu_pd(out, kLanes, value(sum));
}

inline int offer_distances(const double* zf, double to, double* distance) {
  const __m512d none = _mm512_set1_pd(std::numeric_limits<double>::quiet_NaN());
  const __m512d gap =
      zf ? _mm512_mask_abs_pd(
               none, 0xff, _mm512_mask_sub_pd(none, 0xff, _mm512_loadu_pd(zf), _mm512_set1_pd(to)))
         : none;
  _mm512_storeu_pd(distance, gap);
  return __builtin_popcount(_mm512_mask_cmp_pd_mask(0xff, gap, gap, _CMP_ORD_Q));
}

// n a multiple of 8, at most 32.
inline int closest(const double* distance, int n) {
  const __m512d none = _mm512_set1_pd(kNone);
  __m512d least_of = none;
  for (int b = 0; b < n; b += 8) {  // NaN (none, or taken) reads as no distance at all
    const __m512d d = _mm512_loadu_pd(distance + b);
    least_of = _mm512_mask_min_pd(
        none, 0xff, least_of,
        _mm512_mask_mov_pd(none, _mm512_mask_cmp_pd_mask(0xff, d, d, _CMP_ORD_Q), d));
  }
  const __m512d least = _mm512_set1_pd(smallest_lane(least_of, kNone));
  uint32_t holding = 0;
  for (int b = 0; b < n; b += 8) {
    const __m512d d = _mm512_loadu_pd(distance + b);
    holding |= uint32_t(_mm512_mask_cmp_pd_mask(0xff, d, least, _CMP_EQ_OQ)) << b;
  }
  return __builtin_ctz(holding);
}

}  // namespace mb::lp::fast::lanes::avx512
#endif
