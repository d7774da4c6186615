#include "lp/fast_backend.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>
#include <type_traits>

#ifdef __AVX__
#include <immintrin.h>
#endif

#include "lp/double_double.h"
#include "lp/glpk_backend.h"
#include "lp/kkt_checker.h"
#include "lp/row_count.h"
#include "util/error.h"

namespace mb::lp {

namespace {

// Tolerances. Weights are probabilities (sum w = 1 is the first row) and the rows are
// orthonormal, so absolute tolerances are meaningful. By weak duality with sum w = 1, a basis
// whose reduced costs are >= -eps is within eps of the optimum: the certificate's 1e-11 keeps G
// two orders inside the promised 1e-9.
constexpr double kFeasibilityTolerance = 1e-11;  // Harris: x_B >= -tol during iterations
constexpr double kOptimalityTolerance = 1e-11;   // reduced cost >= -tol counts as optimal
constexpr double kPivotTolerance = 1e-9;         // smallest |u_i| accepted as a pivot
constexpr double kPhase1Tolerance = 1e-10;       // residual artificial mass that means infeasible
constexpr double kCertifyBound = 1e-9;           // certified bound on |G - G*| (see certify)
// Largest |B max(x_B, 0) - rhs| a certificate accepts. The bound's |y| * residual term alone is not
// enough: it bounds how far G lies *above* the optimum (weak duality), but only a (nearly)
// feasible x_B bounds it from below, and with y = 0 (every basic point behind z_f) the term
// vanishes: a basis with a negative weight, clamped, then passed as optimal with G = 0 where the
// optimum was 0.065 (about one LP in a million of the default dataset's, found by comparing
// sweeps with different warm-start settings fragment by fragment).
constexpr double kCertifyResidual = 1e-12;
// And no weight of x_B, refined in double-double, below this: a negative weight is a basis that is
// not feasible, however small the residual clamping it leaves (|y| reaches 1e9, and a basis whose
// weights were -1e-13 then moved G by ~1e-7 against another path's; 5 LPs of a power4 sweep of the
// default dataset). Double-double leaves weights that are exactly zero at ~cond(B) 1e-32, far
// inside this.
constexpr double kNegligibleWeight = 1e-18;
// The residual a GLPK fallback answer may leave (its weights, rounded to double, leave ~1e-16).
constexpr double kFallbackResidual = 1e-14;
// Rank-1 updates between fresh inverses. The updates carry over from LP to LP in the left texel's
// factors, and the certificates refine x_B and y against B itself. 32 instead of 16 (with
// kChangedColumns 3 instead of 2): 0.36 instead of 0.46 factorisations an LP on lp_bench's warm
// runs at grid 256, the same pivots, and the 100 000 random instances' and three sweeps' unstable
// counts as they were. Only run's retry from scratch, the last resort of ill-conditioned LPs (70
// pivots on a narrow kernel, |y| ~ 1e6), keeps 16: with 32 that LP stayed unstable
// (LpFastBackend.NarrowKernelThatExtrasFirstPricingLeftUnstableIsSolved).
constexpr int kRefactorInterval = 32;
constexpr int kCarefulRefactorInterval = 16;
constexpr int kDegenerateBeforeBland = 24;  // degenerate pivots in a row before Bland's rule
// Bracket-shift rounds per warm basis: the closest z_f's gets 4k, the others, which succeed less
// often, 6: on the default dataset that saved 3.1M of 17.6M exchanges for 0.15M more pivots (power4
// sweep, ~4 % faster). 8k for the first cut repairs 102k -> 91k but cost the failing starts more.
constexpr int kLaterTryRounds = 6;
constexpr int kGuidedSteps = 8;  // certificate-guided steps per LP (solve_phase2)
constexpr int kWarmTries = 5;    // warm bases tried before the composite repair
// update_factors: product-form updates instead of a factorisation for up to this many changed
// columns (see kRefactorInterval).
constexpr int kChangedColumns = 3;
constexpr double kHopelessWeight = 10;  // a warm try with a weight below -10 is given up

// In-place LU with partial pivoting and inverse for k <= 8, in long double for the certificate's
// last resort: when the double inverse cannot refine x_B and y (cond(B) of boundary instances
// reaches 1e8 and more), the long double one carries ~3 more digits.
// The same routine in double serves every refactorisation: Eigen's general FullPivLU inverse
// cost as much as all pricing passes together at k <= 8 (measured with perf).
// K = k at compile time, so the loops unroll.
template <class Real, int K>
bool invert_fixed(Real a[kMaxRows][kMaxRows], Real inv[kMaxRows][kMaxRows], Real singular) {
  constexpr int k = K;
  int perm[kMaxRows];
  Real reciprocal[kMaxRows];
  for (int i = 0; i < k; ++i) perm[i] = i;
  Real largest = 0;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) largest = std::max(largest, std::abs(a[i][j]));
  for (int c = 0; c < k; ++c) {
    int p = c;
    for (int r = c + 1; r < k; ++r)
      if (std::abs(a[r][c]) > std::abs(a[p][c])) p = r;
    if (std::abs(a[p][c]) <= singular * largest) return false;
    if (p != c) {
      for (int j = 0; j < k; ++j) std::swap(a[p][j], a[c][j]);
      std::swap(perm[p], perm[c]);
    }
    // One division per pivot, not one per entry: 35 divisions (latency ~13 cycles each) were
    // most of a factorisation's time.
    reciprocal[c] = Real(1) / a[c][c];
    for (int r = c + 1; r < k; ++r) {
      Real f = a[r][c] *= reciprocal[c];
      for (int j = c + 1; j < k; ++j) a[r][j] -= f * a[c][j];
    }
  }
  for (int col = 0; col < k; ++col) {
    Real v[kMaxRows];
    for (int i = 0; i < k; ++i) v[i] = perm[i] == col ? Real(1) : Real(0);
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < i; ++j) v[i] -= a[i][j] * v[j];
    for (int i = k - 1; i >= 0; --i) {
      for (int j = i + 1; j < k; ++j) v[i] -= a[i][j] * v[j];
      v[i] *= reciprocal[i];
    }
    for (int i = 0; i < k; ++i) inv[i][col] = v[i];
  }
  return true;
}

// std::lower_bound (strict: false) or std::upper_bound (strict: true) of z in an ascending grid,
// started where z would be on a uniform grid (every grid here is) and corrected by steps, so the
// answer is the same for any ascending grid and O(1) for ours; a warm start's bracket shifts
// needed two binary searches each. `scale` = (n - 1) / (last - first point), or 0, precomputed:
// a division here was ~4 % of a warm LP.
int grid_bound(const std::vector<double>& grid, double z, bool strict, double scale) {
  const int n = int(grid.size());
  double guess = (z - grid[0]) * scale;
  int i = guess >= 0 ? (guess < n ? int(guess) : n) : 0;  // also maps NaN to 0
  auto before = [&](int j) {
    return strict ? grid[j] <= z : grid[j] < z;
  };  // j is left of the bound
  while (i > 0 && !before(i - 1)) --i;
  while (i < n && before(i)) ++i;
  return i;
}

#ifdef __AVX512F__
// The lanes of the block of eight starting at index j that lie below n: all eight but in the last
// block (the AVX-512 loops load, compare and store with it, so they need no scalar tail).
__mmask8 lanes_below(int n, int j) {
  return n - j >= 8 ? __mmask8(0xff) : __mmask8((1u << (n - j)) - 1);
}
// min(start, the smallest lane of low).
double smallest_lane(__m512d low, double start = 0) {
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

// The previous fragment's optimal basis, in terms that carry over to a neighbouring fragment:
// grid columns by index, kernel columns by the tap they came from (texel_tap maps it to the tap of
// the next kernel that sees the same texel), z_f's column and the composite column by role.
enum class Role { Grid, Tap, Zf, Composite };
struct WarmBasis {
  double zf = 0;
  int rows = 0, grid = 0;
  int column = -1, row = -1;  // the texel it was solved at (WarmPosition), -1: unknown
  Role role[kMaxRows];
  int index[kMaxRows];
};

// The warm bases offered to one LP (the texel to the left by layer, the texels above and above to
// the right by layer) with the distance of their z_f to the LP's (NaN: no basis), taken closest
// first, ties in the order offered. Taken one at a time, since most LPs need only the first:
// ranking all of them up front was a 24 x 24 comparison. Offered a block of kWarmLanes at a time
// (the lanes of one texel lie side by side), so that with AVX-512 each block is one vector and a
// take three minimums and a compare (offered one by one and taken in a scalar loop, they were ~3 %
// of a warm LP).
struct WarmOffers {
  static constexpr int kBlocks = 3, kCount = kBlocks * kWarmLanes;
  static_assert(kWarmLanes == 8, "a block is one vector of eight doubles");
  double distance[kCount];
  const WarmBasis* first[kBlocks] = {};  // the block's bases, kWarmLanes in a row
  int usable = 0;                        // offers with a basis, not yet taken
  // Block b: bases[l] with z_f zf[l] (NaN: no basis), or none when bases is null.
  void offer(int b, const WarmBasis* bases, const double* zf, double to) {
    first[b] = bases;
    double* d = distance + b * kWarmLanes;
#ifdef __AVX512F__
    // (The masked forms with every lane set: GCC 12's unmasked ones warn of an uninitialised
    // variable, as in smallest_lane.)
    const __m512d none = _mm512_set1_pd(std::numeric_limits<double>::quiet_NaN());
    const __m512d gap =
        bases ? _mm512_mask_abs_pd(
                    none, 0xff,
                    _mm512_mask_sub_pd(none, 0xff, _mm512_loadu_pd(zf), _mm512_set1_pd(to)))
              : none;
    _mm512_storeu_pd(d, gap);
    usable += __builtin_popcount(_mm512_mask_cmp_pd_mask(0xff, gap, gap, _CMP_ORD_Q));
    return;
#endif
    for (int l = 0; l < kWarmLanes; ++l) {
      d[l] = bases ? std::abs(zf[l] - to) : std::numeric_limits<double>::quiet_NaN();
      usable += d[l] == d[l];
    }
  }
  // The closest not yet taken (the first offered on ties), or null when none is left.
  const WarmBasis* take() {
    if (usable == 0) return nullptr;
    int best = 0;
#ifdef __AVX512F__
    {
      constexpr double kNone = std::numeric_limits<double>::infinity();
      __m512d block[kBlocks];
      const __m512d none = _mm512_set1_pd(kNone);
      for (int b = 0; b < kBlocks; ++b) {  // NaN (none, or taken) reads as no distance at all
        const __m512d d = _mm512_loadu_pd(distance + b * kWarmLanes);
        block[b] = _mm512_mask_mov_pd(none, _mm512_mask_cmp_pd_mask(0xff, d, d, _CMP_ORD_Q), d);
      }
      // (Masked forms: see offer.)
      const __m512d least = _mm512_set1_pd(smallest_lane(
          _mm512_mask_min_pd(none, 0xff, _mm512_mask_min_pd(none, 0xff, block[0], block[1]),
                             block[2]),
          kNone));
      uint32_t holding = 0;
      for (int b = 0; b < kBlocks; ++b)
        holding |= uint32_t(_mm512_mask_cmp_pd_mask(0xff, block[b], least, _CMP_EQ_OQ))
                   << (b * kWarmLanes);
      best = __builtin_ctz(holding);  // usable > 0: some lane holds a finite least
    }
#else
    double least = distance[0];
    for (int i = 1; i < kCount; ++i) {  // NaN (none, or taken) never compares less
      const bool closer = distance[i] < least || least != least;
      least = closer ? distance[i] : least;
      best = closer ? i : best;
    }
#endif
    distance[best] = std::numeric_limits<double>::quiet_NaN();
    --usable;
    return first[best / kWarmLanes] + best % kWarmLanes;
  }
};

// K = m + 1 rows, fixed at compile time: every loop over rows or basis positions unrolls (at run
// time k, the 5x5 products of the duals, the entering column and the pivot were ~20 % of an LP).
template <int K>
class FastSimplex {
 public:
  FastSimplex() { std::fill(std::begin(lane_zf_), std::end(lane_zf_), kNoBasis); }

  // at == nullptr: from scratch, and every basis is forgotten; otherwise the warm bases of the
  // texel to the left and of the texel above are tried first (Backend::solve_next).
  void run(const Problem& p, const WarmPosition* at, Solution& s) {
    if (!at) {
      std::fill(std::begin(lane_zf_), std::end(lane_zf_), kNoBasis);
      std::fill(above_zf_.begin(), above_zf_.end(), kNoBasis);
    }
    const int layer = at ? std::clamp(at->layer, 0, kWarmLanes - 1) : 0;
    const int column = at ? at->column : -1;
    if (column >= 0 && size_t(column + 1) * kWarmLanes > above_.size()) {
      above_.resize(size_t(column + 1) * kWarmLanes);
      above_zf_.resize(above_.size(), kNoBasis);
    }
    // Warm bases to try, closest z_f first: layers of neighbouring texels do not always count the
    // same surfaces, so the fragment's own lane is not always the best guess, and where the
    // surfaces change from left to right (a silhouette along the column) the texel above often
    // still sees the same ones: with it, a third fewer LPs need the composite repair. The texel
    // above and to the right (the row above has passed it, this row not yet) adds what a silhouette
    // running down to the left hides from both: 12 % fewer pivots, 20 % fewer repairs (power4,
    // 256).
    WarmOffers offers;
    if (at) {
      const bool above = column >= 0,
                 right = above && size_t(column + 2) * kWarmLanes <= above_.size();
      const size_t slot = above ? size_t(column) * kWarmLanes : 0;
      offers.offer(0, lanes_, lane_zf_, p.zf);
      offers.offer(1, above ? &above_[slot] : nullptr, above ? &above_zf_[slot] : nullptr, p.zf);
      offers.offer(2, right ? &above_[slot + kWarmLanes] : nullptr,
                   right ? &above_zf_[slot + kWarmLanes] : nullptr, p.zf);
    }
    s.reset();
    at_ = at;
    solve(p, offers, s);
    if (s.status == ProblemStatus::Unstable) {
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
    lane_zf_[layer] = remember_basis(s, lanes_[layer]);
    if (!std::isnan(lane_zf_[layer])) save_basis(lane_factors_[layer]);
    if (column >= 0) {  // the same basis for the row below
      const size_t slot = size_t(column) * kWarmLanes + layer;
      above_[slot] = lanes_[layer];
      above_zf_[slot] = lane_zf_[layer];
    }
  }

 private:
  // A basis with its inverse and x_B, as the warm start leaves it or an LP ended
  // with it.
  struct BasisState {
    int basis[kMaxRows];
    double x[kMaxRows], binv[kMaxRows][kMaxRows], basic[kMaxRows][kMaxRows];
    int updates;
  };

  // Into `s`, fresh (reset).
  void solve(const Problem& p, WarmOffers& warm, Solution& s) {
    p_ = &p;
    priced_phase_ = -1;  // reduced_ belongs to the previous problem
    duals_fresh_ = false;
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
    const int in_front = grid_bound(grid, p.zf, false, cell_scale_);
    const int taps = int(p.tap_extra.size());
    if (taps != kernel_taps_) {  // the same kernel for every problem of a run, nearly always
      const int side = int(std::lround(std::sqrt(double(taps))));
      kernel_taps_ = taps;
      kernel_side_ = side * side == taps ? side : 0;
      // Each tap's column and row in the kernel: texel_tap needs them for every kernel column of
      // every warm try, and a division each was ~1 % of an LP.
      tap_column_.resize(taps), tap_row_.resize(taps);
      for (int t = 0; t < taps && kernel_side_ > 0; ++t)
        tap_column_[t] = t % kernel_side_, tap_row_[t] = t / kernel_side_;
    }
    // Along a run the grid stays and z_f moves by a few cells, so only the cells between the last
    // problem's prefix and this one's are rewritten (the whole fill was ~2 % of a warm LP).
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
#ifdef __AVX512F__
    {
      const __m512d zf = _mm512_set1_pd(p.zf), one = _mm512_set1_pd(1.0),
                    zero = _mm512_setzero_pd();
      for (int e = 0; e < e_; e += 8) {
        const __mmask8 live = lanes_below(e_, e);
        const __mmask8 front = _mm512_mask_cmp_pd_mask(
            live, _mm512_maskz_loadu_pd(live, extra_points_ + e), zf, _CMP_LT_OQ);
        _mm512_mask_storeu_pd(cost_.data() + g_ + e, live, _mm512_mask_blend_pd(front, zero, one));
      }
    }
#else
    for (int e = 0; e < e_; ++e) cost_[g_ + e] = p.extra.points[e] < p.zf ? 1.0 : 0.0;
#endif
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
    if (artificial > kPhase1Tolerance) {
      s.status = ProblemStatus::Infeasible;
      return;
    }
    if (!drive_out_artificials()) return unstable(s);
    phase_ = 2;
    if (solve_phase2(s)) return;
    unstable(s);
  }

  // A failed start: only the pivots it spent are kept.
  static void start_over(Solution& s) {
    const int spent = s.iterations;
    s.reset();
    s.iterations = spent;
  }

  // The basis position of the most negative weight (the first, on ties).
  int most_negative() const {
    int worst = 0;
    double least = x_[0];
    for (int i = 1; i < k_; ++i) {  // selects, not branches (they mispredicted: ~3 % of an LP)
      const bool less = x_[i] < least;
      least = less ? x_[i] : least;
      worst = less ? i : worst;
    }
    return worst;
  }

  // Point j of I (Problem::point without its vectors' bookkeeping, and selects, not a branch).
  double point(int j) const {
    const bool on_grid = j < g_;
    return (on_grid ? grid_points_ : extra_points_)[on_grid ? j : j - g_];
  }

  // A warm basis that no bracket shift made feasible: its most negative column makes way for the
  // composite column (the kernel distribution, which alone reproduces the moments), so x = e_i is
  // a basic feasible solution next to the old basis; the primal simplex goes on from there.
  bool repair_with_composite(Solution& s) {
    if (p_->start_support.empty() || is_basic(composite_)) return false;
    const int worst = most_negative();
    basis_[worst] = composite_;
    if (!refactor()) return false;
    for (int i = 0; i < k_; ++i) x_[i] = i == worst ? 1.0 : 0.0;  // exact: B e_worst = rhs
    return solve_phase2(s);
  }

  bool is_artificial(int j) const {
    return j >= n_ && j < n_ + k_;
  }

  // Into `warm`; its z_f for run's selection, NaN when the basis cannot be carried over.
  double remember_basis(const Solution& s, WarmBasis& warm) {
    if (!(s.status == ProblemStatus::Optimal && s.call == CallStatus::Ok && phase_ == 2))
      return kNoBasis;
    warm.rows = k_;
    warm.grid = g_;
    warm.column = at_ ? at_->column : -1;
    warm.row = at_ ? at_->row : -1;
    warm.zf = p_->zf;
    // Roles by selects, not a chain of branches: which basis position holds which kind of column
    // varies from LP to LP, and the branches mispredicted (with start_from_previous_basis's switch
    // ~2 % of the solver's samples).
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
  bool start_from_previous_basis(const WarmBasis& warm, int rounds, const BasisState* factors) {
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
      if (x_[worst] >= -kFeasibilityTolerance || !shift_bracket(worst)) break;
    }
    return true;
  }

  // The inverse of the mapped basis from `factors` (its previous LP's) by a product-form update per
  // column that changed, instead of a factorisation: with the same texels mapped to the same taps,
  // most columns come back unchanged (grid points and kernel depths; z_f's and the composite's
  // are new). False (the caller factorises) when too many changed or an update would be (nearly)
  // singular. x_B from the new moments.
  bool update_factors(const BasisState& factors) {
    double a[kMaxRows][kMaxRows];
    int changed[kMaxRows], count = 0;
    for (int i = 0; i < k_; ++i) {
      load_column(basis_[i], a[i]);
      if (!same_row(a[i], factors.basic[i])) changed[count++] = i;
    }
    if (count > kChangedColumns || factors.updates + count > refactor_interval()) return false;
    for (int i = 0; i < k_; ++i) {
      copy_row(factors.binv[i], binv_[i]);
      copy_row(factors.basic[i], basic_[i]);
    }
    updates_ = factors.updates;
    duals_fresh_ = false;
    for (int c = 0; c < count; ++c) {
      const int i = changed[c];
      double u[kMaxRows] = {};  // (GCC cannot see that in_basis fills k_ <= kMaxRows)
      in_basis(a[i], u);
      if (!stable_pivot(u, i)) return false;
      pivot(i, basis_[i], u);
    }
    in_basis(p_->rhs.data(), x_);
    return true;
  }

  // The tap of this problem's kernel that sees the texel tap `t` of `warm`'s saw (taps in row-major
  // order of a square kernel, as kernel_distribution lists them), so that the same depth, and so
  // the same column, comes back; `t` itself when that texel is outside this kernel or either
  // position is unknown (the same offset then sees a nearby surface).
  // (`shift`: tap_shift(warm), once per warm basis.)
  struct TapShift {
    bool known = false;         // both positions known, and the kernel square
    int columns = 0, rows = 0;  // this texel's position less warm's
  };
  TapShift tap_shift(const WarmBasis& warm) const {
    if (!at_ || at_->row < 0 || warm.row < 0 || warm.column < 0 || at_->column < 0 ||
        kernel_side_ == 0)
      return {};
    return {true, at_->column - warm.column, at_->row - warm.row};
  }
  int texel_tap(const TapShift& shift, int t) const {
    const int side = kernel_side_;
    if (!shift.known || t < 0 || t >= kernel_taps_) return t;
    const int x = tap_column_[t] - shift.columns, y = tap_row_[t] - shift.rows;
    return x >= 0 && y >= 0 && x < side && y < side ? y * side + x : t;
  }

  // Basic column `i` (negative weight) and the basic point closest to it (its partner) stand for
  // one node of the distribution (a basic solution: at most m + 1 points of I, REFERENCE.md §2),
  // which moved past them since the previous fragment. The pair moves to the node's bracket when
  // bracket_node finds it; otherwise towards the node's estimate, the pair's weighted mean (an
  // extrapolation while one weight is negative): `i` to the nearest point of I beyond its partner,
  // or both to the two points of I around the estimate when it lies further. False, with the basis
  // unchanged, when there is no such point, the exchange would be (nearly) singular, or the start
  // is hopeless.
  bool shift_bracket(int i) {
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
  bool bracket_node(int i, int partner, double direction, const double* points) {
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
  double fused_dot(const double* v, int j) const {
    double a[kMaxRows];
    load_column(j, a);
    double sum = 0;
    for (int r = 0; r < K; ++r) sum = std::fma(v[r], a[r], sum);
    return sum;
  }
  // The first grid index strictly beyond `from` in `direction` (-1 or g_ past the ends): the
  // neighbour of `column` when that is the grid point at `from` (the grid ascends strictly), else
  // by grid_bound.
  int grid_beyond(double from, double direction, int column) const {
    const auto& grid = p_->grid->points;
    if (column >= 0 && column < g_) return column + (direction > 0 ? 1 : -1);
    return direction > 0 ? grid_bound(grid, from, true, cell_scale_)
                         : grid_bound(grid, from, false, cell_scale_) - 1;
  }

  // From grid point g on, in steps of `step`: the first grid point where phi = v.a <= 0, or -1 when
  // the grid ends or `limit` is reached first (at or beyond it).
  int first_sign_change(const double* v, int g, int step, double limit) const {
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
  template <int Q>
  void points_beyond(const double (&from)[Q], const double (&direction)[Q], const int (&column)[Q],
                     int (&out)[Q]) const {
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
        if (!(least < distance[q]))
          continue;  // the grid point is as near (or no extra point beyond)
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
        const int mask =
            _mm256_movemask_pd(_mm256_cmp_pd(d, _mm256_set1_pd(nearest[q]), _CMP_EQ_OQ));
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
  bool exchange(int i, int entering) {
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

  // The first warm basis that is primal feasible after the bracket shifts: the primal simplex
  // from there, ~1 pivot. If none is, the composite column repairs the closest one. (Dual simplex
  // steps from bases whose old duals stayed feasible were tried: 24 pivots on average, half of
  // them failing; the repair takes ~20.)
  bool solve_from_previous_basis(WarmOffers& warm, Solution& s) {
    phase_ = 2;
    int usable = -1;
    double least_infeasibility = 0;  // the usable try's sum of negative weights
    bool usable_is_current = false;  // the basis in place is still the usable try's
    const int tries = std::min(warm.usable, kWarmTries);
    for (int c = 0; c < tries; ++c) {
      const WarmBasis* w = warm.take();
      const bool left = w >= lanes_ && w < lanes_ + kWarmLanes;
      const bool started = start_from_previous_basis(*w, shift_rounds(c),
                                                     left ? &lane_factors_[w - lanes_] : nullptr);
      if (!started) {
        usable_is_current = false;
        continue;
      }
      if (x_[most_negative()] >= -kFeasibilityTolerance) return solve_phase2(s);
      // The repair starts from the least infeasible try (sum of its negative weights), not the
      // closest z_f's: 1.86 -> 1.84 pivots an LP (power4, 256), 1.89 -> 1.83 (trig4).
      double infeasibility = 0;
      for (int i = 0; i < k_; ++i) infeasibility += std::min(x_[i], 0.0);
      usable_is_current = usable < 0 || infeasibility > least_infeasibility;
      if (!usable_is_current) continue;
      usable = c;
      least_infeasibility = infeasibility;
      // Kept for the repair, should the later tries fail too: redoing its mapping and up to 4k
      // shifts (what this used to do) was ~4 % of the LP time.
      if (c + 1 < tries) save_basis(usable_basis_);
    }
    if (usable < 0) return false;
    if (!usable_is_current) restore_basis(usable_basis_);
    return repair_with_composite(s);
  }

  // k entries of a row of B, B^-1 or x_B: one masked vector move with AVX-512 (the element loops
  // of k = 5 were a 32- and an 8-byte move each).
  static void copy_row(const double* from, double* to) {
#ifdef __AVX512F__
    _mm512_mask_storeu_pd(to, kLanes, _mm512_maskz_loadu_pd(kLanes, from));
#else
    std::copy(from, from + K, to);
#endif
  }
  // The points of the basic structural columns by basis position, NaN for the others (the
  // composite, artificials) and in out[k..kMaxRows).
  void basic_points(double (&out)[kMaxRows]) const {
#ifdef __AVX512F__
    // Two gathers instead of k point() calls (AVX-512F alone: the column indices widened to 64-bit
    // lanes; basis_ holds kMaxRows entries, set or not).
    const __m512i j = _mm512_maskz_cvtepi32_epi64(
        kLanes, _mm256_loadu_si256(reinterpret_cast<const __m256i*>(basis_)));
    const __mmask8 on_grid = _mm512_mask_cmplt_epi64_mask(kLanes, j, _mm512_set1_epi64(g_));
    const __mmask8 extra =
        _mm512_mask_cmplt_epi64_mask(kLanes, j, _mm512_set1_epi64(n_)) & ~on_grid;
    const __m512d none = _mm512_set1_pd(std::numeric_limits<double>::quiet_NaN());
    const __m512d grid = _mm512_mask_i64gather_pd(none, on_grid, j, grid_points_, 8);
    _mm512_storeu_pd(
        out, _mm512_mask_i64gather_pd(grid, extra, _mm512_sub_epi64(j, _mm512_set1_epi64(g_)),
                                      extra_points_, 8));
#else
    for (int q = 0; q < kMaxRows; ++q)
      out[q] =
          q < K && basis_[q] < n_ ? point(basis_[q]) : std::numeric_limits<double>::quiet_NaN();
#endif
  }
  // Whether the k entries of two rows are equal (==: NaN never is).
  static bool same_row(const double* a, const double* b) {
#ifdef __AVX512F__
    return _mm512_mask_cmp_pd_mask(kLanes, _mm512_maskz_loadu_pd(kLanes, a),
                                   _mm512_maskz_loadu_pd(kLanes, b), _CMP_EQ_OQ) == kLanes;
#else
    bool same = true;
    for (int r = 0; r < K; ++r) same &= a[r] == b[r];
    return same;
#endif
  }
  void save_basis(BasisState& to) const {
    std::copy(basis_, basis_ + k_, to.basis);
    copy_row(x_, to.x);
    for (int i = 0; i < k_; ++i) {
      copy_row(binv_[i], to.binv[i]);
      copy_row(basic_[i], to.basic[i]);
    }
    to.updates = updates_;
  }
  void restore_basis(const BasisState& from) {
    std::copy(from.basis, from.basis + k_, basis_);
    copy_row(from.x, x_);
    for (int i = 0; i < k_; ++i) {
      copy_row(from.binv[i], binv_[i]);
      copy_row(from.basic[i], basic_[i]);
    }
    updates_ = from.updates;
    duals_fresh_ = false;
  }
  int shift_rounds(int try_index) const {
    return try_index == 0 ? 4 * k_ : kLaterTryRounds;
  }

  static void unstable(Solution& s) {
    s.status = ProblemStatus::Unstable;
  }

  double column_entry(int j, int r) const {
    if (j < n_) return p_->at(r, j);
    if (j == composite_) return p_->rhs[r];
    return r == j - n_ ? artificial_sign_[r] : 0.0;
  }
  // values[0..n) when they are all the same (bit for bit), else NaN.
  static double constant_first_row(const double* values, int n) {
    for (int j = 1; j < n; ++j)
      if (std::bit_cast<uint64_t>(values[j]) != std::bit_cast<uint64_t>(values[0]))
        return std::numeric_limits<double>::quiet_NaN();
    return n > 0 ? values[0] : std::numeric_limits<double>::quiet_NaN();
  }

  // Column j's k entries, with the block decided once.
  void load_column(int j, double* a) const {
    if (j < g_) {
      const double* v = p_->grid->values.data() + j;
      for (int r = 0; r < k_; ++r) a[r] = v[size_t(r) * g_];
    } else if (j < n_) {
      const double* v = p_->extra.values.data() + (j - g_);
      for (int r = 0; r < k_; ++r) a[r] = v[size_t(r) * e_];
    } else {
      for (int r = 0; r < k_; ++r) a[r] = column_entry(j, r);
    }
  }
  double cost(int j) const {
    if (phase_ == 1) return is_artificial(j) ? 1.0 : 0.0;
    if (j < n_) return cost_[j];
    return j == composite_ ? composite_cost() : 0.0;
  }

  // Phase 2, then certification; a failed certificate resumes from the accurate basis. One that
  // failed on a negative reduced cost only the precise (double-double) pass sees (|y| ~ 1e8: the
  // double pass rounds ~1e-8, so its entering tolerance is that wide) names the column, and a step
  // brings it in: the double iterations could not have found it, and such LPs used to end unstable
  // (477 of a power4 sweep's 2.4M, then GLPK's answer or "lit"; now 1).
  bool solve_phase2(Solution& s) {
    int guided = 0;
    for (int attempt = 0; attempt < 3; ++attempt) {
      if (!iterate(s)) return false;
      if (certify(s)) return true;
      for (; certificate_entering_ >= 0 && guided < kGuidedSteps; ++guided) {
        double u[kMaxRows];
        column_in_basis(certificate_entering_, u);
        if (!(step(certificate_entering_, u, false, s) >= 0) || !iterate(s)) return false;
        if (certify(s)) return true;
      }
      if (!dual_simplex(s)) return false;
      if (certify(s)) return true;
    }
    return false;
  }

  void start_with_artificials() {
    for (int r = 0; r < k_; ++r) {
      artificial_sign_[r] = p_->rhs[r] >= 0 ? 1.0 : -1.0;
      basis_[r] = n_ + r;
      x_[r] = std::abs(p_->rhs[r]);
    }
    for (int i = 0; i < k_; ++i) {
      load_column(basis_[i], basic_[i]);
      for (int r = 0; r < k_; ++r) binv_[i][r] = i == r ? artificial_sign_[r] : 0.0;
    }
    updates_ = 0;
    duals_fresh_ = false;
  }

  // The known distribution as one composite column (its moment vector, which is the rhs, at its
  // cost F_Z(z_f)): a convex combination of columns, so adding it leaves the optimum unchanged,
  // and with weight 1 it is a feasible basic solution. The other k - 1 basic columns are grid
  // columns spread over I, at level zero. No phase 1, no Carathéodory reduction.
  bool start_from_distribution() {
    // Where the mass and z_f are, on the grid: the optimal support lies around them, so the start
    // columns do too (spread over all of I, narrow kernels took ~100 pivots instead of ~10).
    double lo = p_->zf, hi = p_->zf;
    for (int j : p_->start_support) lo = std::min(lo, point(j)), hi = std::max(hi, point(j));
    const auto& grid = p_->grid->points;
    int first = grid_bound(grid, lo, false, cell_scale_) - 1;
    int last = grid_bound(grid, hi, false, cell_scale_) + 1;
    for (int widen = 0; widen < 6; ++widen) {
      first = std::max(0, first - widen * (k_ - 1));
      last = std::min(g_ - 1, last + widen * (k_ - 1));
      if (last - first + 1 < k_ - 1) continue;
      basis_[0] = composite_;
      for (int i = 1; i < k_; ++i)  // k - 1 columns spread evenly over [first, last]
        basis_[i] = k_ == 2 ? (first + last) / 2
                            : first + int(std::lround(double(i - 1) * (last - first) / (k_ - 2)));
      if (refactor()) {
        for (int i = 0; i < k_; ++i) x_[i] = i == 0 ? 1.0 : 0.0;  // exact: B e_1 = rhs
        return true;
      }
    }
    return false;
  }

  bool refactor() {
    double b[kMaxRows][kMaxRows], inv[kMaxRows][kMaxRows];
    for (int i = 0; i < k_; ++i) {
      load_column(basis_[i], basic_[i]);
      for (int r = 0; r < k_; ++r) b[r][i] = basic_[i][r];
    }
    // Partial pivoting; a pivot below 1e-13 of the largest entry means rank loss (the merely
    // ill-conditioned bases of tiny-valued columns, z^6 near 0, must still pass).
    if (!invert_fixed<double, K>(b, inv, 1e-13)) return false;
    for (int i = 0; i < k_; ++i) std::copy(inv[i], inv[i] + k_, binv_[i]);
    in_basis(p_->rhs.data(), x_);
    updates_ = 0;
    duals_fresh_ = false;
    return true;
  }

  // y = B^{-T} c_B with one step of iterative refinement (the product-form inverse drifts), then
  // reduced costs of all structural columns, block by block (vectorised). The certificate computes
  // its y the same way, so at an optimal basis it finds these reduced costs already in place.
  void price() {
    dual_values(y_);
    duals_fresh_ = true;
    precise_duals_ = false;
    reduced_costs();
  }
  void dual_values(double* y) const {
    double basic_cost[kMaxRows], misfit[kMaxRows];
    for (int i = 0; i < k_; ++i) basic_cost[i] = cost(basis_[i]);
    for (int r = 0; r < k_; ++r) {
      double v = 0;
      for (int i = 0; i < k_; ++i) v += basic_cost[i] * binv_[i][r];
      y[r] = v;
    }
    for (int i = 0; i < k_; ++i) {  // c_B - B^T y
      double v = basic_cost[i];
      for (int r = 0; r < k_; ++r) v -= basic_[i][r] * y[r];
      misfit[i] = v;
    }
    for (int r = 0; r < k_; ++r) {
      double v = 0;
      for (int i = 0; i < k_; ++i) v += misfit[i] * binv_[i][r];
      y[r] += v;
    }
  }
  void reduced_costs() {
    priced_smallest_ =
        subtract_row_combination(y_, phase_ == 1 ? nullptr : cost_.data(), reduced_.data());
    priced_phase_ = phase_;
    for (int r = 0; r < k_; ++r) priced_y_[r] = y_[r];
  }
  // Whether reduced_ holds the reduced costs of these duals (in the current phase).
  bool priced_with(const double* y) const {
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
  double subtract_row_combination(const double* w, const double* base, double* out) const {
#ifdef __AVX512F__
    __m512d weight[K], low = _mm512_setzero_pd();
    for (int r = 0; r < K; ++r) weight[r] = _mm512_set1_pd(w[r]);
    combine_masked(weight, p_->grid->values.data(), g_, base, out, g_, low, grid_first_row_);
    combine_masked(weight, p_->extra.values.data(), e_, base ? base + g_ : nullptr, out + g_, e_,
                   low);
    return smallest_lane(low);
#endif
    const double* rows[K];
    for (int r = 0; r < K; ++r) rows[r] = p_->grid->values.data() + size_t(r) * g_;
    const double grid_smallest = combine_block(w, rows, base, out, g_);
    for (int r = 0; r < K; ++r)
      rows[r] = p_->extra.values.data() + size_t(r) * e_;  // data(): the block may be empty
    const double extra_smallest = combine_block(w, rows, base ? base + g_ : nullptr, out + g_, e_);
    return extra_smallest < grid_smallest ? extra_smallest : grid_smallest;
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
  static void combine_masked(const __m512d* weight, const double* values, size_t stride,
                             const double* base, double* out, int n, __m512d& low,
                             double first_row = std::numeric_limits<double>::quiet_NaN()) {
    const bool constant_first_row = !std::isnan(first_row);
    const __m512d first_row_values = _mm512_set1_pd(first_row);
    for (int j = 0; j < n; j += 8) {
      const __mmask8 live = lanes_below(n, j);
      __m512d v = base ? _mm512_maskz_loadu_pd(live, base + j) : _mm512_setzero_pd();
      v = _mm512_fnmadd_pd(
          weight[0],
          constant_first_row ? first_row_values : _mm512_maskz_loadu_pd(live, values + j), v);
      for (int r = 1; r < K; ++r)
        v = _mm512_fnmadd_pd(weight[r], _mm512_maskz_loadu_pd(live, values + r * stride + j), v);
      _mm512_mask_storeu_pd(out + j, live, v);
      low = _mm512_mask_min_pd(low, live, v, low);
    }
  }
  // The index of the least of the lanes that hold one (index >= 0; each lane keeps its first strict
  // best, so the lowest index among the lanes holding the least is the first overall), or -1.
  static int first_least_lane(__m512d best, __m512i index) {
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
    low =
        _mm512_mask_min_epi64(low, 0xff, low, _mm512_mask_shuffle_i64x2(low, 0xff, low, low, 0x4e));
    low =
        _mm512_mask_min_epi64(low, 0xff, low, _mm512_mask_shuffle_i64x2(low, 0xff, low, low, 0xb1));
    low = _mm512_mask_min_epi64(low, 0xff, low, _mm512_mask_permutex_epi64(low, 0xff, low, 0xb1));
    return _mm512_cvtsi512_si32(low);  // a column index: its low half
  }
#endif
  // Each out_j is the chain base_j - w_0 a_0j - w_1 a_1j - ... in fused multiply-adds, as the
  // compiler contracts the scalar loop, so both paths give the same bits.
  static double combine_block(const double* w, const double* const* rows, const double* base,
                              double* out, int n) {
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
        for (int r = 0; r < K; ++r)
          v = _mm256_fnmadd_pd(weights[r], _mm256_loadu_pd(rows[r] + j), v);
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
  static double smallest_of(const double* d, int n) {
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
  static bool any_below(const double* d, int n, double threshold) {
    int j = 0;
#ifdef __AVX512F__
    const __m512d limit = _mm512_set1_pd(threshold);
    __mmask8 below = 0;
    for (; j < n; j += 8) {
      const __mmask8 live = lanes_below(n, j);
      below |=
          _mm512_mask_cmp_pd_mask(live, _mm512_maskz_loadu_pd(live, d + j), limit, _CMP_NGE_UQ);
    }
    return below != 0;
#endif
    bool found = false;
    for (; j < n; ++j) found |= !(d[j] >= threshold);
    return found;
  }

  // The reduced cost below which a column may enter, for the duals y_. It grows with |y|: with
  // |y| ~ 1e8 (narrow kernels) reduced costs carry ~1e-16 |y| of rounding, and basic columns would
  // look attractive; the precise certificate, not this tolerance, decides optimality.
  double entering_tolerance() const {
    double largest_dual = 0;
    for (int r = 0; r < k_; ++r) largest_dual = std::max(largest_dual, std::abs(y_[r]));
    return std::max(kOptimalityTolerance, 1e-15 * largest_dual);
  }

  // Dantzig (or Bland) over non-basic columns, with reduced_ fresh for y_.
  int choose_entering(bool bland) {
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
  int slide_entering() {
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
  // The ratio test's step for column a without Harris' relaxation: min over u_i > kPivotTolerance
  // of max(x_i, 0) / u_i, u = B^-1 a as a fused chain over r from 0 (infinity when no u_i is). The
  // ratios are compared as products (x_i den < num u_i), so one division, not k: eight columns' k
  // divisions each made the search cost more than the pivots it saved at grid 1024.
  double blocking_step(const double* a) const {
    double num = std::numeric_limits<double>::infinity(), den = 1;
    for (int i = 0; i < K; ++i) {
      double u = 0;
      for (int r = 0; r < K; ++r) u = std::fma(binv_[i][r], a[r], u);
      const double x = std::max(x_[i], 0.0);
      if (u > kPivotTolerance && x * den < num * u) num = x, den = u;
    }
    return num / den;
  }
#ifdef __AVX512F__
  // slide_entering's search over one column block (rows `stride` apart, reduced costs from
  // reduced_[offset]), eight columns at a time in the same chains as blocking_step; each lane
  // keeps its first strict least d_j theta_j (below 0) and its column.
  void greatest_decrease(const double* values, size_t stride, int offset, int n, double tolerance,
                         __m512d& best, __m512i& index) const {
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
  int enter_from_extras() {
    priced_phase_ = -1;
#ifdef __AVX512F__
    {
      __m512d weight[K], low = _mm512_setzero_pd();
      for (int r = 0; r < K; ++r) weight[r] = _mm512_set1_pd(y_[r]);
      combine_masked(weight, p_->extra.values.data(), e_, cost_.data() + g_, reduced_.data() + g_,
                     e_, low);
      return extra_holding(smallest_lane(low));
    }
#endif
    const double* rows[K];
    for (int r = 0; r < K; ++r)
      rows[r] = p_->extra.values.data() + size_t(r) * e_;  // data(): the block may be empty
    return extra_holding(combine_block(y_, rows, cost_.data() + g_, reduced_.data() + g_, e_));
  }
  // The same choice from reduced_ fresh from a full pass (no arithmetic, the same bits): the first
  // iteration after a start prices every column first, since most warm starts are optimal already
  // (84 % of lp_bench's LPs need no pivot) and then a pass over the extras alone was wasted.
  int enter_among_extras() const {
    return extra_holding(smallest_of(reduced_.data() + g_, e_));
  }
  // Dantzig's choice among the extra columns (reduced_ fresh on them), `smallest` their least
  // reduced cost or 0: the first extra column holding it, or -1 when it is not below the entering
  // tolerance, or when that column is basic (rounding: the full pass then decides).
  int extra_holding(double smallest) const {
    if (!(smallest < -entering_tolerance())) return -1;
    const int first = g_ + first_holding(reduced_.data() + g_, e_, smallest);
    return is_basic(first) ? -1 : first;
  }

  // The first index j < n with d[j] == value, eight at a time (a scalar search was 40 % of a
  // pivot), or -1.
  static int first_holding(const double* d, int n, double value) {
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
  bool is_basic(int j) const {
    return basic_position(j) >= 0;
  }
  // The position of column j among basis_[0..among), or -1. Selects, no early exit: k is fixed,
  // and std::find was a call (~1 % of an LP).
  int basic_position(int j, int among = K) const {
    int at = -1;
    for (int i = 0; i < among; ++i) at = basis_[i] == j ? i : at;
    return at;
  }

  // u = B^{-1} a_j, the entering column in basis coordinates.
  void column_in_basis(int j, double* u) const {
    double a[kMaxRows];
    load_column(j, a);
    in_basis(a, u);
  }
  // u = B^{-1} a for any k-vector a (a column, a residual, the moments).
  void in_basis(const double* a, double* u) const {
    for (int i = 0; i < k_; ++i) {
      double v = 0;
      for (int r = 0; r < k_; ++r) v += binv_[i][r] * a[r];
      u[i] = v;
    }
  }
  // Whether u_i (u = B^{-1} a) is large enough, against the largest |u_q|, for a to replace basic
  // column i without a (nearly) singular basis (exchange, update_factors).
  bool stable_pivot(const double* u, int i) const {
    double largest = 0;
    for (int q = 0; q < k_; ++q) largest = std::max(largest, std::abs(u[q]));
    return std::abs(u[i]) > 1e-7 * largest;
  }

  // One simplex run to optimality for the current phase. False on numerical failure.
  bool iterate(Solution& s) {
    int degenerate = 0;
    // A node slides when the last two pivots left the same basis position, or the last one entered
    // an end of the grid, where Dantzig's steepest column often lies and from where a node of small
    // weight then walks back (slide_entering; the ends as a trigger: 0.94 -> 0.90 pivots an LP,
    // power4, 256).
    bool sliding = false;
    int previous_leave = -1;
    // Optimal bases are reached in ~20-40 pivots (measured on dataset fragments); a run past 1000
    // is stalling on an ill-conditioned basis and goes to the fallback instead.
    const int limit = std::min(20 * (n_ + k_), 1000);
    for (int guard = 0; guard < limit; ++guard) {
      if (updates_ >= refactor_interval() && !refactor()) return false;
      bool bland = degenerate >= kDegenerateBeforeBland;
      // The extra columns first (phase 2 only, after the first iteration: see enter_among_extras):
      // only when none of them may enter does a full pass decide, so every run still ends with one,
      // and optimality is never judged on the extras alone.
      dual_values(y_);  // once per iteration, for the extras and the full pass alike
      duals_fresh_ = true;
      precise_duals_ = false;
      const bool partial = phase_ == 2 && !bland && !retrying_;
      int entering = partial && guard > 0 && !sliding ? enter_from_extras() : -1;
      if (entering < 0) {
        // Duals too large for the double certificate (|y| ~ 1e8: narrow kernels) are refined in
        // double-double before the full pass, so that the precise certificate finds the reduced
        // costs of its duals in place; it used to refine them itself and price again (~8 % of a
        // warm LP: 44 % of the LPs need it, and most of them end after this pass).
        if (phase_ == 2 && pricing_rounding(y_) > 0.1 * kCertifyBound)
          refine_duals_for_certificate();
        reduced_costs();
        // (Only when some column may enter at all: most warm LPs are optimal, and their smallest
        // reduced cost is rounding, below zero but inside the tolerance.)
        if (partial && guard == 0 && priced_smallest_ < -entering_tolerance())
          entering = enter_among_extras();
        if (entering < 0 && sliding && partial) entering = slide_entering();  // (not run's retry)
        if (entering < 0) entering = choose_entering(bland);
      }
      if (entering < 0) return true;
      double u[kMaxRows];
      column_in_basis(entering, u);
      const double theta = step(entering, u, bland, s);
      if (!(theta >= 0)) return false;
      // Near-zero steps count as degenerate too: Harris steps of 1e-18 can cycle as well.
      degenerate = theta < 1e-12 ? degenerate + 1 : 0;
      const int left = basic_position(entering);  // the position the step's leaving column held
      sliding = left == previous_leave || entering == 0 || entering == g_ - 1;
      previous_leave = left;
    }
    return false;
  }

  // One primal simplex step: `entering` (u = B^{-1} a_entering) comes in, the ratio test picks the
  // leaving row. The step length, or -1 when no row may leave (numerical failure).
  double step(int entering, const double* u, bool bland, Solution& s) {
    int leave = -1;
    if (!bland) {
      // Harris ratio test: a relaxed bound first, then the largest pivot within it.
      // Selects, not branches (which rows block varies from pivot to pivot).
      double theta_max = std::numeric_limits<double>::infinity();
      for (int i = 0; i < k_; ++i) {
        const double ratio = (x_[i] + kFeasibilityTolerance) / u[i];
        theta_max = u[i] > kPivotTolerance && ratio < theta_max ? ratio : theta_max;
      }
      if (!std::isfinite(theta_max)) return -1;  // unbounded: impossible with sum w = 1
      const double limit = std::max(theta_max, 0.0);
      double best_pivot = 0;
      for (int i = 0; i < k_; ++i) {
        const bool better = u[i] > kPivotTolerance && !(x_[i] / u[i] > limit) && u[i] > best_pivot;
        leave = better ? i : leave;
        best_pivot = better ? u[i] : best_pivot;
      }
    } else {
      // Bland's rule needs the textbook ratio test (Harris' relaxation can cycle): the minimum
      // ratio, ties to the smallest column index.
      double best_ratio = std::numeric_limits<double>::infinity();
      for (int i = 0; i < k_; ++i) {
        if (u[i] <= kPivotTolerance) continue;
        double ratio = std::max(x_[i], 0.0) / u[i];
        if (ratio < best_ratio || (ratio == best_ratio && leave >= 0 && basis_[i] < basis_[leave]))
          leave = i, best_ratio = ratio;
      }
    }
    if (leave < 0) return -1;
    const double theta = std::max(x_[leave], 0.0) / u[leave];
    for (int i = 0; i < k_; ++i) x_[i] -= theta * u[i];
    x_[leave] = theta;
    pivot(leave, entering, u);
    ++s.iterations;
    return theta;
  }

  // Product-form update of the explicit inverse: column `entering` replaces basis row `leave`.
  void pivot(int leave, int entering, const double* u) {
    const double reciprocal = 1 / u[leave];  // one division, not k (8.8 exchanges and pivots an LP)
#ifdef __AVX512F__
    // A row of B^-1 a vector: one multiply-add a row, rows left alone masked, not branched (the
    // scalar loops, with a branch a row, were ~3 % of the solver's samples). The same bits: the
    // compiler contracts the scalar update into the same fused multiply-add.
    const __m512d pivot_row =
        _mm512_mul_pd(_mm512_maskz_loadu_pd(kLanes, binv_[leave]), _mm512_set1_pd(reciprocal));
    _mm512_mask_storeu_pd(binv_[leave], kLanes, pivot_row);
    for (int i = 0; i < K; ++i) {
      const __mmask8 update = i == leave || u[i] == 0 ? 0 : kLanes;
      const __m512d row = _mm512_maskz_loadu_pd(kLanes, binv_[i]);
      _mm512_mask_storeu_pd(binv_[i], update,
                            _mm512_fnmadd_pd(_mm512_set1_pd(u[i]), pivot_row, row));
    }
#else
    for (int r = 0; r < k_; ++r) binv_[leave][r] *= reciprocal;
    for (int i = 0; i < k_; ++i) {
      if (i == leave || u[i] == 0) continue;
      for (int r = 0; r < k_; ++r) binv_[i][r] -= u[i] * binv_[leave][r];
    }
#endif
    basis_[leave] = entering;
    load_column(entering, basic_[leave]);
    ++updates_;
    duals_fresh_ = false;
  }

  // Dual simplex steps from a dual feasible but slightly primal infeasible basis, which
  // ill-conditioned instances (z^3, z^6 near z = 0) can end the primal phase with: the most
  // negative basic variable leaves, the entering column keeps every reduced cost >= 0. Every step
  // starts from a fresh inverse, since x_B is judged at 1e-12.
  bool dual_simplex(Solution& s) {
    alpha_.resize(n_);
    for (int step = 0; step < 4 * k_ + 16; ++step) {
      if (!refactor()) return false;
      // x_B refined with double-double residuals, so that a weight the certificate found negative
      // (it refines the same way) leaves here too: in double, cond(B) ~ 1e8 hides -1e-12.
      refine_weights();
      const int leave = most_negative();
      if (!(x_[leave] < -kNegligibleWeight)) return true;
      price();
      // alpha_j = (B^{-1} A)_{leave, j}, stored negated: -alpha_j = 0 - row_leave . a_j.
      subtract_row_combination(binv_[leave], nullptr, alpha_.data());
      for (int i = 0; i < k_; ++i)
        if (basis_[i] < n_) alpha_[basis_[i]] = 0;  // basic columns cannot enter
      // Dual Harris ratio test: a relaxed bound on the step in the duals, then the largest
      // |alpha| within it, so that the new basis stays well conditioned.
      double alpha_max = 0;
#pragma omp simd reduction(max : alpha_max)
      for (int j = 0; j < n_; ++j) alpha_max = std::max(alpha_max, alpha_[j]);
      const double pivot_floor = std::max(kPivotTolerance, 1e-7 * alpha_max);
      double bound = std::numeric_limits<double>::infinity();
      for (int j = 0; j < n_; ++j)
        if (alpha_[j] > pivot_floor)
          bound = std::min(bound, (reduced_[j] + kOptimalityTolerance) / alpha_[j]);
      int entering = -1;
      double best_alpha = 0;
      for (int j = 0; j < n_; ++j)
        if (alpha_[j] > pivot_floor && reduced_[j] / alpha_[j] <= bound && alpha_[j] > best_alpha)
          entering = j, best_alpha = alpha_[j];
      if (entering < 0) return false;
      double u[kMaxRows];
      column_in_basis(entering, u);
      double theta = x_[leave] / u[leave];
      for (int i = 0; i < k_; ++i) x_[i] -= theta * u[i];
      x_[leave] = theta;
      pivot(leave, entering, u);
      ++s.iterations;
    }
    return false;
  }

  // One step of iterative refinement of x_B with a double-double residual (rhs - B x_B), rounded
  // back to double.
  void refine_weights() {
    DoubleDouble x[kMaxRows];
    for (int i = 0; i < k_; ++i) x[i] = {x_[i], 0};
    refine_precisely<false>(x, p_->rhs.data(), binv_);
    for (int i = 0; i < k_; ++i) x_[i] = x[i].value();
  }

  // After phase 1 every artificial left in the basis sits at zero; pivot each out on the
  // structural column with the largest entry in its row of B^{-1} A.
  bool drive_out_artificials() {
    for (int i = 0; i < k_; ++i) {
      if (!is_artificial(basis_[i])) continue;
      int best = -1;
      double best_value = 1e-7;
      for (int j = 0; j < n_; ++j) {
        if (std::find(basis_, basis_ + k_, j) != basis_ + k_) continue;
        double v = 0;
        for (int r = 0; r < k_; ++r) v += binv_[i][r] * p_->at(r, j);
        if (std::abs(v) > best_value) best = j, best_value = std::abs(v);
      }
      if (best < 0) return false;
      basis_[i] = best;
      if (!refactor()) return false;
    }
    return refactor();
  }

  // |a_rj| <= column_bound() for every column.
  double column_bound() const {
    return std::max(p_->grid->max_abs, p_->extra.max_abs);
  }
  // A bound on the rounding error of any reduced cost the double pass computes with duals y:
  // gamma (1 + |y|_1 max |a_rj|), gamma = (k + 2) eps.
  double pricing_rounding(const double* y) const {
    double y_norm = 0;
    for (int r = 0; r < k_; ++r) y_norm += std::abs(y[r]);
    return (k_ + 2) * std::numeric_limits<double>::epsilon() * (1 + y_norm * column_bound());
  }

  // The certificate, in double when that is provably enough, else in double-double.
  bool certify(Solution& s) {
    certificate_entering_ = -1;
    return certify_in_double(s) || certify_precisely(s);
  }

  // Most bases have moderate duals, and then double arithmetic certifies them with room to spare:
  // the same first-order bound as below, with the true residual B x - rhs (double x_B is only
  // cond(B) eps accurate) and every computed term widened by its rounding error bound
  // gamma (|terms|), gamma = (k + 2) eps. Narrow kernels (|y| ~ 1e8) fail this on rounding alone
  // and go to double-double. Every bound term is computed from the data (true residuals, reduced
  // costs of the y used), so the inverse need not be fresh: the product-form one, with one step of
  // refinement for y as for x_B, serves as well, and saves a factorisation per LP.
  bool certify_in_double(Solution& s) {
    constexpr double kEps = std::numeric_limits<double>::epsilon();
    const double gamma = (k_ + 2) * kEps;
    double y[kMaxRows] = {};  // (GCC cannot see that the copy fills k_ <= kMaxRows)
    if (duals_fresh_)  // the iterations' last duals, of this very basis and inverse: the same bits
      std::copy(y_, y_ + k_, y);
    else
      dual_values(y);
    const double reduced_cost_error = pricing_rounding(y);
    if (reduced_cost_error > 0.1 * kCertifyBound) return false;
    // One step of iterative refinement: x_B from the double inverse misses rhs by ~cond(B) eps;
    // after it the residual is at the level of its own rounding (backward stable).
    double correction[kMaxRows], misfit[kMaxRows];
    for (int r = 0; r < k_; ++r) {
      double v = p_->rhs[r];
      for (int i = 0; i < k_; ++i) v -= basic_[i][r] * x_[i];
      misfit[r] = v;
    }
    in_basis(misfit, correction);
    for (int i = 0; i < k_; ++i) x_[i] += correction[i];
    // A weight below what double-double would call zero is for the precise pass (and then the
    // dual simplex) to judge: the bound's terms would not notice it (kCertifyResidual; a clamped
    // weight of ~-1e-12 passed here with G = 1.41e-8 where the optimum, a basis primal and dual
    // feasible in __float128, is 2.50e-8).
    double clamped[kMaxRows];
    for (int i = 0; i < k_; ++i) {
      if (!(x_[i] >= -kNegligibleWeight)) return false;
      clamped[i] = std::max(x_[i], 0.0);
    }
    double bound = 0;
    for (int r = 0; r < k_; ++r) {
      double residual = -p_->rhs[r], size = std::abs(p_->rhs[r]);
      for (int i = 0; i < k_; ++i) {
        const double term = basic_[i][r] * clamped[i];
        residual += term;
        size += std::abs(term);
      }
      // The reported support must reproduce the moments as accurately as long double's does
      // (the KKT checker and the users' own checks look at the residual alone).
      if (!(std::abs(residual) + gamma * size <= kCertifyResidual)) return false;
      bound += std::abs(y[r]) * (std::abs(residual) + gamma * size);
    }
    const bool priced = priced_with(y);
    for (int r = 0; r < k_; ++r) y_[r] = y[r];
    if (!priced) reduced_costs();
    auto reduced_cost = [&](int j) { return std::abs(reduced_[j]) + reduced_cost_error; };
    for (int i = 0; i < k_; ++i) {
      if (clamped[i] <= 0) continue;
      if (basis_[i] < n_) bound += clamped[i] * reduced_cost(basis_[i]);
      if (basis_[i] == composite_)
        for (size_t t = 0; t < p_->start_support.size(); ++t)
          bound += clamped[i] * p_->start_weights[t] * reduced_cost(p_->start_support[t]);
    }
    // Weak duality with sum w = 1: no distribution beats y.(1, b) by more than -min_j d_j.
    bound += std::max(0.0, reduced_cost_error - priced_smallest_);  // reduced_ is y's (above)
    if (!(bound <= kCertifyBound)) return false;
    double objective = 0;
    for (int i = 0; i < k_; ++i) objective += cost(basis_[i]) * clamped[i];
    report(s, objective, clamped, y);
    return true;
  }

  // weights: x_B clamped at 0; y: the duals, double or double-double (Solution keeps long double).
  template <class Dual>
  void report(Solution& s, double objective, const double* weights, const Dual* y) const {
    s.status = ProblemStatus::Optimal;
    s.support.clear();
    s.weights.clear();
    if (is_basic(composite_)) {
      s.support.reserve(k_);  // one allocation each, not one per doubling
      s.weights.reserve(k_);
      for (int i = 0; i < k_; ++i) {
        const double w = weights[i];
        if (w <= 0) continue;
        if (basis_[i] == composite_) {
          // The composite column stands for the known distribution: report its atoms.
          for (size_t t = 0; t < p_->start_support.size(); ++t)
            add_support(s, p_->start_support[t], w * p_->start_weights[t]);
        } else {
          add_support(s, basis_[i], w);
        }
      }
    } else {
      // Distinct basic columns: no atom to merge, so no search (add_support's was ~1 % of an LP).
      s.support.resize(k_);
      s.weights.resize(k_);
      int count = 0;
      for (int i = 0; i < k_; ++i) {
        s.support[count] = basis_[i];
        s.weights[count] = weights[i];
        count += weights[i] > 0;
      }
      s.support.resize(count);
      s.weights.resize(count);
    }
    s.G = objective;
    s.duals.resize(k_);
    for (int r = 0; r < k_; ++r) s.duals[r] = to_long_double(y[r]);
  }

  // The precise certificate, in double-double: x_B and y refined from the double inverse first
  // (two steps with double-double residuals reach well past long double accuracy for cond(B) up to
  // ~1e8, at a fraction of a factorisation's cost; most bases need one), then, if that does not
  // certify, with B inverted afresh in long double. On that failure the accurate inverse and x_B
  // are kept, so the caller resumes from them. (In x87 long double this was ~4000 cycles an LP,
  // a fifth of the LP time of a sweep.)
  bool certify_precisely(Solution& s) {
    DoubleDouble x[kMaxRows], y[kMaxRows];
    double basic_cost[kMaxRows];
    const bool refined = duals_fresh_ && precise_duals_;  // y_ refined by iterate already
    for (int i = 0; i < k_; ++i) {
      basic_cost[i] = cost(basis_[i]);
      x[i] = {x_[i], 0};
      y[i] = refined ? precise_y_[i] : DoubleDouble{y_[i], 0};
    }
    auto refine = [&](const auto& inverse, int steps) {
      for (int step = 0; step < steps; ++step) {
        refine_precisely<false>(x, p_->rhs.data(), inverse);
        refine_precisely<true>(y, basic_cost, inverse);
      }
    };
    // x_B: one step, then its residual, which the bound needs anyway, decides whether a second
    // step is taken (a third of the bounds fail on |y| times the residual one step leaves); the
    // second starts from that residual, so no residual is computed twice.
    refine_precisely<false>(x, p_->rhs.data(), binv_);
    double residual[kMaxRows];
    misfit_of<false>(x, p_->rhs.data(), residual);
    if (!refined) refine_precisely<true>(y, basic_cost, binv_);
    if (precise_bound(x, y, s, residual)) return true;
    correct_precisely<false>(x, residual, binv_);
    if (precise_bound(x, y, s)) return true;
    refine(binv_, 1);
    if (precise_bound(x, y, s)) return true;
    long double factors[kMaxRows][kMaxRows], inv[kMaxRows][kMaxRows];
    for (int r = 0; r < k_; ++r)
      for (int i = 0; i < k_; ++i) factors[r][i] = basic_[i][r];
    if (!invert_fixed<long double, K>(factors, inv, 1e-14L)) return false;
    for (int i = 0; i < k_; ++i) {
      long double v = 0;
      for (int r = 0; r < k_; ++r) v += inv[i][r] * (long double)p_->rhs[r];
      x[i] = to_double_double(v);
      for (int r = 0; r < k_; ++r) binv_[i][r] = double(inv[i][r]);
    }
    updates_ = 0;
    duals_fresh_ = false;
    for (int r = 0; r < k_; ++r) {
      long double v = 0;
      for (int i = 0; i < k_; ++i) v += basic_cost[i] * inv[i][r];
      y[r] = to_double_double(v);
    }
    // The solve alone leaves a residual of ~cond(B) long double epsilons, which |y| ~ 1e8 would
    // turn into a failed bound: refine with the long double inverse.
    refine(inv, 2);
    for (int i = 0; i < k_; ++i) x_[i] = x[i].value();
    return precise_bound(x, y, s);
  }

  // One step of iterative refinement of v in B v = target (Transposed: B^T v = target; x_B from the
  // moments, y from the basic costs) with a double-double residual and the given inverse of B
  // (double or long double): each step gains the digits that cond(B) times the inverse's precision
  // leaves.
  template <bool Transposed, class Inverse>
  void refine_precisely(DoubleDouble* v, const double* target, const Inverse& inverse) const {
    double misfit[kMaxRows];
    misfit_of<Transposed>(v, target, misfit);
    correct_precisely<Transposed>(v, misfit, inverse);
  }
  // v += B^{-1} misfit (Transposed: B^{-T} misfit): refine_precisely's step from its residual.
  template <bool Transposed, class Inverse>
  void correct_precisely(DoubleDouble* v, const double* misfit, const Inverse& inverse) const {
    using Real = std::remove_cvref_t<decltype(inverse[0][0])>;
    for (int i = 0; i < k_; ++i) {
      Real correction = 0;
      for (int r = 0; r < k_; ++r)
        correction += misfit[r] * (Transposed ? inverse[r][i] : inverse[i][r]);
      add(v[i], double(correction));
    }
  }
  // misfit = target - B v (Transposed: target - B^T v), summed in double-double and rounded: the
  // refinements' residuals, the certificate's residual of the clamped x_B, and its basic columns'
  // reduced costs (c_B - B^T y). The k sums side by side: one at a time, each double-double sum is
  // a chain of dependent adds, and latency dominated.
  template <bool Transposed>
  void misfit_of(const DoubleDouble* v, const double* target, double* misfit) const {
#ifdef __AVX512F__
    // As the lanes of one vector: rows of B v from B's columns (basic_[i]), or positions of B^T v
    // from its rows.
    DoubleDouble8 sum{_mm512_maskz_loadu_pd(kLanes, target)};
    if constexpr (Transposed) {
      __m512d row[K];
      basic_rows(row);
      for (int r = 0; r < K; ++r) add_product(sum, v[r], negated(row[r]));
    } else {
      for (int i = 0; i < K; ++i)
        add_product(sum, v[i], negated(_mm512_maskz_loadu_pd(kLanes, basic_[i])));
    }
    _mm512_mask_storeu_pd(misfit, kLanes, value(sum));
#else
    DoubleDouble sum[kMaxRows];
    for (int q = 0; q < k_; ++q) sum[q] = {target[q], 0};
    if constexpr (Transposed) {
      for (int r = 0; r < k_; ++r)
        for (int i = 0; i < k_; ++i) add_product(sum[i], v[r], -basic_[i][r]);
    } else {
      for (int i = 0; i < k_; ++i)
        for (int r = 0; r < k_; ++r) add_product(sum[r], v[i], -basic_[i][r]);
    }
    for (int q = 0; q < k_; ++q) misfit[q] = sum[q].value();
#endif
  }
#ifdef __AVX512F__
  static constexpr __mmask8 kLanes = __mmask8((1u << K) - 1);  // one lane a row or basis position
  // row[r] = (basic_[0][r], ..., basic_[k-1][r]): row r of B, one lane a basis position.
  void basic_rows(__m512d (&row)[K]) const {
    static_assert(kMaxRows == 8, "basic_[i][r] lies 8 doubles after basic_[i - 1][r]");
    const __m512i position = _mm512_set_epi64(56, 48, 40, 32, 24, 16, 8, 0);
    for (int r = 0; r < K; ++r)
      row[r] = _mm512_mask_i64gather_pd(_mm512_setzero_pd(), kLanes, position, &basic_[0][r], 8);
  }
  // -v exactly (the sign bit flipped, as the scalar unary minus).
  static __m512d negated(__m512d v) {
    return _mm512_castsi512_pd(
        _mm512_xor_si512(_mm512_castpd_si512(v), _mm512_set1_epi64(int64_t(1) << 63)));
  }
#endif
  // y_ (dual_values' of the current basis) refined by one double-double step into precise_y_, and
  // rounded back into y_ (iterate, for certify_precisely).
  void refine_duals_for_certificate() {
    double basic_cost[kMaxRows];
    for (int i = 0; i < k_; ++i) basic_cost[i] = cost(basis_[i]), precise_y_[i] = {y_[i], 0};
    refine_precisely<true>(precise_y_, basic_cost, binv_);
    for (int i = 0; i < k_; ++i) y_[i] = precise_y_[i].value();
    precise_duals_ = true;
  }

  // d_j = c_j - y.a_j in double-double.
  double precise_reduced_cost(int j, const DoubleDouble* y) const {
    double a[kMaxRows];
    load_column(j, a);
    DoubleDouble d{cost_[j], 0};
    for (int r = 0; r < k_; ++r) add_product(d, y[r], -a[r]);
    return d.value();
  }

  // Accepts x_B and y when the same first-order bound on |G - G*| as the KKT checker's (|y| times
  // the residual of the clamped x_B, plus complementarity, plus dual infeasibility) is <= 1e-9,
  // every term from double-double sums (the bound's own double rounding is ~1e-16 of it).
  // `residual_of_x`: rhs - B x when known (used when no weight is clamped).
  bool precise_bound(const DoubleDouble* x, const DoubleDouble* y, Solution& s,
                     const double* residual_of_x = nullptr) {
    DoubleDouble clamped[kMaxRows];
    bool unclamped = true;
    for (int i = 0; i < k_; ++i) {
      if (!(x[i].value() >= -kNegligibleWeight)) return false;
      clamped[i] = x[i].hi > 0 ? x[i] : DoubleDouble{};
      unclamped &= x[i].hi > 0 || (x[i].hi == 0 && x[i].lo == 0);
    }
    // rhs - B max(x, 0): only its size counts below.
    double residual[kMaxRows];
    if (residual_of_x && unclamped)
      std::copy(residual_of_x, residual_of_x + k_, residual);
    else
      misfit_of<false>(clamped, p_->rhs.data(), residual);
    // Its part of the bound first: when it alone is too large (refinement needs another step), the
    // rest is not computed.
    double bound = 0;
    for (int r = 0; r < k_; ++r) {
      if (!(std::abs(residual[r]) <= kCertifyResidual)) return false;  // x_B not feasible
      bound += std::abs(y[r].value() * residual[r]);
    }
    if (!(bound <= kCertifyBound)) return false;
    // Complementarity as the KKT checker sees it: basic reduced costs, zero in exact arithmetic,
    // are |y| times rounding in practice. Computed for every basic column, since each is also a
    // suspect below (judged twice, they were ~15 % of this certificate).
    // (Read for the structural columns only: the composite's atoms count instead.)
    double basic_cost[kMaxRows], basic_reduced[kMaxRows];
    for (int i = 0; i < k_; ++i) basic_cost[i] = basis_[i] < n_ ? cost_[basis_[i]] : 0.0;
    misfit_of<true>(y, basic_cost, basic_reduced);
    for (int i = 0; i < k_; ++i) {
      const double w = clamped[i].value();
      if (w <= 0) continue;
      if (basis_[i] < n_) bound += w * std::abs(basic_reduced[i]);
      if (basis_[i] == composite_)  // reported as its atoms, so their reduced costs count
        for (size_t t = 0; t < p_->start_support.size(); ++t)
          bound +=
              w * p_->start_weights[t] * std::abs(precise_reduced_cost(p_->start_support[t], y));
    }
    if (!(bound <= kCertifyBound)) return false;
    // Double pricing with the rounded duals finds the suspects, double-double judges them: a
    // column whose double reduced cost is at least its rounding bound (that of the pass plus the
    // rounding of y) cannot be negative.
    double rounding = 0;
    for (int r = 0; r < k_; ++r) {
      y_[r] = y[r].value();
      rounding += std::abs((y[r].hi - y_[r]) + y[r].lo);
    }
    if (!priced_with(y_)) reduced_costs();
    const double suspect_below = (pricing_rounding(y_) + rounding * column_bound()) * (1 + 1e-6);
    // Weak duality with sum w = 1: no distribution beats y.(1, b) by more than -min_j d_j, so the
    // most negative reduced cost counts, once (as in the KKT checker).
    // (The first column holding it on ties, as a scan in column order would find it.)
    double infeasibility = 0;
    int most_negative_column = -1;
    auto judge = [&](int j, double d) {
      if (-d > infeasibility || (-d == infeasibility && -d > 0 && j < most_negative_column))
        infeasibility = -d, most_negative_column = j;
    };
    // The basic columns, suspects by their rounding alone, are judged by their double-double
    // values, then hidden (read +inf), so that one branch-free pass nearly always shows that no
    // other column is a suspect (a scan branching on every block holding a suspect was ~4 % of an
    // LP).
    for (int i = 0; i < k_; ++i)
      if (basis_[i] < n_) judge(basis_[i], basic_reduced[i]);
    const BasicColumnsHidden hidden(*this, std::numeric_limits<double>::infinity());
    const double* reduced = reduced_.data();
    int j = any_below(reduced, n_, suspect_below) ? 0 : n_;
    auto judge_precisely = [&](int column) { judge(column, precise_reduced_cost(column, y)); };
#ifdef __AVX512F__
    // Eight at a time, masked at the end, skipping blocks without a suspect.
    const __m512d threshold = _mm512_set1_pd(suspect_below);
    for (; j < n_; j += 8) {
      const __mmask8 live = lanes_below(n_, j);
      unsigned mask = _mm512_mask_cmp_pd_mask(live, _mm512_maskz_loadu_pd(live, reduced + j),
                                              threshold, _CMP_NGE_UQ);
      for (; mask; mask &= mask - 1) judge_precisely(j + __builtin_ctz(mask));
    }
#elif defined(__AVX__)
    // Four at a time, skipping blocks without a suspect (a branch per column was ~20 % of this).
    const __m256d below = _mm256_set1_pd(suspect_below);
    for (; j + 4 <= n_; j += 4) {
      int mask =
          _mm256_movemask_pd(_mm256_cmp_pd(_mm256_loadu_pd(reduced + j), below, _CMP_NGE_UQ));
      for (; mask; mask &= mask - 1) judge_precisely(j + __builtin_ctz(mask));
    }
#endif
    for (; j < n_; ++j)
      if (!(reduced[j] >= suspect_below)) judge_precisely(j);
    if (!(bound + infeasibility <= kCertifyBound)) {
      // Dual infeasible beyond the budget: the most negative column, unless basic (rounding).
      if (infeasibility > 0 && !is_basic(most_negative_column))
        certificate_entering_ = most_negative_column;
      return false;
    }
    // G and the weights from double-double sums, rounded once (x87 long double here was ~100
    // ticks of this certificate's ~600).
    DoubleDouble objective;
    double weights[kMaxRows];
    for (int i = 0; i < k_; ++i) {
      weights[i] = clamped[i].value();
      add_product(objective, clamped[i], cost(basis_[i]));
      x_[i] = x[i].value();
    }
    report(s, objective.value(), weights, y);
    return true;
  }

  static void add_support(Solution& s, int j, double w) {
    for (size_t t = 0; t < s.support.size(); ++t)
      if (s.support[t] == j) {
        s.weights[t] += w;
        return;
      }
    s.support.push_back(j);
    s.weights.push_back(w);
  }

  const Problem* p_ = nullptr;
  const WarmPosition* at_ = nullptr;  // where the problem being solved sits (run), or null
  static constexpr int k_ = K;
  int n_ = 0, g_ = 0, e_ = 0, composite_ = 0;
  int certificate_entering_ = -1;  // set by a failed precise certificate (solve_phase2)
  bool duals_fresh_ = false;       // y_ is dual_values' of the current basis and inverse
  bool precise_duals_ = false;     // and refined into precise_y_ (refine_duals_for_certificate)
  DoubleDouble precise_y_[kMaxRows];
  int phase_ = 1;
  int basis_[kMaxRows] = {};
  double x_[kMaxRows], y_[kMaxRows], artificial_sign_[kMaxRows];
  double binv_[kMaxRows][kMaxRows];
  double basic_[kMaxRows][kMaxRows];  // basic_[i] = column basis_[i] (kept by refactor and pivot)
  // F_Z(z_f), the composite column's cost, computed the first time it is asked for: the column
  // enters few LPs (repairs, cold starts), and the sum over the taps was ~2 % of every LP.
  mutable double composite_cost_ = 0;
  double composite_cost() const {
    if (composite_cost_ != composite_cost_) {
      double sum = 0;
      for (size_t t = 0; t < p_->start_support.size(); ++t)
        sum += p_->start_weights[t] * cost_[p_->start_support[t]];
      composite_cost_ = sum;
    }
    return composite_cost_;
  }
  int updates_ = 0;
  // run's retry from scratch: no partial pricing over the extra columns (iterate), and fresh
  // inverses every kCarefulRefactorInterval updates.
  bool retrying_ = false;
  int refactor_interval() const {
    return retrying_ ? kCarefulRefactorInterval : kRefactorInterval;
  }
  int kernel_side_ = 0;   // taps a side of the problem's square kernel, 0: not square (texel_tap)
  int kernel_taps_ = -1;  // the taps kernel_side_, tap_column_ and tap_row_ are for
  std::vector<int> tap_column_, tap_row_;
  const double* grid_points_ = nullptr;  // the problem's grid and extra points (point)
  const double* extra_points_ = nullptr;

  double cell_scale_ = 0;           // grid cells per unit of z
  BasisState usable_basis_;         // solve_from_previous_basis: the first usable warm try
  double priced_y_[kMaxRows] = {};  // the duals reduced_ was computed with, in priced_phase_
  int priced_phase_ = -1;
  double priced_smallest_ = 0;  // min(0, min_j reduced_[j]), set with reduced_
  std::vector<double> reduced_, alpha_, cost_;
  // The grid whose costs cost_[0, g_) holds, ones up to costed_front_ (solve).
  std::shared_ptr<const ColumnBlock> costed_grid_;
  int costed_front_ = 0;
  // The value of every entry of that grid's first row, or NaN when they differ (combine_masked).
  double grid_first_row_ = std::numeric_limits<double>::quiet_NaN();
  WarmBasis lanes_[kWarmLanes];          // by layer: the texel to the left
  BasisState lane_factors_[kWarmLanes];  // their inverses (update_factors)
  std::vector<WarmBasis> above_;         // by column and layer: the row above
  // Their z_f, NaN where there is no basis: the selection reads these alone (a WarmBasis spans
  // ~80 bytes, and the 16 of a selection were ~8 % of a warm LP's time).
  double lane_zf_[kWarmLanes];
  std::vector<double> above_zf_;
  static constexpr double kNoBasis =
      std::numeric_limits<double>::quiet_NaN();  // a z_f slot without one
};

class FastBackend : public Backend {
 public:
  std::string name() const override { return "fast"; }
  int max_functions() const override { return kMaxRows - 1; }
  Solution solve(const Problem& p) override {
    Solution s;
    solve_into(p, nullptr, s);
    return s;
  }
  Solution solve_next(const Problem& p, WarmPosition at) override {
    Solution s;
    solve_into(p, &at, s);
    return s;
  }
  void solve_into(const Problem& p, const WarmPosition* at, Solution& s) override {
    if (p.rows > kMaxRows) {
      s.reset();
      s.call = CallStatus::Failed;
      s.call_message =
          "the fast backend handles at most " + std::to_string(kMaxRows - 1) + " basis functions";
      return;
    }
    with_row_count<kMaxRows>(p.rows,
                             [&](auto rows) { std::get<rows() - 1>(simplices_).run(p, at, s); });
    s.engine = Engine::Fast;  // `s` may hold an earlier fallback answer's tag
    if (s.status != ProblemStatus::Unstable) return;
    // The rare instance our simplex cannot certify goes to GLPK, and its answer is accepted only
    // if the independent KKT checker certifies it, with its first-order error bound, and its
    // weights reproduce the moments to double rounding. The bound alone is one-sided (see
    // kCertifyResidual): GLPK's answer 1.2e-10 to an LP whose optimum is 2.0e-7 (a basis feasible
    // and dual feasible in __float128) had a residual of 2e-12 and a bound of 5e-11. Otherwise
    // the LP stays unstable.
    if (!glpk_) glpk_ = make_glpk_backend();
    Solution reference = glpk_->solve(p);
    const KktReport check = check_kkt(p, reference, kCertifyBound);
    if (reference.status == ProblemStatus::Optimal && check.ok &&
        check.error_bound <= kCertifyBound && check.primal_residual <= kFallbackResidual) {
      reference.iterations += s.iterations;
      s = std::move(reference);
      return;
    }
    // GLPK's "infeasible" is wrong by construction when a feasible distribution is known.
    if (reference.status == ProblemStatus::Infeasible && p.start_support.empty())
      s = std::move(reference);
  }

  // One simplex per row count (each keeps the warm bases of its own problems).
  std::tuple<FastSimplex<1>, FastSimplex<2>, FastSimplex<3>, FastSimplex<4>, FastSimplex<5>,
             FastSimplex<6>, FastSimplex<7>, FastSimplex<8>>
      simplices_;
  std::unique_ptr<Backend> glpk_;
};

}  // namespace

std::unique_ptr<Backend> make_fast_backend() {
  return std::make_unique<FastBackend>();
}

const char* to_string(Engine engine) {
  return engine == Engine::Fast ? "fast" : "glpk";
}

const char* to_string(ProblemStatus status) {
  switch (status) {
    case ProblemStatus::Optimal:
      return "optimal";
    case ProblemStatus::Infeasible:
      return "infeasible";
    case ProblemStatus::Unstable:
      return "unstable";
  }
  return "?";
}

std::vector<std::string> backend_names() {
  return {"fast", "glpk"};
}

std::unique_ptr<Backend> make_backend(const std::string& name) {
  if (name == "fast") return make_fast_backend();
  if (name == "glpk") return make_glpk_backend();
  throw InputError("unknown LP backend '" + name + "'; valid: fast, glpk");
}

void check_backend_rows(const std::string& name, int functions, const std::string& what) {
  const int limit = make_backend(name)->max_functions();
  if (functions > limit)
    throw InputError(
        what + ": " + std::to_string(functions) + " basis functions, but LP backend '" + name +
        "' solves at most " + std::to_string(limit) +
        (name == "fast" ? " (lp.backend glpk takes up to " +
                              std::to_string(make_backend("glpk")->max_functions()) + ")"
                        : ""));
}

}  // namespace mb::lp
