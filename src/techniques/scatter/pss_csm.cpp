// pss_csm (docs/scattering.md §3.2; Klehm et al. 2014, seed 004 §2.6): prefiltered single
// scattering with a convolution shadow map, the predecessor the seed compares with. The shadow
// test [d < z] is a square wave of period 2 in z - d, 1/2 + 2 Σ_k sin(c_k (z - d)) / c_k with
// c_k = (2k - 1) pi, k = 1..M (scatter.csm_terms); its terms split into cos(c_k d) and sin(c_k d),
// 2M channels whose prefix sums along a row give the series of the ray's shadowed fraction. Term k
// is damped by exp(-damping (k / M)²) (scatter.csm_damping, as csm.damping damps the hard-shadow
// csm row; a key of its own, as every family's options are its own). Unlike that
// row, the series is not sharpened (2S - 1): the shadowed fraction is the mean of the test over the
// row, which the series' mean gives, and sharpening would not commute with that mean. The
// truncated series rings: not a bound.
#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include "techniques/registry.h"
#include "techniques/scatter/prefiltered_scatter.h"

namespace mb {

namespace {

const TechniqueOption kScatterCsmTerms{
    {"scatter.csm_terms", OptionType::Integer, "16",
     "Fourier terms M of pss_csm (2M real coefficients per texel; docs/scattering.md §3.2). 16: "
     "seed 004 §2.6's 32 coefficients.",
     1, 64}};

const TechniqueOption kScatterCsmDamping{
    {"scatter.csm_damping", OptionType::Number, "2",
     "Ringing suppression of pss_csm (docs/scattering.md §3.2): term k scaled by "
     "exp(-damping (k/M)^2), as csm.damping damps the hard-shadow csm row. 2: csm.damping's "
     "default; seed 004 §2.6 does not state its damping.",
     0, 100}};

class PssCsm : public PrefilteredScatter {
 public:
  PssCsm(const std::string& name, const ScatterParams& params)
      : PrefilteredScatter(name, params),
        terms_(params.technique.integer(kScatterCsmTerms)),
        damping_(params.technique.number(kScatterCsmDamping)) {}

 protected:
  void prefilter(const RectifiedMap& map) override {
    const int terms = terms_;
    sums_ = std::make_unique<RowPrefixSums>(map, 2 * terms, [terms](double d, double* out) {
      for (int k = 1; k <= terms; ++k) {
        const double c = (2 * k - 1) * std::numbers::pi;
        out[2 * (k - 1)] = std::cos(c * d), out[2 * (k - 1) + 1] = std::sin(c * d);
      }
    });
  }
  double shadowed_fraction(const RectifiedRay& ray) const override {
    std::vector<double> b(size_t(2 * terms_));
    sums_->mean(ray, b.data());
    double series = 0.5;
    for (int k = 1; k <= terms_; ++k) {
      const double c = (2 * k - 1) * std::numbers::pi;
      const double weight = 2 / c * std::exp(-damping_ * double(k * k) / double(terms_ * terms_));
      series += weight * (std::sin(c * ray.depth) * b[size_t(2 * (k - 1))] -
                          std::cos(c * ray.depth) * b[size_t(2 * (k - 1) + 1)]);
    }
    return std::clamp(series, 0.0, 1.0);
  }

 private:
  int terms_;
  double damping_;
  std::unique_ptr<RowPrefixSums> sums_;
};

std::vector<TechniqueRow> rows() {
  return {{.name = "pss_csm",
           .family = TechniqueFamily::Scattering,
           .rank = 55,
           .summary = "prefiltered single scattering with a convolution shadow map: a damped "
                      "Fourier series of the shadow test, 2 scatter.csm_terms coefficients "
                      "(Klehm et al. 2014; seed 004 §2.6)",
           .storage = "rectified map, prefix sums of 2M Fourier coefficients in double",
           .bound = "not proven: the truncated series rings (Gibbs)",
           .unproven_reason = "a truncated Fourier series of the shadow test rings",
           .options = {&kScatterCsmTerms, &kScatterCsmDamping},
           .family_options = {"scatter.light_resolution", "scatter.guard_band"},
           .default_run = true,
           .make_scatter = [](const std::string& name,
                              const ScatterParams& params) -> std::unique_ptr<ScatterTechnique> {
             return std::make_unique<PssCsm>(name, params);
           }}};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

}  // namespace mb
