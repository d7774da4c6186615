// pss_msm4 and pss_msm4_16bit (docs/scattering.md §3.2; seed 004 §2.4): prefiltered single
// scattering with four power moments. Each rectified row's transmittance-weighted prefix sums of
// (d, d², d³, d⁴) are the moments of the row's depth distribution up to a ray's end; Hamburger's
// canonical distribution through the ray's depth (moments/hamburger.h) gives the sharp lower bound
// G on the shadowed fraction and its weight at the depth the upper bound G + w_1, blended by
// scatter.beta. pss_msm4 keeps the sums in double; pss_msm4_16bit stores them as the seed
// evaluates them, seed 000's theta_4 rounded to 16 bits a channel (moments/storage.h), and reads
// them back through its inverse.
#include <cmath>
#include <memory>
#include <mutex>

#include "moments/canonical.h"
#include "moments/hamburger.h"
#include "moments/storage.h"
#include "techniques/registry.h"
#include "techniques/scatter/prefiltered_scatter.h"

namespace mb {

namespace {

const TechniqueOption kPssMsm4Alpha{
    .spec = {"pss_msm4.alpha", OptionType::Number, "1e-10",
             "Moment bias of pss_msm4 (docs/scattering.md §3.2): the prefix sums' moments are "
             "pulled towards b* = (1/2, ..) by alpha before Hamburger's reconstruction. 1e-10, "
             "as hamburger4.alpha in double: enough to keep a row of one depth (a singular Hankel "
             "matrix) solvable, too little to move any answer visibly.",
             0, 1},
    .moment_bias = true};
const TechniqueOption kPssMsm416bitAlpha{
    .spec = {"pss_msm4_16bit.alpha", OptionType::Number, "3e-5",
             "Moment bias of pss_msm4_16bit (docs/scattering.md §3.2). 3e-5: seed 000's bias "
             "for theta_4 at 16 bits (hamburger4_16bit.alpha), which covers the rounding of the "
             "stored moments; seed 004 §2.6 biases more strongly for scattering without giving "
             "its value.",
             0, 1},
    .moment_bias = true};

void power4(double z, double* out) {
  out[0] = z, out[1] = z * z, out[2] = out[1] * z, out[3] = out[1] * out[1];
}

class PssMsm4 : public PrefilteredScatter {
 public:
  PssMsm4(const std::string& name, const ScatterParams& params, MomentStorage storage, double alpha)
      : PrefilteredScatter(name, params),
        storage_(std::move(storage)),
        alpha_(alpha),
        beta_(params.beta) {}
  size_t failures() const override { return failures_; }
  std::optional<StoredFormat> stored_format() const override {
    if (storage_.kind == StorageKind::Double) return std::nullopt;
    return StoredFormat{named_basis_set("power4"), storage_};
  }
  // verify (docs/scattering.md §6): in double, Hamburger's bounds on R equal the continuous LP's
  // on an interval holding the canonical nodes; MBOIT's four power moments are judged on the same
  // interval (techniques/oit/mboit_power.cpp), wide because near-singular moments put a node far
  // out. The 16-bit row's moments are rounded: no LP on them is sharp.
  std::optional<ScatterVerifyRecipe> verify_recipe() const override {
    if (storage_.kind != StorageKind::Double) return std::nullopt;
    return ScatterVerifyRecipe{
        .lp_technique = "pss_lp:power4", .lo = -400, .hi = 401, .tolerance = 1e-6};
  }

 protected:
  void prefilter(const RectifiedMap& map) override {
    sums_ = std::make_unique<RowPrefixSums>(map, 4, power4);
    // What a 16-bit target holds of each normalised prefix sum, read back as moments.
    if (storage_.kind != StorageKind::Double) sums_->round_through(storage_);
  }
  double shadowed_fraction(const RectifiedRay& ray) const override {
    double b[4];
    const double star[4] = {0.5, 0.5, 0.5, 0.5};
    sums_->mean(ray, b);
    // Every texel of the row segment holds the normalised depth 0 or 1 (values are clamped to
    // [0, 1], 1 where no surface lies over the ray, docs/scattering.md §3.1): equal moments, since
    // E z = E z^2 holds on [0, 1] only for mass at 0 and 1 alone, and they determine the
    // distribution: mass 1 - b1 at 0, b1 at 1. Seed 000's b* = (δ0 + δ1) / 2 keeps such moments
    // on the moment space's boundary for any alpha (a singular Hankel matrix), so their bounds,
    // which are exact, are answered here (results/FINDINGS.md §12).
    if (b[0] == b[1] && b[1] == b[2] && b[2] == b[3]) {
      const double below = ray.depth > 0 ? 1 - b[0] : 0;
      const double at = ray.depth <= 0 ? 1 - b[0] : ray.depth >= 1 ? b[0] : 0;
      return below + beta_ * at;
    }
    bias_moments(b, 4, alpha_, star);
    const MsmBound<double> r = hamburger4(b, ray.depth);
    const double g = r.lower + beta_ * r.at_zf;
    if (std::isfinite(g)) return g;
    std::lock_guard<std::mutex> lock(mutex_);
    ++failures_;  // a singular Hankel matrix: counted, answered as lit
    return 0;
  }

 private:
  MomentStorage storage_;
  double alpha_, beta_;
  std::unique_ptr<RowPrefixSums> sums_;
  mutable std::mutex mutex_;
  mutable size_t failures_ = 0;
};

template <MomentStorage (*kStorage)(), const TechniqueOption* kAlpha>
std::unique_ptr<ScatterTechnique> make(const std::string& name, const ScatterParams& params) {
  return std::make_unique<PssMsm4>(name, params, kStorage(), params.technique.number(*kAlpha));
}

std::vector<TechniqueRow> rows() {
  const std::vector<std::string> family{"scatter.light_resolution", "scatter.guard_band",
                                        "scatter.resample", "scatter.beta"};
  return {{.name = "pss_msm4",
           .family = TechniqueFamily::Scattering,
           .rank = 30,
           .summary = "prefiltered single scattering with four power moments in double: "
                      "Hamburger's bounds on the row's prefix sums, blended by scatter.beta "
                      "(seed 004 §2.4)",
           .storage = "rectified map, prefix sums of four power moments in double",
           .bound = "at scatter.beta 0 never too dark against pss_exact, up to alpha",
           .unproven_reason = "scatter.beta > 0 blends towards the upper bound",
           .options = {&kPssMsm4Alpha},
           .family_options = family,
           .default_run = true,
           .make_scatter = make<double_storage, &kPssMsm4Alpha>},
          {.name = "pss_msm4_16bit",
           .family = TechniqueFamily::Scattering,
           .rank = 40,
           .summary = "pss_msm4 from prefix sums stored with seed 000's theta_4 at 16 bits, as "
                      "seed 004 §2.6 evaluates it",
           .storage = "rectified map, prefix sums of theta_4 at 16 bits",
           .bound = "not proven: 16-bit rounding of the moments",
           .unproven_reason = "16-bit rounding of the moments and scatter.beta",
           .options = {&kPssMsm416bitAlpha},
           .family_options = family,
           .default_run = true,
           .make_scatter = make<unorm16_power4_storage, &kPssMsm416bitAlpha>}};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

}  // namespace mb
