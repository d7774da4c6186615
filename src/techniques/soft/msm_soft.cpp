// Moment soft shadow mapping (seed 004 §3, docs/soft-shadows.md §2), and the same with Problem 1
// as its final step (msm_soft:lp:<basis>): the search region's four moments, biased by alpha, give
// the canonical three-atom distribution through z_s; its atoms in front of z_s are the blockers,
// their mean depth softened towards z_s by eps_z1; above 1 - eps_u they are umbra. The blocker
// search is audited against its sharp bounds (docs/soft-shadows.md §3).
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "lp/blocker_bounds.h"
#include "moments/canonical.h"
#include "moments/hamburger.h"
#include "techniques/lp_technique.h"
#include "techniques/registry.h"
#include "techniques/soft/soft_technique.h"
#include "util/error.h"
#include "util/parallel_errors.h"

namespace mb {

const TechniqueOption kMsmSoftBlockerEpsilon{
    {"soft.blocker_epsilon", OptionType::Number, "0.01",
     "msm_soft: eps_z1, the weight of the receiver's own depth in the blocker average "
     "(seed 004 §3.3).",
     1e-12, 1}};
const TechniqueOption kMsmSoftUmbraEpsilon{
    {"soft.umbra_epsilon", OptionType::Number, "0.01",
     "msm_soft: eps_u; a search region whose blockers weigh above 1 - eps_u is umbra "
     "(seed 004 §3.4).",
     0, 1}};
const TechniqueOption kMsmSoftAlpha{
    {"soft.msm_alpha", OptionType::Number, "5e-6",
     "msm_soft: the moment bias alpha of Hamburger 4MSM (seed 004's value for fixed-point "
     "moments).",
     0, 1}};

namespace {

constexpr const char* kLpPrefix = "msm_soft:lp:";

// msm_soft's own constants (seed 004 §3.3-3.4), from its option records.
struct MsmSoftConstants {
  explicit MsmSoftConstants(const TechniqueParams& p)
      : alpha(p.number(kMsmSoftAlpha)),
        blocker_epsilon(p.number(kMsmSoftBlockerEpsilon)),
        umbra_epsilon(p.number(kMsmSoftUmbraEpsilon)) {}
  double alpha, blocker_epsilon, umbra_epsilon;
};

std::unique_ptr<SummedAreaTable> power4_table(const ShadowMap& map, const SoftParams& p) {
  return soft_summed_area_table(
      map, p, 4,
      [](double z, double* v) { v[0] = z, v[1] = z * z, v[2] = v[1] * z, v[3] = v[2] * z; },
      std::vector<double>(4, 1.0));
}

struct MsmBlocker {
  double depth = 0;   // seed 004's estimate, eps_z1 included
  double weight = 0;  // the canonical distribution's mass in front of z_s
  double zs = 0;
};

MsmBlocker msm_blocker(const SoftContext& c, const MsmSoftConstants& k, const SummedAreaTable& sat,
                       const Receiver& r) {
  const double star[4] = {0.5, 0.5, 0.5, 0.5};
  double b[4];
  search_mean(sat, r, c.params.sat_search, b);
  bias_moments(b, 4, k.alpha, star);
  MsmBlocker out;
  out.zs = c.search_depth(r);
  const MsmBound<double> canonical = hamburger4(b, out.zs);
  double sum = 0;
  for (int i = 1; i < canonical.node_count; ++i)
    if (canonical.nodes[i] < out.zs)
      out.weight += canonical.weights[i], sum += canonical.weights[i] * canonical.nodes[i];
  const double eps = k.blocker_epsilon;
  out.depth = (eps * out.zs + sum) / (eps + out.weight);
  return out;
}

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

std::vector<BlockerAuditRow> blocker_audit(const ShadowMap& map, const Fragments& fragments,
                                           const SoftReceivers& soft, const GaussianKernel& kernel,
                                           const BiasParams& bias, const SoftParams& params,
                                           const TechniqueParams& technique, int threads) {
  std::vector<BlockerAuditRow> rows;
  if (params.audit == 0 || fragments.size() == 0) return rows;
  const MsmSoftConstants constants(technique);
  const SoftContext context = make_soft_context({map, soft, kernel, bias, params, technique});
  const auto sat = power4_table(map, params);
  lp::Discretization grid;
  grid.grid = 256;
  const lp::ProblemFactory factory(Basis::parse({"power4"}), grid);
  const size_t stride = std::max<size_t>(1, fragments.size() / size_t(params.audit));
  std::vector<size_t> picked;
  for (size_t k = stride / 2; k < fragments.size(); k += stride) picked.push_back(k);
  std::vector<BlockerAuditRow> found(picked.size());
  std::vector<char> kept(picked.size(), 0);
  ParallelErrors errors;
#pragma omp parallel num_threads(threads)
  {
    // One backend per thread, made and dropped in it (GLPK's memory is the thread's); every solve
    // starts cold, so the schedule changes no answer.
    std::unique_ptr<lp::Backend> backend;
    errors.capture([&] { backend = lp::make_backend("fast"); });
#pragma omp for schedule(dynamic, 1)
    for (size_t p = 0; p < picked.size(); ++p)
      errors.capture([&] {
        if (!backend) return;
        const Receiver r = receiver_of(fragments, soft, picked[p]);
        const MsmBlocker seed = msm_blocker(context, constants, *sat, r);
        // The search region as its texels: their depths join the grid, its moments are theirs.
        const int side = params.sat_search, x0 = r.x - side / 2, y0 = r.y - side / 2;
        std::vector<double> depths;
        double mass = 0, sum = 0;
        for (int y = y0; y < y0 + side; ++y)
          for (int x = x0; x < x0 + side; ++x) {
            const double z = map.at(x, y);
            depths.push_back(z);
            if (z < seed.zs) mass += 1, sum += z;
          }
        if (mass == 0) return;
        const std::vector<double> weights(depths.size(), 1.0 / double(depths.size()));
        const BlockerBounds bounds =
            blocker_bounds_dinkelbach(factory, depths, weights, seed.zs, *backend);
        if (!bounds.feasible) return;
        BlockerAuditRow& row = found[p];
        row.receiver = picked[p];
        row.zs = seed.zs;
        row.exact = sum / mass;
        row.seed = seed.depth;
        row.lo = bounds.lo, row.hi = bounds.hi;
        // Both sides start from the region's own mean, so lo <= exact <= hi.
        row.penumbra_lo = 2 * soft.rim_shear * std::max(r.zf - bounds.hi, 0.0);
        row.penumbra_hi = 2 * soft.rim_shear * std::max(r.zf - bounds.lo, 0.0);
        row.penumbra_exact = 2 * soft.rim_shear * std::max(r.zf - row.exact, 0.0);
        row.penumbra_seed = 2 * soft.rim_shear * std::max(r.zf - row.seed, 0.0);
        kept[p] = 1;
      });
  }
  errors.rethrow();
  for (size_t p = 0; p < picked.size(); ++p)
    if (kept[p]) rows.push_back(found[p]);
  return rows;
}

}  // namespace mb
