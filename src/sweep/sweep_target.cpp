#include "sweep/sweep_target.h"

#include "techniques/lp_technique.h"
#include "techniques/technique.h"

namespace mb {

namespace {

class ShadowTarget : public SweepTarget {
 public:
  ShadowTarget(const std::vector<ViewData>& views, const EvalSettings& settings)
      : views_(views), settings_(settings), evaluator_(views, settings) {}

  std::vector<std::string> view_names() const override {
    std::vector<std::string> names;
    for (const auto& v : views_) names.push_back(v.scene + "/" + v.view);
    return names;
  }
  uint64_t lp_fragments() const override { return evaluator_.lp_fragments(); }
  CandidateResult evaluate(const Basis& basis,
                           std::vector<std::vector<double>>* answers) const override {
    return evaluator_.evaluate(basis, answers);
  }
  CandidateResult unanswered() const override {
    CandidateResult result;
    result.unstable = evaluator_.lp_fragments();
    for (const auto& view : views_) {
      ErrorStats stats;
      stats.add_all(view.fragments.pcf, std::vector<double>(view.fragments.size(), 0.0));
      result.overall.merge(stats);
      result.per_view.push_back(stats);
    }
    return result;
  }
  ScreenSample screen_sample(const std::vector<std::vector<double>>& pilot, double fraction,
                             uint64_t seed) const override {
    return make_screen_sample(views_, evaluator_.lp_lists(), pilot, fraction, seed);
  }
  std::vector<double> screen(const Basis& basis, const ScreenSample& sample,
                             CandidateResult* outcome) const override {
    return evaluator_.screen(basis, sample, outcome);
  }
  std::vector<double> unanswered_unit_errors(const ScreenSample& sample) const override {
    return sampled_unit_errors(sample, views_, {});
  }
  void check_reference(const std::string& name) const override {
    make_technique(name, settings_.technique);
  }
  ReferenceResult reference(const std::string& name) const override {
    auto technique = make_technique(name, settings_.technique);
    ReferenceResult r;
    for (const auto& view : views_) {
      TechniqueResult result = evaluate_technique(view, name, settings_, nullptr);
      ErrorStats stats;
      stats.add_all(view.fragments.pcf, result.shadow);
      stats.failures = result.failures;
      r.overall.merge(stats);
      r.per_view.push_back(stats);
    }
    r.darkening_bound = technique->darkening_bound();
    r.darkening_reason = technique->darkening_reason();
    return r;
  }
  double candidate_darkening_bound() const override { return kLpDarkeningBound; }

 private:
  const std::vector<ViewData>& views_;
  const EvalSettings& settings_;
  CandidateEvaluator evaluator_;
};

}  // namespace

std::unique_ptr<SweepTarget> make_shadow_target(const std::vector<ViewData>& views,
                                                const EvalSettings& settings) {
  return std::make_unique<ShadowTarget>(views, settings);
}

ScreenUnits image_row_units(const std::vector<uint32_t>& pixels, int width, uint64_t lps) {
  const uint64_t w = uint64_t(width);
  const uint64_t blocks = (w + kScreenUnitColumns - 1) / kScreenUnitColumns;
  const auto unit_of = [&](uint32_t p) { return p / w * blocks + p % w / kScreenUnitColumns; };
  ScreenUnits units;
  units.items = pixels;  // ascending pixel order is unit order
  units.lps = lps;
  for (size_t i = 0; i < units.items.size(); ++i)
    if (i == 0 || unit_of(units.items[i]) != unit_of(units.items[i - 1])) {
      units.begin.push_back(i);
      units.key.push_back(unit_of(units.items[i]));
    }
  units.begin.push_back(units.items.size());
  return units;
}

}  // namespace mb
