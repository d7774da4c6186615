// Weighted blended order-independent transparency (docs/transparency.md §3).
#include <algorithm>
#include <cmath>

#include "techniques/oit/oit_technique.h"
#include "techniques/registry.h"

namespace mb {

namespace {

// Weighted blended OIT (McGuire and Bavoil 2013, their weight function (7) of the view depth z):
// w = alpha max(1e-2, min(3e3, 10 / (1e-5 + (z / 5)^2 + (z / 200)^6))). The composite normalises
// the weights, so only their ratios matter; the scenes' depths (2-20 units) lie where the
// function falls steadily.
class WeightedBlendedOit : public OitTechnique {
 public:
  explicit WeightedBlendedOit(std::string name) : OitTechnique(std::move(name)) {}
  bool normalised() const override { return true; }
  void transmittance(const PixelFragments& px, std::span<const double>,
                     std::span<double> out) override {
    for (size_t l = 0; l < px.size(); ++l) {
      const double z = std::abs(px.depth[l]);
      const double falloff = 10 / (1e-5 + std::pow(z / 5, 2) + std::pow(z / 200, 6));
      out[l] = px.alpha[l] * std::clamp(falloff, 1e-2, 3e3);
    }
  }
};

std::vector<TechniqueRow> rows() {
  return {
      {.name = "wboit",
       .family = TechniqueFamily::Transmittance,
       .rank = 20,
       .summary = "weighted blended OIT (McGuire and Bavoil 2013, their weight (7))",
       .storage = "RGBA + revealage",
       .bound = "none: weighted blended OIT: depth weights, no bound",
       .unproven_reason = "weighted blended OIT: depth weights, no bound",
       .default_run = true,
       .make_oit = [](const std::string& name, const OitParams&) -> std::unique_ptr<OitTechnique> {
         return std::make_unique<WeightedBlendedOit>(name);
       }}};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

}  // namespace mb
