#include "sweep/oit_target.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "techniques/lp_technique.h"
#include "techniques/registry.h"
#include "util/name_list.h"
#include "util/parallel_errors.h"

namespace mb {

namespace {

// A camera frame's candidate-independent data: per fragment (frame order) the warped depth and
// the exact transmittance; the pixels that need LPs (two or more fragments), ascending.
struct FramePlan {
  std::vector<double> warped, reference;
  std::vector<uint32_t> lp_pixels;
  uint64_t lp_fragments = 0;
  double weight = 0;
};

FramePlan plan_frame(const DeepFrame& frame, WarpKind kind, DepthRangeKind range) {
  FramePlan plan;
  const DepthWarp warp = frame_warp(frame, kind, range);
  plan.warped.resize(frame.fragments());
  plan.reference.resize(frame.fragments());
  for (size_t f = 0; f < frame.fragments(); ++f) plan.warped[f] = warp(frame.depth[f]);
  for (size_t p = 0; p < frame.pixels(); ++p) {
    const PixelFragments px = pixel_of(frame, p);
    const size_t first = frame.offsets[p];
    exact_transmittance(px, std::span(plan.reference).subspan(first, px.size()));
    for (double a : px.alpha) plan.weight += a;
    if (px.size() < 2) continue;
    plan.lp_pixels.push_back(uint32_t(p));
    plan.lp_fragments += px.size();
  }
  return plan;
}

constexpr const char* kRoundingReason =
    "not proven: the moments of close fragments, rounded to double, move the LP's bound "
    "(docs/transparency.md §7)";

// The candidate's technique name: the LP of its functions.
std::string lp_name(const Basis& basis) {
  return lp_technique_name(joined(basis.names(), "; "));
}

class OitTarget : public SweepTarget {
 public:
  OitTarget(const std::vector<SceneFrame>& frames, const OitParams& params, int threads)
      : frames_(frames), params_(params), threads_(threads) {
    for (const auto& f : frames_)
      plans_.push_back(plan_frame(f.frame, params_.warp, params_.depth_range));
  }

  std::vector<std::string> view_names() const override {
    std::vector<std::string> names;
    for (const auto& f : frames_) names.push_back(f.scene + "/" + f.frame.camera);
    return names;
  }
  uint64_t lp_fragments() const override {
    uint64_t n = 0;
    for (const auto& p : plans_) n += p.lp_fragments;
    return n;
  }

  CandidateResult evaluate(const Basis& basis,
                           std::vector<std::vector<double>>* answers) const override {
    CandidateResult result;
    for (size_t v = 0; v < frames_.size(); ++v) {
      std::vector<double> t(frames_[v].frame.fragments(), 1.0);
      const size_t failed = solve_pixels(v, plans_[v].lp_pixels, basis, t);
      result.unstable += failed;
      result.solved += plans_[v].lp_fragments - failed;
      result.per_view.push_back(frame_stats(v, &t));
      result.overall.merge(result.per_view.back());
      if (answers) answers->push_back(std::move(t));
    }
    finish(result);
    return result;
  }

  CandidateResult unanswered() const override {
    CandidateResult result;
    result.unstable = lp_fragments();
    for (size_t v = 0; v < frames_.size(); ++v) {
      result.per_view.push_back(frame_stats(v, nullptr));
      result.overall.merge(result.per_view.back());
    }
    finish(result);
    return result;
  }

  // Strata are cameras; a unit is a segment of kScreenUnitColumns pixels of one row, its LP
  // pixels in order. Single-fragment pixels add nothing to any candidate's error.
  ScreenSample screen_sample(const std::vector<std::vector<double>>& pilot, double fraction,
                             uint64_t seed) const override {
    ScreenSample sample;
    sample.fraction = fraction;
    for (size_t v = 0; v < frames_.size(); ++v) {
      sample.weight += plans_[v].weight;
      ScreenUnits units =
          image_row_units(plans_[v].lp_pixels, frames_[v].frame.width, plans_[v].lp_fragments);
      for (size_t r = 0; r < units.units(); ++r)
        units.pilot.push_back(
            unit_error(v, units.items, units.begin[r], units.begin[r + 1], &pilot[v]));
      sample.strata.push_back(draw_screen_stratum(units, v, fraction, seed));
    }
    return sample;
  }

  std::vector<double> screen(const Basis& basis, const ScreenSample& sample,
                             CandidateResult* outcome) const override {
    CandidateResult counts;
    std::vector<double> errors;
    for (size_t v = 0; v < frames_.size(); ++v) {
      const ScreenStratum& s = sample.strata[v];
      std::vector<double> t(frames_[v].frame.fragments(), 1.0);
      const size_t failed = solve_pixels(v, s.list, basis, t);
      uint64_t fragments = 0;
      for (uint32_t p : s.list)
        fragments += frames_[v].frame.offsets[p + 1] - frames_[v].frame.offsets[p];
      counts.unstable += failed;
      counts.solved += fragments - failed;
      for (size_t r = 0; r < s.sampled(); ++r)
        errors.push_back(unit_error(v, s.list, s.run_begin[r], s.run_begin[r + 1], &t));
    }
    if (outcome) *outcome = counts;
    return errors;
  }

  std::vector<double> unanswered_unit_errors(const ScreenSample& sample) const override {
    std::vector<double> errors;
    for (size_t v = 0; v < frames_.size(); ++v) {
      const ScreenStratum& s = sample.strata[v];
      for (size_t r = 0; r < s.sampled(); ++r)
        errors.push_back(unit_error(v, s.list, s.run_begin[r], s.run_begin[r + 1], nullptr));
    }
    return errors;
  }

  void check_reference(const std::string& name) const override {
    make_oit_technique(name, params_);
  }

  // As `oit` measures it: the transmittance the composite weighs each fragment with.
  ReferenceResult reference(const std::string& name) const override {
    ReferenceResult r;
    size_t failures = 0;
    for (size_t v = 0; v < frames_.size(); ++v) {
      const DeepFrame& frame = frames_[v].frame;
      std::vector<double> t(frame.fragments(), 1.0);
      std::vector<uint32_t> all(frame.pixels());
      for (size_t p = 0; p < all.size(); ++p) all[p] = uint32_t(p);
      failures += for_each_pixel(v, all, name, true, t);
      r.per_view.push_back(frame_stats(v, &t));
      r.overall.merge(r.per_view.back());
    }
    r.overall.failures = failures;
    const auto bound = reference_bound(name);
    r.darkening_bound = bound.first;
    r.darkening_reason = bound.second;
    return r;
  }

  // Not proven (docs/transparency.md §7): the LP is certified for the moments as rounded to
  // double, and where two fragments of a pixel lie close in warped depth, that rounding moves the
  // sharp bound past the certificate (fragments 2.3e-4 apart: G above the pixel's own mass in
  // front by 3.9e-7, which the exact LP of the same rounded moments confirms).
  double candidate_darkening_bound() const override {
    return std::numeric_limits<double>::infinity();
  }
  std::string candidate_darkening_reason() const override { return kRoundingReason; }

 private:
  // Solves `pixels` of frame v with the candidate's LP into t (frame order); failed fragments.
  size_t solve_pixels(size_t v, const std::vector<uint32_t>& pixels, const Basis& basis,
                      std::vector<double>& t) const {
    const std::string name = lp_name(basis);
    make_oit_technique(name, params_);  // a dependent basis fails here, not in the threads
    return for_each_pixel(v, pixels, name, false, t);
  }

  // Runs technique `name` on `pixels` (rows in parallel, each pixel on its own, so the answers are
  // the same for any thread count), its transmittance per fragment into t; with `effective`, the
  // weight the composite uses (techniques/oit/oit_technique.h). Returns the technique's failures.
  size_t for_each_pixel(size_t v, const std::vector<uint32_t>& pixels, const std::string& name,
                        bool effective, std::vector<double>& t) const {
    const DeepFrame& frame = frames_[v].frame;
    const FramePlan& plan = plans_[v];
    const long chunks = long((pixels.size() + 63) / 64);
    ParallelErrors parallel;
    size_t failed = 0;
#pragma omp parallel num_threads(threads_) reduction(+ : failed)
    {
      auto technique = make_oit_technique(name, params_);
#pragma omp for schedule(dynamic, 1)
      for (long c = 0; c < chunks; ++c)
        parallel.capture([&] {
          const size_t end = std::min(pixels.size(), size_t(c + 1) * 64);
          for (size_t i = size_t(c) * 64; i < end; ++i) {
            const PixelFragments px = pixel_of(frame, pixels[i]);
            const size_t first = frame.offsets[pixels[i]];
            const std::span<double> out(t.data() + first, px.size());
            technique->transmittance(
                px, std::span<const double>(plan.warped).subspan(first, px.size()), out);
            if (effective) effective_transmittance(*technique, px, out);
          }
        });
      failed += technique->failures();
    }
    parallel.rethrow();
    return failed;
  }

  // Frame v's statistics of transmittance t (frame order; null: T = 1 everywhere).
  ErrorStats frame_stats(size_t v, const std::vector<double>* t) const {
    ErrorStats stats;
    const FramePlan& plan = plans_[v];
    const DeepFrame& frame = frames_[v].frame;
    for (size_t f = 0; f < frame.fragments(); ++f)
      stats.add_weighted(1 - plan.reference[f], 1 - (t ? (*t)[f] : 1.0), frame.alpha[f]);
    return stats;
  }

  // The error sum of pixels[begin, end) of frame v (t null: T = 1).
  double unit_error(size_t v, const std::vector<uint32_t>& pixels, size_t begin, size_t end,
                    const std::vector<double>* t) const {
    const DeepFrame& frame = frames_[v].frame;
    ErrorStats unit;  // the tables' per-fragment error, summed in fragment order
    for (size_t i = begin; i < end; ++i)
      for (uint64_t f = frame.offsets[pixels[i]]; f < frame.offsets[pixels[i] + 1]; ++f)
        unit.add_weighted(1 - plans_[v].reference[f], 1 - (t ? (*t)[f] : 1.0), frame.alpha[f]);
    return unit.sum_abs;
  }

  void finish(CandidateResult& result) const {
    result.overall.failures = result.unstable;
    uint64_t total = 0;
    for (const auto& f : frames_) total += f.frame.fragments();
    result.skipped = total - result.solved - result.unstable;
  }

  // What a reference technique proves about transmittance below T_ref.
  std::pair<double, std::string> reference_bound(const std::string& name) const {
    const TechniqueRow& row = technique_row(name, TechniqueFamily::Transmittance);
    if (row.solves_lp) return {candidate_darkening_bound(), kRoundingReason};
    if (row.unproven_reason.empty()) return {0, ""};
    return {std::numeric_limits<double>::infinity(), row.unproven_reason};
  }

  const std::vector<SceneFrame>& frames_;
  OitParams params_;
  int threads_;
  std::vector<FramePlan> plans_;
};

}  // namespace

std::unique_ptr<SweepTarget> make_oit_target(const std::vector<SceneFrame>& frames,
                                             const OitParams& params, int threads) {
  return std::make_unique<OitTarget>(frames, params, threads);
}

}  // namespace mb
