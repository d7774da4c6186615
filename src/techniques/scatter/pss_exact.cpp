// pss_exact (docs/scattering.md §3.2): the rectified row's own transmittance-weighted visibility,
// no moments. The shadowed fraction of a view ray is the weighted share of its row's texels up to
// the ray's end whose first surface lies in front of the ray's depth: what prefiltering alone
// answers. Its distance to `exact` is the rectification's (nearest row, nearest light-map texel,
// Delta(v) at the row's mean inclination); a moment row's distance to it is its moments' loss.
#include <vector>

#include "techniques/registry.h"
#include "techniques/scatter/prefiltered_scatter.h"

namespace mb {

namespace {

class PssExact : public PrefilteredScatter {
 public:
  PssExact(const std::string& name, const ScatterParams& params)
      : PrefilteredScatter(name, params) {}

 protected:
  void prefilter(const RectifiedMap&) override {}
  double shadowed_fraction(const RectifiedRay& ray) const override {
    const std::span<const double> row = map().row(ray.row);
    const int width = map().width();
    if (!(ray.x > 0)) return row[0] < ray.depth ? 1 : 0;
    double shadowed = 0;
    const int whole = int(std::min(std::floor(ray.x), double(width)));
    for (int u = 0; u < whole; ++u)
      if (row[size_t(u)] < ray.depth) shadowed += map().texel_weight(ray.row, u);
    if (whole < width && row[size_t(whole)] < ray.depth)
      shadowed += (ray.x - whole) * map().texel_weight(ray.row, whole);
    // Beyond the map every light ray is empty (depth 1): lit.
    return shadowed / map().weight_sum(ray.row, ray.x);
  }
};

std::vector<TechniqueRow> rows() {
  return {{.name = "pss_exact",
           .family = TechniqueFamily::Scattering,
           .rank = 20,
           .summary = "prefiltered single scattering without moments: the transmittance-weighted "
                      "share of the rectified row's texels up to the ray's end that shadow its "
                      "depth (docs/scattering.md §3.2)",
           .storage = "rectified map (depths)",
           .bound = "none: the rectification's error has either sign",
           .unproven_reason = "the rectified map resamples the light map and takes Delta(v) at "
                              "the row's mean inclination",
           .family_options = {"scatter.light_resolution", "scatter.guard_band"},
           .default_run = true,
           .make_scatter = [](const std::string& name,
                              const ScatterParams& params) -> std::unique_ptr<ScatterTechnique> {
             return std::make_unique<PssExact>(name, params);
           }}};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

}  // namespace mb
