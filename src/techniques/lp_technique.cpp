#include "techniques/lp_technique.h"

#include <algorithm>
#include <limits>

#include "lp/solution.h"
#include "moments/storage.h"
#include "techniques/lp_fragment_solver.h"
#include "techniques/registry.h"
#include "util/error.h"
#include "util/name_list.h"

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
        solver_(this->basis(), factory_, p),
        beta_(p.lp_beta) {}
  // lp_stored:<technique> (and pss_lp_stored:): a stored map's basis over its own format's box,
  // whatever lp.moment_box says. Each fragment's box LP is solved from scratch by GLPK (no warm
  // start), so eval answers it fragment by fragment (no lp_factory) as it does a closed form.
  LpTechnique(const std::string& name, Basis basis, const MomentStorage& storage,
              const TechniqueParams& p)
      : Technique(name, std::move(basis), storage),
        factory_((this->basis().check_independent(p.lp.lo, p.lp.hi), this->basis()), p.lp),
        solver_(this->basis(), factory_, p, lp_moment_box(storage, this->basis())),
        beta_(p.lp_beta),
        own_box_(true) {}
  bool needs_distribution() const override { return true; }
  double darkening_bound() const override {
    return beta_ > 0 ? std::numeric_limits<double>::infinity() : kLpDarkeningBound;
  }
  std::string darkening_reason() const override {
    return beta_ > 0 ? "lp.beta > 0 blends the sharp lower bound towards the LP's maximum" : "";
  }
  const lp::ProblemFactory* lp_factory() const override { return own_box_ ? nullptr : &factory_; }

  double shadow(const FragmentInput& in) override {
    // F_Z at z_f, here already z_f - delta_f (docs/reference.md §3).
    double cdf = 0;
    for (size_t t = 0; t < in.kernel_depths.size(); ++t)
      if (in.kernel_depths[t] < in.zf) cdf += in.kernel_weights[t];
    if (!needs_lp(cdf, beta_)) return 0;
    // The kernel's own distribution fixes the moments, so the program is feasible by construction.
    // One fragment alone, from scratch: evaluate_technique solves whole views with warm starts
    // instead (eval/lp_view_solver.h), through the same solver, to the same certified answers.
    if (solver_.reads_problem())
      problem_ = factory_.from_distribution(in.kernel_depths, in.kernel_weights, in.zf);
    const lp::Solution& s =
        own_box_ && !in.stored_values.empty()
            ? solver_.solve_stored(in.stored_values, in.kernel_depths, in.zf)
            : solver_.solve(problem_, in.kernel_depths, in.kernel_weights, in.zf);
    if (s.call != lp::CallStatus::Ok || s.status != lp::ProblemStatus::Optimal) {
      ++failures_;
      return 0;
    }
    return std::clamp(s.G, 0.0, 1.0);
  }
  size_t failures() const override { return failures_; }

 private:
  lp::ProblemFactory factory_;
  LpFragmentSolver solver_;
  lp::Problem problem_;  // reused: no allocation per LP
  double beta_ = 0;
  bool own_box_ = false;
  size_t failures_ = 0;
};

constexpr std::string_view kStoredPrefix = "lp_stored:";

// The stored technique an lp_stored: name names: a hard-shadow row of its own (not a family) whose
// map is not double, made with `p`.
std::unique_ptr<Technique> stored_technique(const std::string& name, const TechniqueParams& p) {
  const std::string inner = name.substr(kStoredPrefix.size());
  const TechniqueRow* row = find_technique(inner, TechniqueFamily::HardShadow);
  std::unique_ptr<Technique> t =
      row && !row->prefix() && !row->solves_lp && row->make ? row->make(inner, p) : nullptr;
  if (!t || t->storage().kind == StorageKind::Double) {
    std::vector<std::string> valid;
    for (const TechniqueRow* r : family_rows(TechniqueFamily::HardShadow))
      if (!r->prefix() && !r->solves_lp && r->make &&
          r->make(r->name, p)->storage().kind != StorageKind::Double)
        valid.push_back(r->name);
    throw InputError("technique '" + name +
                     "': expected lp_stored:<a hard-shadow technique with a stored format>, one "
                     "of " +
                     joined(valid, ", "));
  }
  return t;
}

std::vector<TechniqueRow> rows() {
  return {
      {.name = "lp:",
       .rank = 200,
       .summary = "Problem 1 as an LP for any basis, e.g. lp:power4, lp:trig4",
       .storage = "double",
       .bound = "the LP's certified tolerance (lp::kCertifiedError)",
       .family_options = {"lp.grid", "lp.lo", "lp.hi", "lp.discretization", "lp.quantize",
                          "lp.backend", "lp.moment_box", "lp.moment_transform", "lp.beta"},
       .solves_lp = true,
       .make = make_lp_technique,
       // The seed paper's two bases (seed 000 §3.2: 2.19 % and 1.93 %, the best).
       .sweep_references = {{.name = "lp:power4", .moments = "power", .seed_error = 0.0219},
                            {.name = "lp:trig4",
                             .moments = "trigonometric",
                             .seed_error = 0.0193}}},
      {.name = std::string(kStoredPrefix),
       .rank = 210,
       .summary = "Problem 1 as an LP over the moment box of a stored technique's own format "
                  "(its basis, transform and bits), e.g. lp_stored:hamburger4_16bit: the "
                  "least a closed form reading that map can lose (docs/reference.md §8)",
       .storage = "the named technique's",
       .bound = "the LP's certified tolerance: the kernel's own moments lie in the box",
       .family_options = {"lp.grid", "lp.lo", "lp.hi", "lp.discretization"},
       .example = "lp_stored:hamburger4_16bit",
       .solves_lp = true,
       .make = [](const std::string& name, const TechniqueParams& p) -> std::unique_ptr<Technique> {
         const std::unique_ptr<Technique> stored = stored_technique(name, p);
         return std::make_unique<LpTechnique>(name, stored->basis(), stored->storage(), p);
       },
       .check = [](const std::string& name,
                   const TechniqueParams& p) { stored_technique(name, p); },
       .parameter = "<technique>"}};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

std::unique_ptr<Technique> make_lp_technique(const std::string& name, const Basis& basis,
                                             const MomentStorage& storage,
                                             const TechniqueParams& p) {
  return std::make_unique<LpTechnique>(name, basis, storage, p);
}

std::vector<std::string> lp_technique_basis(const std::string& name) {
  const std::vector<std::string> items = split_list(std::string_view(name).substr(3), ";,");
  if (items.empty())
    throw InputError("technique '" + name + "': expected lp:<basis>, e.g. lp:power4");
  return items;
}

std::string lp_technique_name(const std::string& basis) {
  return "lp:" + basis;
}

std::string continuous_lp_of(const TechniqueRow& row) {
  if (!row.verify || row.verify->judge != VerifyRecipe::Judge::Exact || row.verify->on_r ||
      row.verify->lo != 0 || row.verify->hi != 1)
    return "";
  const std::vector<std::string> basis = row.verify->lp_basis(TechniqueParams());
  return basis.size() == 1 ? lp_technique_name(basis[0]) : "";
}

std::unique_ptr<Technique> make_lp_technique(const std::string& name, const TechniqueParams& p) {
  return std::make_unique<LpTechnique>(name, Basis::parse(lp_technique_basis(name)), p);
}

}  // namespace mb
