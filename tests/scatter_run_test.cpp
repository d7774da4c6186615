// `scatter`'s run (docs/scattering.md §4): its checks of the dataset, the phase function's
// direction, and answers that do not depend on the thread count.
#include "scatter/scatter_run.h"

#include <gtest/gtest.h>

#include "raster/render_view.h"
#include "report/scatter_report.h"
#include "scene/light_view.h"
#include "test_support.h"

namespace mb {
namespace {

using testing_support::input_error_of;

ScatterRunOptions small_run(std::vector<std::string> techniques) {
  ScatterRunOptions run;
  run.techniques = std::move(techniques);
  run.reference_resolution = 96, run.max_distance = 50;
  run.light_resolution = 96, run.guard_band = 4, run.reference = "exact";
  return run;
}

std::vector<ScatterFrameResult> run_tiny(const ScatterRunOptions& run, int threads) {
  std::vector<ScatterFrameResult> frames;
  run_scatter(scatter_scenes(load_dataset("scattering_tiny")), run, threads, true,
              [&](const ScatterFrameResult& r) { frames.push_back(r); });
  return frames;
}

TEST(ScatterRun, ForwardScatteringBrightensRaysLookingIntoTheLight) {
  MediumDesc m;
  m.extinction = 0.1, m.albedo = 0.5, m.phase = PhaseKind::HenyeyGreenstein, m.g = 0.5;
  const Eigen::Vector3d to_light = direction_to_light(40, 30);
  const double into = scattering_factor(m, to_light, to_light);
  const double away = scattering_factor(m, to_light, -to_light);
  EXPECT_GT(into, 20 * away);
  EXPECT_NEAR(into, 0.05 * m.phase_value(1), 1e-15);
  m.g = -0.5;  // backward: brightest looking away from the light
  EXPECT_LT(scattering_factor(m, to_light, to_light), scattering_factor(m, to_light, -to_light));
}

TEST(ScatterRun, SameAnswersForAnyThreadCountAndTheReferenceRowIsExact) {
  const ScatterRunOptions run = small_run({"exact", "raymarch:16"});
  const auto one = run_tiny(run, 1), two = run_tiny(run, 2);
  ASSERT_EQ(one.size(), 1u);
  ASSERT_EQ(two.size(), 1u);
  EXPECT_EQ(one[0].reference, two[0].reference);
  EXPECT_EQ(one[0].inscatter, two[0].inscatter);
  const ScatterStats& exact = one[0].stats[0];
  EXPECT_EQ(exact.mean_error(), 0);
  EXPECT_EQ(exact.pixels, size_t(one[0].width) * one[0].height);
  const ScatterStats& march = one[0].stats[1];
  EXPECT_GT(march.mean_error(), 0);
  EXPECT_NEAR(march.too_bright() + march.too_dark(), march.mean_error(), 1e-15);
  // The house shadows part of the air: the reference is below S_max somewhere, never above it.
  size_t shadowed = 0;
  for (size_t p = 0; p < one[0].reference.size(); ++p) {
    EXPECT_LE(one[0].reference[p], one[0].s_max[p] * (1 + 1e-12));
    shadowed += one[0].reference[p] < 0.99 * one[0].s_max[p];
  }
  EXPECT_GT(shadowed, 0u);
}

// docs/scattering.md §3.2: a ray whose LP the floating-point backend cannot certify is solved once
// more in exact arithmetic, so that none of scattering_tiny's is answered lit (12 of its rays were
// at scatter's defaults, power6 on the grid). A ray that fails even so is counted: the count
// reaches the rows (per frame and `all`) and report.md.
TEST(ScatterRun, RaysWhoseLpFailedAreRetriedInExactArithmeticAndCounted) {
  ScatterRunOptions run;
  read_options(Config(option_specs(scatter_run_options())), scatter_run_options(), run);
  run.techniques = {"pss_exact", "pss_lp:power6"};
  const auto one = run_tiny(run, 2);
  ASSERT_EQ(one.size(), 1u);
  ASSERT_EQ(one[0].failures.size(), 2u);
  EXPECT_EQ(one[0].failures[0], 0u);  // pss_exact solves nothing that can fail
  EXPECT_EQ(one[0].failures[1], 0u);
  ScatterFrameResult frame = one[0];
  const size_t failed = 7;  // as if 7 had failed twice
  frame.failures[1] = failed;
  ScatterRows rows(run.techniques);
  rows.add(frame);
  EXPECT_EQ(rows.overall()[1].failures, failed);
  EXPECT_EQ(rows.per_frame()[1].failures, failed);
  ScatterReportContext context;
  context.reference = "exact";
  const ScatterReport report = render_scatter_report(context, rows.overall(), rows.per_frame());
  const std::string row = "| pss_lp:power6 | all | all | all | " + std::to_string(failed) + " | " +
                          std::to_string(frame.stats[1].pixels) + " | ";
  EXPECT_NE(report.markdown.find(row), std::string::npos) << report.markdown;
  // errors.csv keeps its columns (the count is report.md's).
  EXPECT_EQ(report.errors_csv.substr(0, report.errors_csv.find('\n')),
            "technique,scene,view,camera,mean_error,too_bright,too_dark,max_error,time_s");
}

// A ray whose row segment holds only depths 0 and 1 (equal moments, (1, 1, 1, 1) where no surface
// lies over it) has exact bounds, not a failure: seed 000's bias target keeps those moments
// singular (results/FINDINGS.md §12).
TEST(ScatterRun, FourMomentsAnswerRowsWithoutOccluders) {
  const ScatterRunOptions run = small_run({"pss_exact", "pss_msm4"});
  const auto one = run_tiny(run, 1);
  ASSERT_EQ(one.size(), 1u);
  ASSERT_EQ(one[0].failures.size(), 2u);
  EXPECT_EQ(one[0].failures[1], 0u);
  EXPECT_GT(one[0].stats[1].pixels, 0u);
}

// pss_lp merges a row's repeated depths before its LP (the same distribution) and solves a ray
// its floating-point LP cannot certify once more exactly (docs/scattering.md §3.2): with every
// copy a column of its own and no retry, the grid LP of four power moments left 4 of
// scattering_tiny's 1 536 rays without a certified answer at scatter's defaults, answered lit.
TEST(ScatterRun, TheLpCertifiesRowsThatRepeatTheirDepths) {
  ScatterRunOptions run;
  read_options(Config(option_specs(scatter_run_options())), scatter_run_options(), run);
  run.techniques = {"pss_lp:power4"};
  const auto one = run_tiny(run, 2);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].stats[0].pixels, 1536u);
  EXPECT_EQ(one[0].failures[0], 0u);
}

TEST(ScatterRun, RefusesDatasetsItCannotMeasure) {
  const std::string scene =
      testing_support::write_temp_file("scene.yaml", "parts:\n  - box: {}\nviews:\n  - {}\n");
  const std::string dataset = testing_support::write_temp_file(
      "dataset.yaml", "scenes: [" + scene + "]\nmedium: {extinction: 1}\n");
  EXPECT_NE(input_error_of([&] {
              scatter_scenes(load_dataset(dataset));
            }).find("no scene names a camera"),
            std::string::npos);
  // The tiny dataset's scenes have cameras but no medium.
  EXPECT_NE(input_error_of([] { scatter_scenes(load_dataset("tiny")); }).find("no medium"),
            std::string::npos);
  EXPECT_NE(
      input_error_of([] { scatter_scenes(load_dataset("transparency")); }).find("translucent"),
      std::string::npos);
}

// The house of the scattering dataset is seed 004 Figure 4's situation: its interior is entirely
// shadowed, so a view ray through the south window gathers nothing beyond the window (the part
// from the wall's inner face, z = 2, to the north wall's, z = -2, adds no in-scattering).
TEST(ScatterRun, TheHouseInteriorIsEntirelyShadowed) {
  const std::vector<ScatterScene> scenes = scatter_scenes(load_dataset("scattering_tiny"));
  ASSERT_EQ(scenes.size(), 1u);
  const Scene& scene = scenes[0].scene;
  LightViewDesc view = scene.views.at(0);
  view.resolution = 512;
  const LayerStack stack = render_view(scene, view, 1);
  const LightFrame frame(view, scene.mesh.vertices);
  const LightDepthMap map(frame, stack);
  const auto exact = make_scatter_technique("exact", {});
  const Eigen::Vector3d camera = scene.cameras.at(0).position;
  exact->prepare({&map, &scene, &view, &scene.cameras[0], camera, scenes[0].medium.extinction});
  int rays = 0;
  double outside_total = 0;
  // Points of the window opening (x in [-0.8, 0.8], y in [0.9, 2.1]) kept 0.2 from its edges.
  for (double x = -0.6; x <= 0.6 + 1e-9; x += 0.3)
    for (double y = 1.1; y <= 1.9 + 1e-9; y += 0.2) {
      const Eigen::Vector3d w = (Eigen::Vector3d(x, y, 2.0) - camera).normalized();
      const double inner = (2.0 - camera.z()) / w.z(), back = (-2.0 - camera.z()) / w.z();
      const double outside = exact->lit_length({w, inner, 0});
      EXPECT_GT(outside, 0);
      EXPECT_NEAR(exact->lit_length({w, back, 0}), outside, 1e-12 * outside) << x << " " << y;
      outside_total += outside, ++rays;
    }
  EXPECT_EQ(rays, 25);
  EXPECT_GT(outside_total, 0);
}

}  // namespace
}  // namespace mb
