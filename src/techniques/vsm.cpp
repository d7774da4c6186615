// Variance shadow maps (in double and from 16-bit maps with seed 000's theta_2) and layered VSM:
// Cantelli's inequality on the depth, or on the depth clamped into the receiver's layer
// (docs/reference.md §4, §8).
#include <algorithm>
#include <cmath>
#include <limits>

#include "moments/chebyshev.h"
#include "techniques/hard_rows.h"

namespace mb {

namespace {

class VsmTechnique : public Technique {
 public:
  VsmTechnique(const std::string& name, MomentStorage storage, double min_variance)
      : Technique(name, Basis::parse({"power2"}), std::move(storage)),
        min_variance_(min_variance) {}
  double shadow(const FragmentInput& in) override {
    return vsm_bound(in.moments.data(), in.zf, min_variance_);
  }
  // Rounded stored moments may lie off the kernel's moment set: no bound then.
  double darkening_bound() const override {
    return storage().kind == StorageKind::Double ? 0 : std::numeric_limits<double>::infinity();
  }
  std::string darkening_reason() const override {
    return storage().kind == StorageKind::Double
               ? ""
               : "moments stored in " + storage().name() +
                     " are rounded off the kernel's moment set, which Cantelli assumes";
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
  return {
      {.name = "vsm",
       .rank = 20,
       .summary = "variance shadow maps: Cantelli",
       .storage = "double",
       .bound = kProvenBound,
       .options = {&kVsmMinVariance},
       .default_run = true,
       .make = [](const std::string&, const P& p) -> std::unique_ptr<Technique> {
         return std::make_unique<VsmTechnique>("vsm", double_storage(), p.number(kVsmMinVariance));
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
      {.name = "vsm_16bit",
       .rank = 25,
       .summary = "VSM from 16-bit maps with the transform theta_2 = (z, 4z - 4z^2)",
       .storage = "unorm16",
       // The stored variance's rounding can make it negative or shrink it, and Cantelli then
       // claims more shadow than the kernel holds; vsm.min_variance clamps it as in double.
       .bound = std::string(kNotProven) + ": 16-bit rounding of the moments",
       .options = {&kVsmMinVariance},
       .make = [](const std::string&, const P& p) -> std::unique_ptr<Technique> {
         return std::make_unique<VsmTechnique>("vsm_16bit", unorm16_power2_storage(),
                                               p.number(kVsmMinVariance));
       },
       .verify = storage_box(fixed_lp_basis<kPower2>, -20, 21, true, nullptr)},
      {.name = "lvsm",
       .rank = 100,
       .summary = "layered VSM: Cantelli on the depth clamped to z_f's layer",
       .storage = "double",
       .bound = kProvenBound,
       .options = {&kLvsmLayers, &kVsmMinVariance},
       .make = [](const std::string&, const P& p) -> std::unique_ptr<Technique> {
         return std::make_unique<LvsmTechnique>(p.integer(kLvsmLayers), p.number(kVsmMinVariance));
       }}};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

}  // namespace mb
