#pragma once
// FastSimplex<K>: the dense revised simplex for Problem 1 with K = m + 1 rows (docs/reference.md
// §2). The class holds the state; its members are defined, one concept per file, in the headers
// named beside each group below, all included by lp/fast_backend.cpp.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <type_traits>
#include <vector>

#include "lp/double_double.h"
#include "lp/fast/dense_lu.h"
#include "lp/fast/grid_bound.h"
#include "lp/fast/settings.h"
#include "lp/fast/warm_offers.h"
#include "lp/lanes/lanes.h"
#include "lp/solution.h"

namespace mb::lp::fast {

// K = m + 1 rows, fixed at compile time: every loop over rows or basis positions unrolls, and the
// k x k products of the duals, the entering column and the pivot stay in registers.
template <int K>
class FastSimplex {
 public:
  FastSimplex() { std::fill(std::begin(lane_zf_), std::end(lane_zf_), kNoBasis); }
  void use(const SimplexSettings& settings) { settings_ = settings; }

  // at == nullptr: from scratch, and every basis is forgotten; otherwise the warm bases of the
  // lanes and memories `at` offers are tried first (Backend::solve_next).
  void run(const Problem& p, const WarmStart* at, Solution& s);

 private:
  // A basis with its inverse and x_B, as the warm start leaves it or an LP ended
  // with it.
  struct BasisState {
    int basis[kMaxRows];
    double x[kMaxRows], binv[kMaxRows][kMaxRows], basic[kMaxRows][kMaxRows];
    int updates;
  };

  // While it lives, the basic columns' reduced costs (rounding; zero in exact arithmetic) read 0
  // (or `reading`), so that no rule picks a basic column.
  struct BasicColumnsHidden {
    FastSimplex& simplex;
    double saved[kMaxRows] = {};
    explicit BasicColumnsHidden(FastSimplex& s, double reading = 0) : simplex(s) {
      for (int i = 0; i < K; ++i)
        if (int j = s.basis_[i]; j < s.n_) saved[i] = s.reduced_[j], s.reduced_[j] = reading;
    }
    ~BasicColumnsHidden() {
      for (int i = 0; i < K; ++i)
        if (int j = simplex.basis_[i]; j < simplex.n_) simplex.reduced_[j] = saved[i];
    }
    BasicColumnsHidden(const BasicColumnsHidden&) = delete;
    BasicColumnsHidden& operator=(const BasicColumnsHidden&) = delete;
  };

  // driver.h: one LP from the warm bases or from scratch, with the retry
  void solve(const Problem& p, WarmOffers& warm, Solution& s);
  static void start_over(Solution& s);
  void cost_behind(const Problem& p);
  void cost_given(const Problem& p);
  bool repair_with_composite(Solution& s);
  void unstable(Solution& s) const;
  bool solve_phase2(Solution& s);

  // starts.h: cold starts (artificials for phase 1, the composite column)
  void start_with_artificials();
  bool start_from_distribution();
  bool drive_out_artificials();

  // iterations.h: primal simplex (pricing -> ratio test -> update), dual simplex
  int most_negative() const;
  bool iterate(Solution& s);
  double ratio_test_step(int entering, const double* u, bool bland, Solution& s);
  void move_along(int leave, int entering, const double* u, double theta);
  bool dual_simplex(Solution& s);
  void refine_weights();

  // pricing.h: BTRAN's reduced costs and the entering column (CHUZC)
  void price();
  void reduced_costs();
  bool priced_with(const double* y) const;
  double subtract_row_combination(const double* w, const double* base, double* out) const;
  double entering_tolerance() const;
  int choose_entering(bool bland);
  int slide_entering();
  int enter_from_extras();
  int enter_among_extras() const;
  int extra_holding(double smallest) const;

  // factorisation.h: B^-1 (LU, FTRAN, BTRAN, product-form update)
  double point(int j) const;
  bool is_artificial(int j) const;
  bool update_factors(const BasisState& factors);
  void save_basis(BasisState& to) const;
  void restore_basis(const BasisState& from);
  double column_entry(int j, int r) const;
  static double constant_first_row(const double* values, int n);
  void load_column(int j, double* a) const;
  double cost(int j) const;
  bool refactor();
  void btran(double* y) const;
  bool is_basic(int j) const;
  int basic_position(int j, int among = K) const;
  void ftran_column(int j, double* u) const;
  void ftran(const double* a, double* u) const;
  bool stable_pivot(const double* u, int i) const;
  void pivot(int leave, int entering, const double* u);
  double column_bound() const;
  double composite_cost() const;
  int refactor_interval() const;

  // certificates.h: optimality certificates in double and double-double
  double pricing_rounding(const double* y) const;
  bool certify(Solution& s);
  bool certify_in_double(Solution& s);
  template <class Dual>
  void report(Solution& s, double objective, const double* weights, const Dual* y) const;
  bool certify_precisely(Solution& s);
  void refine_duals_for_certificate();
  double precise_reduced_cost(int j, const DoubleDouble* y) const;
  bool precise_bound(const DoubleDouble* x, const DoubleDouble* y, Solution& s,
                     const double* residual_of_x = nullptr);
  static void add_support(Solution& s, int j, double w);

  // refinement.h: iterative refinement in double-double
  template <bool Transposed, class Inverse>
  void refine_precisely(DoubleDouble* v, const double* target, const Inverse& inverse) const;
  template <bool Transposed, class Inverse>
  void correct_precisely(DoubleDouble* v, const double* misfit, const Inverse& inverse) const;
  template <bool Transposed>
  void misfit_of(const DoubleDouble* v, const double* target, double* misfit) const;

  // warm_start.h: a previous fragment's basis mapped onto this problem
  double remember_basis(const Solution& s, WarmBasis& warm);
  bool start_from_previous_basis(const WarmBasis& warm, int rounds, const BasisState* factors);
  bool solve_from_previous_basis(WarmOffers& warm, Solution& s);
  int shift_rounds(int try_index) const;

  // bracket_shift.h: bracket shifts that repair a warm basis
  bool shift_bracket(int i);
  bool bracket_node(int i, int partner, double direction, const double* points);
  int grid_beyond(double from, double direction, int column) const;
  int first_sign_change(const double* v, int g, int step, double limit) const;
  template <int Q>
  void points_beyond(const double (&from)[Q], const double (&direction)[Q], const int (&column)[Q],
                     int (&out)[Q]) const;
  bool exchange(int i, int entering);
  void basic_points(double (&out)[kMaxRows]) const;

 private:
  SimplexSettings settings_;
  const Problem* p_ = nullptr;
  const WarmStart* at_ = nullptr;  // where the problem being solved sits (run), or null
  static constexpr int k_ = K;
  int n_ = 0, g_ = 0, e_ = 0, composite_ = 0;
  int certificate_entering_ = -1;  // set by a failed precise certificate (solve_phase2)
  // What the cached duals and reduced costs are still valid for, in one place: every change of
  // the basis or of its inverse (pivot, refactor, update_factors, restore_basis, a start) calls
  // basis_changed(); btran (into y_) calls duals_computed(); reduced_costs() records
  // the duals and phase it priced with, and partial pricing marks reduced_ stale.
  struct Freshness {
    bool duals = false;          // y_ is btran's duals of the current basis and inverse
    bool precise_duals = false;  // and refined into precise_y_ (refine_duals_for_certificate)
    bool reduced = false;        // reduced_ = c - A^T reduced_y for every column, in reduced_phase
    int reduced_phase = 0;
    double reduced_y[kMaxRows] = {};
    double smallest_reduced = 0;  // min(0, min_j reduced_[j]), set with reduced_
    void basis_changed() { duals = false; }
    void duals_computed() { duals = true, precise_duals = false; }
    void new_problem() { duals = false, reduced = false; }
  };
  Freshness fresh_;
  DoubleDouble precise_y_[kMaxRows];
  int phase_ = 1;
  int basis_[kMaxRows] = {};
  double x_[kMaxRows], y_[kMaxRows], artificial_sign_[kMaxRows];
  double binv_[kMaxRows][kMaxRows];
  double basic_[kMaxRows][kMaxRows];  // basic_[i] = column basis_[i] (kept by refactor and pivot)
  // F_Z(z_f), the composite column's cost, computed the first time it is asked for: the column
  // enters few LPs (repairs, cold starts), and the sum over the atoms would be paid by every LP.
  mutable double composite_cost_ = 0;
  int updates_ = 0;
  // run's retry from scratch: no partial pricing over the extra columns (iterate), and fresh
  // inverses every settings_.careful_refactor_interval updates.
  bool retrying_ = false;
  // An attempt of this solve ran out of iterations (iterate): a failure is then reported as
  // ProblemStatus::IterationLimit rather than Unstable.
  bool iteration_limit_ = false;
  const double* grid_points_ = nullptr;  // the problem's grid and extra points (point)
  const double* extra_points_ = nullptr;

  double cell_scale_ = 0;    // grid cells per unit of z
  BasisState usable_basis_;  // solve_from_previous_basis: the first usable warm try
  std::vector<double> reduced_, alpha_, cost_;
  // The grid whose costs cost_[0, g_) holds, ones up to costed_front_ (solve).
  std::shared_ptr<const ColumnBlock> costed_grid_;
  int costed_front_ = 0;
  // The value of every entry of that grid's first row, or NaN when they differ (lanes::combine).
  double grid_first_row_ = std::numeric_limits<double>::quiet_NaN();
  WarmBasis lanes_[kWarmLanes];          // each lane's last basis
  BasisState lane_factors_[kWarmLanes];  // their inverses (update_factors)
  std::vector<WarmBasis> memories_;      // by memory and lane (WarmStart::memory)
  // Their z_f, NaN where there is no basis: the selection reads these alone (a WarmBasis spans
  // ~80 bytes, and a selection would otherwise touch 24 of them).
  double lane_zf_[kWarmLanes];
  std::vector<double> memory_zf_;
  static constexpr double kNoBasis =
      std::numeric_limits<double>::quiet_NaN();  // a z_f slot without one
};

}  // namespace mb::lp::fast
