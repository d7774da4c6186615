#pragma once
// Warm starts: the optimal basis of a neighbouring fragment, mapped onto this problem's columns.
#include "lp/fast/simplex.h"

namespace mb::lp::fast {

// Into `warm`; its z_f for run's selection, NaN when the basis cannot be carried over.
template <int K>
inline double FastSimplex<K>::remember_basis(const Solution& s, WarmBasis& warm) {
  if (!(s.status == ProblemStatus::Optimal && s.call == CallStatus::Ok && phase_ == 2))
    return kNoBasis;
  warm.rows = k_;
  warm.grid = g_;
  warm.place = at_ ? at_->place : Place{};
  warm.zf = p_->zf;
  // Roles by selects, not a chain of branches: which basis position holds which kind of column
  // varies from LP to LP, and the branches mispredict.
  const int* extra_atom = p_->extra_atom.empty() ? nullptr : p_->extra_atom.data();
  for (int i = 0; i < k_; ++i) {
    const int j = basis_[i];
    const bool composite = j == composite_, grid = j < g_, extra = !grid && j < n_;
    const int e = extra ? j - g_ : 0;
    const bool zf = extra && e == p_->zf_extra;
    const int atom = extra && extra_atom ? extra_atom[e] : -1;
    // An extra point without an atom (from_moments), or an artificial: nothing to map.
    if (!(composite || grid || zf || atom >= 0)) return kNoBasis;
    warm.role[i] = composite ? Role::Composite : grid ? Role::Grid : zf ? Role::Zf : Role::Atom;
    warm.index[i] = grid ? j : composite || zf ? 0 : atom;
  }
  return warm.zf;
}

// `factors`: the basis's inverse as its own LP left it, when kept (a lane's own last basis).
template <int K>
inline bool FastSimplex<K>::start_from_previous_basis(const WarmBasis& warm, int rounds,
                                                      const BasisState* factors) {
  if (warm.rows != k_ || warm.grid != g_) return false;
  // Each position's column by its role, picked from the four candidates by index rather than by
  // a switch (see remember_basis); -1: none in this problem.
  static_assert(int(Role::Grid) == 0 && int(Role::Atom) == 1 && int(Role::Zf) == 2 &&
                int(Role::Composite) == 3);
  int candidate[4];
  candidate[int(Role::Zf)] = p_->zf_extra < 0 ? -1 : g_ + p_->zf_extra;
  candidate[int(Role::Composite)] = p_->start_support.empty() ? -1 : composite_;
  const int atoms = int(p_->atom_extra.size());
  // The atoms of `warm`'s problem as this one's (once per warm basis; null: the same indices).
  const bool mapped = at_ && at_->atoms;
  const int* map = mapped ? at_->atoms->table(warm.place, at_->place) : nullptr;
  const int mapped_atoms = map ? at_->atoms->size() : 0;
  for (int i = 0; i < k_; ++i) {
    const Role role = warm.role[i];
    candidate[int(Role::Grid)] = warm.index[i];
    const int a = role == Role::Atom ? warm.index[i] : 0;
    const int t = unsigned(a) < unsigned(mapped_atoms) ? map[a] : a;
    const int atom = unsigned(t) < unsigned(atoms) ? p_->atom_extra[t] : -1;
    candidate[int(Role::Atom)] = atom >= 0 ? g_ + atom : -1;
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

// The first warm basis that is primal feasible after the bracket shifts: the primal simplex
// from there, ~1 pivot. If none is, the composite column repairs the closest one. (Dual simplex
// steps from bases whose old duals stayed feasible were tried: 24 pivots on average, half of
// them failing; the repair takes ~20.)
template <int K>
inline bool FastSimplex<K>::solve_from_previous_basis(WarmOffers& warm, Solution& s) {
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
inline int FastSimplex<K>::shift_rounds(int try_index) const {
  return try_index == 0 ? 4 * k_ : settings_.later_try_rounds;
}

}  // namespace mb::lp::fast
