// lp:<basis> as a transparency technique (docs/transparency.md §3).
#include <cmath>

#include "techniques/lp_technique.h"
#include "techniques/oit/oit_technique.h"
#include "techniques/registry.h"
#include "util/error.h"
#include "util/number_text.h"

namespace mb {

namespace {

// The LP's interval must hold the warped depth [0, 1] (docs/transparency.md §3): one that misses
// part of it cannot hold the pixel's own fragments, and its bound would be no bound.
const TechniqueParams& checked(const std::string& name, const TechniqueParams& params) {
  if (params.lp.lo > 0 || params.lp.hi < 1)
    throw InputError("lp.lo, lp.hi: [" + round_trip(params.lp.lo) + ", " +
                     round_trip(params.lp.hi) + "] excludes part of the warped depth [0, 1] of " +
                     name + " (expected lp.lo <= 0 and lp.hi >= 1)");
  return params;
}

// lp:<basis> on the warped depth u in [0, 1]: Problem 1 on the grid and the pixel's own fragment
// depths (techniques/lp_technique.h), A = b_0 G with G the sharp lower bound, or with lp.beta the
// blend towards the LP's maximum. e^{-A} >= T_ref at every fragment when lp.beta = 0.
class LpOit : public MomentOit {
 public:
  LpOit(const std::string& name, const TechniqueParams& params)
      : MomentOit(name), technique_(make_lp_technique(name, checked(name, params))) {}
  size_t failures() const override { return technique_->failures(); }

 protected:
  void reconstruct(const AbsorbanceDistribution& d, std::span<const double> warped,
                   std::span<double> out) override {
    FragmentInput in;
    in.kernel_depths = d.depths;
    in.kernel_weights = d.weights;
    for (size_t l = 0; l < warped.size(); ++l) {
      in.zf = warped[l];
      const size_t before = technique_->failures();
      const double g = technique_->shadow(in);
      out[l] = technique_->failures() > before ? 1.0 : std::exp(-d.total * g);
    }
  }

 private:
  std::unique_ptr<Technique> technique_;
};

std::vector<TechniqueRow> rows() {
  return {{.name = "lp:",
           .family = TechniqueFamily::Transmittance,
           .rank = 300,
           .summary = "Problem 1 for any basis on the warped depth, the pixel's fragment depths "
                      "joining the grid: A = b_0 G",
           .storage = "double",
           .bound = "the LP's certified tolerance at lp.beta = 0 (e^{-A} >= T)",
           .family_options = {"oit.warp", "oit.depth_range", "lp.grid", "lp.lo", "lp.hi",
                              "lp.discretization", "lp.quantize", "lp.backend", "lp.moment_box",
                              "lp.beta"},
           .default_run = true,
           .example = "lp:power4",
           .solves_lp = true,
           .make_oit = [](const std::string& name,
                          const OitParams& p) -> std::unique_ptr<OitTechnique> {
             return std::make_unique<LpOit>(name, p.technique);
           },
           // The six-moment LP beside the candidates of a transparency sweep.
           .sweep_references = {{.name = "lp:power6"}}}};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

}  // namespace mb
