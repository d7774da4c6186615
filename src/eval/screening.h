#pragma once
// Screening a sweep (issue 33): every candidate is evaluated on one stratified sample of the
// dataset's warm-start runs, the same sample for all of them, and its mean error is estimated
// with a standard error; then the candidates whose interval reaches the best K are evaluated
// exactly. A sampled run is solved exactly as the full evaluation solves it (runs start from
// scratch, eval/warm_runs.h), so a run's error sum is the same bits in both.
//
// The estimator is the stratified difference estimator of survey sampling: strata are views, units
// are warm-start runs, and the auxiliary variable is a pilot candidate's error sum of each run,
// known for every run from one exact evaluation. Candidates find the same fragments hard, so a
// candidate's run errors follow the pilot's closely and only their differences are sampled: the
// standard error is that of the differences, several times smaller than that of the run errors.
// Fragments without an LP (F_Z(z_f - delta_f) = 0, G = 0 for every candidate, REFERENCE.md §2) are
// summed exactly once and never sampled.
#include <cstdint>
#include <vector>

#include "eval/evaluation.h"

namespace mb {

// One stratum: a view's warm-start runs that have LP fragments.
struct ScreenStratum {
  std::vector<uint32_t> list;     // the LP fragments of the sampled runs, ascending
  std::vector<size_t> run_begin;  // where each sampled run begins in `list`, size appended
  size_t runs = 0;                // the view's runs
  uint64_t lps = 0;               // the view's LP fragments
  double pilot_total = 0;         // the pilot's error sum over all the view's runs
  std::vector<double> pilot;      // the pilot's error sum of each sampled run
  size_t sampled() const { return run_begin.empty() ? 0 : run_begin.size() - 1; }
};

struct ScreenSample {
  double fraction = 0;
  std::vector<ScreenStratum> strata;  // one per view, in view order
  double fixed_error = 0;             // sum of |PCF - 0| over the fragments without an LP
  uint64_t fragments = 0;             // every receiver of every view
  size_t sampled_runs() const;        // over all strata: the length of a run-error vector
  uint64_t sampled_lps() const;
  size_t runs() const;
};

// The sample: in each view, ceil(fraction x its runs) of them (at least 2 where it has 2, all with
// fraction >= 1), chosen by a seeded hash of (seed, view, run), identical for every candidate.
// `needs_lp` per view: its LP fragments, ascending (CandidateEvaluator's lists); `pilot_shadow`
// per view: the pilot's G of every fragment (CandidateEvaluator::evaluate's `shadow`).
ScreenSample make_screen_sample(const std::vector<ViewData>& views,
                                const std::vector<std::vector<uint32_t>>& needs_lp,
                                const std::vector<std::vector<double>>& pilot_shadow,
                                double fraction, uint64_t seed);

// A candidate's screened mean error: the estimate and its standard error.
struct ScreenEstimate {
  double mean = 0, se = 0;
};
// From the sampled runs' error sums (sum of |PCF - G| over each run's fragments, strata in order).
// Linear in `run_errors`: the estimate of a difference of candidates is the difference of their
// estimates, and its standard error is this function's of the run-wise differences.
ScreenEstimate estimate_mean_error(const ScreenSample& sample,
                                   const std::vector<double>& run_errors);

// Which candidates to evaluate exactly (indices into `run_errors`, ascending): with r the K-th best
// estimate, every candidate c with  est_c - est_r - sigmas * SE(c - r) <= margin,  the standard
// error taken of the paired run-wise differences (the same sample makes them far less noisy than
// either mean). Every candidate when there are at most `top`.
struct ScreenRule {
  int top = 20;
  double sigmas = 3, margin = 0;
};
std::vector<size_t> candidates_to_confirm(const ScreenSample& sample,
                                          const std::vector<std::vector<double>>& run_errors,
                                          const ScreenRule& rule);

}  // namespace mb
