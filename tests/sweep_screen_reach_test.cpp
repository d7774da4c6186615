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

}  // namespace
}  // namespace mb
