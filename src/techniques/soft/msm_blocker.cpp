#include "techniques/soft/msm_blocker.h"

#include "moments/canonical.h"
#include "moments/hamburger.h"

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

std::unique_ptr<SummedAreaTable> power4_table(const ShadowMap& map, const SoftParams& p) {
  return soft_summed_area_table(
      map, p, 4,
      [](double z, double* v) { v[0] = z, v[1] = z * z, v[2] = v[1] * z, v[3] = v[2] * z; },
      std::vector<double>(4, 1.0));
}

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

}  // namespace mb
