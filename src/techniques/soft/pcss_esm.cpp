// ESM through a summed-area table (seed 001 "PCSS + ESM", docs/soft-shadows.md §2): channels
// exp(c (z - 1)) and z. The lit share at depth d is E[exp(c (z - d))], clamped to 1 (seed 002); the
// blocker search takes it at z_s and the rest of the region at one depth, as the VSM one does.
#include <algorithm>
#include <cmath>

#include "techniques/registry.h"
#include "techniques/soft/soft_technique.h"

namespace mb {

const TechniqueOption kPcssEsmC{
    {"soft.esm_c", OptionType::Number, "30",
     "pcss_esm: c in exp(c (z - 1)), stored in the summed-area table (seed 001 tunes 10 to 30; "
     "seed 002's 80 underflows a fixed-point table's 2^-22 beyond depth differences of 0.19).",
     0.1, 200}};

namespace {

class PcssEsm : public SoftTechnique {
 public:
  explicit PcssEsm(const SoftSetup& s)
      : c_(s.technique.number(kPcssEsmC)),
        sat_(soft_summed_area_table(
            s.map, s.params, 2,
            [c = c_](double z, double* v) { v[0] = std::exp(c * (z - 1)), v[1] = z; },
            {1.0, 1.0})) {}
  double shadow(const SoftContext& c, const Receiver& r, SoftScratch&) const override {
    const double k = c_;
    const auto lit = [&](const double* b, double d) {
      return std::min(b[0] * std::exp(k * (1 - d)), 1.0);
    };
    double b[2];
    search_mean(*sat_, r, c.params.sat_search, b);
    const double zs = c.search_depth(r);
    double blocker = 0;
    if (!blocker_from_lit_share(b[1], lit(b, zs), zs, &blocker)) return 0;
    const double w = c.box_width(c.penumbra(r, blocker));
    filter_mean(*sat_, r, w, b);
    return 1 - lit(b, c.test_depth(r, w / 2));
  }

 private:
  double c_;
  std::unique_ptr<SummedAreaTable> sat_;
};

std::vector<TechniqueRow> rows() {
  return {
      {.name = "pcss_esm",
       .family = TechniqueFamily::SoftShadow,
       .rank = 30,
       .summary = "PCSS through a summed-area table of exp(c (z - 1)) and z: Markov's lit share "
                  "(seed 001 PCSS + ESM)",
       .storage = "summed-area table (soft.sat)",
       .bound = "none: the penumbra is estimated (docs/soft-shadows.md §2)",
       .unproven_reason = kSoftUnproven,
       .options = {&kPcssEsmC},
       .family_options = {"soft.sat_search", "soft.min_filter", "soft.max_filter", "soft.sat"},
       .make_soft = [](const std::string&, const SoftSetup& s) -> std::unique_ptr<SoftTechnique> {
         return std::make_unique<PcssEsm>(s);
       }}};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

}  // namespace mb
