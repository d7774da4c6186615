// lp:<basis> as a transparency technique (docs/transparency.md §3).
#include <cmath>

#include "techniques/lp_technique.h"
#include "techniques/oit/oit_technique.h"
#include "techniques/registry.h"

namespace mb {

namespace {

// lp:<basis> on the warped depth u in [0, 1]: Problem 1 on the grid and the pixel's own fragment
// depths (techniques/lp_technique.h), A = b_0 G with G the sharp lower bound, or with lp.beta the
// blend towards the LP's maximum. e^{-A} >= T_ref at every fragment when lp.beta = 0.
class LpOit : public MomentOit {
 public:
  LpOit(const std::string& name, const TechniqueParams& params)
      : MomentOit(name), technique_(make_lp_technique(name, params)) {}
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
           .family_options = {"oit.warp", "oit.depth_range", "lp.grid", "lp.backend", "lp.beta"},
           .default_run = true,
           .example = "lp:power4",
           .solves_lp = true,
           .make_oit = [](const std::string& name, const OitParams& p)
               -> std::unique_ptr<OitTechnique> { return std::make_unique<LpOit>(name, p.lp); },
           // The six-moment LP beside the candidates of a transparency sweep.
           .sweep_references = {{.name = "lp:power6"}}}};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

}  // namespace mb
