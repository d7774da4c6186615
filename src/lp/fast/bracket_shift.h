#pragma once
// Bracket shifts: a warm basis's negative weight repaired by moving its pair of points.
#include "lp/fast/simplex.h"

namespace mb::lp::fast {

// Basic column `i` (negative weight) and the basic point closest to it (its partner) stand for
// one node of the distribution (a basic solution: at most m + 1 points of I, REFERENCE.md §2),
// which moved past them since the previous fragment. The pair moves to the node's bracket when
// bracket_node finds it; otherwise towards the node's estimate, the pair's weighted mean (an
// extrapolation while one weight is negative): `i` to the nearest point of I beyond its partner,
// or both to the two points of I around the estimate when it lies further. False, with the basis
// unchanged, when there is no such point, the exchange would be (nearly) singular, or the start
// is hopeless.
template <int K>
bool FastSimplex<K>::shift_bracket(int i) {
  const int j = basis_[i];
  // Weights are probabilities: one below -kHopelessWeight means a basis far from any feasible
  // one, and shifts from such starts nearly always ran out of rounds.
  if (j >= n_ || x_[i] < -kHopelessWeight) return false;
  const double z = point(j);
  // Once for the partner and bracket_node's limit (the basis stays until an exchange).
  double points[kMaxRows];
  basic_points(points);
  int partner = -1;
#ifdef __AVX512F__
  {  // the first nearest, as the scalar loop finds it, in lanes (the loop was ~2 % of a warm LP)
    constexpr double kNone = std::numeric_limits<double>::infinity();
    const __m512d gaps = _mm512_abs_pd(_mm512_sub_pd(_mm512_loadu_pd(points), _mm512_set1_pd(z)));
    const __mmask8 others = _mm512_mask_cmp_pd_mask(kLanes & ~(1u << i), gaps, gaps, _CMP_ORD_Q);
    const double least =
        smallest_lane(_mm512_mask_mov_pd(_mm512_set1_pd(kNone), others, gaps), kNone);
    const unsigned holding =
        _mm512_mask_cmp_pd_mask(others, gaps, _mm512_set1_pd(least), _CMP_EQ_OQ);
    partner = least < kNone && holding ? __builtin_ctz(holding) : -1;
  }
#else
  double gap = std::numeric_limits<double>::infinity();
  for (int q = 0; q < k_; ++q)  // (NaN, no point, is never nearer)
    if (q != i && std::abs(points[q] - z) < gap) partner = q, gap = std::abs(points[q] - z);
#endif
  if (partner < 0) return false;
  const double from = points[partner], direction = from > z ? 1.0 : -1.0;
  // A pair whose weights sum to <= 0 stands for no node: a shift only drags the negative weight
  // along, a cell a round (seen in most starts that ran out of rounds). The try fails at once.
  const double mass = x_[i] + x_[partner];
  if (!(mass > 0)) return false;
  if (bracket_node(i, partner, direction, points)) return true;
  const double node = (x_[i] * z + x_[partner] * from) / mass;
  // The point beyond the partner, and the two around the node, in one pass over the extra points
  // (most shifts move both: three passes were ~8 % of a warm LP).
  int beyond[3];
  points_beyond<3>({from, node, node}, {direction, direction, -direction},
                   {basis_[partner], -1, -1}, beyond);
  const int next = beyond[0], far = beyond[1], near = beyond[2];
  if (next < 0) return false;
  if ((node - point(next)) * direction > 0) {
    if (far >= 0 && near >= 0 && near != far && exchange(i, far)) {
      exchange(partner, near);  // if refused (basic, or singular), the first half still helps
      return true;
    }
  }
  return exchange(i, next);
}

// The pair (i, partner) replaced by two other points l, m of I, with the other basic columns S
// kept: with v = x_p (row i of B^-1) - x_i (row p of B^-1), orthogonal to the moments and to
// every column of S (rows of B^-1 are orthogonal to the other basic columns), the new weights
// satisfy 0 = v.rhs = w_l phi(l) + w_m phi(m), phi(z) = v.a(z). So they share a sign exactly when
// phi changes sign between l and m: that is the node's bracket, found in one walk. (The estimate
// alone, a Newton step on the node's position, converges slowly where the pair nearly cancels, a
// node of small weight: six shifts and more were common.) phi(z_i) = x_p and phi(z_p) = -x_i are
// both positive, so the walk goes from the partner away from i over grid points to the first with
// phi <= 0, and the extra points between it and the last positive one narrow the bracket. S's
// points are roots of phi too: a walk that would cross one is left to the estimate, as are walks
// that leave the grid and exchanges that would be (nearly) singular (false, basis unchanged; 9 %
// of the calls on lp_bench). On its warm runs at grid 256: 30.4 k shifts instead of 43.5 k, 1.37
// (power4) and 1.34 (trig4) pivots an LP instead of 1.43 and 1.41; at 1024, 1.59 instead of 1.71
// and 1.70.
// `points`: basic_points' of the current basis.
template <int K>
bool FastSimplex<K>::bracket_node(int i, int partner, double direction, const double* points) {
  double v[K];
  for (int r = 0; r < K; ++r) v[r] = x_[partner] * binv_[i][r] - x_[i] * binv_[partner][r];
  const int from_column = basis_[partner], step = direction > 0 ? 1 : -1;
  const double from = point(from_column);
  const auto& grid = p_->grid->points;
  int g = grid_beyond(from, direction, from_column);
  // The walk ends before S's nearest point beyond the partner (a root of phi that is no node's).
  double limit = direction * std::numeric_limits<double>::infinity();
#ifdef __AVX512F__
  {  // the least z direction beyond `from`, in lanes; NaN lanes (no point) never count
    constexpr double kNone = std::numeric_limits<double>::infinity();
    const __m512d basic = _mm512_loadu_pd(points), sign = _mm512_set1_pd(direction);
    const __mmask8 beyond =
        _mm512_mask_cmp_pd_mask(kLanes & ~(1u << i) & ~(1u << partner),
                                _mm512_mul_pd(_mm512_sub_pd(basic, _mm512_set1_pd(from)), sign),
                                _mm512_setzero_pd(), _CMP_GT_OQ);
    const double nearest = smallest_lane(
        _mm512_mask_mov_pd(_mm512_set1_pd(kNone), beyond, _mm512_mul_pd(basic, sign)), kNone);
    limit = direction * nearest;  // (z direction) direction = z exactly
  }
#else
  for (int q = 0; q < K; ++q)  // (NaN, no point, never counts)
    if (q != i && q != partner && (points[q] - from) * direction > 0 &&
        (limit - points[q]) * direction > 0)
      limit = points[q];
#endif
  const int first = g;
  g = first_sign_change(v, g, step, limit);
  if (g < 0) return false;
  const double previous = g == first ? from : grid[g - step];
  // The bracket: near (phi > 0: the partner itself or the grid point before g) and far (g), then
  // the extra points strictly between them, the nearest to the sign change on either side.
  int near = g == first ? from_column : g - step, far = g;
  if (near != from_column && is_basic(near)) return false;
  const double lo = std::min(previous, grid[g]), hi = std::max(previous, grid[g]);
#ifdef __AVX512F__
  // The extra points inside, eight at a time, judged in lanes: a narrow kernel's depths crowd
  // into the cell (4.5 judged a call on lp_bench's power4 runs at grid 256), and judged one by
  // one, each a chain of k fused multiply-adds and two unpredictable branches, they were ~40 %
  // of a shift. Each lane keeps its first strict best, so the first index of the best overall
  // wins, as in the scalar path's order; phi in lanes is fused_dot's chain.
  const __m512d low = _mm512_set1_pd(lo), high = _mm512_set1_pd(hi);
  const __m512d from_point = _mm512_set1_pd(previous), zero = _mm512_setzero_pd();
  __m512d weight[K];
  for (int r = 0; r < K; ++r) weight[r] = _mm512_set1_pd(v[r]);
  __m512d near_best = _mm512_setzero_pd(), far_best = _mm512_set1_pd(hi - lo);
  __m512i near_index = _mm512_set1_epi64(-1), far_index = _mm512_set1_epi64(-1);
  const __m512i lane_index = _mm512_set_epi64(7, 6, 5, 4, 3, 2, 1, 0);
  const double* values = p_->extra.values.data();
  for (int e = 0; e < e_; e += 8) {
    const __mmask8 live = lanes_below(e_, e);
    const __m512d points = _mm512_maskz_loadu_pd(live, extra_points_ + e);
    const __mmask8 above = _mm512_mask_cmp_pd_mask(live, points, low, _CMP_GT_OQ);
    const __mmask8 inside = _mm512_mask_cmp_pd_mask(above, points, high, _CMP_LT_OQ);
    if (!inside) continue;
    __m512d sum = zero;
    for (int r = 0; r < K; ++r) {
      const __m512d row = _mm512_maskz_loadu_pd(inside, values + size_t(r) * e_ + e);
      sum = _mm512_fmadd_pd(weight[r], row, sum);
    }
    const __mmask8 positive = _mm512_mask_cmp_pd_mask(inside, sum, zero, _CMP_GT_OQ);
    const __m512d progress = _mm512_abs_pd(_mm512_sub_pd(points, from_point));
    const __m512i index = _mm512_add_epi64(_mm512_set1_epi64(e), lane_index);
    const __mmask8 nearer = _mm512_mask_cmp_pd_mask(positive, progress, near_best, _CMP_GT_OQ);
    near_best = _mm512_mask_mov_pd(near_best, nearer, progress);
    near_index = _mm512_mask_mov_epi64(near_index, nearer, index);
    const __mmask8 closer =
        _mm512_mask_cmp_pd_mask(inside & ~positive, progress, far_best, _CMP_LT_OQ);
    far_best = _mm512_mask_mov_pd(far_best, closer, progress);
    far_index = _mm512_mask_mov_epi64(far_index, closer, index);
  }
  const int nearest_positive = first_least_lane(negated(near_best), near_index);
  const int nearest_other = first_least_lane(far_best, far_index);
  if (nearest_positive >= 0) near = g_ + nearest_positive;
  if (nearest_other >= 0) far = g_ + nearest_other;
#else
  double near_progress = 0, far_progress = hi - lo;
  for (int e = 0; e < e_; ++e) {
    if (!(extra_points_[e] > lo && extra_points_[e] < hi)) continue;
    const double progress = std::abs(extra_points_[e] - previous);
    if (fused_dot(v, g_ + e) > 0) {
      if (progress > near_progress) near_progress = progress, near = g_ + e;
    } else if (progress < far_progress) {
      far_progress = progress, far = g_ + e;
    }
  }
#endif
  if (!exchange(i, far)) return false;
  // If the second exchange is refused (singular), the first half still helps.
  if (near != from_column) exchange(partner, near);
  return true;
}

// v.a_j as one chain of fused multiply-adds, r = 0 first: the same bits as first_sign_change's
// lanes, so that bracket_node's judgements agree whichever path computed them.
template <int K>
double FastSimplex<K>::fused_dot(const double* v, int j) const {
  double a[kMaxRows];
  load_column(j, a);
  double sum = 0;
  for (int r = 0; r < K; ++r) sum = std::fma(v[r], a[r], sum);
  return sum;
}

// The first grid index strictly beyond `from` in `direction` (-1 or g_ past the ends): the
// neighbour of `column` when that is the grid point at `from` (the grid ascends strictly), else
// by grid_bound.
template <int K>
int FastSimplex<K>::grid_beyond(double from, double direction, int column) const {
  const auto& grid = p_->grid->points;
  if (column >= 0 && column < g_) return column + (direction > 0 ? 1 : -1);
  return direction > 0 ? grid_bound(grid, from, true, cell_scale_)
                       : grid_bound(grid, from, false, cell_scale_) - 1;
}

// From grid point g on, in steps of `step`: the first grid point where phi = v.a <= 0, or -1 when
// the grid ends or `limit` is reached first (at or beyond it).
template <int K>
int FastSimplex<K>::first_sign_change(const double* v, int g, int step, double limit) const {
  const double* grid = grid_points_;
#ifdef __AVX512F__
  const double* values = p_->grid->values.data();
  // Eight grid points at a time (walks at grid 1024 are ~4x longer than at 256).
  __m512d weight[K];
  for (int r = 0; r < K; ++r) weight[r] = _mm512_set1_pd(v[r]);
  const __m512d bound = _mm512_set1_pd(limit), zero = _mm512_setzero_pd();
  for (; g >= 0 && g < g_; g += 8 * step) {
    const int start = step > 0 ? g : std::max(0, g - 7);
    const __mmask8 live = step > 0 ? lanes_below(g_, g) : __mmask8((1u << (g - start + 1)) - 1);
    __m512d sum = zero;
    for (int r = 0; r < K; ++r) {
      const __m512d row = _mm512_maskz_loadu_pd(live, values + size_t(r) * g_ + start);
      sum = _mm512_fmadd_pd(weight[r], row, sum);
    }
    const __m512d points = _mm512_maskz_loadu_pd(live, grid + start);
    const unsigned beyond = step > 0 ? _mm512_mask_cmp_pd_mask(live, points, bound, _CMP_GE_OQ)
                                     : _mm512_mask_cmp_pd_mask(live, points, bound, _CMP_LE_OQ);
    const unsigned stop = beyond | _mm512_mask_cmp_pd_mask(live, sum, zero, _CMP_LE_OQ);
    if (!stop) continue;
    const int lane = step > 0 ? __builtin_ctz(stop) : 31 - __builtin_clz(stop);
    return beyond >> lane & 1 ? -1 : start + lane;
  }
  return -1;
#else
  for (; g >= 0 && g < g_; g += step) {
    if ((grid[g] - limit) * step >= 0) return -1;
    if (fused_dot(v, g) <= 0) return g;
  }
  return -1;
#endif
}

// The point of I nearest beyond from[q] in direction[q] (a column index, or -1), for Q queries:
// the grid point of each by grid_bound (or the neighbour of column[q] when that is the grid point
// at from[q]: the grid ascends strictly), then one pass over the extra points for all of them (an
// extra point wins only if strictly nearer), then (without AVX-512) one more for the first index
// holding each nearest distance.
template <int K>
template <int Q>
void FastSimplex<K>::points_beyond(const double (&from)[Q], const double (&direction)[Q],
                                   const int (&column)[Q], int (&out)[Q]) const {
  constexpr double kNone = std::numeric_limits<double>::infinity();
  const auto& grid = p_->grid->points;
  double distance[Q];
  for (int q = 0; q < Q; ++q) {
    const int g = grid_beyond(from[q], direction[q], column[q]);
    out[q] = -1, distance[q] = kNone;
    if (g >= 0 && g < g_) out[q] = g, distance[q] = std::abs(grid[g] - from[q]);
  }
  const double* points = extra_points_;
#ifdef __AVX512F__
  // Eight lanes, masked (the tail in the same loop), in one pass: each lane keeps its nearest
  // distance and the first index holding it (updated only on a strictly nearer point), so the
  // lanes' nearest, ties to the smaller index, is the first index holding the nearest distance
  // (the searches were ~6 % of a warm LP; a second pass for the index, a third of them).
  {
    __m512d origin[Q], sign[Q], low[Q];
    __m512i where[Q];
    const __m512d zero = _mm512_setzero_pd();
    const __m512i step = _mm512_set1_epi64(8);
    __m512i index = _mm512_set_epi64(7, 6, 5, 4, 3, 2, 1, 0);
    for (int q = 0; q < Q; ++q) {
      origin[q] = _mm512_set1_pd(from[q]), sign[q] = _mm512_set1_pd(direction[q]);
      low[q] = _mm512_set1_pd(kNone), where[q] = _mm512_setzero_si512();
    }
    for (int e = 0; e < e_; e += 8, index = _mm512_add_epi64(index, step)) {
      const __mmask8 live = lanes_below(e_, e);
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
      if (!(least < distance[q])) continue;  // the grid point is as near (or no extra point beyond)
      const __mmask8 holding = _mm512_cmp_pd_mask(low[q], _mm512_set1_pd(least), _CMP_EQ_OQ);
      int64_t index_of[8];
      _mm512_storeu_si512(index_of,
                          _mm512_mask_mov_epi64(_mm512_set1_epi64(e_), holding, where[q]));
      int64_t first = e_;
      for (int64_t v : index_of) first = v < first ? v : first;
      out[q] = g_ + int(first);
    }
    return;
  }
#else
  double nearest[Q];
  for (int q = 0; q < Q; ++q) nearest[q] = kNone;
  int e = 0;
#ifdef __AVX__
  {
    // Per query, the smallest positive (p - from) * direction in four lanes (independent chains).
    __m256d origin[Q], sign[Q], low[Q];
    const __m256d none = _mm256_set1_pd(kNone), zero = _mm256_setzero_pd();
    for (int q = 0; q < Q; ++q)
      origin[q] = _mm256_set1_pd(from[q]), sign[q] = _mm256_set1_pd(direction[q]), low[q] = none;
    for (; e + 4 <= e_; e += 4) {
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
#endif
  for (; e < e_; ++e)
    for (int q = 0; q < Q; ++q) {
      const double d = (points[e] - from[q]) * direction[q];
      if (d > 0 && d < nearest[q]) nearest[q] = d;
    }
  // The first index holding each nearest distance that beats its grid point.
  int open = 0;
  bool wanted[Q];
  for (int q = 0; q < Q; ++q) open += wanted[q] = nearest[q] < distance[q];
  e = 0;
#ifdef __AVX__
  // Four at a time (a scalar search was the hottest loop of the shifts).
  for (; open > 0 && e + 4 <= e_; e += 4) {
    const __m256d p = _mm256_loadu_pd(points + e);
    for (int q = 0; q < Q; ++q) {
      if (!wanted[q]) continue;
      const __m256d d =
          _mm256_mul_pd(_mm256_sub_pd(p, _mm256_set1_pd(from[q])), _mm256_set1_pd(direction[q]));
      const int mask = _mm256_movemask_pd(_mm256_cmp_pd(d, _mm256_set1_pd(nearest[q]), _CMP_EQ_OQ));
      if (mask) out[q] = g_ + e + __builtin_ctz(mask), wanted[q] = false, --open;
    }
  }
#endif
  for (; open > 0 && e < e_; ++e)
    for (int q = 0; q < Q; ++q)
      if (wanted[q] && (points[e] - from[q]) * direction[q] == nearest[q])
        out[q] = g_ + e, wanted[q] = false, --open;
#endif
}

// Column `entering` replaces basic column `i`: one product-form update of the inverse and of
// x_B, not a new factorisation. False, with nothing changed, if it is basic already or the
// exchange would be (nearly) singular.
template <int K>
bool FastSimplex<K>::exchange(int i, int entering) {
  if (is_basic(entering)) return false;
  // A fresh inverse rather than an end to the shifts: the limit used to stop the first warm
  // basis's shifts in most of the starts that then failed (~85 k of the 119 k composite repairs
  // of a power4 sweep).
  if (updates_ >= refactor_interval() && !refactor()) return false;
  double u[kMaxRows] = {};  // (GCC cannot see that column_in_basis fills k_ <= kMaxRows)
  column_in_basis(entering, u);
  if (!stable_pivot(u, i)) return false;
  const double theta = x_[i] / u[i];
  for (int q = 0; q < k_; ++q) x_[q] -= theta * u[q];
  x_[i] = theta;
  pivot(i, entering, u);
  return true;
}

// The points of the basic structural columns by basis position, NaN for the others (the
// composite, artificials) and in out[k..kMaxRows).
template <int K>
void FastSimplex<K>::basic_points(double (&out)[kMaxRows]) const {
#ifdef __AVX512F__
  // Two gathers instead of k point() calls (AVX-512F alone: the column indices widened to 64-bit
  // lanes; basis_ holds kMaxRows entries, set or not).
  const __m512i j = _mm512_maskz_cvtepi32_epi64(
      kLanes, _mm256_loadu_si256(reinterpret_cast<const __m256i*>(basis_)));
  const __mmask8 on_grid = _mm512_mask_cmplt_epi64_mask(kLanes, j, _mm512_set1_epi64(g_));
  const __mmask8 extra = _mm512_mask_cmplt_epi64_mask(kLanes, j, _mm512_set1_epi64(n_)) & ~on_grid;
  const __m512d none = _mm512_set1_pd(std::numeric_limits<double>::quiet_NaN());
  const __m512d grid = _mm512_mask_i64gather_pd(none, on_grid, j, grid_points_, 8);
  _mm512_storeu_pd(out,
                   _mm512_mask_i64gather_pd(grid, extra, _mm512_sub_epi64(j, _mm512_set1_epi64(g_)),
                                            extra_points_, 8));
#else
  for (int q = 0; q < kMaxRows; ++q)
    out[q] = q < K && basis_[q] < n_ ? point(basis_[q]) : std::numeric_limits<double>::quiet_NaN();
#endif
}

}  // namespace mb::lp::fast
