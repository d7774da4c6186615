// verify's run as a library unit: its plan rejects settings that would prove nothing before any
// output exists, and a small run judges every target on exactly the instances it was given.
#include "verify/verify_run.h"

#include <gtest/gtest.h>

#include "test_support.h"

namespace mb {
namespace {

using testing_support::input_error_of;

VerifySettings small_settings() {
  Config config(option_specs(verify_options()));
  VerifySettings v;
  read_options(config, verify_options(), v);
  v.techniques = {"hamburger4", "vsm"};
  v.random = 40;
  v.fragments = 0;
  v.grids = {256};
  return v;
}

TEST(VerifyRun, PlanRejectsUnorderedGridsAndNothingToVerify) {
  VerifySettings v = small_settings();
  v.grids = {1024, 256};
  EXPECT_NE(input_error_of([&] { make_verify_plan(v, TechniqueParams{}); }).find("ascending"),
            std::string::npos);
  v = small_settings();
  v.random = 0;
  EXPECT_NE(input_error_of([&] { make_verify_plan(v, TechniqueParams{}); }).find("nothing to"),
            std::string::npos);
  v = small_settings();
  v.techniques = {"hamburger5"};
  EXPECT_FALSE(input_error_of([&] { make_verify_plan(v, TechniqueParams{}); }).empty());
}

// The options' defaults are the plan's: the continuous interval decides, storage boxes judge the
// float rows; a run on random instances alone checks each target on every instance and passes.
TEST(VerifyRun, RandomInstancesAloneJudgeEveryTarget) {
  const VerifyPlan plan = make_verify_plan(small_settings(), TechniqueParams{});
  EXPECT_TRUE(plan.continuous);
  ASSERT_EQ(plan.targets.size(), 2u);
  EvalSettings settings;
  settings.threads = 2;
  const VerifyRun run = run_verification(plan, DatasetOptions{}, settings, true);
  EXPECT_EQ(run.dataset_name, "none");
  EXPECT_EQ(run.random_count, run.instances.size());
  ASSERT_EQ(run.results.size(), 2u);
  for (const auto& r : run.results) {
    EXPECT_EQ(r.instances, run.instances.size()) << r.target.technique;
    EXPECT_TRUE(r.passed()) << r.target.technique;
  }
}

}  // namespace
}  // namespace mb
