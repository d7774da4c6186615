// eval's run of techniques over views as a library unit: its rows are the per-view errors of
// evaluate_technique, its "all" rows their merge, and the sink sees every shadow once, in order.
#include "eval/eval_run.h"

#include <gtest/gtest.h>

#include "eval/eval_config.h"
#include "test_support.h"

namespace mb {
namespace {

TEST(EvalRun, RowsAreEachViewsErrorsAndTheirMerge) {
  EvalSettings settings;
  settings.threads = 2;
  const auto views = prepare_views(load_dataset("tiny"), 0, settings, true);
  ASSERT_GE(views.size(), 2u);
  std::vector<std::string> seen;
  const auto sink = [&](const std::string& name, const ViewData& view,
                        const std::vector<double>& shadow) {
    EXPECT_EQ(shadow.size(), view.fragments.size());
    seen.push_back(name + " " + view.scene + "/" + view.view);
  };
  const EvalRows rows = evaluate_techniques(views, {"pcf", "vsm"}, settings, true, sink);
  ASSERT_EQ(rows.overall.size(), 2u);
  ASSERT_EQ(rows.per_view.size(), 2 * views.size());
  ASSERT_EQ(seen.size(), 2 * views.size());
  EXPECT_EQ(seen.front(), "pcf " + views[0].scene + "/" + views[0].view);
  EXPECT_EQ(rows.overall[0].stats.mean(), 0.0);  // PCF against itself
  for (size_t t = 0; t < 2; ++t) {
    ErrorStats merged;
    for (size_t v = 0; v < views.size(); ++v) {
      const EvalRow& row = rows.per_view[t * views.size() + v];
      EXPECT_EQ(row.technique, rows.overall[t].technique);
      ErrorStats direct;
      direct.add_all(views[v].fragments.pcf,
                     evaluate_technique(views[v], row.technique, settings, nullptr).shadow);
      EXPECT_EQ(row.stats.mean(), direct.mean()) << row.technique << " view " << v;
      merged.merge(direct);
    }
    // Interior and silhouette receivers hold all of an exact technique's error: on unshadowed ones
    // the reference is 0 and so is G.
    const EvalRow& all = rows.overall[t];
    EXPECT_LE(all.interior.count + all.silhouette.count, all.stats.count);
    EXPECT_GT(all.silhouette.count, 0u);
    EXPECT_NEAR(all.interior.sum_abs + all.silhouette.sum_abs, all.stats.sum_abs, 1e-9);
    EXPECT_EQ(rows.overall[t].scene, "all");
    EXPECT_EQ(rows.overall[t].stats.mean(), merged.mean());
  }
  EXPECT_GT(rows.overall[1].stats.mean(), 0.0);  // VSM leaks on the tiny dataset
}

}  // namespace
}  // namespace mb

namespace mb {
namespace {

// Defaults are written once, in the option records: settings made without a config hold what a
// config of nothing but defaults reads, and the shadow stage's own BiasParams and GaussianKernel
// defaults (what its tests use) agree with them.
TEST(EvalRun, DefaultSettingsAreTheRecordsDefaults) {
  const EvalSettings made;
  const EvalSettings read = shadow_settings_from(Config(shadow_option_specs()), 1);
  EXPECT_EQ(made.kernel.size, read.kernel.size);
  EXPECT_EQ(made.kernel.sigma, read.kernel.sigma);
  EXPECT_EQ(made.kernel.weights, read.kernel.weights);
  EXPECT_EQ(made.bias.constant, read.bias.constant);
  EXPECT_EQ(made.bias.slope, read.bias.slope);
  EXPECT_EQ(made.bias.reference, read.bias.reference);
  EXPECT_EQ(made.blend, read.blend);
  EXPECT_EQ(made.light.angle_deg, read.light.angle_deg);
  EXPECT_EQ(made.light.directions, read.light.directions);
  EXPECT_EQ(made.soft.sat_search, read.soft.sat_search);
  EXPECT_EQ(made.technique.lp.grid, read.technique.lp.grid);
  const BiasParams shadow_stage;
  EXPECT_EQ(shadow_stage.constant, read.bias.constant);
  EXPECT_EQ(shadow_stage.slope, read.bias.slope);
  EXPECT_EQ(shadow_stage.reference, read.bias.reference);
  const GaussianKernel kernel;
  EXPECT_EQ(kernel.size, read.kernel.size);
  EXPECT_EQ(kernel.sigma, read.kernel.sigma);
  // A record changed in a config reaches the settings.
  Config config(shadow_option_specs());
  config.set("kernel.sigma=1.5");
  EXPECT_EQ(shadow_settings_from(config, 1).kernel.sigma, 1.5);
}

}  // namespace
}  // namespace mb

namespace mb {
namespace {

// What `eval` checks before and after rendering (eval/eval_run.h): the rows it runs, each made
// before any work; the LP interval where a row solves the LP, and only there; the blocker audit
// where a row asks for it, and only there; the receivers it reports.
TEST(EvalRun, TechniqueListIsCheckedAndGainsTheOracleUnderReceiverPlane) {
  EvalSettings settings;
  const std::string empty = testing_support::input_error_of([&] { eval_techniques({}, settings); });
  EXPECT_EQ(empty.rfind("techniques:", 0), 0u) << empty;
  const std::string unknown = testing_support::input_error_of([&] {
    eval_techniques({"pcf", "vsm_nope"}, settings);
  });
  EXPECT_NE(unknown.find("vsm_nope"), std::string::npos) << unknown;
  // A name its row parses, with a part the row's own check refuses.
  EXPECT_NE(testing_support::input_error_of([&] {
              eval_techniques({"pcf", "msm_soft:lp:nobasis"}, settings);
            }),
            "");
  settings.bias.reference = Reference::Biased;
  EXPECT_EQ(eval_techniques({"pcf", "vsm"}, settings), (std::vector<std::string>{"pcf", "vsm"}));
  settings.bias.reference = Reference::ReceiverPlane;
  EXPECT_EQ(eval_techniques({"pcf", "vsm"}, settings),
            (std::vector<std::string>{"pcf", "vsm", "oracle"}));
}

TEST(EvalRun, LpIntervalAndBlockerAuditOnlyWhereARowNeedsThem) {
  EvalSettings settings;
  settings.threads = 2;
  settings.light.angle_deg = 2;
  settings.light.directions = 4;
  const auto views = prepare_views(load_dataset("tiny"), 24, settings, true);
  ASSERT_FALSE(views.empty());
  size_t receivers = 0;
  for (const auto& v : views) receivers += v.fragments.size();
  EXPECT_GT(receivers, 0u);
  EXPECT_EQ(receiver_count(views), receivers);

  settings.technique.lp.lo = 0.999;  // excludes the tiny views' depths
  EXPECT_EQ(testing_support::input_error_of([&] {
              check_eval_views(views, {"pcf", "vsm"}, settings);
            }),
            "");
  const std::string lp = testing_support::input_error_of([&] {
    check_eval_views(views, {"pcf", "lp:power4"}, settings);
  });
  EXPECT_EQ(lp.rfind("lp.lo, lp.hi:", 0), 0u) << lp;
  settings.technique.lp.lo = EvalSettings().technique.lp.lo;
  EXPECT_EQ(testing_support::input_error_of([&] {
              check_eval_views(views, {"pcf", "lp:power4"}, settings);
            }),
            "");

  EXPECT_TRUE(eval_blocker_audits(views, {"pcf", "pcss"}, settings).empty());
  const auto audits = eval_blocker_audits(views, {"pcf", "msm_soft"}, settings);
  ASSERT_EQ(audits.size(), views.size());  // every view is lit by the area light
  EXPECT_EQ(audits[0].scene + "/" + audits[0].view, views[0].scene + "/" + views[0].view);
  EXPECT_FALSE(audits[0].rows.empty());
}

}  // namespace
}  // namespace mb
