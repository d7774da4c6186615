// Variance shadow maps and layered VSM: Cantelli's inequality on the depth, or on the depth
// clamped into the receiver's layer (docs/reference.md §4).
#include <algorithm>
#include <cmath>

#include "moments/chebyshev.h"
#include "techniques/hard_rows.h"

namespace mb {

namespace {

class VsmTechnique : public Technique {
 public:
  explicit VsmTechnique(double min_variance)
      : Technique("vsm", Basis::parse({"power2"}), double_storage()), min_variance_(min_variance) {}
  double shadow(const FragmentInput& in) override {
    return vsm_bound(in.moments.data(), in.zf, min_variance_);
  }

 private:
  double min_variance_;
};

// Layered VSM (seed 001 "Layered VSM"): [0, 1] split into L even layers; layer l keeps the depth
// clamped to it, w_l(z) = clamp(L z - l, 0, 1), and a fragment is judged by Cantelli on the warped
// depths of its own layer. The warp does not decrease, so w_l(Z) < w_l(z_f) implies Z < z_f and
// the bound stays a lower bound; occluders in earlier layers warp to 0, and light leaking from
// depths beyond z_f's layer is gone (seed 000 §2: Problem 1 if the layers' overlap is ignored).
class LvsmTechnique : public Technique {
 public:
  LvsmTechnique(int layers, double min_variance)
      : Technique("lvsm", lvsm_basis(layers), double_storage()),
        layers_(layers),
        min_variance_(min_variance) {}
  double shadow(const FragmentInput& in) override {
    const int layer = std::clamp(int(std::floor(layers_ * in.zf)), 0, layers_ - 1);
    const double wf = std::clamp(layers_ * in.zf - layer, 0.0, 1.0);
    return std::clamp(vsm_bound(in.moments.data() + 2 * layer, wf, min_variance_), 0.0, 1.0);
  }

 private:
  static Basis lvsm_basis(int layers) {
    std::vector<std::string> functions;
    for (int l = 0; l < layers; ++l) {
      const std::string warp =
          "min(max(" + std::to_string(layers) + "*z-" + std::to_string(l) + ",0),1)";
      functions.push_back(warp);
      functions.push_back(warp + "^2");
    }
    return Basis::parse(functions);
  }
  int layers_;
  double min_variance_;
};

using P = TechniqueParams;

const TechniqueOption kVsmMinVariance{
    .spec = {"vsm.min_variance", OptionType::Number, "0", "VSM variance clamp.", 0, 1},
    .zero_is_sharp = true};
const TechniqueOption kLvsmLayers{
    {"lvsm.layers", OptionType::Integer, "4",
     "LVSM depth layers: [0, 1] split evenly, a VSM per layer on the depth clamped to it.", 1, 8}};

std::vector<TechniqueRow> rows() {
  return {{.name = "vsm",
           .rank = 20,
           .summary = "variance shadow maps: Cantelli",
           .storage = "double",
           .bound = kProvenBound,
           .options = {&kVsmMinVariance},
           .default_run = true,
           .make = [](const std::string&, const P& p) -> std::unique_ptr<Technique> {
             return std::make_unique<VsmTechnique>(p.number(kVsmMinVariance));
           },
           // Cantelli's second point mu - sigma^2 / (z_f - mu) runs far out when z_f ~ mu, hence
           // the wide interval (docs/reference.md §6).
           .verify = VerifyRecipe{.lp_basis = fixed_lp_basis<kPower2>,
                                  .lo = -20,
                                  .hi = 21,
                                  .on_r = true,
                                  .cantelli_support = true},
           .verify_place = 4,
           .sweep_references = {{.expectation = "two moments: far behind every four-function "
                                                "candidate (seed 000 Figure 4)",
                                 .place = 1}}},
          {.name = "lvsm",
           .rank = 100,
           .summary = "layered VSM: Cantelli on the depth clamped to z_f's layer",
           .storage = "double",
           .bound = kProvenBound,
           .options = {&kLvsmLayers, &kVsmMinVariance},
           .make = [](const std::string&, const P& p) -> std::unique_ptr<Technique> {
             return std::make_unique<LvsmTechnique>(p.integer(kLvsmLayers),
                                                    p.number(kVsmMinVariance));
           }}};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

}  // namespace mb
