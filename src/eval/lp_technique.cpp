#include "eval/lp_technique.h"

#include "lp/discretized.h"
#include "lp/solution.h"
#include "util/error.h"

namespace mb {

namespace {

class LpTechnique : public Technique {
 public:
  LpTechnique(const std::string& name, Basis basis, const lp::Discretization& disc,
              const std::string& backend)
      : Technique(name, std::move(basis), double_storage()),
        factory_(
            (lp::check_backend_rows(backend, int(this->basis().size()), "technique '" + name + "'"),
             this->basis().check_independent(disc.lo, disc.hi), this->basis()),
            disc),
        backend_(lp::make_backend(backend)) {}
  bool needs_distribution() const override { return true; }
  double darkening_bound() const override { return kLpDarkeningBound; }
  const lp::ProblemFactory* lp_factory() const override { return &factory_; }

  double shadow(const FragmentInput& in) override {
    // REFERENCE.md §2: G <= F_Z(z_f), so F_Z(z_f) = 0 gives G = 0 without solving (z_f here is
    // already z_f - delta_f, REFERENCE.md §3).
    double cdf = 0;
    for (size_t t = 0; t < in.kernel_depths.size(); ++t)
      if (in.kernel_depths[t] < in.zf) cdf += in.kernel_weights[t];
    if (cdf == 0) return 0;
    // The kernel's own distribution fixes the moments, so the program is feasible by construction.
    // One fragment alone, from scratch: evaluate_technique solves whole views with warm starts
    // instead (solve_lp_view), to the same certified answers.
    lp::Problem problem = factory_.from_distribution(in.kernel_depths, in.kernel_weights, in.zf);
    if (factory_.discretization().continuous) {
      solution_ =
          lp::solve_discretized(factory_, problem, *backend_, in.kernel_depths, in.kernel_weights)
              .finite;
    } else {
      backend_->solve_into(problem, nullptr, solution_);
    }
    const lp::Solution& s = solution_;
    if (s.call != lp::CallStatus::Ok || s.status != lp::ProblemStatus::Optimal) {
      ++failures_;
      return 0;
    }
    return std::clamp(s.G, 0.0, 1.0);
  }
  size_t failures() const override { return failures_; }

 private:
  lp::ProblemFactory factory_;
  std::unique_ptr<lp::Backend> backend_;
  lp::Solution solution_;  // reused: no allocation per LP
  size_t failures_ = 0;
};

}  // namespace

std::vector<std::string> lp_technique_basis(const std::string& name) {
  std::string spec = name.substr(3);
  std::vector<std::string> items;
  size_t start = 0;
  for (size_t i = 0; i <= spec.size(); ++i)
    if (i == spec.size() || spec[i] == ';' || spec[i] == ',') {
      std::string item = spec.substr(start, i - start);
      item.erase(0, item.find_first_not_of(' '));
      item.erase(item.find_last_not_of(' ') + 1);
      if (!item.empty()) items.push_back(item);
      start = i + 1;
    }
  if (items.empty())
    throw InputError("technique '" + name + "': expected lp:<basis>, e.g. lp:power4");
  return items;
}

std::unique_ptr<Technique> make_lp_technique(const std::string& name,
                                             const lp::Discretization& disc,
                                             const std::string& backend) {
  return std::make_unique<LpTechnique>(name, Basis::parse(lp_technique_basis(name)), disc, backend);
}

}  // namespace mb
