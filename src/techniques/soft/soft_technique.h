#pragma once
// Soft-shadow techniques (docs/soft-shadows.md §2): percentage-closer soft shadows (seed 001) with
// PCF, exactly and as sampled in practice, and through summed-area tables of VSM, ESM, CSM and four
// power moments (seed 004 §3, moment soft shadow mapping). Each searches the shadow map around the
// receiver for blockers, estimates the penumbra's width from their mean depth and the light's
// angle, and filters the map over a box that wide. What they share: their options (SoftParams),
// the receiver and the view's context, the exact box filter, and the loop over a view's receivers.
// Each technique's file declares its row (techniques/registry.h, family SoftShadow).
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "lp/problem.h"
#include "lp/solution.h"
#include "shadow/area_light.h"
#include "shadow/fragments.h"
#include "shadow/summed_area.h"
#include "techniques/lp_fragment_solver.h"
#include "techniques/technique.h"
#include "util/option_record.h"

namespace mb {

// The soft family's shared options: the search regions, the filter's limits and the summed-area
// table's format that every technique's context and table read, and eval's blocker audit. Each
// option record states its source and holds the default. A technique's own constants (msm_soft's
// alpha, pcss_csm's terms, ...) are its own option records in its file (TechniqueParams).
struct SoftParams {
  SoftParams();
  int pcss_search;    // texels a side of PCSS's blocker search (seed 004 §3.6)
  int sat_search;     // ... of the SAT techniques' (seed 004 §3.6)
  double min_filter;  // texels: the narrowest penumbra box; the kernel filters besides
  int max_filter;     // texels: the widest filter; N = (max_filter + 2)^2 at least
  std::string sat;    // fixed32 (seed 004 §3.2) or exact
  int audit;          // receivers per view whose blocker search is audited (§3)
};

const std::vector<OptionRecord<SoftParams>>& soft_option_records();

// Why no soft technique proves a darkening bound (TechniqueRow::unproven_reason).
inline const char* const kSoftUnproven =
    "a soft technique estimates its penumbra (docs/soft-shadows.md §2)";

// What a soft technique of one view is made with.
struct SoftSetup {
  const ShadowMap& map;
  const SoftReceivers& soft;
  const GaussianKernel& kernel;
  const BiasParams& bias;
  const SoftParams& params;
  const TechniqueParams& technique;  // each technique's own options, lp.* for the LP's
};

struct Receiver {
  int x = 0, y = 0;
  double zf = 0, slope = 0;  // slope: |dz/dx| + |dz/dy|
  double gx = 0, gy = 0;
  double cx() const { return x + 0.5; }
  double cy() const { return y + 0.5; }
};
Receiver receiver_of(const Fragments& f, const SoftReceivers& soft, size_t k);

// What a view's receivers share: the map, the light, the protocol's bias and kernel, and the
// filter limits.
struct SoftContext {
  const ShadowMap& map;
  const SoftReceivers& soft;
  const GaussianKernel& kernel;
  const BiasParams& bias;
  const SoftParams& params;
  double kernel_variance = 0;  // per axis, of the protocol's discrete kernel
  // The protocol's bias (docs/reference.md §3) for a filter reaching `radius` texels: the
  // receiver's plane stays behind z_f - delta at every texel the filter reads.
  double test_depth(const Receiver& r, double radius) const {
    return r.zf - (bias.constant + bias.slope * radius * r.slope);
  }
  // A search-region texel is a blocker where the protocol's own test would count it, the bias of
  // the kernel's reach (docs/soft-shadows.md §2): a bias grown with the region drops the nearest
  // blockers, and with them the contact shadows, while the reference keeps them.
  double search_depth(const Receiver& r) const { return test_depth(r, kernel.radius()); }
  // Texels a side of PCSS's search region: the option, or (0) seed 001's region from the light's
  // size, the light's cone from the receiver back to the depth range's near end (z = 0).
  int pcss_search(const Receiver& r) const {
    if (params.pcss_search > 0) return params.pcss_search;
    return int(std::min(2 * std::ceil(soft.rim_shear * r.zf) + 1, 255.0));
  }
  // PCSS's penumbra for a directional light (seed 001, its directional form): the blockers' light
  // cone widens by 2 tan(theta / 2) per unit of depth, here in texels; clamped to the filter range.
  double penumbra(const Receiver& r, double blocker_depth) const {
    const double w = 2 * soft.rim_shear * std::max(r.zf - blocker_depth, 0.0);
    return std::clamp(w, params.min_filter, double(params.max_filter));
  }
  // The box a technique that filters with one box uses for the penumbra w: the variance of the
  // penumbra's box and the protocol's kernel together (docs/soft-shadows.md §2), the box of
  // width W over texels having (W^2 - 1) / 12.
  double box_width(double w) const {
    return std::min(std::sqrt(w * w + 12 * kernel_variance + 1), double(params.max_filter));
  }
};
SoftContext make_soft_context(const SoftSetup& setup);

// One thread's LP state (GLPK, the fast backend's fallback, frees memory only in the thread that
// allocated it: each thread makes, uses and drops its own) and the storage it reuses.
struct SoftScratch {
  std::unique_ptr<LpFragmentSolver> lp;
  std::vector<double> depths, weights;
  lp::Problem problem;
};

// A soft technique made for one view (its summed-area table built once), answering any receiver
// from any thread.
class SoftTechnique {
 public:
  virtual ~SoftTechnique() = default;
  // Makes what a thread's scratch needs (an LP solver), in that thread.
  virtual void prepare(SoftScratch&) const {}
  // One receiver's shadow; NaN when the technique gives no answer there.
  virtual double shadow(const SoftContext& c, const Receiver& r, SoftScratch& scratch) const = 0;
};

// Every texel (i, j) the square of side w centred on (cx, cy) overlaps, with the overlap's extent
// along x and y: the exact box filter weights it by wx wy / w^2.
template <class F>
void for_each_box_texel(double cx, double cy, double w, F&& f) {
  const double ax = cx - w / 2, bx = cx + w / 2, ay = cy - w / 2, by = cy + w / 2;
  for (int j = int(std::floor(ay)); j < int(std::ceil(by)); ++j) {
    const double wy = std::min(by, j + 1.0) - std::max(ay, double(j));
    for (int i = int(std::floor(ax)); i < int(std::ceil(bx)); ++i)
      f(i, j, std::min(bx, i + 1.0) - std::max(ax, double(i)), wy);
  }
}

// The summed-area table of `channels` functions of depth f(z, values) over the map's texels (E
// over a texel's atoms on a translucent map, docs/reference.md §7), `far` beyond the map, sized
// for the widest box the options allow (seed 004 §3.2).
std::unique_ptr<SummedAreaTable> soft_summed_area_table(
    const ShadowMap& map, const SoftParams& p, int channels,
    const std::function<void(double, double*)>& f, std::vector<double> far);
// The blocker search's integer box: the search region matched to the texel grid (seed 004 §3.6).
void search_mean(const SummedAreaTable& sat, const Receiver& r, int side, double* mean);
// The penumbra's box of width w around the receiver.
void filter_mean(const SummedAreaTable& sat, const Receiver& r, double w, double* mean);
// The one-depth blocker estimate of a region whose lit share is p at z_s and whose mean depth
// is mu: the rest, at one depth, averages (mu - p z_s) / (1 - p); none when p is (nearly) 1.
bool blocker_from_lit_share(double mu, double p, double zs, double* blocker);

// One shadow per receiver of `fragments` for the soft technique `name` (its registry row), on the
// view's shadow map, lit by the light `soft` describes; every receiver on its own, so any thread
// count gives these bits. InputError when the light has no extent (soft.angle_deg = 0) or `name`
// is no soft technique. `technique` holds the technique's own options; LP final steps solve on
// its lp.lo, lp.hi, lp.grid with its lp.backend.
struct SoftResult {
  std::vector<double> shadow;
  size_t failures = 0;  // receivers whose answer was not a number (left at 0)
};
SoftResult soft_shadow(const std::string& name, const ShadowMap& map, const Fragments& fragments,
                       const SoftReceivers& soft, const GaussianKernel& kernel,
                       const BiasParams& bias, const SoftParams& params, int threads,
                       const TechniqueParams& technique = {});
// Every soft technique's name but the family rows' (msm_soft:lp:<basis>), in registry order.
std::vector<std::string> soft_technique_names();

// The blocker search of the row that audits its own (TechniqueRow::audits_blocker) against its
// sharp bounds (docs/soft-shadows.md §3) on evenly spaced receivers of a view (about `count`)
// whose search region holds a blocker: the region's own mean blocker depth, seed 004's estimate
// from the region's fixed-point moments, and the smallest and largest mean any distribution on the
// grid and the region's depths with the region's four power moments allows (blocker_bounds), with
// the penumbra widths those allow. Layer-0 depths: on a translucent map the audit reads the first
// surfaces only.
struct BlockerAuditRow {
  size_t receiver = 0;
  double zs = 0, exact = 0, seed = 0, lo = 0, hi = 0;
  double penumbra_lo = 0, penumbra_hi = 0;       // texels, from hi and lo
  double penumbra_exact = 0, penumbra_seed = 0;  // texels, from exact and seed
  bool outside() const { return seed < lo - 1e-9 || seed > hi + 1e-9; }
};
std::vector<BlockerAuditRow> blocker_audit(const ShadowMap& map, const Fragments& fragments,
                                           const SoftReceivers& soft, const GaussianKernel& kernel,
                                           const BiasParams& bias, const SoftParams& params,
                                           const TechniqueParams& technique, int threads);

}  // namespace mb
