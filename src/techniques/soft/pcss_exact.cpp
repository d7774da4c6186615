// PCSS computed exactly (docs/soft-shadows.md §2): every texel of the search region, the exact
// mean of the blockers' depths, the exact box filter under the protocol's kernel. Every soft row's
// second reference (EvalRow::against_pcss): PCSS with nothing sampled.
#include <algorithm>
#include <cmath>

#include "techniques/registry.h"
#include "techniques/soft/soft_technique.h"

namespace mb {

namespace {

// The exact box filter: every texel the square of side w centred on (cx, cy) overlaps, weighted
// by the overlap's area, tested against the receiver's plane through depth z at the centre
// (gradient g in depth per texel); below a texel's width, the texel under the centre.
double box_pcf(const ShadowMap& map, double cx, double cy, double w, double z, double gx,
               double gy) {
  if (w < 1e-9) return texel_cdf(map, int(std::floor(cx)), int(std::floor(cy)), z);
  double sum = 0;
  for_each_box_texel(cx, cy, w, [&](int i, int j, double wx, double wy) {
    const double zj = z + gy * (j + 0.5 - cy);
    sum += wx * wy * texel_cdf(map, i, j, zj + gx * (i + 0.5 - cx));
  });
  return std::min(sum / (w * w), 1.0);
}

// The penumbra's box seen through the protocol's kernel: each kernel tap at the protocol's biased
// depth, as the reference tests it, widened to the exact box of width w over which the depth
// follows the receiver's plane (docs/soft-shadows.md §2). The reference is the area light's
// visibility under the kernel, so a light of no extent gives the protocol's PCF exactly; the
// plane keeps a wide box off the receiver's own surface without a bias grown with the box.
double kernel_box_pcf(const SoftContext& c, const Receiver& r, double w) {
  const int k = c.kernel.radius();
  const double z = c.test_depth(r, k);
  double sum = 0;
  for (int dy = -k; dy <= k; ++dy)
    for (int dx = -k; dx <= k; ++dx)
      sum += c.kernel.weight(dx, dy) * box_pcf(c.map, r.cx() + dx, r.cy() + dy, w, z, r.gx, r.gy);
  return std::min(sum, 1.0);
}

class PcssExact : public SoftTechnique {
 public:
  double shadow(const SoftContext& c, const Receiver& r, SoftScratch&) const override {
    const int side = c.pcss_search(r), half = side / 2;
    const double z = c.search_depth(r);
    double sum = 0, count = 0;
    for (int j = r.y - half; j < r.y - half + side; ++j)
      for (int i = r.x - half; i < r.x - half + side; ++i) {
        const double d = c.map.at(i, j);
        if (d < z) sum += d, count += 1;
      }
    if (count == 0) return 0;  // seed 001: no blocker, no shadow
    return kernel_box_pcf(c, r, c.penumbra(r, sum / count));
  }
};

std::vector<TechniqueRow> rows() {
  return {{.name = "pcss_exact",
           .family = TechniqueFamily::SoftShadow,
           .rank = 0,
           .summary = "PCSS computed exactly: every texel of the blocker search, the exact box "
                      "filter under the protocol's kernel (seed 001)",
           .storage = "depth",
           .bound = "none: the penumbra is estimated (docs/soft-shadows.md §2)",
           .unproven_reason = kSoftUnproven,
           .family_options = {"soft.pcss_search", "soft.min_filter", "soft.max_filter"},
           .role = RowRole::ExactReference,
           .make_soft = [](const std::string&, const SoftSetup&) -> std::unique_ptr<SoftTechnique> {
             return std::make_unique<PcssExact>();
           }}};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

}  // namespace mb
