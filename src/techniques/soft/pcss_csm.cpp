// CSM through a summed-area table (seed 001 "SACSM", docs/soft-shadows.md §2): the lit share
// saturate(2 f) (seed 001 scales by 2 so that f = 1/2 at d = z reads lit); the blocker search
// averages z over the region weighted by CSM's own shadow estimate 1 - f at z_s,
// E[z (1 - f)] / E[1 - f], from the z cos and z sin channels.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "techniques/registry.h"
#include "techniques/soft/soft_technique.h"

namespace mb {

const TechniqueOption kPcssCsmTerms{
    {"soft.csm_terms", OptionType::Integer, "8",
     "pcss_csm: Fourier terms M of the shadow test (seed 001: M = 8); the table holds 4M + 1 "
     "channels (the blocker search needs z cos and z sin too).",
     1, 32}};
const TechniqueOption kPcssCsmAbsorption{
    {"soft.csm_absorption", OptionType::Number, "1",
     "pcss_csm: alpha of the ringing attenuation exp(-alpha (k / M)^2) of term k (seed 001's "
     "AbsorptionFactor; it names no value); 0: none.",
     0, 100}};

namespace {

// CSM's channels per term k = 1..M, c_k = (2k - 1) pi: cos(c_k z), sin(c_k z), z cos(c_k z),
// z sin(c_k z); then z. Each in [-1, 1], stored as (v + 1) / 2 in the table.
void csm_channels(int terms, double z, double* v) {
  for (int k = 0; k < terms; ++k) {
    const double ck = (2 * k + 1) * std::numbers::pi;
    v[4 * k] = std::cos(ck * z), v[4 * k + 1] = std::sin(ck * z);
    v[4 * k + 2] = z * v[4 * k], v[4 * k + 3] = z * v[4 * k + 1];
  }
  v[4 * terms] = z;
  for (int i = 0; i <= 4 * terms; ++i) v[i] = (v[i] + 1) / 2;
}

std::vector<double> far_channels(int terms) {
  std::vector<double> far(4 * terms + 1);
  csm_channels(terms, 1.0, far.data());
  return far;
}

// Seed 001's CSM test, the Fourier series of the step H(z - d) truncated at M terms, each
// attenuated by exp(-alpha (k / M)^2) against ringing, on filtered channels `m` (unscaled):
// f = 1/2 + 2 sum_k a_k / c_k (cos(c_k d) E[sin(c_k z)] - sin(c_k d) E[cos(c_k z)]). `offset`
// 2 reads E[z cos], E[z sin] instead, giving E[z f] without its 1/2 E[z] term.
double csm_series(int terms, double absorption, const double* m, double d, int offset) {
  double sum = 0;
  for (int k = 0; k < terms; ++k) {
    const double ck = (2 * k + 1) * std::numbers::pi;
    const double a = std::exp(-absorption * double(k + 1) * (k + 1) / (terms * terms));
    sum +=
        a / ck * (std::cos(ck * d) * m[4 * k + offset + 1] - std::sin(ck * d) * m[4 * k + offset]);
  }
  return 2 * sum;
}

class PcssCsm : public SoftTechnique {
 public:
  explicit PcssCsm(const SoftSetup& s)
      : terms_(s.technique.integer(kPcssCsmTerms)),
        absorption_(s.technique.number(kPcssCsmAbsorption)),
        sat_(soft_summed_area_table(
            s.map, s.params, 4 * terms_ + 1,
            [terms = terms_](double z, double* v) { csm_channels(terms, z, v); },
            far_channels(terms_))) {}
  double shadow(const SoftContext& c, const Receiver& r, SoftScratch&) const override {
    const int n = 4 * terms_ + 1;
    std::vector<double> m(n);
    search_mean(*sat_, r, c.params.sat_search, m.data());
    for (double& v : m) v = 2 * v - 1;
    const double zs = c.search_depth(r), mu = m[n - 1];
    const double shadowed = 0.5 - series(m.data(), zs, 0);       // E[1 - f]
    const double weighted = 0.5 * mu - series(m.data(), zs, 2);  // E[z (1 - f)]
    if (shadowed < 1e-6) return 0;
    const double blocker = std::clamp(weighted / shadowed, 0.0, zs);
    const double w = c.box_width(c.penumbra(r, blocker));
    filter_mean(*sat_, r, w, m.data());
    for (double& v : m) v = 2 * v - 1;
    const double f = 0.5 + series(m.data(), c.test_depth(r, w / 2), 0);
    return 1 - std::clamp(2 * f, 0.0, 1.0);
  }

 private:
  double series(const double* m, double d, int offset) const {
    return csm_series(terms_, absorption_, m, d, offset);
  }
  int terms_;
  double absorption_;
  std::unique_ptr<SummedAreaTable> sat_;
};

std::vector<TechniqueRow> rows() {
  return {
      {.name = "pcss_csm",
       .family = TechniqueFamily::SoftShadow,
       .rank = 40,
       .summary = "PCSS through a summed-area table of CSM's Fourier channels (seed 001 SACSM)",
       .storage = "summed-area table (soft.sat)",
       .bound = "none: the penumbra is estimated (docs/soft-shadows.md §2)",
       .unproven_reason = kSoftUnproven,
       .options = {&kPcssCsmTerms, &kPcssCsmAbsorption},
       .family_options = {"soft.sat_search", "soft.min_filter", "soft.max_filter", "soft.sat"},
       .make_soft = [](const std::string&, const SoftSetup& s) -> std::unique_ptr<SoftTechnique> {
         return std::make_unique<PcssCsm>(s);
       }}};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

}  // namespace mb
