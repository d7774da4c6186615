// Sweep building blocks: candidate ids, the plan, and the sweep's per-candidate error against the
// `lp:` technique of eval on the same basis (one loop, solve_lp_view: a named set and its function
// list give the same bits, for any thread count), and that loop against cold per-fragment solves.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>

#include "eval/evaluation.h"
#include "sweep/candidate_evaluation.h"
#include "sweep/candidates.h"
#include "sweep/sweep_plan.h"
#include "test_support.h"

namespace mb {
namespace {

void expect_round_trip(int n, int k) {
  const uint64_t total = binomial(n, k);
  std::vector<int> previous;
  for (uint64_t rank = 0; rank < total; ++rank) {
    auto c = combination_unrank(rank, n, k);
    ASSERT_EQ(int(c.size()), k);
    for (int i = 0; i < k; ++i) ASSERT_TRUE(c[i] >= 0 && c[i] < n && (i == 0 || c[i - 1] < c[i]));
    ASSERT_EQ(combination_rank(c, n), rank);
    if (rank > 0) {
      ASSERT_TRUE(
          std::lexicographical_compare(previous.begin(), previous.end(), c.begin(), c.end()));
    }
    previous = c;
  }
}

TEST(Candidates, RankAndCombinationRoundTrip) {
  EXPECT_EQ(binomial(37, 4), 66045u);
  expect_round_trip(37, 4);
  expect_round_trip(37, 2);
  expect_round_trip(10, 3);
  EXPECT_EQ(combination_rank({0, 1, 2, 3}, 37), 0u);
  EXPECT_EQ(combination_rank({33, 34, 35, 36}, 37), 66044u);
}

TEST(Candidates, PlanSamplesShardsAndRejectsBadCatalogs) {
  SweepPlan sample = make_sweep_plan({}, 4, {}, 100, 7);
  EXPECT_EQ(sample.ids.size(), 100u);
  EXPECT_EQ(make_sweep_plan({}, 4, {}, 100, 7).ids, sample.ids);  // seeded
  EXPECT_NE(make_sweep_plan({}, 4, {}, 100, 8).ids, sample.ids);
  std::set<uint64_t> all;
  for (int k = 1; k <= 3; ++k)
    for (uint64_t id : shard_ids(sample, k, 3)) EXPECT_TRUE(all.insert(id).second);
  EXPECT_EQ(all.size(), 100u);
  SweepPlan power = make_sweep_plan({}, 4, {"z^4; z; z^3; z^2"}, 0, 0);
  ASSERT_EQ(power.ids.size(), 1u);
  EXPECT_EQ(power.name(power.ids[0]), "z; z^2; z^3; z^4");
  // Explicit candidates join a sample: power moments ranked among sampled candidates.
  ASSERT_FALSE(std::binary_search(sample.ids.begin(), sample.ids.end(), power.ids[0]));
  SweepPlan joined = make_sweep_plan({}, 4, {"z; z^2; z^3; z^4"}, 100, 7);
  EXPECT_EQ(joined.ids.size(), 101u);
  EXPECT_TRUE(std::binary_search(joined.ids.begin(), joined.ids.end(), power.ids[0]));
  EXPECT_TRUE(
      std::includes(joined.ids.begin(), joined.ids.end(), sample.ids.begin(), sample.ids.end()));
  std::string m = testing_support::input_error_of([] {
    make_sweep_plan({"z", "z^2", "z^3"}, 4, {}, 0, 0);
  });
  EXPECT_NE(m.find("4 functions cannot be drawn from a catalog of 3"), std::string::npos) << m;
  m = testing_support::input_error_of([] { make_sweep_plan({}, 4, {"z; z^2; z^3; z^9"}, 0, 0); });
  EXPECT_NE(m.find("not in the catalog"), std::string::npos) << m;
}

TEST(Sweep, PowerBasisErrorEqualsEvalLpTechnique) {
  EvalSettings settings;
  settings.threads = 2;
  settings.technique.lp.grid = 64;
  auto views = prepare_views(load_dataset("tiny"), 0, settings, true);
  CandidateEvaluator evaluator(views, settings);
  CandidateResult sweep = evaluator.evaluate(Basis::parse({"z", "z^2", "z^3", "z^4"}));
  ErrorStats eval;
  for (const auto& v : views) {
    TechniqueResult r = evaluate_technique(v, "lp:z;z^2;z^3;z^4", settings, nullptr);
    ErrorStats s;
    s.add_all(v.fragments.pcf, r.shadow);
    eval.merge(s);
  }
  EXPECT_EQ(sweep.overall.count, eval.count);
  EXPECT_EQ(sweep.overall.sum_abs, eval.sum_abs);  // bit-identical, not merely close
  EXPECT_EQ(sweep.overall.sum_leak, eval.sum_leak);
  EXPECT_GT(sweep.solved, 1000u);
  EXPECT_GT(sweep.skipped, 0u);
  // And independent of the thread count.
  settings.threads = 1;
  CandidateEvaluator one_thread(views, settings);
  EXPECT_EQ(one_thread.evaluate(Basis::parse({"power4"})).overall.sum_abs, sweep.overall.sum_abs);
}

// The default dataset's power and trigonometric sweeps (1.24 M LPs each, grid 256 as in
// configs/sweeps/default.yaml) leave at most 2 LPs unstable. The tiny dataset's runs are too short
// and too tame to show some faults: partial pricing with unrefined duals once made 1191 of the
// power4 sweep's LPs unstable (steps that raised the objective, between the windows' choice and
// the full pass's, until the iteration limit) while every other test passed.
TEST(Sweep, DefaultDatasetLeavesAtMostTwoLpsUnstable) {
  if (!std::filesystem::exists(std::string(MOMENTBENCH_SOURCE_DIR) + "/data/buildings.obj"))
    GTEST_SKIP() << "data/ not fetched (scripts/fetch_data)";
  EvalSettings settings;
  settings.threads = 2;
  settings.technique.lp.grid = 256;
  auto views = prepare_views(load_dataset("default"), 0, settings, true);
  CandidateEvaluator evaluator(views, settings);
  for (const char* basis : {"power4", "trig4"}) {
    const CandidateResult r = evaluator.evaluate(Basis::parse({basis}));
    EXPECT_GT(r.solved, 1200000u) << basis;  // 1.24 M LPs with delta_f (docs/reference.md §3)
    EXPECT_EQ(r.infeasible, 0u) << basis;    // the kernel distribution is always feasible
    EXPECT_LE(r.unstable, 2u) << basis;
  }
}

}  // namespace
}  // namespace mb

namespace mb {
namespace {

// The view loop (warm-start runs, columns built once per texel, z_f's column moved along a texel)
// against the technique's own per-fragment path (each LP built from the kernel's distribution and
// solved from scratch): the same certified G to 1e-9 at every fragment of the tiny dataset.
TEST(Sweep, ViewLoopAgreesWithColdPerFragmentSolves) {
  EvalSettings settings;
  settings.threads = 2;
  settings.technique.lp.grid = 128;
  const auto views = prepare_views(load_dataset("tiny"), 0, settings, true);
  for (const char* name : {"lp:power4", "lp:z;exp(-z);sin(pi z);1/(1+z)"}) {
    auto technique = make_technique(name, settings.technique);
    size_t compared = 0;
    for (const auto& view : views) {
      const TechniqueResult warm = evaluate_technique(view, name, settings, nullptr);
      std::vector<double> depths(81), weights(81);
      for (size_t k = 0; k < view.fragments.size(); k += 3) {
        const size_t t = view.fragments.texel[k];
        kernel_distribution(view.map, settings.kernel, int(t % view.map.width),
                            int(t / view.map.width), depths, weights);
        FragmentInput in;
        in.zf = view.fragments.ztest[k];
        in.kernel_depths = depths;
        in.kernel_weights = weights;
        ASSERT_NEAR(technique->shadow(in), warm.shadow[k], 1e-9) << name << " fragment " << k;
        ++compared;
      }
    }
    EXPECT_EQ(technique->failures(), 0u) << name;
    EXPECT_GT(compared, 2000u);
  }
}

}  // namespace
}  // namespace mb
