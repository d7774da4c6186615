#pragma once
// The LPs the sweep solves, for the benchmarks that time the engine on them (lp_bench,
// batch_bench): the default dataset's views (the tiny one without data/), and runs of consecutive
// fragments as a warm-start band orders them (docs/reference.md §3: z_f - delta_f, skipping the
// fragments with F_Z(z_f - delta_f) = 0).
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#ifdef __x86_64__
#include <x86intrin.h>
#endif

#include "eval/evaluation.h"
#include "eval/warm_runs.h"
#include "lp/problem.h"
#include "lp/solution.h"
#include "run_fragments.h"

namespace mb::bench {

inline const std::vector<ViewData>& views() {
  static std::vector<ViewData> v = [] {
    bool have_data =
        std::filesystem::exists(std::string(MOMENTBENCH_SOURCE_DIR) + "/data/buildings.obj");
    EvalSettings settings;
    settings.threads = 2;
    return prepare_views(load_dataset(have_data ? "default" : "tiny"), 0, settings, true);
  }();
  return v;
}

// The fragments of the runs as the sweep solves them: the fragments of a warm-start band
// (kWarmRunRows texel rows) in fragment order, the LP ones among them, within a window of
// kRunColumns columns so that a pass stays short; three windows at evenly spaced places of every
// view. The same fragments for every basis.
inline const FragmentRuns& fragment_runs() {
  static const FragmentRuns out = [] {
    FragmentRuns runs;
    GaussianKernel kernel = make_gaussian_kernel(9, 2.4);
    constexpr int kRunsPerView = 3, kRunColumns = 48;
    for (const auto& v : views()) {
      const int bands = v.map.height / kWarmRunRows;
      for (int r = 0; r < kRunsPerView && bands > 0; ++r) {
        std::vector<RunFragment> run;
        const int band = bands * (2 * r + 1) / (2 * kRunsPerView);
        const int x0 =
            std::max(0, v.map.width * (2 * r + 1) / (2 * kRunsPerView) - kRunColumns / 2);
        for (size_t k = 0; k < v.fragments.size(); ++k) {
          const size_t t = v.fragments.texel[k];
          const int x = int(t % v.map.width), y = int(t / v.map.width);
          if (warm_run_of(t, v.map.width) != band || x < x0 || x >= x0 + kRunColumns) continue;
          if (v.fragments.oracle[k] == 0) continue;
          RunFragment f{v.fragments.layer[k],   x, y, v.fragments.ztest[k], std::vector<double>(81),
                        std::vector<double>(81)};
          kernel_distribution(v.map, kernel, x, y, f.depths, f.weights);
          run.push_back(std::move(f));
        }
        runs.push_back(std::move(run));
      }
    }
    return runs;
  }();
  return out;
}

// The runs' LPs for one basis: run r's i-th problem is one fragment whatever `functions` are.
inline const std::vector<Run>& runs(const std::vector<std::string>& functions, int grid) {
  static std::map<std::pair<std::vector<std::string>, int>, std::vector<Run>> cache;
  auto& out = cache[{functions, grid}];
  if (out.empty()) out = build_runs(fragment_runs(), functions, grid);
  return out;
}

// The sweep builds each problem into one reused Problem right before solving it, so its columns are
// in cache when the solver reads them; read from the bench's ~55 MB of stored problems instead,
// they were not, and the misses were ~25 % of our solver's time (~0.3 % of GLPK's). So each LP is
// copied into one reused Problem first, as the sweep's factory would write it, and only the solve
// is timed (manual time around solve_into, the same for both backends).
// The clock: two steady_clock reads cost ~110 ns on this VM (~5 % of one of our LPs, 0.1 % of
// GLPK's), two TSC reads ~60 ns; so on x86 the solves are timed in TSC ticks, converted to seconds
// by the ratio of steady_clock to TSC over the whole pass (no assumption on the TSC's rate).
// The TSC reads are fenced (mfence, lfence): unfenced, the read before a solve executed while the
// copy's stores were still in flight, and ~5 % of our solver's measured time was the copy's
// (session 18: fencing raised our rate 1.04-1.05x and GLPK's 1.01x, 4 paired runs).
struct TimedSolver {
  std::unique_ptr<lp::Backend> backend;
  lp::Problem problem;  // the in-cache copy
  lp::Solution solution;
#ifdef __x86_64__
  using Ticks = unsigned long long;
  static Ticks now() {
    _mm_mfence();
    _mm_lfence();
    const Ticks t = __rdtsc();
    _mm_lfence();
    return t;
  }
#else
  using Ticks = std::chrono::steady_clock::rep;
  static Ticks now() {
    return std::chrono::steady_clock::now().time_since_epoch().count();
  }
#endif
  Ticks solving = 0;
  Ticks pass_ticks = now();
  std::chrono::steady_clock::time_point pass_start = std::chrono::steady_clock::now();
  Ticks last = 0;  // the last solve's ticks
  const lp::Solution& solve(const lp::Problem& stored, const lp::WarmStart* at) {
    problem = stored;
    const Ticks start = now();
    backend->solve_into(problem, at, solution);
    last = now() - start;
    solving += last;
    return solution;
  }
  // The solving time since the last call, for State::SetIterationTime.
  double take_seconds() {
    const Ticks ticks = now();
    const auto clock = std::chrono::steady_clock::now();
    const double seconds_per_tick =
        std::chrono::duration<double>(clock - pass_start).count() / double(ticks - pass_ticks);
    const double seconds = double(solving) * seconds_per_tick;
    solving = 0, pass_ticks = ticks, pass_start = clock;
    return seconds;
  }
};

}  // namespace mb::bench
