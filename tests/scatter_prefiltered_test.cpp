// The prefiltered rows on the scattering_tiny house (docs/scattering.md §3.2): pss_lp at beta 0 is
// never too dark against pss_exact, pss_exact approaches the exact reference as the light map
// grows, and every prefiltered row answers the same for any thread count.
#include <gtest/gtest.h>

#include <cstdio>

#include "scatter/scatter_run.h"

namespace mb {
namespace {

// Every scatter option at its record's default, then small maps and no images.
ScatterRunOptions defaults(std::vector<std::string> techniques) {
  ScatterRunOptions run;
  const Config config(option_specs(scatter_run_options()));
  read_options(config, scatter_run_options(), run);
  run.techniques = std::move(techniques);
  run.reference_resolution = 128, run.images = false;
  run.light_resolution = 128, run.guard_band = 8;  // the default's 1/16 of the depth range
  return run;
}

std::vector<ScatterFrameResult> run_on(const std::vector<ScatterScene>& scenes,
                                       const ScatterRunOptions& run, int threads) {
  std::vector<ScatterFrameResult> frames;
  run_scatter(scenes, run, threads, true,
              [&](const ScatterFrameResult& r) { frames.push_back(r); });
  return frames;
}

std::vector<ScatterScene> tiny() {
  return scatter_scenes(load_dataset("scattering_tiny"));
}

TEST(ScatterPrefiltered, SameAnswersForAnyThreadCount) {
  const ScatterRunOptions run =
      defaults({"pss_exact", "pss_lp:power4", "pss_msm4", "pss_msm4_16bit", "pss_msm6", "pss_csm"});
  const auto one = run_on(tiny(), run, 1), two = run_on(tiny(), run, 2);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].inscatter, two[0].inscatter);
  for (const auto& stats : one[0].stats) EXPECT_GT(stats.mean_error(), 0);
}

// The LP's lower bound on the shadowed fraction of the row's own distribution (docs/reference.md
// §11): the in-scattering is never below pss_exact's, but for the LP's certified tolerance.
TEST(ScatterPrefiltered, LpAtBetaZeroIsNeverTooDarkAgainstPssExact) {
  ScatterRunOptions run = defaults({"pss_lp:power4", "pss_lp:trig4"});
  run.reference = "pss_exact", run.beta = 0;
  const auto frames = run_on(tiny(), run, 2);
  ASSERT_EQ(frames.size(), 1u);
  const ScatterFrameResult& r = frames[0];
  for (size_t k = 0; k < r.inscatter.size(); ++k) {
    size_t darker = 0, brighter = 0;
    for (size_t p = 0; p < r.reference.size(); ++p) {
      EXPECT_GE(r.inscatter[k][p], r.reference[p] - 1e-8 * r.s_max[p]) << k << " " << p;
      darker += r.inscatter[k][p] < r.reference[p];
      brighter += r.inscatter[k][p] > r.reference[p] * (1 + 1e-9);
    }
    std::printf("%s at beta 0: too dark %.3g, too bright %.3g (%zu pixels brighter)\n",
                run.techniques[k].c_str(), r.stats[k].too_dark(), r.stats[k].too_bright(),
                brighter);
    EXPECT_LT(r.stats[k].too_dark(), 1e-9);
    EXPECT_GT(brighter, 0u);  // not pss_exact itself: the moments lose something
  }
}

// Rectification's error shrinks as the light map and the rectified map grow; in a thin medium
// Delta(v)'s heuristic weighs little (the weights tend to equal), so pss_exact nears the reference.
TEST(ScatterPrefiltered, PssExactApproachesTheReferenceAsTheLightMapGrows) {
  std::vector<ScatterScene> scenes = tiny();
  scenes[0].medium.extinction = 0.005;
  double previous = 1;
  for (const int resolution : {32, 64, 128, 256, 512}) {
    ScatterRunOptions run = defaults({"pss_exact"});
    run.reference_resolution = 512, run.light_resolution = resolution;
    run.guard_band = resolution / 16.0;
    const double error = run_on(scenes, run, 2)[0].stats[0].mean_error();
    std::printf("pss_exact at light_resolution %d: mean error %.4g\n", resolution, error);
    EXPECT_LT(error, previous) << resolution;
    previous = error;
  }
  EXPECT_LT(previous, 0.01);
}

}  // namespace
}  // namespace mb
