// Screening at full scale in a results database (sweep/screen_reach.h, docs/sweeps.md "Full
// scale"): eight shards of one database drop the unit errors of the candidates out of reach of
// their own K-th best; the merge finds exactly those it cannot prove out of reach of the sweep's
// K-th best (checked against screen/screening.h's proof, and every one it does prove is out of
// reach by the confirmation's own test); screened again, the confirmation is the one of every unit
// error.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <numeric>
#include <random>
#include <set>

#include "screen_synthetic_sample.h"
#include "sweep/screen_reach.h"

namespace mb {
namespace {

TEST(ScreenReach, ShardsDropMergeScreensAgainOnlyWhatItCannotProve) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("momentbench_screen_reach_" +
                     std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + ".sqlite");
  std::filesystem::remove(path);
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(0, 1);
  const ScreenSample sample = testing_support::synthetic_screen_sample(random);
  const size_t count = 400;
  std::vector<EstimateRow> rows(count);
  std::vector<std::vector<double>> runs(count);
  ResultsStore store = ResultsStore::create(path.string(), {{"config", "x"}});
  for (size_t c = 0; c < count; ++c) {
    const double level = 0.05 * unit(random), noise = 0.05 + 0.3 * unit(random);
    for (const auto& s : sample.strata)
      for (double p : s.pilot) runs[c].push_back(p * (1 + level) + noise * (unit(random) - 0.5));
    rows[c].id = c;
    rows[c].name = "candidate " + std::to_string(c);
    rows[c].run_errors = runs[c];
    rows[c].mean = estimate_mean_error(sample, runs[c]).mean;
    store.put_estimate(rows[c]);
  }
  ScreenRule rule;
  rule.top = 10;
  // Eight shards: their K-th best rank far below the sweep's, where the merged database's own
  // screen-out would drop them but for the proofs that name them.
  std::vector<uint64_t> all(count), shard[8];
  std::iota(all.begin(), all.end(), uint64_t(0));
  for (uint64_t c : all) shard[c % 8].push_back(c);
  for (const auto& mine : shard) screen_out_unreachable(store, 1, mine, sample, rule, 3);

  // The sweep's K-th best, and what the merge must screen again: the screened out it cannot prove.
  std::vector<uint64_t> order = all;
  std::stable_sort(order.begin(), order.end(),
                   [&](uint64_t a, uint64_t b) { return rows[a].mean < rows[b].mean; });
  const uint64_t rp = order[size_t(rule.top) - 1];
  std::set<uint64_t> anchors;
  std::vector<uint64_t> expected_again;
  size_t proven = 0;
  for (const EstimateRow& e : store.estimates(1, false)) {
    if (!e.screened_out) continue;
    anchors.insert(e.reach_against);
    if (!proven_out_of_reach(sample, e.reach_lower, runs[e.reach_against], runs[rp], rows[rp].mean,
                             rule)) {
      expected_again.push_back(e.id);
      continue;
    }
    ++proven;
    EXPECT_GT(rows[e.id].mean - rows[rp].mean -
                  rule.sigmas * paired_standard_error(sample, runs[e.id], runs[rp]),
              rule.margin)
        << "candidate " << e.id << " proven out of reach but in reach";
  }
  EXPECT_EQ(anchors.size(), 8u);  // one K-th best per shard
  EXPECT_GT(proven, count / 2) << expected_again.size() << " to screen again";
  EXPECT_FALSE(expected_again.empty()) << "no proof failed: the test exercises too little";
  EXPECT_EQ(unproven_screened_out(store, 1, all, sample, rule), expected_again);

  // Screened again (the same estimates), then the merged database's own screen-out keeps the
  // shards' K-th best, whose unit errors every earlier proof is.
  for (uint64_t id : expected_again) store.put_estimate(rows[id]);
  EXPECT_TRUE(unproven_screened_out(store, 1, all, sample, rule).empty());
  screen_out_unreachable(store, 1, all, sample, rule, 3);
  for (uint64_t a : anchors) EXPECT_EQ(store.run_errors(a, 1).size(), sample.sampled_runs());
  EXPECT_TRUE(unproven_screened_out(store, 1, all, sample, rule).empty());

  std::vector<uint64_t> kept;
  std::vector<std::vector<double>> left;
  for (const EstimateRow& e : store.estimates(1))
    if (!e.screened_out) kept.push_back(e.id), left.push_back(e.run_errors);
  std::vector<uint64_t> confirmed;
  for (size_t i : candidates_to_confirm(sample, left, rule)) confirmed.push_back(kept[i]);
  std::vector<uint64_t> expected;
  for (size_t i : candidates_to_confirm(sample, runs, rule)) expected.push_back(all[i]);
  EXPECT_EQ(confirmed, expected);
  std::filesystem::remove(path);
}

// A translucent shard's unit errors (270 units, 2 KB a candidate) fit inside their table pages:
// dropping them frees no page, and the database must still shrink to what is kept.
TEST(ScreenReach, DroppingSmallUnitErrorsShrinksTheDatabase) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("momentbench_screen_small_" +
                     std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + ".sqlite");
  std::filesystem::remove(path);
  const size_t count = 2000, units = 270;
  std::vector<EstimateRow> rows(count);
  {
    ResultsStore store = ResultsStore::create(path.string(), {{"config", "x"}});
    store.batch([&] {
      for (size_t c = 0; c < count; ++c) {
        rows[c].id = c;
        rows[c].name = "candidate " + std::to_string(c);
        rows[c].run_errors.assign(units, 0.001 * double(c % 97));
        store.put_estimate(rows[c]);
      }
    });
    const auto before = std::filesystem::file_size(path);
    std::vector<EstimateRow> out(rows.begin() + 10, rows.end());
    store.screen_out(1, out);
    const auto after = std::filesystem::file_size(path);
    EXPECT_GT(before, count * units * sizeof(double));
    // What is left: 10 candidates' unit errors and 2 000 small rows.
    EXPECT_LT(after, before / 8) << before << " -> " << after << " bytes";
    EXPECT_EQ(store.run_errors(3, 1).size(), units);
    EXPECT_TRUE(store.run_errors(30, 1).empty());
  }
  std::filesystem::remove(path);
}

// A confirmation leaves a tie unconfirmed; exact means above their estimates put it first
// (results/FINDINGS.md §13): it is named, by its latest stage's estimate, and nothing else is.
TEST(ScreenReach, EstimatesAheadOfTheBestExactMeanAreNamed) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("momentbench_ahead_" +
                     std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + ".sqlite");
  std::filesystem::remove(path);
  ResultsStore store = ResultsStore::create(path.string(), {{"config", "x"}});
  auto estimate = [&](uint64_t id, int stage, double mean) {
    EstimateRow e;
    e.id = id, e.stage = stage, e.name = "c" + std::to_string(id), e.mean = mean, e.se = 1e-4;
    store.put_estimate(e);
  };
  auto exact = [&](uint64_t id, double mean) {
    ResultRow r;
    r.id = id, r.name = "c" + std::to_string(id), r.mean = mean;
    store.put_candidate(r);
  };
  // Nothing exact yet: nothing to rank against.
  estimate(1, 1, 0.010);
  EXPECT_TRUE(estimates_ahead_of_best_exact(store, {1}).empty());
  exact(2, 0.0113);  // confirmed: its estimate (below) was lower than its exact mean
  estimate(2, 1, 0.0110);
  estimate(3, 1, 0.0112);  // a tie left unconfirmed, now below the best exact mean
  estimate(4, 1, 0.0114);  // above it
  estimate(5, 1, 0.0109);  // below at stage 1, above after refining: the report shows stage 2
  estimate(5, 2, 0.0115);
  estimate(6, 1, 0.0116);  // refined below it
  estimate(6, 2, 0.0111);
  estimate(7, 1, 0.0100);  // below, but not a candidate of this plan
  EXPECT_EQ(estimates_ahead_of_best_exact(store, {1, 2, 3, 4, 5, 6}),
            (std::vector<uint64_t>{1, 3, 6}));
  // A lower exact mean moves the bar: only 1 (0.0100) and 6 (0.0111) lie below 0.01115.
  exact(4, 0.01115);
  EXPECT_EQ(estimates_ahead_of_best_exact(store, {1, 2, 3, 4, 5, 6}),
            (std::vector<uint64_t>{1, 6}));
  // Once they are exact, none is ahead.
  exact(1, 0.0120), exact(6, 0.0117);
  EXPECT_TRUE(estimates_ahead_of_best_exact(store, {1, 2, 3, 4, 5, 6}).empty());
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace mb
