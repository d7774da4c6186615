// PCSS as seed 001 runs it (docs/soft-shadows.md §2): point taps spread evenly over the search
// region and over the filter.
#include <algorithm>
#include <cmath>

#include "techniques/registry.h"
#include "techniques/soft/soft_technique.h"

namespace mb {

namespace {

class PcssSampled : public SoftTechnique {
 public:
  double shadow(const SoftContext& c, const Receiver& r, SoftScratch&) const override {
    const int nb = c.params.blocker_taps, nf = c.params.filter_taps;
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
};

std::vector<TechniqueRow> rows() {
  return {{.name = "pcss",
           .family = TechniqueFamily::SoftShadow,
           .rank = 10,
           .summary = "PCSS as sampled in practice: point taps over the blocker search and the "
                      "filter (seed 001)",
           .storage = "depth",
           .bound = "none: the penumbra is estimated (docs/soft-shadows.md §2)",
           .unproven_reason = kSoftUnproven,
           .family_options = {"soft.pcss_search", "soft.blocker_taps", "soft.filter_taps",
                              "soft.min_filter", "soft.max_filter"},
           .make_soft = [](const std::string&, const SoftSetup&) -> std::unique_ptr<SoftTechnique> {
             return std::make_unique<PcssSampled>();
           }}};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

}  // namespace mb
