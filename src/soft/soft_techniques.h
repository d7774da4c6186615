#pragma once
// Soft-shadow techniques (docs/soft-shadows.md §2): percentage-closer soft shadows (seed 001) with
// PCF, exactly and as sampled in practice, and through summed-area tables of VSM and four
// power moments (seed 004 §3, moment soft shadow mapping). Each searches the shadow map around the
// receiver for blockers, estimates the penumbra's width from their mean depth and the light's
// angle, and filters the map over a box that wide.
#include <string>
#include <vector>

#include "shadow/fragments.h"
#include "soft/area_light.h"
#include "techniques/technique.h"
#include "util/option_record.h"

namespace mb {

// The seeds' constants as defaults; each option record states its source.
struct SoftParams {
  int pcss_search = 15;           // texels a side of PCSS's blocker search (seed 004 §3.6)
  int sat_search = 27;            // ... of the SAT techniques' (seed 004 §3.6)
  int blocker_taps = 5;           // pcss: point taps a side in the blocker search (seed 001)
  int filter_taps = 9;            // pcss: PCF taps a side (seed 001's 9x9)
  double min_filter = 0;          // texels: the narrowest penumbra box; the kernel filters besides
  int max_filter = 31;            // texels: the widest filter; N = (max_filter + 2)^2 at least
  double blocker_epsilon = 0.01;  // msm_soft: eps_z1 (seed 004 §3.3)
  double umbra_epsilon = 0.01;    // msm_soft: eps_u, the umbra skip (seed 004 §3.4)
  double msm_alpha = 5e-6;        // msm_soft: moment bias (seed 004's alpha)
  std::string sat = "fixed32";    // fixed32 (seed 004 §3.2) or exact
  double esm_c = 30;              // pcss_esm: the exponent's scale (seed 001 tunes 10 to 30)
  int csm_terms = 8;              // pcss_csm: Fourier terms M (seed 001: M = 8)
  double csm_absorption = 1;      // pcss_csm: alpha of the ringing attenuation exp(-alpha (k/M)^2)
  int audit = 500;                // receivers per view whose blocker search is audited (§3)
};

const std::vector<OptionRecord<SoftParams>>& soft_option_records();

// pcss_exact, pcss, pcss_vsm, pcss_esm, pcss_csm, msm_soft.
const std::vector<std::string>& soft_technique_names();
// One of those, or msm_soft:lp:<basis>: msm_soft's blocker search and penumbra box with Problem 1
// for <basis> (an lp: technique's basis) on the box's moments as its final step.
bool is_soft_technique(const std::string& name);
constexpr const char* kMsmSoftLp = "msm_soft:lp:";
bool soft_technique_solves_lp(const std::string& name);
// InputError, before any work, when msm_soft:lp:<basis> names no basis or cannot be solved with
// `technique`'s LP settings.
void check_soft_technique(const std::string& name, const TechniqueParams& technique);

// One shadow per receiver of `fragments` for the technique `name`, on the view's shadow map, lit
// by the light `soft` describes; every receiver on its own, so any thread count gives these bits.
// InputError when the light has no extent (soft.angle_deg = 0). msm_soft:lp:<basis> solves its LPs
// on `technique`'s lp.lo, lp.hi, lp.grid with its lp.backend.
struct SoftResult {
  std::vector<double> shadow;
  size_t failures = 0;  // receivers whose answer was not a number (left at 0)
};
SoftResult soft_shadow(const std::string& name, const ShadowMap& map, const Fragments& fragments,
                       const SoftReceivers& soft, const GaussianKernel& kernel,
                       const BiasParams& bias, const SoftParams& params, int threads,
                       const TechniqueParams& technique = {});

// msm_soft's blocker search against its sharp bounds (docs/soft-shadows.md §3) on evenly spaced
// receivers of a view (about `count`) whose search region holds a blocker: the region's own mean
// blocker depth, seed 004's estimate from the region's fixed-point moments, and the smallest and
// largest mean any distribution on the grid and the region's depths with the region's four power
// moments allows (blocker_bounds), with the penumbra widths those allow. Layer-0 depths: on a
// translucent map the audit reads the first surfaces only.
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
                                           int threads);

}  // namespace mb
