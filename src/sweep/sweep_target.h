#pragma once
// What a sweep measures its candidates on (docs/sweeps.md, "Targets"). `shadows`: a shadow
// dataset's views, Problem 1's G per receiver against PCF (docs/reference.md §3). `transparency`:
// a transparency dataset's camera frames, the LP's sharp absorbance bound per fragment against the
// exact transmittance (docs/transparency.md §7). `scattering`: a scattering dataset's light views
// and cameras, pss_lp:<candidate> at beta 0 per view ray against pss_exact (docs/scattering.md
// §7). The orchestration (sweep_run.cpp) sees only this interface, so resume, shards, screening
// and the results store are the same for all.
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "basis/basis.h"
#include "eval/evaluation.h"
#include "screen/screening.h"
#include "sweep/candidate_evaluation.h"

namespace mb {

// A reference technique on the whole target.
struct ReferenceResult {
  ErrorStats overall;
  std::vector<ErrorStats> per_view;
  double darkening_bound = 0;  // what the technique proves of its over-darkening
  std::string darkening_reason;
};

class SweepTarget {
 public:
  virtual ~SweepTarget() = default;
  // "scene/view" (or "scene/camera") of each stratum, in order.
  virtual std::vector<std::string> view_names() const = 0;
  virtual uint64_t lp_fragments() const = 0;  // LPs per candidate
  // A candidate on everything; with `answers`, its answer per work element of every view (what
  // screen_sample's pilot is).
  virtual CandidateResult evaluate(const Basis& basis,
                                   std::vector<std::vector<double>>* answers = nullptr) const = 0;
  // The row of a candidate that answers nothing (a numerically dependent combination): every LP
  // failed, the fragments shown lit.
  virtual CandidateResult unanswered() const = 0;
  // The screen's sample (screen/screening.h) with the pilot's answers (evaluate's `answers`).
  virtual ScreenSample screen_sample(const std::vector<std::vector<double>>& pilot, double fraction,
                                     uint64_t seed) const = 0;
  // The sampled units' error sums of a candidate; `outcome` gets its LP counts.
  virtual std::vector<double> screen(const Basis& basis, const ScreenSample& sample,
                                     CandidateResult* outcome) const = 0;
  // unanswered()'s unit errors.
  virtual std::vector<double> unanswered_unit_errors(const ScreenSample& sample) const = 0;
  // InputError for a reference name the target does not know (before anything is written).
  virtual void check_reference(const std::string& name) const = 0;
  virtual ReferenceResult reference(const std::string& name) const = 0;
  // What a candidate (the exact LP) proves of its over-darkening in this target's units.
  virtual double candidate_darkening_bound() const = 0;
  virtual std::string candidate_darkening_reason() const { return ""; }
};

// The screening units of one camera image (transparency and scattering): segments of
// kScreenUnitColumns pixels of one row, over `pixels` (ascending, the image `width` wide); `lps`
// the stratum's LPs. The pilot errors are left for the caller (ScreenUnits::pilot).
ScreenUnits image_row_units(const std::vector<uint32_t>& pixels, int width, uint64_t lps);

// Shadows: keeps references to `views` and `settings`.
std::unique_ptr<SweepTarget> make_shadow_target(const std::vector<ViewData>& views,
                                                const EvalSettings& settings);

}  // namespace mb
