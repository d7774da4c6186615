// PCSS as seed 001 runs it (docs/soft-shadows.md §2): point taps spread evenly over the search
// region and over the filter.
#include <algorithm>
#include <cmath>

#include "techniques/registry.h"
#include "techniques/soft/soft_technique.h"

namespace mb {

const TechniqueOption kPcssBlockerTaps{
    {"soft.blocker_taps", OptionType::Integer, "5",
     "pcss: point taps a side spread over the blocker search (seed 001: 4x4 or 5x5 suffice).", 1,
     255}};
const TechniqueOption kPcssFilterTaps{
    {"soft.filter_taps", OptionType::Integer, "9",
     "pcss: PCF taps a side spread over the penumbra's filter (seed 001 shows 5x5, 9x9, 17x17).", 1,
     255}};

namespace {

class PcssSampled : public SoftTechnique {
 public:
  explicit PcssSampled(const SoftSetup& s)
      : blocker_taps_(s.technique.integer(kPcssBlockerTaps)),
        filter_taps_(s.technique.integer(kPcssFilterTaps)) {}
  double shadow(const SoftContext& c, const Receiver& r, SoftScratch&) const override {
    const int nb = blocker_taps_, nf = filter_taps_;
    const double span = c.pcss_search(r) - 1;
    const double zs = c.search_depth(r);
    double sum = 0, count = 0;
    for (int j = 0; j < nb; ++j)
      for (int i = 0; i < nb; ++i) {
        const double u = nb == 1 ? 0 : double(i) / (nb - 1) - 0.5,
                     v = nb == 1 ? 0 : double(j) / (nb - 1) - 0.5;
        const double d =
            c.map.at(int(std::floor(r.cx() + u * span)), int(std::floor(r.cy() + v * span)));
        if (d < zs) sum += d, count += 1;
      }
    if (count == 0) return 0;
    // Taps over the penumbra's box widened by the kernel, against the receiver's plane.
    const double w = c.box_width(c.penumbra(r, sum / count)),
                 z = c.test_depth(r, c.kernel.radius());
    double shadow = 0;
    for (int j = 0; j < nf; ++j)
      for (int i = 0; i < nf; ++i) {
        const double u = (i + 0.5) / nf - 0.5, v = (j + 0.5) / nf - 0.5;
        const int tx = int(std::floor(r.cx() + u * w)), ty = int(std::floor(r.cy() + v * w));
        shadow += texel_cdf(c.map, tx, ty, z + r.gx * (tx - r.x) + r.gy * (ty - r.y));
      }
    return std::min(shadow / (nf * nf), 1.0);
  }

 private:
  int blocker_taps_, filter_taps_;
};

std::vector<TechniqueRow> rows() {
  return {
      {.name = "pcss",
       .family = TechniqueFamily::SoftShadow,
       .rank = 10,
       .summary = "PCSS as sampled in practice: point taps over the blocker search and the "
                  "filter (seed 001)",
       .storage = "depth",
       .bound = "none: the penumbra is estimated (docs/soft-shadows.md §2)",
       .unproven_reason = kSoftUnproven,
       .options = {&kPcssBlockerTaps, &kPcssFilterTaps},
       .family_options = {"soft.pcss_search", "soft.min_filter", "soft.max_filter"},
       .make_soft = [](const std::string&, const SoftSetup& s) -> std::unique_ptr<SoftTechnique> {
         return std::make_unique<PcssSampled>(s);
       }}};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

}  // namespace mb
