// pss_msm6 and pss_msm6_10bit (docs/scattering.md §3.2; seed 004 §2.5): prefiltered single
// scattering with six power moments in double, or stored as seed 004 stores them: 10 bits a
// channel after a transform (this project's theta_6, moments/storage.h), read back through its
// inverse. A rectified row stretches through the whole scene, so its depth distribution
// rarely has the two atoms four moments reconstruct exactly; six moments' canonical distribution
// through the ray's depth (moments/hamburger.h, hamburger6) has three more. scatter.beta blends its
// lower bound G and upper bound G + w_1, as for four moments.
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

const TechniqueOption kPssMsm6Alpha{
    .spec = {"pss_msm6.alpha", OptionType::Number, "1e-8",
             "Moment bias of pss_msm6 (docs/scattering.md §3.2). 1e-8: six power moments "
             "rounded to double leave a narrow distribution's moment set by more than smaller "
             "biases pull them back (hamburger6.alpha's finding, docs/reference.md §4); seed "
             "004 §2.5 uses 4e-3 for its 10-bit storage; results/FINDINGS.md §12 measures both.",
             0, 1},
    .moment_bias = true};
const TechniqueOption kPssMsm610bitAlpha{
    .spec = {"pss_msm6_10bit.alpha", OptionType::Number, "4e-3",
             "Moment bias of pss_msm6_10bit (docs/scattering.md §3.2). 4e-3: seed 004 §2.5's for "
             "its six moments at 10 bits a channel.",
             0, 1},
    .moment_bias = true};

void power6(double z, double* out) {
  out[0] = z;
  for (int j = 1; j < 6; ++j) out[j] = out[j - 1] * z;
}

class PssMsm6 : public PrefilteredScatter {
 public:
  PssMsm6(const std::string& name, const ScatterParams& params, MomentStorage storage, double alpha)
      : PrefilteredScatter(name, params),
        storage_(std::move(storage)),
        alpha_(alpha),
        beta_(params.beta) {}
  size_t failures() const override { return failures_; }
  std::optional<StoredFormat> stored_format() const override {
    if (storage_.kind == StorageKind::Double) return std::nullopt;
    return StoredFormat{named_basis_set("power6"), storage_};
  }
  // verify (docs/scattering.md §6): as pss_msm4, on MBOIT's interval for six power moments
  // (techniques/oit/mboit_power.cpp), whose sixth powers keep their digits there.
  // The 10-bit row's moments are rounded: no LP on them is sharp.
  std::optional<ScatterVerifyRecipe> verify_recipe() const override {
    if (storage_.kind != StorageKind::Double) return std::nullopt;
    return ScatterVerifyRecipe{
        .lp_technique = "pss_lp:power6", .lo = -20, .hi = 21, .tolerance = 1e-5};
  }

 protected:
  void prefilter(const RectifiedMap& map) override {
    sums_ = std::make_unique<RowPrefixSums>(map, 6, power6);
    // What a 10-bit target holds of each normalised prefix sum, read back as moments.
    if (storage_.kind != StorageKind::Double) sums_->round_through(storage_);
  }
  double shadowed_fraction(const RectifiedRay& ray) const override {
    double b[6];
    const double star[6] = {0.5, 0.5, 0.5, 0.5, 0.5, 0.5};
    sums_->mean(ray, b);
    bias_moments(b, 6, alpha_, star);
    const MsmBound<double> r = hamburger6(b, ray.depth);
    const double g = r.lower + beta_ * r.at_zf;
    if (std::isfinite(g)) return g;
    std::lock_guard<std::mutex> lock(mutex_);
    ++failures_;  // no canonical distribution: counted, answered as lit
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
  return std::make_unique<PssMsm6>(name, params, kStorage(), params.technique.number(*kAlpha));
}

std::vector<TechniqueRow> rows() {
  const std::vector<std::string> family{"scatter.light_resolution", "scatter.guard_band",
                                        "scatter.resample", "scatter.beta"};
  return {{.name = "pss_msm6",
           .family = TechniqueFamily::Scattering,
           .rank = 50,
           .summary = "prefiltered single scattering with six power moments in double, "
                      "Hamburger's bounds blended by scatter.beta (seed 004 §2.5)",
           .storage = "rectified map, prefix sums of six power moments in double",
           .bound = "not proven: six moments rounded to double (docs/reference.md §4)",
           .unproven_reason = "six moments rounded to double, and scatter.beta",
           .options = {&kPssMsm6Alpha},
           .family_options = family,
           .default_run = true,
           .make_scatter = make<double_storage, &kPssMsm6Alpha>},
          {.name = "pss_msm6_10bit",
           .family = TechniqueFamily::Scattering,
           .rank = 55,
           .summary = "pss_msm6 from prefix sums stored with this project's theta_6 at 10 bits a "
                      "channel, as seed 004 §2.5 stores six moments",
           .storage = "rectified map, prefix sums of theta_6 at 10 bits",
           .bound = "not proven: 10-bit rounding of the moments",
           .unproven_reason = "10-bit rounding of the moments and scatter.beta",
           .options = {&kPssMsm610bitAlpha},
           .family_options = family,
           .make_scatter = make<unorm10_power6_storage, &kPssMsm610bitAlpha>}};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

}  // namespace mb
