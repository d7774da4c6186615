#pragma once
// Screening a sweep (issue 33): every candidate is evaluated on one stratified sample of the
// dataset's fragments, the same sample for all of them, and its mean error is estimated with a
// standard error; then the candidates whose interval reaches the best K are evaluated exactly.
//
// Units are segments of one shadow-map row and kScreenUnitColumns columns: a sampled unit is solved
// as a warm-start run of its own, so its answers agree with the full evaluation's to the LP's
// tolerance, not always bit for bit. Small units make the estimate precise and its standard error
// honest: errors cluster (contact shadows, silhouettes), and a large unit carries a whole cluster
// in or out of the sample at once, so that a few units hold most of the variance and a sample
// that misses them underrates it. Measured on the default dataset at F = 0.05 (docs/sweeps.md,
// "Calibration"): blocks of 8 rows (272 units sampled) missed the exact means by up to 13 standard
// errors, rows of 16 texels (1 992 units) by at most 3.5, with the same LPs per candidate.
//
// The estimator is the stratified difference estimator of survey sampling: strata are views, and
// the auxiliary variable is a pilot candidate's error sum of each unit, known for every unit from
// one exact evaluation. Candidates find the same fragments hard, so a candidate's unit errors
// follow the pilot's closely and only their differences are sampled: the standard error is that of
// the differences, several times smaller than that of the errors. Fragments without an LP
// (F_Z(z_f - delta_f) = 0, G = 0 for every candidate, docs/reference.md §2) are summed exactly once
// and never sampled.
#include <cstdint>
#include <span>
#include <vector>

#include "eval/evaluation.h"

namespace mb {

// Columns of a screening unit (one texel row).
constexpr int kScreenUnitColumns = 16;

// One stratum: a view's units that have LP fragments.
struct ScreenStratum {
  std::vector<uint32_t> list;     // the LP fragments of the sampled units, unit by unit
  std::vector<size_t> run_begin;  // where each sampled unit begins in `list`, size appended
  size_t runs = 0;                // the view's units (with LP fragments)
  uint64_t lps = 0;               // the view's LP fragments
  double pilot_total = 0;         // the pilot's error sum over all the view's units
  std::vector<double> pilot;      // the pilot's error sum of each sampled unit
  size_t sampled() const { return run_begin.empty() ? 0 : run_begin.size() - 1; }
};

struct ScreenSample {
  double fraction = 0;
  std::vector<ScreenStratum> strata;  // one per view, in view order
  double fixed_error = 0;             // sum of |PCF - 0| over the fragments without an LP
  // The mean's denominator: every receiver of every view (shadows), or the opacity of every
  // transparent fragment (transparency, whose errors are opacity-weighted).
  double weight = 0;
  size_t sampled_runs() const;  // sampled units over all strata: a run-error vector's size
  uint64_t sampled_lps() const;
  size_t runs() const;
};

// One stratum's units before the draw, as a sweep target cuts its work: each unit's LP work items
// in order (fragments, or pixels for transparency), the key the seeded draw hashes, and the
// pilot's error sum of each unit.
struct ScreenUnits {
  std::vector<uint32_t> items;  // unit by unit
  std::vector<size_t> begin;    // where each unit begins in `items`, size appended
  std::vector<uint64_t> key;    // per unit: unique within the stratum
  std::vector<double> pilot;    // per unit
  uint64_t lps = 0;             // the stratum's LPs
  size_t units() const { return begin.empty() ? 0 : begin.size() - 1; }
};
// Stratum `index` of a sample: ceil(fraction x its units) of them (at least 2 where it has 2, all
// with fraction >= 1), chosen by a seeded hash of (seed, index, key), identical for every
// candidate.
ScreenStratum draw_screen_stratum(const ScreenUnits& units, size_t index, double fraction,
                                  uint64_t seed);

// The sample: in each view, ceil(fraction x its units) of them (at least 2 where it has 2, all
// with fraction >= 1), chosen by a seeded hash of (seed, view, unit), identical for every
// candidate. `needs_lp` per view: its LP fragments, ascending (CandidateEvaluator's lists);
// `pilot_shadow` per view: the pilot's G of every fragment (CandidateEvaluator::evaluate's
// `shadow`).
ScreenSample make_screen_sample(const std::vector<ViewData>& views,
                                const std::vector<std::vector<uint32_t>>& needs_lp,
                                const std::vector<std::vector<double>>& pilot_shadow,
                                double fraction, uint64_t seed);

// Sum of |PCF - G| over `fragments` in their order, G from `shadow` (by fragment index; null:
// every fragment lit, G = 0).
double unit_error(std::span<const uint32_t> fragments, const std::vector<double>& pcf,
                  const std::vector<double>* shadow);
// Every sampled unit's error sum, strata in order, with `shadow` per view (G by fragment index);
// no shadows: a candidate that answers nothing (G = 0), how the sweep records a numerically
// dependent combination.
std::vector<double> sampled_unit_errors(const ScreenSample& sample,
                                        const std::vector<ViewData>& views,
                                        const std::vector<std::vector<double>>& shadow);

// A candidate's screened mean error: the estimate and its standard error.
struct ScreenEstimate {
  double mean = 0, se = 0;
};
// From the sampled units' error sums (sum of |PCF - G| over each unit's fragments, strata in
// order).
ScreenEstimate estimate_mean_error(const ScreenSample& sample,
                                   const std::vector<double>& run_errors);
// The estimate is linear in the run errors: the estimated difference of two candidates' mean
// errors is the difference of their estimates, and this is its standard error, from the run-wise
// differences a_i - b_i.
double paired_standard_error(const ScreenSample& sample, const std::vector<double>& a,
                             const std::vector<double>& b);

// Which candidates to evaluate exactly (indices into `run_errors`, ascending): the `top` best
// estimates, and with r the top-th, every candidate c with
//   est_c - est_r - sigmas * SE(c - r) <= margin,
// the standard error taken of the paired unit-wise differences (the same sample makes them far
// less noisy than either mean). With margin = 0 the exact top K among them is the exact top K
// unless an estimate missed by more than `sigmas` standard errors. A negative margin makes
// differences smaller than |margin| ties: a candidate is then evaluated only if it may beat the
// top-th estimate by more than that, which on a plateau of near-ties (docs/reference.md §5; ~10 000
// candidates within 0.01 pp of the best on the default dataset) keeps the confirmations few.
// Every candidate when there are at most `top`.
struct ScreenRule {
  int top = 20;
  double sigmas = 3, margin = 0;
};
std::vector<size_t> candidates_to_confirm(const ScreenSample& sample,
                                          const std::vector<std::vector<double>>& run_errors,
                                          const ScreenRule& rule);

// Screening at full scale (docs/sweeps.md, "Full scale"). A candidate's unit errors are what the
// confirmation pairs it by, and they are most of a sweep's database (16 KB a candidate on the
// default dataset). A shard that has screened its candidates keeps them only for those that may
// reach the sweep's best; for every other candidate c it keeps
//   reach_lower(c) = est_c - sigmas * SE(c - r),
// r its own K-th best estimate. The standard error is a seminorm of the unit errors (the root of a
// sum of squares of a linear map of them), so SE(c - r') <= SE(c - r) + SE(r - r') for the
// sweep's K-th best r', and
//   est_c - est_r' - sigmas * SE(c - r') >= reach_lower(c) - est_r' - sigmas * SE(r - r'):
// when the right side exceeds the margin, c is out of reach of the whole sweep, proven from r's
// and r''s unit errors alone (r is its shard's K-th best and r' the sweep's, and no K-th best
// that a screened-out candidate names ever drops its own; sweep/screen_reach.h).

// Whether candidate c keeps its unit errors: among the best K (`best`), or within `keep_sigmas`
// paired standard errors of the K-th best r (by the rule's margin). keep_sigmas >= rule.sigmas
// keeps every candidate in reach of r; a larger value leaves room for the sweep's r' to differ
// from the shard's, so that the proof above holds for nearly all the others.
bool keeps_unit_errors(const ScreenSample& sample, const std::vector<double>& c, double mean_c,
                       const std::vector<double>& r, double mean_r, bool best,
                       const ScreenRule& rule, double keep_sigmas);
// est_c - sigmas * SE(c - r): what a screened-out candidate keeps.
double reach_lower_bound(const ScreenSample& sample, const std::vector<double>& c, double mean_c,
                         const std::vector<double>& r, const ScreenRule& rule);
// Whether a candidate screened out against r (`reach_lower`) is proven out of reach of r' (mean
// `mean_rp`, unit errors `rp`), by the inequality above with a margin of rounding.
bool proven_out_of_reach(const ScreenSample& sample, double reach_lower,
                         const std::vector<double>& r, const std::vector<double>& rp,
                         double mean_rp, const ScreenRule& rule);

}  // namespace mb
