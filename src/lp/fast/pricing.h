#pragma once
// Pricing: reduced costs from the duals, and the choice of the entering column (CHUZC).
#include "lp/fast/simplex.h"

namespace mb::lp::fast {

// y = B^{-T} c_B with one step of iterative refinement (the product-form inverse drifts), then
// reduced costs of all structural columns, block by block (vectorised). The certificate computes
// its y the same way, so at an optimal basis it finds these reduced costs already in place.
template <int K>
void FastSimplex<K>::price() {
  dual_values(y_);
  duals_fresh_ = true;
  precise_duals_ = false;
  reduced_costs();
}

template <int K>
void FastSimplex<K>::reduced_costs() {
  priced_smallest_ =
      subtract_row_combination(y_, phase_ == 1 ? nullptr : cost_.data(), reduced_.data());
  priced_phase_ = phase_;
  for (int r = 0; r < k_; ++r) priced_y_[r] = y_[r];
}

// Whether reduced_ holds the reduced costs of these duals (in the current phase).
template <int K>
bool FastSimplex<K>::priced_with(const double* y) const {
  if (priced_phase_ != phase_) return false;
  for (int r = 0; r < k_; ++r)
    if (y[r] != priced_y_[r]) return false;
  return true;
}

// out_j = base_j - sum_r w_r A_rj for every structural column (base 0 when null), in one pass
// over the two contiguous column blocks (rows fixed at compile time, so the K weights stay in
// registers and the loop runs across columns; row by row it was store-bound). Returns
// min(0, min_j out_j), found in the same pass: with it, a pricing pass that finds no entering
// column (every LP ends with one) and the double certificate need no second pass over out.
template <int K>
double FastSimplex<K>::subtract_row_combination(const double* w, const double* base,
                                                double* out) const {
#ifdef __AVX512F__
  __m512d weight[K], low = _mm512_setzero_pd();
  for (int r = 0; r < K; ++r) weight[r] = _mm512_set1_pd(w[r]);
  combine_masked<K>(weight, p_->grid->values.data(), g_, base, out, g_, low, grid_first_row_);
  combine_masked<K>(weight, p_->extra.values.data(), e_, base ? base + g_ : nullptr, out + g_, e_,
                    low);
  return smallest_lane(low);
#endif
  const double* rows[K];
  for (int r = 0; r < K; ++r) rows[r] = p_->grid->values.data() + size_t(r) * g_;
  const double grid_smallest = combine_block<K>(w, rows, base, out, g_);
  for (int r = 0; r < K; ++r)
    rows[r] = p_->extra.values.data() + size_t(r) * e_;  // data(): the block may be empty
  const double extra_smallest = combine_block<K>(w, rows, base ? base + g_ : nullptr, out + g_, e_);
  return extra_smallest < grid_smallest ? extra_smallest : grid_smallest;
}

// The reduced cost below which a column may enter, for the duals y_. It grows with |y|: with
// |y| ~ 1e8 (narrow kernels) reduced costs carry ~1e-16 |y| of rounding, and basic columns would
// look attractive; the precise certificate, not this tolerance, decides optimality.
template <int K>
double FastSimplex<K>::entering_tolerance() const {
  double largest_dual = 0;
  for (int r = 0; r < k_; ++r) largest_dual = std::max(largest_dual, std::abs(y_[r]));
  return std::max(kOptimalityTolerance, 1e-15 * largest_dual);
}

// Dantzig (or Bland) over non-basic columns, with reduced_ fresh for y_.
template <int K>
int FastSimplex<K>::choose_entering(bool bland) {
  const double tolerance = entering_tolerance();
  if (bland) {
    for (int j = 0; j < n_; ++j)
      if (reduced_[j] < -tolerance && !is_basic(j)) return j;
    return -1;
  }
  // Fresh from a full pass: the smallest reduced cost over all columns decides, and when the
  // first column holding it is not basic it is the one Dantzig enters (no basic column comes
  // before it with that value, so excluding the basic ones would find the same).
  if (!(priced_smallest_ < -tolerance)) return -1;
  {
    const int first = first_holding(reduced_.data(), n_, priced_smallest_);
    if (first >= 0 && !is_basic(first)) return first;
  }
  // Basic columns out of the race, then a vectorised minimum and the first index holding it.
  const BasicColumnsHidden hidden(*this);
  const double* d = reduced_.data();
  const double smallest = smallest_of(d, n_);
  return smallest < -tolerance ? first_holding(d, n_, smallest) : -1;
}

// Greatest decrease for a node that slides. When a basis position loses the column that had just
// entered it, twice in a row (or a column at an end of the grid entered), a node of small weight
// is walking through I: Dantzig's column (the steepest reduced cost) moves it a few cells a
// pivot, e.g. 1 -> 0.87 -> 0.77 -> ... -> 0.48 in 14 pivots of one composite repair. The next
// column is then the one whose step decreases the objective most, d_j theta_j (theta_j from the
// ratio test of u = B^-1 a_j), among the columns with d_j below the entering tolerance, ties to
// the first: usually the node's place at once. On lp_bench's warm runs: 1.37 -> 0.90 pivots an LP
// (power4, 256), 1.34 -> 0.96 (trig4), 1.59 -> 0.99 / 1.11 (1024). As the rule for every pivot,
// or for every pivot once a node slid, it needed more (the extras-first pricing is the better
// guess elsewhere). reduced_ fresh for y_; -1 when no column qualifies.
template <int K>
int FastSimplex<K>::slide_entering() {
  const double tolerance = entering_tolerance();
  const BasicColumnsHidden hidden(*this);
  int chosen = -1;
#ifdef __AVX512F__
  __m512d best = _mm512_setzero_pd();
  __m512i index = _mm512_set1_epi64(-1);
  greatest_decrease(p_->grid->values.data(), g_, 0, g_, tolerance, best, index);
  greatest_decrease(p_->extra.values.data(), e_, g_, e_, tolerance, best, index);
  chosen = first_least_lane(best, index);
#else
  double best = 0;
  auto judge = [&](const double* values, size_t stride, int offset, int n) {
    for (int j = 0; j < n; ++j) {
      const double d = reduced_[offset + j];
      if (!(d < -tolerance)) continue;
      double a[kMaxRows];
      for (int r = 0; r < K; ++r) a[r] = values[r * stride + j];
      const double theta = blocking_step(a);
      if (!(theta < std::numeric_limits<double>::infinity())) continue;
      if (d * theta < best) best = d * theta, chosen = offset + j;
    }
  };
  judge(p_->grid->values.data(), g_, 0, g_);
  judge(p_->extra.values.data(), e_, g_, e_);
#endif
  return chosen;
}

#ifdef __AVX512F__
// slide_entering's search over one column block (rows `stride` apart, reduced costs from
// reduced_[offset]), eight columns at a time in the same chains as blocking_step; each lane
// keeps its first strict least d_j theta_j (below 0) and its column.
template <int K>
void FastSimplex<K>::greatest_decrease(const double* values, size_t stride, int offset, int n,
                                       double tolerance, __m512d& best, __m512i& index) const {
  const __m512d limit = _mm512_set1_pd(-tolerance);
  const __m512d pivot_tolerance = _mm512_set1_pd(kPivotTolerance);
  const __m512d infinity = _mm512_set1_pd(std::numeric_limits<double>::infinity());
  __m512d weight[K];
  for (int i = 0; i < K; ++i) weight[i] = _mm512_set1_pd(std::max(x_[i], 0.0));
  const __m512i lane = _mm512_set_epi64(7, 6, 5, 4, 3, 2, 1, 0);
  for (int j = 0; j < n; j += 8) {
    const __mmask8 live = lanes_below(n, j);
    const __m512d d = _mm512_maskz_loadu_pd(live, reduced_.data() + offset + j);
    const __mmask8 entering = _mm512_mask_cmp_pd_mask(live, d, limit, _CMP_LT_OQ);
    if (!entering) continue;
    __m512d a[K];
    for (int r = 0; r < K; ++r) a[r] = _mm512_maskz_loadu_pd(entering, values + r * stride + j);
    __m512d num = infinity, den = _mm512_set1_pd(1);
    for (int i = 0; i < K; ++i) {
      __m512d u = _mm512_setzero_pd();
      for (int r = 0; r < K; ++r) u = _mm512_fmadd_pd(_mm512_set1_pd(binv_[i][r]), a[r], u);
      const __mmask8 blocks = _mm512_mask_cmp_pd_mask(entering, u, pivot_tolerance, _CMP_GT_OQ);
      const __m512d candidate = _mm512_mul_pd(weight[i], den), current = _mm512_mul_pd(num, u);
      const __mmask8 less = _mm512_mask_cmp_pd_mask(blocks, candidate, current, _CMP_LT_OQ);
      num = _mm512_mask_mov_pd(num, less, weight[i]);
      den = _mm512_mask_mov_pd(den, less, u);
    }
    const __m512d theta = _mm512_maskz_div_pd(entering, num, den);
    const __mmask8 finite = _mm512_mask_cmp_pd_mask(entering, theta, infinity, _CMP_LT_OQ);
    const __m512d decrease = _mm512_mul_pd(d, theta);
    const __mmask8 better = _mm512_mask_cmp_pd_mask(finite, decrease, best, _CMP_LT_OQ);
    best = _mm512_mask_mov_pd(best, better, decrease);
    const __m512i column = _mm512_add_epi64(_mm512_set1_epi64(offset + j), lane);
    index = _mm512_mask_mov_epi64(index, better, column);
  }
}
#endif

// Partial pricing over the extra columns (the kernel's depths and z_f, which REFERENCE.md §2 adds
// to the grid): Dantzig among them first, and a full pass only when none of them may enter, so
// optimality is never judged on them. The optimal support of a kernel's LP often lies on the
// kernel's own depths (the distribution's atoms), while a grid column that enters next to a basic
// point tends to walk a cell per pivot towards a node. On lp_bench's runs this needs fewer pivots
// than full Dantzig pricing and than the grid windows it replaced (grid cells around each basic
// point and z_f, plus the extras): 1.43 / 1.41 pivots an LP at grid 256 (power4 / trig4) against
// 1.61 / 1.58 with the windows, and 1.71 against 1.95 at 1024; adding the grid's ±2 cells around
// the basic points to the extras made it 2.75 at 256. Throughput 1.09-1.11x at 256, 1.03-1.04x at
// 1024 (4 alternating rounds). y_ must be the current basis's duals. reduced_ then holds stale
// values on the grid, so the next full pass or certificate prices afresh.
template <int K>
int FastSimplex<K>::enter_from_extras() {
  priced_phase_ = -1;
#ifdef __AVX512F__
  {
    __m512d weight[K], low = _mm512_setzero_pd();
    for (int r = 0; r < K; ++r) weight[r] = _mm512_set1_pd(y_[r]);
    combine_masked<K>(weight, p_->extra.values.data(), e_, cost_.data() + g_, reduced_.data() + g_,
                      e_, low);
    return extra_holding(smallest_lane(low));
  }
#endif
  const double* rows[K];
  for (int r = 0; r < K; ++r)
    rows[r] = p_->extra.values.data() + size_t(r) * e_;  // data(): the block may be empty
  return extra_holding(combine_block<K>(y_, rows, cost_.data() + g_, reduced_.data() + g_, e_));
}

// The same choice from reduced_ fresh from a full pass (no arithmetic, the same bits): the first
// iteration after a start prices every column first, since most warm starts are optimal already
// (84 % of lp_bench's LPs need no pivot) and then a pass over the extras alone was wasted.
template <int K>
int FastSimplex<K>::enter_among_extras() const {
  return extra_holding(smallest_of(reduced_.data() + g_, e_));
}

// Dantzig's choice among the extra columns (reduced_ fresh on them), `smallest` their least
// reduced cost or 0: the first extra column holding it, or -1 when it is not below the entering
// tolerance, or when that column is basic (rounding: the full pass then decides).
template <int K>
int FastSimplex<K>::extra_holding(double smallest) const {
  if (!(smallest < -entering_tolerance())) return -1;
  const int first = g_ + first_holding(reduced_.data() + g_, e_, smallest);
  return is_basic(first) ? -1 : first;
}

}  // namespace mb::lp::fast
