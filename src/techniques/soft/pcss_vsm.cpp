// Variance soft shadows (seed 001 PCSS + SAVSM; the blocker search of Yang et al.'s VSSM;
// docs/soft-shadows.md §2): the search region's mean and variance bound the lit share p by
// Cantelli; the rest, at one depth, must average (mu - p z) / (1 - p).
#include <algorithm>

#include "moments/chebyshev.h"
#include "techniques/registry.h"
#include "techniques/soft/soft_technique.h"

namespace mb {

namespace {

class PcssVsm : public SoftTechnique {
 public:
  explicit PcssVsm(const SoftSetup& s)
      : sat_(soft_summed_area_table(
            s.map, s.params, 2, [](double z, double* v) { v[0] = z, v[1] = z * z; }, {1.0, 1.0})) {}
  double shadow(const SoftContext& c, const Receiver& r, SoftScratch&) const override {
    double b[2];
    search_mean(*sat_, r, c.params.sat_search, b);
    const double zs = c.search_depth(r);
    if (zs <= b[0]) return 0;  // the mean lies behind the receiver: Cantelli bounds nothing
    const double variance = std::max(b[1] - b[0] * b[0], 0.0);
    const double lit = variance / (variance + (zs - b[0]) * (zs - b[0]));
    double blocker = 0;
    if (!blocker_from_lit_share(b[0], lit, zs, &blocker)) return 0;
    const double w = c.box_width(c.penumbra(r, blocker));
    filter_mean(*sat_, r, w, b);
    return vsm_bound(b, c.test_depth(r, w / 2), 0.0);
  }

 private:
  std::unique_ptr<SummedAreaTable> sat_;
};

std::vector<TechniqueRow> rows() {
  return {
      {.name = "pcss_vsm",
       .family = TechniqueFamily::SoftShadow,
       .rank = 20,
       .summary = "PCSS through a summed-area table of z and z^2: Cantelli's lit share in the "
                  "blocker search and the filter (seed 001 SAVSM)",
       .storage = "summed-area table (soft.sat)",
       .bound = "none: the penumbra is estimated (docs/soft-shadows.md §2)",
       .unproven_reason = kSoftUnproven,
       .family_options = {"soft.sat_search", "soft.min_filter", "soft.max_filter", "soft.sat"},
       .make_soft = [](const std::string&, const SoftSetup& s) -> std::unique_ptr<SoftTechnique> {
         return std::make_unique<PcssVsm>(s);
       }}};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

}  // namespace mb
