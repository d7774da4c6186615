#pragma once
// One LP: warm bases first, then the known distribution, then phase 1 from artificials.
#include "lp/fast/simplex.h"

namespace mb::lp::fast {

// at == nullptr: from scratch, and every basis is forgotten; otherwise the bases of the lanes and
// of the memories `at` offers are tried first (Backend::solve_next).
template <int K>
inline void FastSimplex<K>::run(const Problem& p, const WarmStart* at, Solution& s) {
  if (!at) {
    std::fill(std::begin(lane_zf_), std::end(lane_zf_), kNoBasis);
    std::fill(memory_zf_.begin(), memory_zf_.end(), kNoBasis);
  }
  const int lane = at ? std::clamp(at->lane, 0, kWarmLanes - 1) : 0;
  const int memory = at ? at->memory : -1;
  if (memory >= 0 && size_t(memory + 1) * kWarmLanes > memories_.size()) {
    memories_.resize(size_t(memory + 1) * kWarmLanes);
    memory_zf_.resize(memories_.size(), kNoBasis);
  }
  // Warm bases to try, closest z_f first: every lane's last basis, then the offered memories'.
  // (In eval and sweep a lane is a layer and a memory a texel column, offered for the texel above
  // and above to the right: layers of neighbouring texels do not always count the same surfaces,
  // and where the surfaces change from left to right the texel above often still sees the same
  // ones; eval/lp_view_solver.cpp.)
  WarmOffers offers;
  if (at) {
    offers.offer(0, lanes_, lane_zf_, p.zf);
    for (int o = 0; o < 2; ++o) {
      const int m = at->offers[o];
      const bool kept = m >= 0 && size_t(m + 1) * kWarmLanes <= memories_.size();
      const size_t slot = kept ? size_t(m) * kWarmLanes : 0;
      offers.offer(1 + o, kept ? &memories_[slot] : nullptr, kept ? &memory_zf_[slot] : nullptr,
                   p.zf);
    }
  }
  s.reset();
  at_ = at;
  solve(p, offers, s);
  if (s.status == ProblemStatus::Unstable || s.status == ProblemStatus::IterationLimit) {
    // Once more from scratch with Dantzig's rule over every column (no slide_entering either): a
    // narrow kernel's LP (|y| ~ 1e6) that failed every start with the extras priced first (one
    // LP in a power4 sweep of the default dataset;
    // LpFastBackend.NarrowKernelThatExtrasFirstPricingLeftUnstableIsSolved) is optimal in 70
    // pivots this way (G = 1.98e-7, where GLPK's answer, 1.3e-10, is not certified).
    WarmOffers none;
    start_over(s);
    retrying_ = true;
    solve(p, none, s);
    retrying_ = false;
  }
  lane_zf_[lane] = remember_basis(s, lanes_[lane]);
  if (!std::isnan(lane_zf_[lane])) save_basis(lane_factors_[lane]);
  if (memory >= 0) {  // the same basis in its memory (for the row below, in eval)
    const size_t slot = size_t(memory) * kWarmLanes + lane;
    memories_[slot] = lanes_[lane];
    memory_zf_[slot] = lane_zf_[lane];
  }
}

// Into `s`, fresh (reset).
template <int K>
inline void FastSimplex<K>::solve(const Problem& p, WarmOffers& warm, Solution& s) {
  iteration_limit_ = false;
  p_ = &p;
  fresh_.new_problem();  // y_ and reduced_ belong to the previous problem
  n_ = p.cols();
  g_ = p.grid_size();
  e_ = p.extra.size();
  composite_ = n_ + k_;
  reduced_.resize(n_);
  // Costs once per problem: the grid is ascending, so its cost is a prefix of ones.
  cost_.resize(n_);
  const auto& grid = p.grid->points;
  grid_points_ = grid.data();
  extra_points_ = p.extra.points.data();
  cell_scale_ = grid.back() > grid.front() ? (g_ - 1) / (grid.back() - grid.front()) : 0.0;
  if (!p.objective.empty()) {
    cost_given(p);
  } else if (p.behind) {
    cost_behind(p);
  } else {
    const int in_front = grid_bound(grid, p.zf, false, cell_scale_);
    // Along a run the grid stays and z_f moves by a few cells, so only the cells between the last
    // problem's prefix and this one's are rewritten.
    if (p.grid != costed_grid_) {
      std::fill(cost_.begin(), cost_.begin() + in_front, 1.0);
      std::fill(cost_.begin() + in_front, cost_.begin() + g_, 0.0);
      costed_grid_ = p.grid;
      grid_first_row_ = constant_first_row(p.grid->values.data(), g_);
    } else if (in_front != costed_front_) {
      const bool ones = in_front > costed_front_;
      std::fill(cost_.begin() + std::min(in_front, costed_front_),
                cost_.begin() + std::max(in_front, costed_front_), ones ? 1.0 : 0.0);
    }
    costed_front_ = in_front;
    lanes::front_costs(extra_points_, e_, p.zf, cost_.data() + g_);
  }
  composite_cost_ = std::numeric_limits<double>::quiet_NaN();  // cost() computes it if asked

  if (warm.usable > 0) {
    if (solve_from_previous_basis(warm, s)) return;
    start_over(s);
  }
  if (!p.start_support.empty() && start_from_distribution()) {
    phase_ = 2;
    if (solve_phase2(s)) return;
    start_over(s);
  }
  start_with_artificials();
  phase_ = 1;
  if (!iterate(s)) return unstable(s);
  double artificial = 0;
  for (int i = 0; i < k_; ++i)
    if (is_artificial(basis_[i])) artificial += x_[i];
  if (artificial > settings_.phase1_tolerance) {
    s.status = ProblemStatus::Infeasible;
    return;
  }
  if (!drive_out_artificials()) return unstable(s);
  phase_ = 2;
  if (solve_phase2(s)) return;
  unstable(s);
}

// The maximum's objective (Problem::behind): ones on the grid's suffix behind z_f and on the extra
// points behind it. Rare (lp.beta > 0), so every cost is written and the front prefix cache is
// dropped.
template <int K>
inline void FastSimplex<K>::cost_behind(const Problem& p) {
  const int at_or_front = grid_bound(p.grid->points, p.zf, true, cell_scale_);
  std::fill(cost_.begin(), cost_.begin() + at_or_front, 0.0);
  std::fill(cost_.begin() + at_or_front, cost_.begin() + g_, 1.0);
  for (int e = 0; e < e_; ++e) cost_[g_ + e] = extra_points_[e] > p.zf ? 1.0 : 0.0;
  grid_first_row_ = constant_first_row(p.grid->values.data(), g_);
  costed_grid_ = nullptr;
}

// Problem::objective, copied whole; the front prefix cache is dropped as for the maximum.
template <int K>
inline void FastSimplex<K>::cost_given(const Problem& p) {
  std::copy(p.objective.begin(), p.objective.end(), cost_.begin());
  grid_first_row_ = constant_first_row(p.grid->values.data(), g_);
  costed_grid_ = nullptr;
}

// A failed start: only the pivots it spent are kept.
template <int K>
inline void FastSimplex<K>::start_over(Solution& s) {
  const int spent = s.iterations;
  s.reset();
  s.iterations = spent;
}

// A warm basis that no bracket shift made feasible: its most negative column makes way for the
// composite column (the kernel distribution, which alone reproduces the moments), so x = e_i is
// a basic feasible solution next to the old basis; the primal simplex goes on from there.
template <int K>
inline bool FastSimplex<K>::repair_with_composite(Solution& s) {
  if (p_->start_support.empty() || is_basic(composite_)) return false;
  const int worst = most_negative();
  basis_[worst] = composite_;
  if (!refactor()) return false;
  for (int i = 0; i < k_; ++i) x_[i] = i == worst ? 1.0 : 0.0;  // exact: B e_worst = rhs
  return solve_phase2(s);
}

template <int K>
inline void FastSimplex<K>::unstable(Solution& s) const {
  s.status = iteration_limit_ ? ProblemStatus::IterationLimit : ProblemStatus::Unstable;
}

// Phase 2, then certification; a failed certificate resumes from the accurate basis. One that
// failed on a negative reduced cost only the precise (double-double) pass sees (|y| ~ 1e8: the
// double pass rounds ~1e-8, so its entering tolerance is that wide) names the column, and a step
// brings it in: the double iterations could not have found it, and such LPs used to end unstable
// (477 of a power4 sweep's 2.4M, then GLPK's answer or "lit"; now 1).
template <int K>
inline bool FastSimplex<K>::solve_phase2(Solution& s) {
  int guided = 0;
  for (int attempt = 0; attempt < 3; ++attempt) {
    if (!iterate(s)) return false;
    if (certify(s)) return true;
    for (; certificate_entering_ >= 0 && guided < settings_.guided_steps; ++guided) {
      double u[kMaxRows];
      ftran_column(certificate_entering_, u);
      if (!(ratio_test_step(certificate_entering_, u, false, s) >= 0) || !iterate(s)) return false;
      if (certify(s)) return true;
    }
    if (!dual_simplex(s)) return false;
    if (certify(s)) return true;
  }
  return false;
}

}  // namespace mb::lp::fast
