// What the soft-shadow techniques share (techniques/soft/soft_technique.h): the receiver and its
// view's context, the exact box filter, summed-area tables and their queries, and the loop over a
// view's receivers.
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "techniques/registry.h"
#include "techniques/soft/soft_technique.h"
#include "util/error.h"
#include "util/parallel_errors.h"

namespace mb {

Receiver receiver_of(const Fragments& f, const SoftReceivers& soft, size_t k) {
  Receiver r;
  r.x = int(f.texel[k] % f.width);
  r.y = int(f.texel[k] / f.width);
  r.zf = f.zf[k];
  r.slope = std::abs(soft.gx[k]) + std::abs(soft.gy[k]);
  r.gx = soft.gx[k], r.gy = soft.gy[k];
  return r;
}

SoftContext make_soft_context(const SoftSetup& s) {
  SoftContext context{s.map, s.soft, s.kernel, s.bias, s.params};
  for (int d = -s.kernel.radius(); d <= s.kernel.radius(); ++d)
    context.kernel_variance += s.kernel.weights[d + s.kernel.radius()] * d * d;
  return context;
}

std::unique_ptr<SummedAreaTable> soft_summed_area_table(
    const ShadowMap& map, const SoftParams& p, int channels,
    const std::function<void(double, double*)>& f, std::vector<double> far) {
  const SatPrecision precision = p.sat == "exact" ? SatPrecision::Exact : SatPrecision::Fixed32;
  const int side = std::max(p.sat_search, p.max_filter + 2);
  const int64_t n = int64_t(side) * side;
  const int pad = side / 2 + 2;
  // E over the texel's atoms of each function of depth (one atom, the layer-0 depth, on an opaque
  // map; docs/reference.md §7 on a translucent one).
  std::vector<double> values(map.depth.size() * channels, 0.0), one(channels);
  for (size_t t = 0; t < map.depth.size(); ++t) {
    if (!map.translucent()) {
      f(map.depth[t], values.data() + t * channels);
      continue;
    }
    for (uint64_t a = map.atom_offsets[t]; a < map.atom_offsets[t + 1]; ++a) {
      f(map.atom_depth[a], one.data());
      for (int k = 0; k < channels; ++k) values[t * channels + k] += map.blended_mass()[a] * one[k];
    }
  }
  return std::make_unique<SummedAreaTable>(std::move(values), map.width, map.height, channels,
                                           std::move(far), pad, n, precision);
}

void search_mean(const SummedAreaTable& sat, const Receiver& r, int side, double* mean) {
  const int x0 = r.x - side / 2, y0 = r.y - side / 2;
  sat.box_mean(x0, y0, x0 + side, y0 + side, mean);
}

void filter_mean(const SummedAreaTable& sat, const Receiver& r, double w, double* mean) {
  sat.rect_mean(r.cx() - w / 2, r.cy() - w / 2, r.cx() + w / 2, r.cy() + w / 2, mean);
}

bool blocker_from_lit_share(double mu, double p, double zs, double* blocker) {
  if (1 - p < 1e-6) return false;
  *blocker = std::clamp((mu - p * zs) / (1 - p), 0.0, zs);
  return true;
}

std::vector<std::string> soft_technique_names() {
  std::vector<std::string> names;
  for (const TechniqueRow* row : family_rows(TechniqueFamily::SoftShadow))
    if (!row->prefix()) names.push_back(row->name);
  return names;
}

SoftResult soft_shadow(const std::string& name, const ShadowMap& map, const Fragments& fragments,
                       const SoftReceivers& soft, const GaussianKernel& kernel,
                       const BiasParams& bias, const SoftParams& params, int threads,
                       const TechniqueParams& technique) {
  const TechniqueRow* row = find_technique(name, TechniqueFamily::SoftShadow);
  if (!row) throw InputError("technique '" + name + "' is no soft technique");
  if (soft.angle_deg <= 0)
    throw InputError("techniques: " + name +
                     " estimates a penumbra and needs a light with an extent; expected "
                     "light.angle > 0 or a dataset with light_angles (docs/soft-shadows.md)");
  const SoftSetup setup{map, soft, kernel, bias, params, technique};
  const SoftContext context = make_soft_context(setup);
  const std::unique_ptr<SoftTechnique> made = row->make_soft(name, setup);
  std::vector<double> shadow(fragments.size());
  ParallelErrors errors;
  size_t failures = 0;
#pragma omp parallel num_threads(threads) reduction(+ : failures)
  {
    SoftScratch scratch;
    bool ready = false;
    errors.capture([&] { made->prepare(scratch), ready = true; });
#pragma omp for schedule(dynamic, 1024)
    for (size_t k = 0; k < fragments.size(); ++k)
      errors.capture([&] {
        if (!ready) return;  // its error is captured already
        shadow[k] = made->shadow(context, receiver_of(fragments, soft, k), scratch);
        // A closed form on rounded moments can leave its domain (a Hankel matrix no longer
        // positive definite), an LP its certificate: no answer, counted, the receiver unshadowed.
        if (!std::isfinite(shadow[k])) shadow[k] = 0, ++failures;
      });
  }
  errors.rethrow();
  return {std::move(shadow), failures};
}

}  // namespace mb
