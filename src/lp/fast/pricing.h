#pragma once
// Pricing: reduced costs from the duals, and the choice of the entering column (CHUZC).
#include "lp/fast/simplex.h"

namespace mb::lp::fast {

// y = B^{-T} c_B with one step of iterative refinement (the product-form inverse drifts), then
// reduced costs of all structural columns, block by block (vectorised). The certificate computes
// its y the same way, so at an optimal basis it finds these reduced costs already in place.
template <int K>
inline void FastSimplex<K>::price() {
  btran(y_);
  fresh_.duals_computed();
  reduced_costs();
}

template <int K>
inline void FastSimplex<K>::reduced_costs() {
  fresh_.smallest_reduced =
      subtract_row_combination(y_, phase_ == 1 ? nullptr : cost_.data(), reduced_.data());
  fresh_.reduced = true, fresh_.reduced_phase = phase_;
  for (int r = 0; r < k_; ++r) fresh_.reduced_y[r] = y_[r];
}

// Whether reduced_ holds the reduced costs of these duals (in the current phase).
template <int K>
inline bool FastSimplex<K>::priced_with(const double* y) const {
  if (!fresh_.reduced || fresh_.reduced_phase != phase_) return false;
  for (int r = 0; r < k_; ++r)
    if (y[r] != fresh_.reduced_y[r]) return false;
  return true;
}

// out_j = base_j - sum_r w_r A_rj for every structural column (base 0 when null), in one pass
// over the two contiguous column blocks (rows fixed at compile time, so the K weights stay in
// registers and the loop runs across columns; row by row it was store-bound). Returns
// min(0, min_j out_j), found in the same pass: with it, a pricing pass that finds no entering
// column (every LP ends with one) and the double certificate need no second pass over out.
template <int K>
inline double FastSimplex<K>::subtract_row_combination(const double* w, const double* base,
                                                       double* out) const {
  const double grid_smallest =
      lanes::combine<K>(w, p_->grid->values.data(), g_, base, out, g_, grid_first_row_);
  const double extra_smallest =
      lanes::combine<K>(w, p_->extra.values.data(), e_, base ? base + g_ : nullptr, out + g_, e_);
  return extra_smallest < grid_smallest ? extra_smallest : grid_smallest;
}

// The reduced cost below which a column may enter, for the duals y_. It grows with |y|: with
// |y| ~ 1e8 (narrow kernels) reduced costs carry ~1e-16 |y| of rounding, and basic columns would
// look attractive; the precise certificate, not this tolerance, decides optimality.
template <int K>
inline double FastSimplex<K>::entering_tolerance() const {
  double largest_dual = 0;
  for (int r = 0; r < k_; ++r) largest_dual = std::max(largest_dual, std::abs(y_[r]));
  return std::max(settings_.optimality_tolerance, 1e-15 * largest_dual);
}

// Dantzig (or Bland) over non-basic columns, with reduced_ fresh for y_.
template <int K>
inline int FastSimplex<K>::choose_entering(bool bland) {
  const double tolerance = entering_tolerance();
  if (bland) {
    for (int j = 0; j < n_; ++j)
      if (reduced_[j] < -tolerance && !is_basic(j)) return j;
    return -1;
  }
  // Fresh from a full pass: the smallest reduced cost over all columns decides, and when the
  // first column holding it is not basic it is the one Dantzig enters (no basic column comes
  // before it with that value, so excluding the basic ones would find the same).
  if (!(fresh_.smallest_reduced < -tolerance)) return -1;
  {
    const int first = lanes::first_holding(reduced_.data(), n_, fresh_.smallest_reduced);
    if (first >= 0 && !is_basic(first)) return first;
  }
  // Basic columns out of the race, then a vectorised minimum and the first index holding it.
  const BasicColumnsHidden hidden(*this);
  const double* d = reduced_.data();
  const double smallest = lanes::smallest_of(d, n_);
  return smallest < -tolerance ? lanes::first_holding(d, n_, smallest) : -1;
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
inline int FastSimplex<K>::slide_entering() {
  const double tolerance = entering_tolerance();
  const BasicColumnsHidden hidden(*this);
  int chosen = -1;
  double best = 0, weight[kMaxRows];
  for (int i = 0; i < K; ++i) weight[i] = std::max(x_[i], 0.0);
  lanes::greatest_decrease<K>(binv_, weight, p_->grid->values.data(), g_, reduced_.data(), 0, g_,
                              tolerance, settings_.pivot_tolerance, best, chosen);
  lanes::greatest_decrease<K>(binv_, weight, p_->extra.values.data(), e_, reduced_.data() + g_, g_,
                              e_, tolerance, settings_.pivot_tolerance, best, chosen);
  return chosen;
}

// Partial pricing over the extra columns (the kernel's depths and z_f, which docs/reference.md §2
// adds to the grid): Dantzig among them first, and a full pass only when none of them may enter, so
// optimality is never judged on them. The optimal support of a kernel's LP often lies on the
// kernel's own depths (the distribution's atoms), while a grid column that enters next to a basic
// point tends to walk a cell per pivot towards a node. On lp_bench's runs this needs fewer pivots
// than full Dantzig pricing and than the grid windows it replaced (grid cells around each basic
// point and z_f, plus the extras): 1.43 / 1.41 pivots an LP at grid 256 (power4 / trig4) against
// 1.61 / 1.58 with the windows, and 1.71 against 1.95 at 1024; adding the grid's ±2 cells around
// the basic points to the extras made it 2.75 at 256. y_ must be the current basis's duals.
// reduced_ then holds stale values on the grid, so the next full pass or certificate prices afresh.
template <int K>
inline int FastSimplex<K>::enter_from_extras() {
  fresh_.reduced = false;
  return extra_holding(lanes::combine<K>(y_, p_->extra.values.data(), e_, cost_.data() + g_,
                                         reduced_.data() + g_, e_));
}

// The same choice from reduced_ fresh from a full pass (no arithmetic, the same bits): the first
// iteration after a start prices every column first, since most warm starts are optimal already
// (84 % of lp_bench's LPs need no pivot) and then a pass over the extras alone was wasted.
template <int K>
inline int FastSimplex<K>::enter_among_extras() const {
  return extra_holding(lanes::smallest_of(reduced_.data() + g_, e_));
}

// Dantzig's choice among the extra columns (reduced_ fresh on them), `smallest` their least
// reduced cost or 0: the first extra column holding it, or -1 when it is not below the entering
// tolerance, or when that column is basic (rounding: the full pass then decides).
template <int K>
inline int FastSimplex<K>::extra_holding(double smallest) const {
  if (!(smallest < -entering_tolerance())) return -1;
  const int first = g_ + lanes::first_holding(reduced_.data() + g_, e_, smallest);
  return is_basic(first) ? -1 : first;
}

}  // namespace mb::lp::fast
