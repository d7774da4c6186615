// The blends of the fragments themselves, no moments (docs/transparency.md §3): the sorted
// composite (the reference) and submission order.
#include "techniques/oit/oit_technique.h"
#include "techniques/registry.h"

namespace mb {

namespace {

// `exact` and `unsorted`: a blend of the fragments themselves (shadow/compositing.h), no moments.
class BlendOit : public OitTechnique {
 public:
  using Blend = void (*)(const PixelFragments&, std::span<double>);
  BlendOit(std::string name, Blend blend) : OitTechnique(std::move(name)), blend_(blend) {}
  void transmittance(const PixelFragments& px, std::span<const double>,
                     std::span<double> out) override {
    blend_(px, out);
  }

 private:
  Blend blend_;
};

std::vector<TechniqueRow> rows() {
  return {
      {.name = "exact",
       .family = TechniqueFamily::Transmittance,
       .rank = 0,
       .summary = "the depth-peeled composite: fragments sorted, blended front to back (the "
                  "reference)",
       .storage = "every fragment",
       .bound = "0",
       .role = RowRole::Reference,
       .default_run = true,
       .make_oit = [](const std::string& name, const OitParams&) -> std::unique_ptr<OitTechnique> {
         return std::make_unique<BlendOit>(name, exact_transmittance);
       }},
      {.name = "unsorted",
       .family = TechniqueFamily::Transmittance,
       .rank = 10,
       .summary = "fragments blended in submission order, unsorted",
       .storage = "every fragment",
       .bound = "none: submission order: fragments behind count as in front",
       .unproven_reason = "submission order: fragments behind count as in front",
       .default_run = true,
       .make_oit = [](const std::string& name, const OitParams&) -> std::unique_ptr<OitTechnique> {
         return std::make_unique<BlendOit>(name, submission_transmittance);
       }}};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

}  // namespace mb
