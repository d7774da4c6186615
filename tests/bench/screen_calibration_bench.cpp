// Calibration of the screen's standard error (issue 45 item 5; docs/sweeps.md): seeded candidates
// are evaluated exactly once, with G per fragment, so every unit's exact error sum is known; then
// for each of several sample seeds the estimate of every candidate is formed from its sampled units
// (sampled_unit_errors: the same numbers a screened unit gives, to the LP's tolerance) and its miss
// from the exact mean is measured in standard errors. A calibrated standard error gives misses of
// root mean square near 1 and none far beyond 3.
//
//   screen_calibration_bench DATASET RESOLUTION CANDIDATES SEEDS FRACTION [UNITS.csv [ROWS.bin]]
//
// prints, per fraction, the rms of the misses in SE, the largest, and how many exceed 3 and 4;
// with UNITS.csv also writes every unit's exact error sum per candidate (candidate 0 the pilot),
// for trying other estimators offline; with ROWS.bin also the error sums of every one-row segment
// of kScreenUnitColumns texels with LP fragments, as float64 (a header row of segment keys
// view * 2^32 + row * 2^16 + column block, then one row per candidate, the pilot first), for
// trying other unit shapes.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "eval/evaluation.h"
#include "screen/screening.h"
#include "sweep/candidate_evaluation.h"
#include "sweep/sweep_plan.h"

namespace mb {
namespace {

int run(int argc, char** argv) {
  if (argc < 6) {
    std::fprintf(stderr, "usage: %s DATASET RESOLUTION CANDIDATES SEEDS FRACTION [UNITS.csv]\n",
                 argv[0]);
    return 2;
  }
  const std::string dataset = argv[1];
  const int resolution = std::atoi(argv[2]);
  const uint64_t count = std::strtoull(argv[3], nullptr, 10);
  const int seeds = std::atoi(argv[4]);
  const double fraction = std::atof(argv[5]);
  EvalSettings settings;
  settings.threads = 2;
  settings.technique.lp.grid = 256;
  const std::vector<ViewData> views =
      prepare_views(load_dataset(dataset), resolution, settings, true);
  const CandidateEvaluator evaluator(views, settings);
  std::vector<std::vector<double>> pilot;
  evaluator.evaluate(Basis::parse({"z", "z^2", "z^3", "z^4"}), &pilot);
  const ScreenSample every = make_screen_sample(views, evaluator.lp_lists(), pilot, 1.0, 1);

  std::ofstream units;
  if (argc > 6) {
    units.open(argv[6]);
    units << "# fixed_error " << every.fixed_error << " weight " << every.weight << "\n";
    units << "candidate,view,unit,lps,error\n";
    units.precision(17);
  }
  auto dump = [&](size_t candidate, const std::vector<double>& errors) {
    if (!units.is_open()) return;
    size_t at = 0;
    for (size_t v = 0; v < every.strata.size(); ++v) {
      const ScreenStratum& s = every.strata[v];
      for (size_t r = 0; r < s.sampled(); ++r, ++at)
        units << candidate << ',' << v << ',' << r << ',' << s.run_begin[r + 1] - s.run_begin[r]
              << ',' << errors[at] << '\n';
    }
  };
  dump(0, sampled_unit_errors(every, views, pilot));
  // One-row segments: keys once, then each candidate's sums in key order.
  std::vector<std::vector<uint64_t>> segment_of(views.size());
  std::vector<uint64_t> keys;
  for (size_t v = 0; v < views.size(); ++v) {
    const int width = views[v].map.width;
    for (uint32_t f : evaluator.lp_lists()[v]) {
      const uint64_t t = views[v].fragments.texel[f];
      segment_of[v].push_back((uint64_t(v) << 32) | ((t / uint64_t(width)) << 16) |
                              (t % uint64_t(width)) / kScreenUnitColumns);
      keys.push_back(segment_of[v].back());
    }
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  std::ofstream rows;
  if (argc > 7) {
    rows.open(argv[7], std::ios::binary);
    const uint64_t n = keys.size();
    rows.write(reinterpret_cast<const char*>(&n), sizeof n);
    rows.write(reinterpret_cast<const char*>(keys.data()), std::streamsize(n * sizeof n));
  }
  auto dump_rows = [&](const std::vector<std::vector<double>>& shadow) {
    if (!rows.is_open()) return;
    std::vector<double> sums(keys.size(), 0.0);
    for (size_t v = 0; v < views.size(); ++v)
      for (size_t i = 0; i < segment_of[v].size(); ++i) {
        const uint32_t f = evaluator.lp_lists()[v][i];
        const size_t at =
            size_t(std::lower_bound(keys.begin(), keys.end(), segment_of[v][i]) - keys.begin());
        sums[at] += std::abs(views[v].fragments.pcf[f] - shadow[v][f]);
      }
    rows.write(reinterpret_cast<const char*>(sums.data()),
               std::streamsize(sums.size() * sizeof(double)));
  };
  dump_rows(pilot);

  const SweepPlan plan = make_sweep_plan({}, 4, {}, count, 45);
  std::vector<ScreenSample> samples;
  for (int seed = 1; seed <= seeds; ++seed)
    samples.push_back(
        make_screen_sample(views, evaluator.lp_lists(), pilot, fraction, uint64_t(seed)));
  double squares = 0, largest = 0;
  size_t misses = 0, beyond3 = 0, beyond4 = 0;
  for (size_t c = 0; c < plan.ids.size(); ++c) {
    std::vector<std::vector<double>> shadow;
    const double exact =
        evaluator.evaluate(Basis::parse(plan.functions(plan.ids[c])), &shadow).overall.mean();
    dump(c + 1, sampled_unit_errors(every, views, shadow));
    dump_rows(shadow);
    for (const ScreenSample& sample : samples) {
      const ScreenEstimate e =
          estimate_mean_error(sample, sampled_unit_errors(sample, views, shadow));
      if (!(e.se > 0)) continue;
      const double z = (e.mean - exact) / e.se;
      squares += z * z;
      largest = std::max(largest, std::abs(z));
      beyond3 += std::abs(z) > 3;
      beyond4 += std::abs(z) > 4;
      ++misses;
    }
    if ((c + 1) % 20 == 0) std::fprintf(stderr, "%zu candidates\n", c + 1);
  }
  std::printf(
      "%s at %d, F = %g: %zu candidates x %d seeds: rms %.3f SE, largest %.2f, "
      "beyond 3: %zu, beyond 4: %zu of %zu\n",
      dataset.c_str(), resolution, fraction, plan.ids.size(), seeds,
      std::sqrt(squares / double(std::max<size_t>(misses, 1))), largest, beyond3, beyond4, misses);
  return 0;
}

}  // namespace
}  // namespace mb

int main(int argc, char** argv) {
  return mb::run(argc, argv);
}
