#include "techniques/lp_technique.h"

#include <algorithm>
#include <limits>

#include "continuous/discretized.h"
#include "continuous/moment_box.h"
#include "lp/solution.h"
#include "techniques/registry.h"
#include "util/error.h"

namespace mb {

namespace {

class LpTechnique : public Technique {
 public:
  LpTechnique(const std::string& name, Basis basis, const TechniqueParams& p)
      : Technique(name, std::move(basis), double_storage()),
        factory_((lp::check_backend_rows(p.lp_backend, int(this->basis().size()),
                                         "technique '" + name + "'"),
                  this->basis().check_independent(p.lp.lo, p.lp.hi), this->basis()),
                 p.lp),
        backend_(lp::make_backend(p.lp_backend)),
        box_(lp_moment_box(p.lp_moment_box, this->basis())),
        beta_(p.lp_beta) {}
  bool needs_distribution() const override { return true; }
  double darkening_bound() const override {
    return beta_ > 0 ? std::numeric_limits<double>::infinity() : kLpDarkeningBound;
  }
  std::string darkening_reason() const override {
    return beta_ > 0 ? "lp.beta > 0 blends the sharp lower bound towards the LP's maximum" : "";
  }
  const lp::ProblemFactory* lp_factory() const override { return &factory_; }

  double shadow(const FragmentInput& in) override {
    // docs/reference.md §2: G <= F_Z(z_f), so F_Z(z_f) = 0 gives G = 0 without solving (z_f here is
    // already z_f - delta_f, docs/reference.md §3).
    double cdf = 0;
    for (size_t t = 0; t < in.kernel_depths.size(); ++t)
      if (in.kernel_depths[t] < in.zf) cdf += in.kernel_weights[t];
    if (cdf == 0 && beta_ == 0) return 0;
    // The kernel's own distribution fixes the moments, so the program is feasible by construction.
    // One fragment alone, from scratch: evaluate_technique solves whole views with warm starts
    // instead (solve_lp_view), to the same certified answers.
    if (box_) {
      double g = 0;
      if (solve_box_fragment(*box_, basis(), factory_.discretization(), in.kernel_depths,
                             in.kernel_weights, in.zf, g) != lp::ProblemStatus::Optimal) {
        ++failures_;
        return 0;
      }
      return g;
    }
    lp::Problem problem = factory_.from_distribution(in.kernel_depths, in.kernel_weights, in.zf);
    if (factory_.discretization().continuous) {
      solution_ =
          lp::solve_discretized(factory_, problem, *backend_, in.kernel_depths, in.kernel_weights)
              .finite;
    } else {
      backend_->solve_into(problem, nullptr, solution_);
    }
    if (!optimal(solution_)) return 0;
    const double lower = std::clamp(solution_.G, 0.0, 1.0);
    if (beta_ == 0) return lower;
    // lp.beta: the maximum G+ = 1 - (the least mass behind z_f) over the same distributions.
    problem.behind = true;
    backend_->solve_into(problem, nullptr, solution_);
    if (!optimal(solution_)) return 0;
    const double upper = std::clamp(1 - solution_.G, lower, 1.0);
    return lower + beta_ * (upper - lower);
  }
  size_t failures() const override { return failures_; }

 private:
  bool optimal(const lp::Solution& s) {
    const bool ok = s.call == lp::CallStatus::Ok && s.status == lp::ProblemStatus::Optimal;
    failures_ += !ok;
    return ok;
  }

  lp::ProblemFactory factory_;
  std::unique_ptr<lp::Backend> backend_;
  lp::Solution solution_;  // reused: no allocation per LP
  std::optional<LpMomentBox> box_;
  double beta_ = 0;
  size_t failures_ = 0;
};

std::vector<TechniqueRow> rows() {
  return {{.name = "lp:",
           .rank = 200,
           .summary = "Problem 1 as an LP for any basis, e.g. lp:power4, lp:trig4",
           .storage = "double",
           .bound = "the LP's certified tolerance (lp::kCertifiedError)",
           .solves_lp = true,
           .make = make_lp_technique}};
}

const TechniqueRegistration kRegistered(rows);

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

std::unique_ptr<Technique> make_lp_technique(const std::string& name, const TechniqueParams& p) {
  return std::make_unique<LpTechnique>(name, Basis::parse(lp_technique_basis(name)), p);
}

std::optional<LpMomentBox> lp_moment_box(const std::string& setting, const Basis& basis) {
  if (setting == "none") return std::nullopt;
  MomentStorage storage;
  if (setting == "double") {
    storage = double_storage();
  } else if (setting == "float32") {
    storage = float32_storage();
  } else if (setting == "unorm16") {
    const std::vector<std::string> names = basis.names();
    if (names == named_basis_set("power4"))
      storage = unorm16_power4_storage();
    else if (names == named_basis_set("power2"))
      storage = unorm16_power2_storage();
    else
      throw InputError(
          "lp.moment_box: unorm16 needs the basis power4 (theta_4) or power2 "
          "(theta_2) of docs/reference.md §4");
  } else {
    throw InputError("lp.moment_box: expected one of none, double, float32, unorm16; got '" +
                     setting + "'");
  }
  return LpMomentBox{storage, storage_tolerance(storage, basis)};
}

lp::ProblemStatus solve_box_fragment(const LpMomentBox& box, const Basis& basis,
                                     const lp::Discretization& disc, std::span<const double> depths,
                                     std::span<const double> weights, double zf, double& G) {
  const lp::MomentBox moment_box{filtered_stored_values(box.storage, basis, depths, weights),
                                 box.tolerance, box.storage.transform, box.storage.offset};
  std::vector<double> points(depths.begin(), depths.end());
  const int grid = disc.continuous ? std::min(disc.grid, lp::kContinuousSeedGrid) : disc.grid;
  for (int k = 0; k < grid; ++k) points.push_back(disc.lo + (disc.hi - disc.lo) * k / (grid - 1));
  if (disc.continuous) {
    const lp::ContinuousBoxAnswer a = lp::solve_moment_box_continuous(
        basis, moment_box, zf, lp::ContinuousDomain::interval(disc.lo, disc.hi), points);
    G = std::clamp(a.upper, 0.0, 1.0);
    return a.finite.status;
  }
  points.push_back(zf);
  const lp::MomentBoxAnswer a = lp::solve_moment_box(basis, moment_box, zf, points);
  G = a.G;
  return a.status;
}

}  // namespace mb
