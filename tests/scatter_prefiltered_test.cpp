// The prefiltered rows on the scattering_tiny house (docs/scattering.md §3.2): pss_lp at beta 0 is
// never too dark against pss_exact, pss_exact approaches the exact reference as the light map
// grows, and every prefiltered row answers the same for any thread count.
#include <gtest/gtest.h>

#include <cstdio>

#include "scatter/scatter_run.h"
#include "techniques/lp_options.h"
#include "test_support.h"
#include "util/error.h"

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
  for (const std::string resample : {"point", "filtered"}) {
    ScatterRunOptions run = defaults(
        {"pss_exact", "pss_lp:power4", "pss_msm4", "pss_msm4_16bit", "pss_msm6", "pss_csm"});
    run.resample = resample;
    const auto one = run_on(tiny(), run, 1), two = run_on(tiny(), run, 2);
    ASSERT_EQ(one.size(), 1u);
    EXPECT_EQ(one[0].inscatter, two[0].inscatter) << resample;
    for (const auto& stats : one[0].stats) EXPECT_GT(stats.mean_error(), 0) << resample;
  }
}

// The LP's lower bound on the shadowed fraction of the row's own distribution (docs/reference.md
// §11): the in-scattering is never below pss_exact's, but for the LP's certified tolerance. Under
// filtered resampling pss_exact counts each texel's two depths with their weights, the
// distribution whose moments the rows sum, so the bound holds there too.
TEST(ScatterPrefiltered, LpAtBetaZeroIsNeverTooDarkAgainstPssExact) {
  for (const std::string resample : {"point", "filtered"}) {
    ScatterRunOptions run = defaults({"pss_lp:power4", "pss_lp:trig4"});
    run.reference = "pss_exact", run.beta = 0, run.resample = resample;
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
      std::printf(
          "%s at beta 0, %s resampling: too dark %.3g, too bright %.3g (%zu pixels "
          "brighter)\n",
          run.techniques[k].c_str(), resample.c_str(), r.stats[k].too_dark(),
          r.stats[k].too_bright(), brighter);
      EXPECT_LT(r.stats[k].too_dark(), 1e-9);
      EXPECT_GT(brighter, 0u);  // not pss_exact itself: the moments lose something
    }
  }
}

// pss_lp_stored:<row> (docs/scattering.md §3.2): Problem 1 over the moment box of the row's
// stored map holds the ray's own moments, so its shadowed fraction is at most pss_lp's on the same
// basis (more in-scattering at every pixel, for the LP's tolerance), still never too dark against
// pss_exact; the 16-bit box loses something somewhere. A row stored in double has no box.
TEST(ScatterPrefiltered, StoredLpBoundsBelowTheLpOfItsBasis) {
  ScatterRunOptions run = defaults({"pss_lp:power4", "pss_lp_stored:pss_msm4_16bit"});
  run.reference = "pss_exact", run.beta = 0;
  const auto frames = run_on(tiny(), run, 2);
  ASSERT_EQ(frames.size(), 1u);
  const ScatterFrameResult& r = frames[0];
  size_t brighter = 0;
  for (size_t p = 0; p < r.reference.size(); ++p) {
    EXPECT_GE(r.inscatter[1][p], r.inscatter[0][p] - 1e-8 * r.s_max[p]) << p;
    EXPECT_GE(r.inscatter[1][p], r.reference[p] - 1e-8 * r.s_max[p]) << p;
    brighter += r.inscatter[1][p] > r.inscatter[0][p] * (1 + 1e-9);
  }
  EXPECT_GT(brighter, 0u);
  EXPECT_LT(r.stats[1].too_dark(), 1e-9);
  EXPECT_GT(r.stats[1].mean_error(), r.stats[0].mean_error());

  run.techniques = {"pss_lp_stored:pss_msm6"};
  EXPECT_THROW(run_on(tiny(), run, 1), InputError);
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

// scatter.resample (docs/scattering.md §3.1) takes point or filtered; anything else is refused
// with the key, the value and the valid ones.
TEST(ScatterPrefiltered, RefusesAnUnknownResampling) {
  Config config(scatter_run_option_specs());
  const std::string error = testing_support::input_error_of([&] {
    config.set("scatter.resample=bilinear");
    scatter_run_options_from(config);
  });
  EXPECT_NE(error.find("scatter.resample"), std::string::npos) << error;
  EXPECT_NE(error.find("bilinear"), std::string::npos) << error;
  EXPECT_NE(error.find("point, filtered"), std::string::npos) << error;
  Config good(scatter_run_option_specs());
  good.set("scatter.resample=filtered");
  EXPECT_EQ(scatter_params(scatter_run_options_from(good)).resample, Resample::Filtered);
  EXPECT_EQ(scatter_params(defaults({"pss_exact"})).resample, Resample::Point);
}

// pss_lp's lp.* keys (its row's family options: lp.grid, lp.discretization, lp.backend) reach its
// LP from scatter's config and from a scattering sweep's (which declares every lp.* key itself);
// scatter declares no other lp.* key (scatter.beta is the family's one beta).
TEST(ScatterPrefiltered, PssLpReadsItsLpKeys) {
  Config config(scatter_run_option_specs());
  config.set("techniques=[pss_lp:power4]");
  config.set("lp.grid=64");
  config.set("lp.discretization=continuous");
  const ScatterRunOptions run = scatter_run_options_from(config);
  EXPECT_EQ(run.technique.lp.grid, 64);
  EXPECT_TRUE(run.technique.lp.continuous);
  EXPECT_EQ(run.technique.lp.lo, 0);  // undeclared keys keep their defaults
  EXPECT_EQ(run.technique.lp.hi, 1);
  EXPECT_NE(testing_support::input_error_of([&] { config.set("lp.hi=2"); }), "");
  EXPECT_FALSE(
      scatter_run_options_from(Config(scatter_run_option_specs())).technique.lp.continuous);
  std::vector<OptionSpec> sweep_specs = scatter_sweep_option_specs();
  for (const auto& s : sweep_specs) EXPECT_NE(s.name.rfind("lp.", 0), 0u) << s.name;
  for (auto& s : lp_option_specs()) sweep_specs.push_back(s);
  Config sweep(sweep_specs);
  sweep.set("lp.grid=96");
  sweep.set("lp.discretization=continuous");
  const ScatterRunOptions swept = scatter_sweep_options_from(sweep);
  EXPECT_EQ(swept.technique.lp.grid, 96);
  EXPECT_TRUE(swept.technique.lp.continuous);
}

// pss_lp on the continuous interval at scatter.beta 0.5 (its maximum by reflection): the blend of
// its answers at 0 and 1, ray by ray, so its in-scattering lies between theirs.
TEST(ScatterPrefiltered, ContinuousLpBlendsItsBoundsAtAnyBeta) {
  const auto scenes = tiny();
  std::vector<std::vector<double>> inscatter;
  for (double beta : {0.0, 0.5, 1.0}) {
    ScatterRunOptions run = defaults({"pss_lp:power4"});
    run.technique.lp.continuous = true;
    run.beta = beta;
    const auto frames = run_on(scenes, run, 2);
    ASSERT_EQ(frames.size(), 1u);
    ASSERT_EQ(frames[0].inscatter.size(), 1u);
    inscatter.push_back(frames[0].inscatter[0]);
  }
  size_t between = 0, apart = 0;
  for (size_t p = 0; p < inscatter[0].size(); ++p) {
    const double lo = std::min(inscatter[0][p], inscatter[2][p]),
                 hi = std::max(inscatter[0][p], inscatter[2][p]);
    between += inscatter[1][p] >= lo - 1e-12 * hi && inscatter[1][p] <= hi + 1e-12 * hi;
    apart += hi - lo > 1e-6 * hi;
  }
  EXPECT_EQ(between, inscatter[0].size());
  EXPECT_GT(apart, inscatter[0].size() / 10);  // the bounds differ on many rays
}

}  // namespace
}  // namespace mb
