// LP throughput on real fragments (issue 4): identical Problem 1 instances from the default
// dataset's receivers (F_Z(z_f - delta) > 0), solved by our backend and by GLPK in one run; power
// and trigonometric bases, grids of 256 and 1024 points. The ratio of the two items_per_second is
// the speed-up. BM_SolveRuns: runs of consecutive fragments as the sweep solves them (ours warm
// along each run, and cold for comparison); BM_Solve: fragments sampled with a stride, each from
// scratch. Falls back to the tiny dataset without data/.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <utility>

#ifdef __AVX2__
#include "util/simd_intrinsics.h"
#endif

#include "bench_runs.h"

namespace mb {
namespace {

using bench::Run;
using bench::TimedSolver;
using bench::views;
const std::vector<Run>& runs(const std::string& basis, int grid) {
  return bench::runs({basis}, grid);
}

constexpr int kInstances = 1500;

const std::vector<lp::Problem>& problems(const std::string& basis_name, int grid) {
  static std::map<std::pair<std::string, int>, std::vector<lp::Problem>> cache;
  auto& out = cache[{basis_name, grid}];
  if (!out.empty()) return out;
  lp::ProblemFactory factory(Basis::parse({basis_name}), lp::Discretization{0, 1, grid, false});
  GaussianKernel kernel = make_gaussian_kernel(9, 2.4);
  std::vector<double> depths(81), weights(81);
  size_t total = 0;
  for (const auto& v : views()) total += v.fragments.size();
  const size_t stride = std::max<size_t>(1, total / (8 * kInstances));
  size_t index = 0;
  for (const auto& v : views())
    for (size_t k = 0; k < v.fragments.size() && int(out.size()) < kInstances; ++k, ++index) {
      if (index % stride) continue;
      const size_t t = v.fragments.texel[k];
      const int x = int(t % v.map.width), y = int(t / v.map.width);
      // The LPs the sweep solves (docs/reference.md §3): at z_f - delta_f, where F_Z of it is not
      // 0.
      const double zf = v.fragments.ztest[k];
      if (v.fragments.oracle[k] == 0) continue;  // skipped exactly in eval and sweep
      kernel_distribution(v.map, kernel, x, y, depths, weights);
      out.push_back(factory.from_distribution(depths, weights, zf));
    }
  return out;
}

// `warm`: solve_next within a run (what the sweep does); otherwise every LP from scratch.
void BM_SolveRuns(benchmark::State& state, const std::string& backend, const std::string& basis,
                  int grid, bool warm) {
  const auto& list = runs(basis, grid);
  TimedSolver solver{lp::make_backend(backend)};
  size_t unstable = 0, iterations = 0, solved = 0;
  uint64_t answers =
      0;  // a hash of every G's bits in the last pass: equal across builds = the same answers
  // Each LP's ticks and pivots in the last pass: where the time goes (the tail_share counters).
  std::vector<std::pair<double, int>> costs;
  double pass_sum = 0;  // sum of G in the last pass (builds that differ by rounding compare this)
  for (auto _ : state) {
    answers = 0;
    pass_sum = 0;
    costs.clear();
    for (const auto& run : list)
      for (size_t i = 0; i < run.problems.size(); ++i) {
        const lp::Solution& s =
            solver.solve(run.problems[i], warm && i > 0 ? &run.positions[i] : nullptr);
        costs.emplace_back(double(solver.last), s.iterations);
        unstable += s.status != lp::ProblemStatus::Optimal;
        iterations += s.iterations;
        pass_sum += s.G;
        answers = answers * 1099511628211ull ^ std::bit_cast<uint64_t>(s.G);
        ++solved;
      }
    state.SetIterationTime(solver.take_seconds());
  }
  benchmark::DoNotOptimize(pass_sum);
  state.SetItemsProcessed(int64_t(solved));
  state.counters["pivots"] = double(iterations) / double(solved);
  state.counters["not_optimal"] = double(unstable) / double(solved);
  state.counters["lps_per_pass"] = double(solved) / double(state.iterations());
  state.counters["g_sum"] = pass_sum;
  state.counters["answers"] =
      double(answers >> 12);  // exact in a double (52 bits); compare with --benchmark_format=json
  // The share of the last pass's solve time in its slowest 5 % of LPs, and in the LPs that took
  // 8 pivots or more (warm starts that needed the composite repair, and the runs' cold starts).
  double total = 0, many_pivots = 0;
  for (const auto& [ticks, pivots] : costs) total += ticks, many_pivots += pivots >= 8 ? ticks : 0;
  std::sort(costs.begin(), costs.end(), std::greater<>());
  double slowest = 0;
  for (size_t i = 0; i < costs.size() / 20; ++i) slowest += costs[i].first;
  state.counters["tail_share_slowest_5pct"] = total > 0 ? slowest / total : 0;
  state.counters["tail_share_8_pivots"] = total > 0 ? many_pivots / total : 0;
}

BENCHMARK_CAPTURE(BM_SolveRuns, fast_warm_power4_256, "fast", "power4", 256, true)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SolveRuns, fast_cold_power4_256, "fast", "power4", 256, false)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SolveRuns, glpk_power4_256, "glpk", "power4", 256, false)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SolveRuns, fast_warm_trig4_256, "fast", "trig4", 256, true)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SolveRuns, fast_cold_trig4_256, "fast", "trig4", 256, false)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SolveRuns, glpk_trig4_256, "glpk", "trig4", 256, false)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SolveRuns, fast_warm_power4_1024, "fast", "power4", 1024, true)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SolveRuns, glpk_power4_1024, "glpk", "power4", 1024, false)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SolveRuns, fast_warm_trig4_1024, "fast", "trig4", 1024, true)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SolveRuns, glpk_trig4_1024, "glpk", "trig4", 1024, false)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

// What issue 5's budget leaves (8 hours on 2 cores for 66045 candidates x 2.42 M LPs is ~880
// cycles of one core an LP, building included), measured on the same runs: BM_FloorPricing is one
// dual feasibility pass over every column of each LP at its optimal duals, in double, vectorised,
// without any simplex bookkeeping -- what a method that prices columns (every simplex) needs once
// per LP to prove the optimum, and once more per pivot; BM_FloorMoments is the least part of
// building one: the kernel's moment vector from its taps' (precomputed) columns, sum_t w_t a(z_t).
// Both with their data in cache, as in the sweep, where a fragment's columns were just written
// (passes repeated per LP; the first pass from memory would measure the bench's 40 MB of problems).
// Cycles an LP = TSC rate / items_per_second.
constexpr int kHotPasses = 32;
struct FloorInstance {
  std::vector<double> costs, duals;  // c_j for every column; the optimal y
  const lp::Problem* problem;
};
const std::vector<FloorInstance>& floor_instances(const std::string& basis, int grid) {
  static std::map<std::pair<std::string, int>, std::vector<FloorInstance>> cache;
  auto& out = cache[{basis, grid}];
  if (!out.empty()) return out;
  auto solver = lp::make_backend("fast");
  for (const auto& run : runs(basis, grid))
    for (size_t i = 0; i < run.problems.size(); ++i) {
      const lp::Problem& p = run.problems[i];
      lp::Solution s = i > 0 ? solver->solve_next(p, run.positions[i]) : solver->solve(p);
      if (s.status != lp::ProblemStatus::Optimal) continue;
      FloorInstance f{{}, {s.duals.begin(), s.duals.end()}, &p};
      for (int j = 0; j < p.cols(); ++j) f.costs.push_back(p.cost(j));
      out.push_back(std::move(f));
    }
  return out;
}

// min_j (c_j - y.a_j) over one column block, rows fixed at compile time (5: four functions), eight
// columns a step in two independent accumulators (a single running minimum is a dependency chain).
template <int K>
double least_reduced_cost(const double* y, const double* values, const double* costs, int n) {
  double lane[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  int j = 0;
#ifdef __AVX2__
  __m256d weight[K];
  for (int r = 0; r < K; ++r) weight[r] = _mm256_set1_pd(y[r]);
  __m256d low = _mm256_setzero_pd(), high = _mm256_setzero_pd();
  for (; j + 8 <= n; j += 8) {
    __m256d a = _mm256_loadu_pd(costs + j), b = _mm256_loadu_pd(costs + j + 4);
    for (int r = 0; r < K; ++r) {
      a = _mm256_fnmadd_pd(weight[r], _mm256_loadu_pd(values + size_t(r) * n + j), a);
      b = _mm256_fnmadd_pd(weight[r], _mm256_loadu_pd(values + size_t(r) * n + j + 4), b);
    }
    low = _mm256_min_pd(low, a);
    high = _mm256_min_pd(high, b);
  }
  _mm256_storeu_pd(lane, low);
  _mm256_storeu_pd(lane + 4, high);
#endif
  double least = 0;
  for (; j < n; ++j) {
    double d = costs[j];
    for (int r = 0; r < K; ++r) d -= y[r] * values[size_t(r) * n + j];
    least = std::min(least, d);
  }
  for (double v : lane) least = std::min(least, v);
  return least;
}

void BM_FloorPricing(benchmark::State& state, const std::string& basis, int grid) {
  const auto& list = floor_instances(basis, grid);
  double worst = 0;
  for (auto _ : state)
    for (const auto& f : list) {
      const lp::Problem& p = *f.problem;
      const int g = p.grid_size();
      for (int pass = 0; pass < kHotPasses; ++pass) {
        worst = std::min(
            worst, least_reduced_cost<5>(f.duals.data(), p.grid->values.data(), f.costs.data(), g));
        worst = std::min(worst, least_reduced_cost<5>(f.duals.data(), p.extra.values.data(),
                                                      f.costs.data() + g, p.extra.size()));
        benchmark::DoNotOptimize(worst);
        benchmark::ClobberMemory();
      }
    }
  state.SetItemsProcessed(int64_t(state.iterations() * list.size() * kHotPasses));
  state.counters["columns"] = double(list.empty() ? 0 : list.front().costs.size());
}
BENCHMARK_CAPTURE(BM_FloorPricing, power4_256, "power4", 256)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_FloorPricing, trig4_256, "trig4", 256)->Unit(benchmark::kMicrosecond);

void BM_FloorMoments(benchmark::State& state) {
  // The power4 taps of every LP of the runs: their columns T(1, b(z_t)) and weights, 81 a kernel.
  lp::ProblemFactory factory(Basis::parse({"power4"}), lp::Discretization{0, 1, 256, false});
  GaussianKernel kernel = make_gaussian_kernel(9, 2.4);
  const int taps = kernel.size * kernel.size;
  std::vector<double> depths(taps), weights(taps), columns, all_weights;
  size_t lps = 0;
  for (const auto& v : views())
    for (size_t k = 0; k < v.fragments.size() && lps < 20000; k += 97) {
      const size_t t = v.fragments.texel[k];
      kernel_distribution(v.map, kernel, int(t % v.map.width), int(t / v.map.width), depths,
                          weights);
      for (int n = 0; n < taps; ++n) {
        columns.resize(columns.size() + 5);
        factory.column(depths[n], &columns[columns.size() - 5]);
        all_weights.push_back(weights[n]);
      }
      ++lps;
    }
  double checksum = 0;
  for (auto _ : state)
    for (size_t l = 0; l < lps; ++l)
      for (int pass = 0; pass < kHotPasses; ++pass) {
        double sum[5] = {};
        const double* c = &columns[l * taps * 5];
        const double* w = &all_weights[l * taps];
        for (int n = 0; n < taps; ++n)
          for (int r = 0; r < 5; ++r) sum[r] += w[n] * c[n * 5 + r];
        checksum += sum[0] + sum[4];
        benchmark::DoNotOptimize(checksum);
        benchmark::ClobberMemory();
      }
  state.SetItemsProcessed(int64_t(state.iterations() * lps * kHotPasses));
}
BENCHMARK(BM_FloorMoments)->Unit(benchmark::kMicrosecond);

void BM_Solve(benchmark::State& state, const std::string& backend, const std::string& basis,
              int grid) {
  const auto& list = problems(basis, grid);
  TimedSolver solver{lp::make_backend(backend)};
  size_t unstable = 0, iterations = 0, solved = 0;
  for (auto _ : state) {
    for (const auto& p : list) {
      const lp::Solution& s = solver.solve(p, nullptr);
      unstable += s.status != lp::ProblemStatus::Optimal;
      iterations += s.iterations;
      benchmark::DoNotOptimize(s.G);
    }
    solved += list.size();
    state.SetIterationTime(solver.take_seconds());
  }
  state.SetItemsProcessed(int64_t(solved));
  state.counters["pivots"] = double(iterations) / double(solved);
  state.counters["not_optimal"] = double(unstable) / double(solved);
}

BENCHMARK_CAPTURE(BM_Solve, fast_power4_256, "fast", "power4", 256)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Solve, glpk_power4_256, "glpk", "power4", 256)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Solve, fast_trig4_256, "fast", "trig4", 256)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Solve, glpk_trig4_256, "glpk", "trig4", 256)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Solve, fast_power4_1024, "fast", "power4", 1024)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Solve, glpk_power4_1024, "glpk", "power4", 1024)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Solve, fast_trig4_1024, "fast", "trig4", 1024)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Solve, glpk_trig4_1024, "glpk", "trig4", 1024)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace mb

BENCHMARK_MAIN();
