#pragma once
// Warm starts: the optimal basis of a neighbouring fragment, mapped onto this problem's columns.
#include "lp/fast/simplex.h"

namespace mb::lp::fast {

// Into `warm`; its z_f for run's selection, NaN when the basis cannot be carried over.
template <int K>
double FastSimplex<K>::remember_basis(const Solution& s, WarmBasis& warm) {
  if (!(s.status == ProblemStatus::Optimal && s.call == CallStatus::Ok && phase_ == 2))
    return kNoBasis;
  warm.rows = k_;
  warm.grid = g_;
  warm.column = at_ ? at_->column : -1;
  warm.row = at_ ? at_->row : -1;
  warm.zf = p_->zf;
  // Roles by selects, not a chain of branches: which basis position holds which kind of column
  // varies from LP to LP, and the branches mispredict.
  const int* extra_tap = p_->extra_tap.empty() ? nullptr : p_->extra_tap.data();
  for (int i = 0; i < k_; ++i) {
    const int j = basis_[i];
    const bool composite = j == composite_, grid = j < g_, extra = !grid && j < n_;
    const int e = extra ? j - g_ : 0;
    const bool zf = extra && e == p_->zf_extra;
    const int tap = extra && extra_tap ? extra_tap[e] : -1;
    // An extra point without a tap (from_moments), or an artificial: nothing to map.
    if (!(composite || grid || zf || tap >= 0)) return kNoBasis;
    warm.role[i] = composite ? Role::Composite : grid ? Role::Grid : zf ? Role::Zf : Role::Tap;
    warm.index[i] = grid ? j : composite || zf ? 0 : tap;
  }
  return warm.zf;
}

// `factors`: the basis's inverse as its own LP left it, when kept (the texel to the left).
template <int K>
bool FastSimplex<K>::start_from_previous_basis(const WarmBasis& warm, int rounds,
                                               const BasisState* factors) {
  if (warm.rows != k_ || warm.grid != g_) return false;
  // Each position's column by its role, picked from the four candidates by index rather than by
  // a switch (see remember_basis); -1: none in this problem.
  static_assert(int(Role::Grid) == 0 && int(Role::Tap) == 1 && int(Role::Zf) == 2 &&
                int(Role::Composite) == 3);
  int candidate[4];
  candidate[int(Role::Zf)] = p_->zf_extra < 0 ? -1 : g_ + p_->zf_extra;
  candidate[int(Role::Composite)] = p_->start_support.empty() ? -1 : composite_;
  const int taps = int(p_->tap_extra.size());
  const TapShift shift = tap_shift(warm);
  for (int i = 0; i < k_; ++i) {
    const Role role = warm.role[i];
    candidate[int(Role::Grid)] = warm.index[i];
    const int t = texel_tap(shift, role == Role::Tap ? warm.index[i] : 0);
    const int tap = unsigned(t) < unsigned(taps) ? p_->tap_extra[t] : -1;
    candidate[int(Role::Tap)] = tap >= 0 ? g_ + tap : -1;
    const int j = candidate[int(role)];
    if (j < 0 || basic_position(j, i) >= 0) return false;
    basis_[i] = j;
  }
  if (!(factors && update_factors(*factors)) && !refactor()) return false;
  // Most infeasible starts are one bracket off: the LP approximates each interior node of the
  // continuous extremal distribution by the two points of I around it, and when the node moves
  // past one of them, that point's weight turns negative. Moving it past its partner fixes it.
  for (int round = 0; round < rounds; ++round) {
    const int worst = most_negative();
    if (x_[worst] >= -settings_.feasibility_tolerance || !shift_bracket(worst)) break;
  }
  return true;
}

template <int K>
typename FastSimplex<K>::TapShift FastSimplex<K>::tap_shift(const WarmBasis& warm) const {
  if (!at_ || at_->row < 0 || warm.row < 0 || warm.column < 0 || at_->column < 0 ||
      kernel_side_ == 0)
    return {};
  return {true, at_->column - warm.column, at_->row - warm.row};
}

template <int K>
int FastSimplex<K>::texel_tap(const TapShift& shift, int t) const {
  const int side = kernel_side_;
  if (!shift.known || t < 0 || t >= kernel_taps_) return t;
  const int x = tap_column_[t] - shift.columns, y = tap_row_[t] - shift.rows;
  return x >= 0 && y >= 0 && x < side && y < side ? y * side + x : t;
}

// The first warm basis that is primal feasible after the bracket shifts: the primal simplex
// from there, ~1 pivot. If none is, the composite column repairs the closest one. (Dual simplex
// steps from bases whose old duals stayed feasible were tried: 24 pivots on average, half of
// them failing; the repair takes ~20.)
template <int K>
bool FastSimplex<K>::solve_from_previous_basis(WarmOffers& warm, Solution& s) {
  phase_ = 2;
  int usable = -1;
  double least_infeasibility = 0;  // the usable try's sum of negative weights
  bool usable_is_current = false;  // the basis in place is still the usable try's
  const int tries = std::min(warm.usable, settings_.warm_tries);
  for (int c = 0; c < tries; ++c) {
    const WarmBasis* w = warm.take();
    const bool left = w >= lanes_ && w < lanes_ + kWarmLanes;
    const bool started =
        start_from_previous_basis(*w, shift_rounds(c), left ? &lane_factors_[w - lanes_] : nullptr);
    if (!started) {
      usable_is_current = false;
      continue;
    }
    if (x_[most_negative()] >= -settings_.feasibility_tolerance) return solve_phase2(s);
    // The repair starts from the least infeasible try (sum of its negative weights), not the
    // closest z_f's: 1.86 -> 1.84 pivots an LP (power4, 256), 1.89 -> 1.83 (trig4).
    double infeasibility = 0;
    for (int i = 0; i < k_; ++i) infeasibility += std::min(x_[i], 0.0);
    usable_is_current = usable < 0 || infeasibility > least_infeasibility;
    if (!usable_is_current) continue;
    usable = c;
    least_infeasibility = infeasibility;
    // Kept for the repair, should the later tries fail too: otherwise its mapping and up to 4k
    // shifts would be redone.
    if (c + 1 < tries) save_basis(usable_basis_);
  }
  if (usable < 0) return false;
  if (!usable_is_current) restore_basis(usable_basis_);
  return repair_with_composite(s);
}

template <int K>
int FastSimplex<K>::shift_rounds(int try_index) const {
  return try_index == 0 ? 4 * k_ : settings_.later_try_rounds;
}

}  // namespace mb::lp::fast
