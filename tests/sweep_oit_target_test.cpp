// The transparency sweep target (sweep/oit_target.h): a candidate's error is the opacity-weighted
// |T_ref - T| of its LP, computed here independently per pixel; the sharp bound never puts T below
// T_ref where fragments are apart; the same numbers for any thread count; screening a whole frame
// gives the exact mean; MBOIT's normalisation splits its error evenly (Gamma makes
// sum alpha_l T_l exact in every pixel, as blending in any order does).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "shadow/compositing.h"
#include "sweep/oit_target.h"
#include "util/error.h"

namespace mb {
namespace {

// w x h pixels of 0..6 fragments each at depths in [1, 3] at least `gap` apart, opacities in
// [0.05, 0.7], in a shuffled submission order.
DeepFrame random_frame(int w, int h, uint64_t seed, double gap) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  DeepFrame f;
  f.camera = "cam" + std::to_string(seed);
  f.width = w, f.height = h;
  f.offsets.push_back(0);
  for (int p = 0; p < w * h; ++p) {
    const int n = int(rng() % 7);
    std::vector<double> depths;
    while (int(depths.size()) < n) {
      const double z = 1 + 2 * unit(rng);
      bool apart = true;
      for (double d : depths) apart = apart && std::abs(d - z) >= gap;
      if (apart) depths.push_back(z);
    }
    for (double z : depths) {
      f.depth.push_back(z);
      f.alpha.push_back(0.05 + 0.65 * unit(rng));
      f.color.push_back({float(unit(rng)), 0.5f, 0.5f});
    }
    f.offsets.push_back(f.depth.size());
    f.behind.push_back(kBackground);
    f.behind_depth.push_back(4);
  }
  return f;
}

struct Frames {
  std::vector<SceneFrame> frames;
  Frames(double gap) {
    frames.push_back({"a", random_frame(40, 5, 1, gap)});
    frames.push_back({"b", random_frame(23, 7, 2, gap)});
  }
};

OitParams lp_params() {
  OitParams p;
  p.technique.lp.grid = 64;
  return p;
}

TEST(OitTarget, CandidateErrorIsTheOpacityWeightedTransmittanceErrorOfItsLp) {
  const Frames data(0.02);
  const OitParams params = lp_params();
  const auto target = make_oit_target(data.frames, params, 2);
  const CandidateResult r = target->evaluate(Basis::parse({"z", "z^2", "z^3", "z^4"}));
  // By hand: every pixel through `oit`'s technique, one at a time.
  auto lp = make_oit_technique("lp:power4", params);
  double error = 0, alpha = 0;
  uint64_t lps = 0;
  for (const auto& [scene, frame] : data.frames) {
    const DepthWarp warp = DepthWarp::between(frame.nearest(), frame.farthest());
    for (size_t p = 0; p < frame.pixels(); ++p) {
      const PixelFragments px = pixel_of(frame, p);
      std::vector<double> u, t(px.size()), t_ref(px.size());
      for (double z : px.depth) u.push_back(warp(z));
      exact_transmittance(px, t_ref);
      lp->transmittance(px, u, t);
      if (px.size() >= 2) lps += px.size();
      for (size_t l = 0; l < px.size(); ++l)
        error += px.alpha[l] * std::abs(t[l] - t_ref[l]), alpha += px.alpha[l];
    }
  }
  ASSERT_GT(error, 0);
  EXPECT_NEAR(r.overall.mean(), error / alpha, 1e-12 * error / alpha);
  EXPECT_EQ(target->lp_fragments(), lps);
  EXPECT_EQ(r.solved + r.unstable, lps);
  EXPECT_EQ(r.overall.count, r.solved + r.unstable + r.skipped);
  EXPECT_EQ(r.per_view.size(), 2u);
  EXPECT_EQ(target->view_names(), (std::vector<std::string>{"a/cam1", "b/cam2"}));
}

TEST(OitTarget, SharpBoundsNeverUnderestimateTransmittanceWhereFragmentsAreApart) {
  const Frames data(0.05);
  const auto target = make_oit_target(data.frames, lp_params(), 2);
  for (const auto& functions : std::vector<std::vector<std::string>>{
           {"z", "z^2", "z^3", "z^4"},
           {"sin(2 pi z)", "cos(2 pi z)", "sin(4 pi z)", "cos(4 pi z)"},
           {"exp(z)", "exp(-z)", "log(1+z)", "z"}}) {
    const CandidateResult r = target->evaluate(Basis::parse(functions));
    // (sin, cos of 2 pi z cannot tell u = 0 from u = 1: a rare LP there fails, T = 1.)
    EXPECT_LE(r.unstable * 100, target->lp_fragments()) << functions[0];
    EXPECT_LE(r.overall.max_dark, 1e-9) << functions[0];
    EXPECT_NEAR(r.overall.leak(), r.overall.mean(), 1e-9) << functions[0];
    EXPECT_GT(r.overall.mean(), 0) << functions[0];
  }
}

TEST(OitTarget, SameNumbersForAnyThreadCount) {
  const Frames data(0.0);
  const Basis basis = Basis::parse({"z", "exp(-4z)", "sin(pi z)", "1/(1+z)"});
  const CandidateResult one = make_oit_target(data.frames, lp_params(), 1)->evaluate(basis);
  const CandidateResult three = make_oit_target(data.frames, lp_params(), 3)->evaluate(basis);
  for (size_t v = 0; v < 2; ++v) {
    EXPECT_EQ(one.per_view[v].sum_abs, three.per_view[v].sum_abs);
    EXPECT_EQ(one.per_view[v].max, three.per_view[v].max);
    EXPECT_EQ(one.per_view[v].histogram, three.per_view[v].histogram);
  }
}

TEST(OitTarget, ScreeningTheWholeFrameIsExactAndUnitsMatchTheFullEvaluation) {
  const Frames data(0.0);
  const auto target = make_oit_target(data.frames, lp_params(), 2);
  const Basis pilot = Basis::parse({"z", "z^2", "z^3", "z^4"});
  const Basis other = Basis::parse({"z", "exp(z)", "exp(-z)", "log(1+z)"});
  std::vector<std::vector<double>> answers;
  target->evaluate(pilot, &answers);
  const CandidateResult exact = target->evaluate(other);
  const ScreenSample all = target->screen_sample(answers, 1.0, 7);
  const ScreenEstimate e = estimate_mean_error(all, target->screen(other, all, nullptr));
  EXPECT_NEAR(e.mean, exact.overall.mean(), 1e-14);
  EXPECT_EQ(e.se, 0);
  // A partial sample: the pilot's own unit errors, solved again unit by unit, are the recorded
  // pilot values bit for bit (each pixel is solved on its own).
  const ScreenSample half = target->screen_sample(answers, 0.5, 7);
  const std::vector<double> units = target->screen(pilot, half, nullptr);
  std::vector<double> recorded;
  for (const auto& s : half.strata) recorded.insert(recorded.end(), s.pilot.begin(), s.pilot.end());
  EXPECT_EQ(units, recorded);
  EXPECT_LT(half.sampled_runs(), all.sampled_runs());
  const ScreenEstimate h = estimate_mean_error(half, target->screen(other, half, nullptr));
  EXPECT_GT(h.se, 0);
  EXPECT_LT(std::abs(h.mean - exact.overall.mean()), 5 * h.se + 1e-12);
}

TEST(OitTarget, ReferencesAsOitMeasuresThem) {
  const Frames data(0.0);
  const auto target = make_oit_target(data.frames, lp_params(), 2);
  EXPECT_EQ(target->reference("exact").overall.mean(), 0);
  // Gamma = (1 - T_total) / sum alpha_l T_l makes sum alpha_l T_l = 1 - T_total, which blending
  // in any order satisfies (the sum telescopes): the signed errors cancel in every pixel.
  for (const char* name : {"mboit_power4", "wboit", "mboit_trig3", "unsorted"}) {
    const ReferenceResult r = target->reference(name);
    EXPECT_GT(r.overall.mean(), 0.001) << name;
    EXPECT_NEAR(r.overall.leak(), r.overall.dark(), 1e-12) << name;
    EXPECT_TRUE(std::isinf(r.darkening_bound)) << name;
  }
  EXPECT_THROW(target->check_reference("mboit_power5"), InputError);
}

TEST(OitTarget, AnUnansweredCandidateShowsEveryFragmentUnoccluded) {
  const Frames data(0.0);
  const auto target = make_oit_target(data.frames, lp_params(), 2);
  double error = 0, alpha = 0;
  for (const auto& [scene, frame] : data.frames)
    for (size_t p = 0; p < frame.pixels(); ++p) {
      const PixelFragments px = pixel_of(frame, p);
      std::vector<double> t_ref(px.size());
      exact_transmittance(px, t_ref);
      for (size_t l = 0; l < px.size(); ++l)
        error += px.alpha[l] * (1 - t_ref[l]), alpha += px.alpha[l];
    }
  const CandidateResult r = target->unanswered();
  EXPECT_NEAR(r.overall.mean(), error / alpha, 1e-14);
  EXPECT_EQ(r.unstable, target->lp_fragments());
}

}  // namespace
}  // namespace mb
