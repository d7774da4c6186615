#include "sweep/scatter_target.h"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "lp/solution.h"
#include "techniques/registry.h"
#include "util/name_list.h"
#include "util/parallel_errors.h"

namespace mb {

namespace {

// The rectified row's own visibility (docs/scattering.md §7): the row of role ExactReference.
const std::string& reference_name() {
  return role_name(TechniqueFamily::Scattering, RowRole::ExactReference);
}

// A pixel's error as ErrorStats counts it (see the header): nothing where the ray could scatter
// nothing.
void add_pixel(ErrorStats& stats, double reference, double inscatter, double s_max) {
  if (!(s_max > 0)) return;
  stats.add_weighted(1 - reference / s_max, 1 - inscatter / s_max, s_max);
}

class ScatterTarget : public SweepTarget {
 public:
  ScatterTarget(const std::vector<ScatterFrame>& frames, const ScatterRunOptions& options,
                int threads)
      : frames_(frames), params_(scatter_params(options)), threads_(threads) {
    candidate_params_ = params_;
    candidate_params_.beta = 0;
    const auto reference = make_scatter_technique(reference_name(), params_);
    for (const ScatterFrame& f : frames_) {
      reference->prepare(f.setup());
      reference_.push_back(frame_inscatter(*reference, f, threads_));
      std::vector<uint32_t> pixels;
      for (size_t p = 0; p < f.rays.size(); ++p)
        if (f.s_max[p] > 0) pixels.push_back(uint32_t(p));
      weight_ += [&] {
        double w = 0;
        for (uint32_t p : pixels) w += f.s_max[p];
        return w;
      }();
      pixels_.push_back(std::move(pixels));
    }
  }

  std::vector<std::string> view_names() const override {
    std::vector<std::string> names;
    for (const auto& f : frames_) names.push_back(f.name());
    return names;
  }
  uint64_t lp_fragments() const override {
    uint64_t n = 0;
    for (const auto& p : pixels_) n += p.size();
    return n;
  }

  CandidateResult evaluate(const Basis& basis,
                           std::vector<std::vector<double>>* answers) const override {
    const auto technique = make_scatter_technique(scatter_candidate_name(basis), candidate_params_);
    CandidateResult result;
    for (size_t v = 0; v < frames_.size(); ++v) {
      std::vector<double> inscatter(frames_[v].rays.size(), 0.0);
      const size_t failed = answer(*technique, v, pixels_[v], inscatter);
      result.unstable += failed;
      result.solved += pixels_[v].size() - failed;
      result.per_view.push_back(frame_stats(v, &inscatter));
      result.overall.merge(result.per_view.back());
      if (answers) answers->push_back(std::move(inscatter));
    }
    result.overall.failures = result.unstable;
    return result;
  }

  // Every LP failed: every ray answered as lit (I = S_max), as a failed ray is.
  CandidateResult unanswered() const override {
    CandidateResult result;
    result.unstable = lp_fragments();
    for (size_t v = 0; v < frames_.size(); ++v) {
      result.per_view.push_back(frame_stats(v, nullptr));
      result.overall.merge(result.per_view.back());
    }
    result.overall.failures = result.unstable;
    return result;
  }

  // Strata are light view and camera pairs; a unit is a segment of kScreenUnitColumns pixels of
  // one image row (its rays that can scatter light, in order).
  ScreenSample screen_sample(const std::vector<std::vector<double>>& pilot, double fraction,
                             uint64_t seed) const override {
    ScreenSample sample;
    sample.fraction = fraction;
    sample.weight = weight_;
    for (size_t v = 0; v < frames_.size(); ++v) {
      ScreenUnits units = image_row_units(pixels_[v], frames_[v].width, pixels_[v].size());
      for (size_t r = 0; r < units.units(); ++r)
        units.pilot.push_back(
            unit_error(v, units.items, units.begin[r], units.begin[r + 1], &pilot[v]));
      sample.strata.push_back(draw_screen_stratum(units, v, fraction, seed));
    }
    return sample;
  }

  std::vector<double> screen(const Basis& basis, const ScreenSample& sample,
                             CandidateResult* outcome) const override {
    const auto technique = make_scatter_technique(scatter_candidate_name(basis), candidate_params_);
    CandidateResult counts;
    std::vector<double> errors;
    for (size_t v = 0; v < frames_.size(); ++v) {
      const ScreenStratum& s = sample.strata[v];
      std::vector<double> inscatter(frames_[v].rays.size(), 0.0);
      const size_t failed = answer(*technique, v, s.list, inscatter);
      counts.unstable += failed;
      counts.solved += s.list.size() - failed;
      for (size_t r = 0; r < s.sampled(); ++r)
        errors.push_back(unit_error(v, s.list, s.run_begin[r], s.run_begin[r + 1], &inscatter));
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
    make_scatter_technique(name, params_);
  }

  ReferenceResult reference(const std::string& name) const override {
    const auto technique = make_scatter_technique(name, params_);
    ReferenceResult r;
    size_t failures = 0;
    for (size_t v = 0; v < frames_.size(); ++v) {
      std::vector<double> inscatter(frames_[v].rays.size(), 0.0);
      failures += answer(*technique, v, pixels_[v], inscatter);
      r.per_view.push_back(frame_stats(v, &inscatter));
      r.overall.merge(r.per_view.back());
    }
    r.overall.failures = failures;
    // What the row proves against pss_exact: a bound only at beta 0 (the LP's lower bound).
    const TechniqueRow& row = technique_row(name, TechniqueFamily::Scattering);
    if (row.solves_lp && params_.beta == 0) {
      r.darkening_bound = lp::kCertifiedError;
    } else {
      r.darkening_bound = std::numeric_limits<double>::infinity();
      r.darkening_reason = row.unproven_reason.empty()
                               ? "measured against pss_exact, not the reference it is exact for"
                               : row.unproven_reason;
    }
    return r;
  }

  // docs/scattering.md §3.2: at beta 0 the LP's sharp lower bound on the shadowed fraction of the
  // ray's own distribution never exceeds pss_exact's, beyond the LP's certified error.
  double candidate_darkening_bound() const override { return lp::kCertifiedError; }

 private:
  // I of `pixels` of frame v into `inscatter` (prepared per frame; rows of pixels in parallel,
  // each pixel on its own); the rays the technique failed on, answered lit by it.
  size_t answer(ScatterTechnique& technique, size_t v, const std::vector<uint32_t>& pixels,
                std::vector<double>& inscatter) const {
    const ScatterFrame& f = frames_[v];
    technique.prepare(f.setup());
    const size_t before = technique.failures();
    const long chunks = long((pixels.size() + 63) / 64);
    ParallelErrors parallel;
#pragma omp parallel for num_threads(threads_) schedule(dynamic, 1)
    for (long c = 0; c < chunks; ++c)
      parallel.capture([&] {
        const size_t end = std::min(pixels.size(), size_t(c + 1) * 64);
        for (size_t i = size_t(c) * 64; i < end; ++i) {
          const uint32_t p = pixels[i];
          inscatter[p] = technique.lit_length(f.rays[p]) * f.factor[p];
        }
      });
    parallel.rethrow();
    return technique.failures() - before;
  }

  // Frame v's statistics of `inscatter` (null: every ray lit, I = S_max).
  ErrorStats frame_stats(size_t v, const std::vector<double>* inscatter) const {
    ErrorStats stats;
    const ScatterFrame& f = frames_[v];
    for (uint32_t p : pixels_[v])
      add_pixel(stats, reference_[v][p], inscatter ? (*inscatter)[p] : f.s_max[p], f.s_max[p]);
    return stats;
  }

  // The error sum of pixels[begin, end) of frame v (null: I = S_max).
  double unit_error(size_t v, const std::vector<uint32_t>& pixels, size_t begin, size_t end,
                    const std::vector<double>* inscatter) const {
    ErrorStats unit;
    const ScatterFrame& f = frames_[v];
    for (size_t i = begin; i < end; ++i) {
      const uint32_t p = pixels[i];
      add_pixel(unit, reference_[v][p], inscatter ? (*inscatter)[p] : f.s_max[p], f.s_max[p]);
    }
    return unit.sum_abs;
  }

  const std::vector<ScatterFrame>& frames_;
  ScatterParams params_, candidate_params_;
  int threads_;
  std::vector<std::vector<double>> reference_;  // per frame, I of pss_exact per pixel
  std::vector<std::vector<uint32_t>> pixels_;   // per frame, the pixels with S_max > 0
  double weight_ = 0;
};

}  // namespace

std::string scatter_candidate_name(const Basis& basis) {
  return "pss_lp:" + joined(basis.names(), "; ");
}

std::unique_ptr<SweepTarget> make_scatter_target(const std::vector<ScatterFrame>& frames,
                                                 const ScatterRunOptions& options, int threads) {
  return std::make_unique<ScatterTarget>(frames, options, threads);
}

}  // namespace mb
