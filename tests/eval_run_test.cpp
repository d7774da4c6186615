// eval's run of techniques over views as a library unit: its rows are the per-view errors of
// evaluate_technique, its "all" rows their merge, and the sink sees every shadow once, in order.
#include "eval/eval_run.h"

#include <gtest/gtest.h>

#include "eval/eval_config.h"

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
