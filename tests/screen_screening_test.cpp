// Screening (screen/screening.h, issue 33): the estimate against the exact evaluation of the same
// candidates on the same views. A sample of every run is the exact mean; a sampled run's error
// sum is the full evaluation's, bit for bit; the estimates' standard errors cover their misses;
// and on a few hundred candidates the confirmation keeps the exact best K.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>

#include "eval/evaluation.h"
#include "eval/warm_runs.h"
#include "screen/screening.h"
#include "screen_synthetic_sample.h"
#include "sweep/candidate_evaluation.h"
#include "sweep/sweep_plan.h"

namespace mb {
namespace {

struct Fixture {
  EvalSettings settings;
  std::vector<ViewData> views;
  std::unique_ptr<CandidateEvaluator> evaluator;
  std::vector<std::vector<double>> pilot;  // G of z; z^2; z^3; z^4, per view
  Fixture() {
    settings.threads = 2;
    settings.technique.lp.grid = 64;
    // The tiny dataset at 256^2: 41 warm-start runs, enough to sample.
    views = prepare_views(load_dataset("tiny"), 256, settings, true);
    evaluator = std::make_unique<CandidateEvaluator>(views, settings);
    evaluator->evaluate(Basis::parse({"z", "z^2", "z^3", "z^4"}), &pilot);
  }
  ScreenSample sample(double fraction, uint64_t seed = 1) const {
    return make_screen_sample(views, evaluator->lp_lists(), pilot, fraction, seed);
  }
};

const Fixture& fixture() {
  static const Fixture f;
  return f;
}

// The estimator by hand: a stratum of 4 units with 2 sampled (pilot 2 and 3 of a total 10), and a
// stratum sampled whole (1 unit), 5 of error outside the LPs, 100 fragments.
TEST(Screening, EstimateAndStandardErrorByHand) {
  ScreenSample sample;
  sample.fixed_error = 5;
  sample.weight = 100;
  ScreenStratum part;
  part.runs = 4;
  part.run_begin = {0, 1, 2};
  part.pilot_total = 10;
  part.pilot = {2, 3};
  ScreenStratum whole;
  whole.runs = 1;
  whole.run_begin = {0, 1};
  sample.strata = {part, whole};
  // Total 5 + 10 + 4 x mean(0.5, 1.0) + 7 = 25. The variance: z = 2 x (4 / 2) x (0.5, 1.0) =
  // (2, 4), s_z^2 = 2, times (1 - 2 / 4) / 2 = 0.5; the whole stratum adds none.
  const ScreenEstimate e = estimate_mean_error(sample, {2.5, 4.0, 7.0});
  EXPECT_DOUBLE_EQ(e.mean, 0.25);
  EXPECT_DOUBLE_EQ(e.se, std::sqrt(0.5) / 100);
  // A difference of candidates: (2.5, 4, 7) - (2, 3, 1) = (0.5, 1, 6), the same variance.
  EXPECT_DOUBLE_EQ(paired_standard_error(sample, {2.5, 4.0, 7.0}, {2.0, 3.0, 1.0}),
                   std::sqrt(0.5) / 100);
}

TEST(Screening, EveryRunSampledIsTheExactMean) {
  const Fixture& f = fixture();
  const ScreenSample all = f.sample(1.0);
  EXPECT_EQ(all.sampled_runs(), all.runs());
  EXPECT_EQ(all.sampled_lps(), f.evaluator->lp_fragments());
  const Basis basis = Basis::parse({"z", "exp(z)", "cos(pi z)", "1/(1+z)"});
  const CandidateResult exact = f.evaluator->evaluate(basis);
  const ScreenEstimate estimate = estimate_mean_error(all, f.evaluator->screen(basis, all));
  EXPECT_NEAR(estimate.mean, exact.overall.mean(), 1e-13 * exact.overall.mean());
  EXPECT_EQ(estimate.se, 0.0);
}

TEST(Screening, SampledUnitsAgreeWithTheFullEvaluation) {
  const Fixture& f = fixture();
  const ScreenSample sample = f.sample(0.25);
  ASSERT_GT(sample.runs(), 30u);
  ASSERT_LT(sample.sampled_runs(), sample.runs() / 2);
  const Basis basis = Basis::parse({"z^2", "exp(-2z)", "sin(pi z)", "log(1+z)"});
  std::vector<std::vector<double>> shadow;
  f.evaluator->evaluate(basis, &shadow);
  const std::vector<double> screened = f.evaluator->screen(basis, sample);
  size_t at = 0;
  double largest = 0;
  for (size_t v = 0; v < f.views.size(); ++v) {
    const ScreenStratum& s = sample.strata[v];
    for (size_t r = 0; r < s.sampled(); ++r, ++at) {
      ErrorStats run;
      for (size_t i = s.run_begin[r]; i < s.run_begin[r + 1]; ++i)
        run.add(f.views[v].fragments.pcf[s.list[i]], shadow[v][s.list[i]]);
      // A unit is its own warm-start run when screened: other starts, the same optima.
      EXPECT_NEAR(screened[at], run.sum_abs, 1e-9 * double(s.run_begin[r + 1] - s.run_begin[r]))
          << "view " << v << " unit " << r;
      largest = std::max(largest, std::abs(screened[at] - run.sum_abs));
    }
  }
  EXPECT_EQ(at, screened.size());
  std::printf("largest difference of a unit's error sum: %.3g\n", largest);
  // The pilot's estimate is its exact mean: its differences from itself are zero.
  double pilot_total = sample.fixed_error;
  for (const auto& s : sample.strata) pilot_total += s.pilot_total;
  std::vector<double> pilot_runs;
  for (const auto& s : sample.strata)
    pilot_runs.insert(pilot_runs.end(), s.pilot.begin(), s.pilot.end());
  const ScreenEstimate pilot = estimate_mean_error(sample, pilot_runs);
  EXPECT_NEAR(pilot.mean, pilot_total / sample.weight, 1e-15);
  EXPECT_EQ(pilot.se, 0.0);
}

// The standard error is calibrated (docs/sweeps.md, "Calibration"): over 200 candidates and 10
// seeds of the sample, the estimates miss their exact means by z standard errors with z of root
// mean square between 0.8 and 1.2, and by little more than 4 at worst. An SE off by a factor (a
// dropped n or R) breaks the first; units that let a few clusters of hard fragments hold most of
// the variance (blocks of 8 rows: up to 13 SE on the default dataset) break the second. The tiny
// dataset at 256^2 has 1 476 units, so even half of them (739) is fewer than a real screen's
// ~2 000, and its tail is a little heavier: 4.34 at worst here (exp(8z) candidates), where the
// default dataset at F = 0.05 and 0.25 stays within 4 (tests/bench/screen_calibration_bench).
TEST(Screening, StandardErrorsAreCalibratedOverCandidatesAndSeeds) {
  const Fixture& f = fixture();
  const SweepPlan plan = make_sweep_plan({}, 4, {}, 200, 45);
  std::vector<ScreenSample> samples;
  for (uint64_t seed = 1; seed <= 10; ++seed) samples.push_back(f.sample(0.5, seed));
  double squares = 0, largest = 0;
  int count = 0, beyond3 = 0;
  for (uint64_t id : plan.ids) {
    std::vector<std::vector<double>> shadow;
    const double exact =
        f.evaluator->evaluate(Basis::parse(plan.functions(id)), &shadow).overall.mean();
    for (const ScreenSample& sample : samples) {
      // From the full evaluation: a sampled unit's answers are its optima.
      const ScreenEstimate e =
          estimate_mean_error(sample, sampled_unit_errors(sample, f.views, shadow));
      ASSERT_GT(e.se, 0.0) << plan.name(id);
      const double z = (e.mean - exact) / e.se;
      squares += z * z;
      largest = std::max(largest, std::abs(z));
      beyond3 += std::abs(z) > 3;
      ++count;
    }
  }
  const double rms = std::sqrt(squares / count);
  std::printf("screen calibration: %d estimates, rms %.3f SE, largest %.2f, beyond 3: %d\n", count,
              rms, largest, beyond3);
  EXPECT_GT(rms, 0.8) << "standard errors too wide";
  EXPECT_LT(rms, 1.2) << "standard errors too narrow";
  EXPECT_LE(largest, 4.5);
}

// A few hundred seeded candidates, every one exactly and screened on a quarter of the runs.
TEST(Screening, ScreenedTopKIsTheExactTopK) {
  const Fixture& f = fixture();
  const SweepPlan plan = make_sweep_plan({}, 4, {}, 240, 33);
  const ScreenSample sample = f.sample(0.25, 7);
  std::vector<double> exact;
  std::vector<std::vector<double>> runs;
  std::vector<ScreenEstimate> estimates;
  for (uint64_t id : plan.ids) {
    const Basis basis = Basis::parse(plan.functions(id));
    exact.push_back(f.evaluator->evaluate(basis).overall.mean());
    runs.push_back(f.evaluator->screen(basis, sample));
    estimates.push_back(estimate_mean_error(sample, runs.back()));
  }
  const size_t n = exact.size();
  // The sweep's second stage (screen.refine): the candidates in reach again on a larger sample,
  // screened when first confirmed (as the sweep does: those left out are never refined).
  const ScreenSample refine = f.sample(0.6, 8);
  std::vector<std::vector<double>> refined(n);
  auto refined_runs = [&](size_t c) -> const std::vector<double>& {
    if (refined[c].empty())
      refined[c] = f.evaluator->screen(Basis::parse(plan.functions(plan.ids[c])), refine);
    return refined[c];
  };
  auto top_of = [&](std::vector<size_t> candidates, int top) {  // by exact mean
    std::stable_sort(candidates.begin(), candidates.end(),
                     [&](size_t a, size_t b) { return exact[a] < exact[b]; });
    candidates.resize(std::min(candidates.size(), size_t(top)));
    return candidates;
  };
  std::vector<size_t> all(n);
  std::iota(all.begin(), all.end(), size_t(0));
  for (int top : {5, 10, 20}) {
    ScreenRule rule;
    rule.top = top;
    const std::vector<size_t> confirmed = candidates_to_confirm(sample, runs, rule);
    EXPECT_LT(confirmed.size(), n) << "top " << top << ": the screen kept every candidate";
    const std::vector<size_t> exact_top = top_of(all, top);
    EXPECT_EQ(top_of(confirmed, top), exact_top)
        << "top " << top << " (" << confirmed.size() << " confirmed)";
    std::vector<std::vector<double>> second;
    for (size_t c : confirmed) second.push_back(refined_runs(c));
    std::vector<size_t> twice;
    for (size_t i : candidates_to_confirm(refine, second, rule)) twice.push_back(confirmed[i]);
    EXPECT_LT(twice.size(), confirmed.size()) << "top " << top << ": the refining stage kept all";
    EXPECT_EQ(top_of(twice, top), exact_top)
        << "top " << top << " after refining (" << twice.size() << " confirmed)";

    // Ties below 0.01 pp (margin -1e-4): fewer confirmed, and no candidate left out beats the
    // K-th best confirmed one by more than the margin.
    rule.margin = -1e-4;
    const std::vector<size_t> tied = candidates_to_confirm(sample, runs, rule);
    EXPECT_LT(tied.size(), confirmed.size()) << "top " << top;
    std::vector<size_t> kept = tied;
    std::stable_sort(kept.begin(), kept.end(),
                     [&](size_t a, size_t b) { return exact[a] < exact[b]; });
    ASSERT_GE(kept.size(), size_t(top));
    const double kth = exact[kept[size_t(top) - 1]];
    for (size_t c = 0; c < n; ++c)
      if (!std::binary_search(tied.begin(), tied.end(), c)) {
        EXPECT_GE(exact[c], kth - 1e-4) << "top " << top << ": left out " << plan.name(plan.ids[c]);
      }
  }
}

// Full scale (docs/sweeps.md, "Full scale"): two shards keep the unit errors only of the
// candidates near their own K-th best; of the others, those the sweep's K-th best proves out of
// reach are truly out of reach (est_c - est_r' - sigmas SE(c - r') > margin, checked directly),
// and with the rest screened again the confirmation is the one of every unit error kept. Synthetic
// candidates on a hand-made sample: 3 views of 60 units, 12 sampled in each, errors that follow
// the pilot's with a per-candidate level and noise.
TEST(Screening, ShardsScreenOutOnlyWhatIsProvenOutOfReach) {
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> unit(0, 1);
  const ScreenSample sample = testing_support::synthetic_screen_sample(random);
  const size_t count = 400;
  std::vector<std::vector<double>> runs(count);
  std::vector<double> mean(count);
  for (size_t c = 0; c < count; ++c) {
    const double level = 0.2 * unit(random), noise = 0.05 + 0.3 * unit(random);
    for (const auto& s : sample.strata)
      for (double p : s.pilot) runs[c].push_back(p * (1 + level) + noise * (unit(random) - 0.5));
    mean[c] = estimate_mean_error(sample, runs[c]).mean;
  }
  ScreenRule rule;
  rule.top = 10;
  rule.margin = -1e-5;
  const auto kth_of = [&](const std::vector<size_t>& ids) {  // ids ascending
    std::vector<size_t> order = ids;
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return mean[a] < mean[b]; });
    return std::pair(order[size_t(rule.top) - 1],
                     std::vector<size_t>(order.begin(), order.begin() + rule.top));
  };
  std::vector<size_t> all(count);
  std::iota(all.begin(), all.end(), size_t(0));
  const std::vector<size_t> expected = candidates_to_confirm(sample, runs, rule);
  const size_t rp = kth_of(all).first;
  for (double keep_sigmas : {0.0, 3.0, 6.0}) {
    std::vector<bool> kept(count, true);
    size_t proven = 0, again = 0;
    for (size_t shard = 0; shard < 2; ++shard) {
      std::vector<size_t> mine;
      for (size_t c = shard; c < count; c += 2) mine.push_back(c);
      const auto [r, best] = kth_of(mine);
      for (size_t c : mine) {
        const bool is_best = std::find(best.begin(), best.end(), c) != best.end();
        if (keeps_unit_errors(sample, runs[c], mean[c], runs[r], mean[r], is_best, rule,
                              keep_sigmas))
          continue;
        const double lower = reach_lower_bound(sample, runs[c], mean[c], runs[r], rule);
        if (!proven_out_of_reach(sample, lower, runs[r], runs[rp], mean[rp], rule)) {
          ++again;  // the merge screens it again: its unit errors are back
          continue;
        }
        ++proven;
        kept[c] = false;
        EXPECT_GT(
            mean[c] - mean[rp] - rule.sigmas * paired_standard_error(sample, runs[c], runs[rp]),
            rule.margin)
            << "candidate " << c << " proven out of reach but in reach";
      }
    }
    EXPECT_GT(proven, count / 2) << "keep_sigmas " << keep_sigmas;
    if (keep_sigmas == 0) {
      EXPECT_GT(again, 0u) << "no candidate needed screening again";
    }
    std::vector<size_t> ids;
    std::vector<std::vector<double>> left;
    for (size_t c = 0; c < count; ++c)
      if (kept[c]) ids.push_back(c), left.push_back(runs[c]);
    std::vector<size_t> confirmed;
    for (size_t i : candidates_to_confirm(sample, left, rule)) confirmed.push_back(ids[i]);
    EXPECT_EQ(confirmed, expected) << "keep_sigmas " << keep_sigmas;
  }
}

}  // namespace
}  // namespace mb
