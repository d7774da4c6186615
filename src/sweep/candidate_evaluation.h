#pragma once
// One sweep candidate (a basis) on every view of a dataset with the LP (docs/reference.md §3, §5;
// docs/design.md §Performance): basis columns of every texel's layer-0 depth once per view,
// exact skip of fragments with F_Z(z_f - delta) = 0 (G = 0 there, docs/reference.md §2), one LP per
// remaining fragment, errors reduced in fragment order so the result is independent of threads.
#include <cstdint>
#include <vector>

#include "basis/basis.h"
#include "eval/error_stats.h"
#include "eval/evaluation.h"
#include "screen/screening.h"

namespace mb {

struct CandidateResult {
  ErrorStats overall;
  std::vector<ErrorStats> per_view;
  uint64_t solved = 0, skipped = 0, infeasible = 0, unstable = 0;
};

class CandidateEvaluator {
 public:
  // Keeps a reference to `views`; finds the fragments that need an LP (candidate-independent).
  CandidateEvaluator(const std::vector<ViewData>& views, const EvalSettings& settings);
  // With `shadow`, also G per fragment of every view (in fragment order), for tests and images.
  CandidateResult evaluate(const Basis& basis,
                           std::vector<std::vector<double>>* shadow = nullptr) const;
  uint64_t lp_fragments() const;  // LPs per candidate
  // Per view, the fragments that need an LP (ascending): what a screening sample is drawn from.
  const std::vector<std::vector<uint32_t>>& lp_lists() const { return needs_lp_; }
  const std::vector<ViewData>& views() const { return views_; }
  // The sampled units' error sums, sum |PCF - G| of each (screen/screening.h), strata in order;
  // each unit is a warm-start run of its own, so its answers are the full evaluation's optima (to
  // the LP's tolerance). `outcome` (optional) gets the LP counts.
  std::vector<double> screen(const Basis& basis, const ScreenSample& sample,
                             CandidateResult* outcome = nullptr) const;

 private:
  const std::vector<ViewData>& views_;
  EvalSettings settings_;
  std::vector<std::vector<uint32_t>> needs_lp_;  // per view: fragment indices with F_Z > 0
};

}  // namespace mb
