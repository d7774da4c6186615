// Issue 46, step 1: would solving one fragment for a block of K catalog candidates at once, one
// candidate per SIMD lane, raise the exact sweep's LP throughput by >= 2.5x? Measured on lp_bench's
// runs (bench_runs.h), for K = 8 candidates spread over the 66 045 (the same fragments for each),
// in one pass and one run:
//  - single: today's engine, one backend per candidate (each keeps its own warm bases, as the
//    sweep's candidate loop does), every LP warm-started within its run: T per LP;
//  - resolve: each LP solved once more right after, warm from its own optimal basis: the engine's
//    least cost of an LP (a warm start that is already optimal: map the basis, x_B, one pricing
//    pass, the certificate): s0 per LP. T - s0 is what the LP needed beyond that (bracket shifts,
//    pivots, repairs, precise certificates);
//  - batched: a block kernel that does the resolve's work for all K lanes at once, each lane given
//    its LP's optimal basis: the 5 x 5 bases gathered and inverted, x_B (one refinement step) and
//    y in SIMD across the lanes, each lane's pricing pass with the engine's own lane kernel (the
//    lanes share no columns, so SIMD across candidates gains nothing there: the engine already
//    prices eight columns an instruction), the double certificate across the lanes. A lane it does
//    not certify, or whose optimal basis is not five positive weights, costs its resolve time:
//    b per LP.
// The batched engine's best case is then b + (T - s0) per LP: every lane on the common path at
// the kernel's speed, and the rest as today (what a block cannot share: each lane's own pivots,
// with the other lanes masked). The ceiling T / (b + T - s0) is the go/no-go number (counter
// `ceiling`); `batched_agree` counts the lanes whose G is the engine's to 1e-9 (the kernel is
// checked, not only timed). More bounds, below: `ceiling_free_common_path`, `ceiling_lockstep`,
// `ceiling_at_kernel_gain` and `ceiling_lockstep_at_kernel_gain`.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "basis/basis.h"
#include "bench_runs.h"
#include "lp/fast/settings.h"
#include "lp/lanes/lanes.h"
#include "sweep/candidates.h"

namespace mb {
namespace {

constexpr int kLanes = 8;  // doubles in an AVX-512 register
constexpr int kRows = 5;   // four catalog functions and the constant
using Lanes = double __attribute__((vector_size(kLanes * sizeof(double))));
using LaneMask = int64_t __attribute__((vector_size(kLanes * sizeof(int64_t))));

// kLanes candidates spread evenly over the lexicographic ranks of all 4-combinations.
std::vector<std::vector<std::string>> block_candidates() {
  const auto& names = catalog_names();
  const int n = int(names.size());
  const uint64_t total = binomial(n, 4);
  std::vector<std::vector<std::string>> out;
  for (int c = 0; c < kLanes; ++c) {
    std::vector<std::string> functions;
    for (int i : combination_unrank((2 * c + 1) * total / (2 * kLanes), n, 4))
      functions.push_back(names[size_t(i)]);
    out.push_back(functions);
  }
  return out;
}

Lanes splat(double v) {
  return Lanes{} + v;
}
Lanes lane_abs(Lanes v) {
  return v < 0 ? -v : v;
}

// One lane's LP as the block kernel sees it: its problem (in cache), its basis's columns.
struct LaneInput {
  const lp::Problem* problem = nullptr;
  int columns[kRows] = {};
  bool full = false;  // the optimal basis is five columns of positive weight
};

// B^-1 for every lane at once: Gauss-Jordan with partial pivoting, each lane choosing its own
// pivot rows by selects (a lane's row swap is a masked exchange).
void invert(Lanes (&a)[kRows][kRows], Lanes (&inv)[kRows][kRows]) {
  for (int r = 0; r < kRows; ++r)
    for (int c = 0; c < kRows; ++c) inv[r][c] = splat(r == c ? 1.0 : 0.0);
  for (int c = 0; c < kRows; ++c) {
    Lanes best = lane_abs(a[c][c]);
    LaneMask pivot = LaneMask{} + c;
    for (int r = c + 1; r < kRows; ++r) {
      const LaneMask larger = lane_abs(a[r][c]) > best;
      best = larger ? lane_abs(a[r][c]) : best;
      pivot = larger ? LaneMask{} + r : pivot;
    }
    for (int r = c + 1; r < kRows; ++r) {
      const LaneMask swap = pivot == r;
      for (int k = 0; k < kRows; ++k) {
        const Lanes ac = a[c][k], ar = a[r][k], ic = inv[c][k], ir = inv[r][k];
        a[c][k] = swap ? ar : ac, a[r][k] = swap ? ac : ar;
        inv[c][k] = swap ? ir : ic, inv[r][k] = swap ? ic : ir;
      }
    }
    const Lanes scale = 1.0 / a[c][c];
    for (int k = 0; k < kRows; ++k) a[c][k] *= scale, inv[c][k] *= scale;
    for (int r = 0; r < kRows; ++r) {
      if (r == c) continue;
      const Lanes f = a[r][c];
      for (int k = 0; k < kRows; ++k) a[r][k] -= f * a[c][k], inv[r][k] -= f * inv[c][k];
    }
  }
}

// The block kernel: certifies each lane's basis as the engine's certify_in_double would, G into
// `g` (NaN for a lane it does not certify). `cost` is the block's shared objective (every
// candidate's grid and extra points are the same points); `reduced` scratch for one lane.
void solve_block(const LaneInput (&lane)[kLanes], const std::vector<double>& cost,
                 std::vector<double>& reduced, double (&g)[kLanes]) {
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  constexpr double kGamma = (kRows + 2) * kEps;
  Lanes b[kRows][kRows], inv[kRows][kRows], rhs[kRows], cb[kRows];  // b[r][i]: row r, column i
  for (int l = 0; l < kLanes; ++l) {
    const lp::Problem& p = *lane[l].problem;
    for (int i = 0; i < kRows; ++i) {
      const int j = lane[l].full ? lane[l].columns[i] : i;
      for (int r = 0; r < kRows; ++r) b[r][i][l] = p.at(r, j);
      cb[i][l] = cost[size_t(j)];
    }
    for (int r = 0; r < kRows; ++r) rhs[r][l] = p.rhs[size_t(r)];
  }
  Lanes work[kRows][kRows];
  for (int r = 0; r < kRows; ++r)
    for (int i = 0; i < kRows; ++i) work[r][i] = b[r][i];
  invert(work, inv);
  // x_B = B^-1 rhs, one step of refinement; y = B^-T c_B.
  Lanes x[kRows], y[kRows];
  for (int i = 0; i < kRows; ++i) {
    x[i] = Lanes{};
    for (int r = 0; r < kRows; ++r) x[i] += inv[i][r] * rhs[r];
  }
  Lanes misfit[kRows];
  for (int r = 0; r < kRows; ++r) {
    misfit[r] = rhs[r];
    for (int i = 0; i < kRows; ++i) misfit[r] -= b[r][i] * x[i];
  }
  for (int i = 0; i < kRows; ++i)
    for (int r = 0; r < kRows; ++r) x[i] += inv[i][r] * misfit[r];
  for (int r = 0; r < kRows; ++r) {
    y[r] = Lanes{};
    for (int i = 0; i < kRows; ++i) y[r] += cb[i] * inv[i][r];
  }
  // Each lane's pricing pass: the engine's kernel, over its own columns.
  Lanes smallest{}, basic_reduced[kRows], bound_columns{};
  for (int l = 0; l < kLanes; ++l) {
    const lp::Problem& p = *lane[l].problem;
    const int gs = p.grid_size(), es = p.extra.size();
    double w[kRows];
    for (int r = 0; r < kRows; ++r) w[r] = y[r][l];
    const double sg = lp::fast::lanes::combine<kRows>(w, p.grid->values.data(), size_t(gs),
                                                      cost.data(), reduced.data(), gs);
    const double se = lp::fast::lanes::combine<kRows>(w, p.extra.values.data(), size_t(es),
                                                      cost.data() + gs, reduced.data() + gs, es);
    smallest[l] = std::min(sg, se);
    for (int i = 0; i < kRows; ++i)
      basic_reduced[i][l] = lane[l].full ? std::abs(reduced[size_t(lane[l].columns[i])]) : 1.0;
    bound_columns[l] = std::max(p.grid->max_abs, p.extra.max_abs);
  }
  // The double certificate (certificates.h, certify_in_double), across the lanes.
  Lanes y_norm{};
  for (int r = 0; r < kRows; ++r) y_norm += lane_abs(y[r]);
  const Lanes rounding = kGamma * (1.0 + y_norm * bound_columns);
  LaneMask ok = rounding <= 0.1 * lp::fast::kCertifyBound;
  Lanes clamped[kRows];
  for (int i = 0; i < kRows; ++i) {
    ok &= x[i] >= -1e-18;
    clamped[i] = x[i] > 0 ? x[i] : Lanes{};
  }
  Lanes bound{}, objective{};
  for (int r = 0; r < kRows; ++r) {
    Lanes residual = -rhs[r], size = lane_abs(rhs[r]);
    for (int i = 0; i < kRows; ++i) {
      const Lanes term = b[r][i] * clamped[i];
      residual += term;
      size += lane_abs(term);
    }
    const Lanes error = lane_abs(residual) + kGamma * size;
    ok &= error <= 1e-12;
    bound += lane_abs(y[r]) * error;
  }
  for (int i = 0; i < kRows; ++i) {
    bound += clamped[i] * (basic_reduced[i] + rounding);
    objective += cb[i] * clamped[i];
  }
  const Lanes dual_gap = rounding - smallest;
  bound += dual_gap > 0 ? dual_gap : Lanes{};
  ok &= bound <= lp::fast::kCertifyBound;
  for (int l = 0; l < kLanes; ++l)
    g[l] = ok[l] && lane[l].full ? objective[l] : std::numeric_limits<double>::quiet_NaN();
}

// The block's objective: 1 strictly in front of z_f, on the grid and on the extra points (the same
// for every candidate: the same points).
void block_cost(const lp::Problem& p, std::vector<double>& cost) {
  cost.resize(size_t(p.cols()));
  const auto& grid = p.grid->points;
  const int gs = p.grid_size();
  for (int j = 0; j < gs; ++j) cost[size_t(j)] = grid[size_t(j)] < p.zf ? 1.0 : 0.0;
  lp::fast::lanes::front_costs(p.extra.points.data(), p.extra.size(), p.zf, cost.data() + gs);
}

// One pricing pass over a lane's columns (hot), in ticks: the engine's lane kernel with some duals
// (any cost the same), the mean of kPasses so that the clock's own cost (~60 ns) is spread.
double time_pricing_pass(const lp::Problem& p, const std::vector<double>& cost,
                         std::vector<double>& reduced) {
  double w[kRows] = {0.5, -0.25, 0.125, -0.0625, 0.03125};
  const int gs = p.grid_size(), es = p.extra.size();
  reduced.resize(size_t(p.cols()));
  constexpr int kPasses = 8;
  const auto start = bench::TimedSolver::now();
  for (int pass = 0; pass < kPasses; ++pass) {
    double least = lp::fast::lanes::combine<kRows>(w, p.grid->values.data(), size_t(gs),
                                                   cost.data(), reduced.data(), gs);
    least += lp::fast::lanes::combine<kRows>(w, p.extra.values.data(), size_t(es), cost.data() + gs,
                                             reduced.data() + gs, es);
    benchmark::DoNotOptimize(least);
    benchmark::ClobberMemory();
  }
  return double(bench::TimedSolver::now() - start) / kPasses;
}

// What today's engine did with one LP (pass 1), for the block pass.
struct EngineAnswer {
  bench::TimedSolver::Ticks single = 0, resolve = 0;
  int pivots = 0;
  double G = 0;
  bool full = false;
  int columns[kRows] = {};
};

// Pass 1, in today's order (the sweep's: one candidate over every fragment, its grid columns in
// cache throughout): each LP warm within its run (T), then once more from its own optimal basis
// (s0). answers[c][lp], lp counting the runs' problems in order.
void engine_pass(const std::vector<const std::vector<bench::Run>*>& runs,
                 std::vector<bench::TimedSolver>& solvers,
                 std::vector<std::vector<EngineAnswer>>& answers) {
  for (int c = 0; c < kLanes; ++c) {
    bench::TimedSolver& solver = solvers[size_t(c)];
    answers[size_t(c)].clear();
    for (const bench::Run& run : *runs[size_t(c)])
      for (size_t i = 0; i < run.problems.size(); ++i) {
        EngineAnswer a;
        const lp::Solution& s = solver.solve(run.problems[i], i > 0 ? &run.positions[i] : nullptr);
        a.single = solver.last;
        a.pivots = s.iterations;
        a.G = s.status == lp::ProblemStatus::Optimal ? s.G : std::nan("");
        a.full = s.status == lp::ProblemStatus::Optimal && s.support.size() == kRows;
        for (size_t k = 0; a.full && k < kRows; ++k) a.columns[k] = s.support[k];
        solver.solve(run.problems[i], &run.positions[i]);  // the lane just remembered its optimum
        a.resolve = solver.last;
        answers[size_t(c)].push_back(a);
      }
  }
}

void BM_Block(benchmark::State& state, int grid) {
  std::vector<const std::vector<bench::Run>*> runs;
  for (const auto& functions : block_candidates()) runs.push_back(&bench::runs(functions, grid));
  using Ticks = bench::TimedSolver::Ticks;
  double single = 0, resolve = 0, batched = 0, kernel = 0;
  double lockstep = 0;     // the lockstep bound's ticks (below)
  double longest_sum = 0;  // of it, the blocks' longest lanes' work other than pricing
  double passes = 0;       // one pricing pass of every LP
  double priced = 0;       // every LP's pricing passes (one per pivot and one to prove the optimum)
  double pivoting = 0;     // the single solves of the LPs that took a pivot
  size_t without_pivot = 0;
  size_t lps = 0, pivots = 0, lanes_full = 0, lanes_certified = 0, agree = 0, not_optimal = 0;
  std::vector<bench::TimedSolver> solvers;
  for (int c = 0; c < kLanes; ++c) solvers.push_back({lp::make_backend("fast")});
  std::vector<std::vector<EngineAnswer>> answers(kLanes);
  std::vector<lp::Problem> copies(kLanes);
  std::vector<double> cost, reduced;
  for (auto _ : state) {
    single = resolve = batched = kernel = lockstep = passes = priced = pivoting = longest_sum = 0;
    without_pivot = 0;
    lps = pivots = lanes_full = lanes_certified = agree = not_optimal = 0;
    engine_pass(runs, solvers, answers);
    // Pass 2, fragment by fragment: the block kernel on every candidate's LP of the fragment.
    size_t index = 0;
    for (size_t r = 0; r < runs[0]->size(); ++r)
      for (size_t i = 0; i < (*runs[0])[r].problems.size(); ++i, ++index) {
        LaneInput lane[kLanes];
        for (int c = 0; c < kLanes; ++c) {
          const EngineAnswer& a = answers[size_t(c)][index];
          copies[size_t(c)] = (*runs[size_t(c)])[r].problems[i];
          lane[c].problem = &copies[size_t(c)];
          lane[c].full = a.full;
          std::copy(a.columns, a.columns + kRows, lane[c].columns);
          single += double(a.single), resolve += double(a.resolve);
          pivots += size_t(a.pivots);
          not_optimal += std::isnan(a.G);
          ++lps;
        }
        reduced.resize(size_t(copies[0].cols()));
        double g[kLanes];
        const Ticks start = bench::TimedSolver::now();
        block_cost(copies[0], cost);
        solve_block(lane, cost, reduced, g);
        const double spent = double(bench::TimedSolver::now() - start);
        batched += spent, kernel += spent;
        // The lockstep bound: a block whose lanes run one instruction stream costs the longest
        // lane's work other than pricing, plus every lane's pricing passes (lanes share no
        // columns), one pass before each pivot and one to prove the optimum (an estimate: the
        // engine prices the extra columns alone before some pivots).
        double longest = 0, pricing = 0;
        for (int c = 0; c < kLanes; ++c) {
          const EngineAnswer& a = answers[size_t(c)][index];
          const double pass = time_pricing_pass(copies[size_t(c)], cost, reduced);
          const double lane_pricing = pass * (1 + a.pivots);
          passes += pass, priced += lane_pricing;
          pivoting += a.pivots > 0 ? double(a.single) : 0;
          without_pivot += a.pivots == 0;
          pricing += lane_pricing;
          longest = std::max(longest, double(a.single) - lane_pricing);
          lanes_full += a.full;
          if (std::isnan(g[c])) {
            batched += double(a.resolve);  // the engine's own least cost for this lane
            continue;
          }
          ++lanes_certified;
          agree += std::abs(g[c] - a.G) <= 1e-9;
        }
        lockstep += longest + pricing;
        longest_sum += longest;
      }
    // Manual time: the engine's single solves (pass 1's share of its solving time).
    double seconds = 0;
    for (auto& solver : solvers) seconds += solver.take_seconds();
    state.SetIterationTime(seconds * single / std::max(1.0, single + resolve));
  }
  // Per LP, in the TSC's ticks (ratios only).
  const double t = single / double(lps), s0 = resolve / double(lps), b = batched / double(lps);
  state.SetItemsProcessed(int64_t(lps));
  state.counters["lps_per_pass"] = double(lps);
  state.counters["pivots"] = double(pivots) / double(lps);
  state.counters["not_optimal"] = double(not_optimal) / double(lps);
  state.counters["resolve_over_single"] = s0 / t;
  state.counters["batched_over_resolve"] = b / s0;
  state.counters["kernel_over_resolve"] = kernel / double(lps) / s0;
  state.counters["pass_over_single"] = passes / single;
  state.counters["lps_without_pivot"] = double(without_pivot) / double(lps);
  state.counters["pivoting_share"] = pivoting / single;
  state.counters["lanes_full"] = double(lanes_full) / double(lps);
  state.counters["lanes_certified"] = double(lanes_certified) / double(lps);
  state.counters["batched_agree"] = double(agree) / double(std::max<size_t>(1, lanes_certified));
  state.counters["ceiling"] = t / (b + t - s0);
  state.counters["ceiling_free_common_path"] = t / (t - s0);
  state.counters["ceiling_lockstep"] = single / lockstep;
  // The kernel's measured gain on what is not pricing, where it has no divergence at all (the
  // common path: the engine's s0 less a pass, against the kernel's time less a pass), applied to
  // all of each LP's work that is not pricing: the lockstep bound at the efficiency SIMD across
  // candidates reached in practice, still with no cost for divergence.
  const double pass = passes / double(lps), pricing = priced / double(lps);
  const double gain = (s0 - pass) / std::max(1e-9, kernel / double(lps) - pass);
  state.counters["kernel_gain_beyond_pricing"] = gain;
  state.counters["ceiling_at_kernel_gain"] = t / (pricing + (t - pricing) / gain);
  // The lockstep bound with an instruction stream for kLanes lanes costing kLanes / gain times a
  // lane's scalar one (the lockstep bound takes gain = kLanes): divergence and the measured
  // efficiency together.
  state.counters["ceiling_lockstep_at_kernel_gain"] =
      single / (priced + longest_sum * kLanes / gain);
}
BENCHMARK_CAPTURE(BM_Block, grid256, 256)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Block, grid1024, 1024)->UseManualTime()->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace mb

BENCHMARK_MAIN();
