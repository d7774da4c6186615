#include "sweep/candidate_evaluation.h"

#include "eval/lp_view_solver.h"

namespace mb {

CandidateEvaluator::CandidateEvaluator(const std::vector<ViewData>& views,
                                       const EvalSettings& settings)
    : views_(views), settings_(settings) {
  for (const auto& v : views) needs_lp_.push_back(fragments_needing_lp(v.fragments));
}

uint64_t CandidateEvaluator::lp_fragments() const {
  uint64_t n = 0;
  for (const auto& l : needs_lp_) n += l.size();
  return n;
}

CandidateResult CandidateEvaluator::evaluate(const Basis& basis,
                                             std::vector<std::vector<double>>* shadow) const {
  const lp::ProblemFactory factory(basis, settings_.technique.lp);
  CandidateResult result;
  for (size_t v = 0; v < views_.size(); ++v) {
    LpViewAnswers answers = solve_lp_view(views_[v], needs_lp_[v], basis, factory, settings_);
    result.solved += answers.solved;
    result.infeasible += answers.infeasible;
    result.unstable += answers.unstable;
    ErrorStats stats;
    stats.add_all(views_[v].fragments.pcf, answers.shadow);
    result.overall.merge(stats);
    result.per_view.push_back(std::move(stats));
    if (shadow) shadow->push_back(std::move(answers.shadow));
  }
  result.overall.failures = result.infeasible + result.unstable;
  uint64_t total = 0;
  for (const auto& v : views_) total += v.fragments.size();
  result.skipped = total - result.solved - result.infeasible - result.unstable;
  return result;
}

std::vector<double> CandidateEvaluator::screen(const Basis& basis, const ScreenSample& sample,
                                               CandidateResult* outcome) const {
  const lp::ProblemFactory factory(basis, settings_.technique.lp);
  std::vector<std::vector<double>> shadow;
  CandidateResult counts;
  for (size_t v = 0; v < views_.size(); ++v) {
    const ScreenStratum& stratum = sample.strata[v];
    LpViewAnswers answers = solve_lp_view(views_[v], stratum.list, basis, factory, settings_,
                                          nullptr, &stratum.run_begin);
    counts.solved += answers.solved;
    counts.infeasible += answers.infeasible;
    counts.unstable += answers.unstable;
    shadow.push_back(std::move(answers.shadow));
  }
  if (outcome) *outcome = counts;
  return sampled_unit_errors(sample, views_, shadow);
}

}  // namespace mb
