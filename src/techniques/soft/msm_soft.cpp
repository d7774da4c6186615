// Moment soft shadow mapping (seed 004 §3, docs/soft-shadows.md §2), and the same with Problem 1
// as its final step (msm_soft:lp:<basis>): the search region's four moments, biased by alpha, give
// the canonical three-atom distribution through z_s; its atoms in front of z_s are the blockers,
// their mean depth softened towards z_s by eps_z1 (techniques/soft/msm_blocker.h); above 1 - eps_u
// they are umbra.
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "moments/canonical.h"
#include "moments/hamburger.h"
#include "techniques/lp_technique.h"
#include "techniques/registry.h"
#include "techniques/soft/msm_blocker.h"
#include "techniques/soft/soft_technique.h"
#include "util/error.h"

namespace mb {

namespace {

constexpr const char* kLpPrefix = "msm_soft:lp:";

class MsmSoft : public SoftTechnique {
 public:
  explicit MsmSoft(const SoftSetup& s) : k_(s.technique), sat_(power4_table(s.map, s.params)) {}
  double shadow(const SoftContext& c, const Receiver& r, SoftScratch&) const override {
    const MsmBlocker blocker = msm_blocker(c, k_, *sat_, r);
    if (blocker.weight > 1 - k_.umbra_epsilon) return 1;
    const double w = c.box_width(c.penumbra(r, blocker.depth));
    const double star[4] = {0.5, 0.5, 0.5, 0.5};
    double b[4];
    filter_mean(*sat_, r, w, b);
    bias_moments(b, 4, k_.alpha, star);
    return std::clamp(hamburger4(b, c.test_depth(r, w / 2)).lower, 0.0, 1.0);
  }

 protected:
  MsmSoftConstants k_;
  std::unique_ptr<SummedAreaTable> sat_;
};

// The box's own distribution: every texel (each atom, on a translucent map) the square of side w
// centred on the receiver overlaps, weighted by the overlap over w^2, the weights with which
// seed 004's interpolated query takes the box's moments from the table (docs/soft-shadows.md §2).
void box_distribution(const ShadowMap& map, double cx, double cy, double w,
                      std::vector<double>& depths, std::vector<double>& weights) {
  depths.clear(), weights.clear();
  for_each_box_texel(cx, cy, w, [&](int i, int j, double wx, double wy) {
    const double share = wx * wy / (w * w);
    if (!(share > 0)) return;
    if (!map.translucent() || i < 0 || j < 0 || i >= map.width || j >= map.height) {
      depths.push_back(map.at(i, j)), weights.push_back(share);
      return;
    }
    const size_t t = size_t(j) * map.width + i;
    for (uint64_t a = map.atom_offsets[t]; a < map.atom_offsets[t + 1]; ++a)
      depths.push_back(map.atom_depth[a]), weights.push_back(share * map.blended_mass()[a]);
  });
}

// msm_soft:lp:<basis>'s factory: the basis of its lp: part on lp.lo, lp.hi and lp.grid.
std::unique_ptr<lp::ProblemFactory> lp_final_step_factory(const std::string& name,
                                                          const TechniqueParams& technique) {
  const std::string lp_name = name.substr(std::string(kLpPrefix).size() - 3);
  if (lp_name == "lp:")
    throw InputError("technique '" + name + "': expected " + kLpPrefix + "<basis>, e.g. " +
                     kLpPrefix + "power4");
  if (technique.lp.continuous || technique.lp.quantize)
    throw InputError("lp.discretization: " + name +
                     " solves on the grid and the box's own depths; expected lp.discretization "
                     "grid (docs/soft-shadows.md §2)");
  if (technique.lp_beta > 0 || technique.lp_moment_box != "none")
    throw InputError("lp.beta, lp.moment_box: " + name +
                     " takes the sharp lower bound of the box's own moments; expected lp.beta 0 "
                     "and lp.moment_box none (docs/soft-shadows.md §2)");
  const Basis basis = Basis::parse(lp_technique_basis(lp_name));
  lp::check_backend_rows(technique.lp_backend, int(basis.size()), "techniques: " + name);
  return std::make_unique<lp::ProblemFactory>(basis, technique.lp);
}

// msm_soft with Problem 1 as its final step (docs/soft-shadows.md §2): seed 004's blocker search
// and box, then the sharpest lower bound the box's moments in the basis allow, on the grid and the
// box's own depths, solved cold (any schedule gives these bits). The box's distribution is one of
// those the LP ranges over, so below the umbra skip the answer never exceeds the box filter at the
// same depth. NaN when the LP gives no certified answer.
class MsmSoftLp : public MsmSoft {
 public:
  MsmSoftLp(const std::string& name, const SoftSetup& s)
      : MsmSoft(s), factory_(lp_final_step_factory(name, s.technique)), technique_(s.technique) {}
  void prepare(SoftScratch& scratch) const override {
    scratch.lp = std::make_unique<LpFragmentSolver>(factory_->basis(), *factory_, technique_);
  }
  double shadow(const SoftContext& c, const Receiver& r, SoftScratch& step) const override {
    const MsmBlocker blocker = msm_blocker(c, k_, *sat_, r);
    if (blocker.weight > 1 - k_.umbra_epsilon) return 1;
    const double w = c.box_width(c.penumbra(r, blocker.depth)), z = c.test_depth(r, w / 2);
    box_distribution(c.map, r.cx(), r.cy(), w, step.depths, step.weights);
    // F_Z(z) = 0: no distribution with these moments needs mass in front of z (the LP's exact
    // skip).
    if (std::all_of(step.depths.begin(), step.depths.end(), [&](double d) { return d >= z; }))
      return 0;
    step.problem = factory_->from_distribution(step.depths, step.weights, z);
    const lp::Solution& s = step.lp->solve(step.problem, step.depths, step.weights, z);
    if (s.call != lp::CallStatus::Ok || s.status != lp::ProblemStatus::Optimal)
      return std::numeric_limits<double>::quiet_NaN();
    return std::clamp(s.G, 0.0, 1.0);
  }

 private:
  std::unique_ptr<lp::ProblemFactory> factory_;
  TechniqueParams technique_;
};

std::vector<TechniqueRow> rows() {
  const std::vector<const TechniqueOption*> own{&kMsmSoftBlockerEpsilon, &kMsmSoftUmbraEpsilon,
                                                &kMsmSoftAlpha};
  const std::vector<std::string> options{"soft.sat_search", "soft.min_filter", "soft.max_filter",
                                         "soft.sat"};
  std::vector<std::string> audited = options;
  audited.push_back("soft.audit");
  // The final step's LP: on the grid (lp.discretization grid) with lp.backend; the sharp bound
  // (lp.beta 0, lp.moment_box none), which its check requires.
  std::vector<std::string> lp_options = options;
  for (const char* key : {"lp.grid", "lp.lo", "lp.hi", "lp.backend"}) lp_options.push_back(key);
  return {
      {.name = "msm_soft",
       .family = TechniqueFamily::SoftShadow,
       .rank = 50,
       .summary = "moment soft shadow mapping: a summed-area table of four power moments, "
                  "Hamburger 4MSM in the blocker search and the filter (seed 004 §3)",
       .storage = "summed-area table (soft.sat)",
       .bound = "none: the penumbra is estimated (docs/soft-shadows.md §2)",
       .unproven_reason = kSoftUnproven,
       .options = own,
       .family_options = audited,
       .audits_blocker = true,
       .make_soft = [](const std::string&, const SoftSetup& s) -> std::unique_ptr<SoftTechnique> {
         return std::make_unique<MsmSoft>(s);
       }},
      {.name = kLpPrefix,
       .family = TechniqueFamily::SoftShadow,
       .rank = 60,
       .summary = "msm_soft with Problem 1 for <basis> (an lp: technique's) on the box's "
                  "moments as its final step",
       .storage = "summed-area table (soft.sat)",
       .bound = "none: the penumbra is estimated (docs/soft-shadows.md §2)",
       .unproven_reason = kSoftUnproven,
       .options = own,
       .family_options = lp_options,
       .solves_lp = true,
       .make_soft = [](const std::string& name, const SoftSetup& s)
           -> std::unique_ptr<SoftTechnique> { return std::make_unique<MsmSoftLp>(name, s); },
       .check = [](const std::string& name,
                   const TechniqueParams& p) { lp_final_step_factory(name, p); }}};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

}  // namespace mb
