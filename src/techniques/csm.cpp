// Convolution shadow maps (docs/reference.md §4): a damped Fourier series of the shadow test.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "moments/chebyshev.h"
#include "techniques/hard_rows.h"

namespace mb {

namespace {

// Convolution shadow maps (seed 001 "Convolution Shadow Maps", "CSM Ringing"): the shadow test
// [z < z_f] as a Fourier series in t = z_f - z of period 2, 1/2 + 2 sum_k sin(c_k t) / c_k with
// c_k = (2k - 1) pi, whose terms split into E[cos(c_k z)] and E[sin(c_k z)] (the map's 2M
// channels); term k is damped by exp(-damping (k/M)^2) against ringing, and the slides' scaling
// by 2 (G = saturate(2 S - 1) for the series' shadow S) makes a receiver at its own depth lit.
// Not a lower bound: truncation rings (darkening_bound infinite; verify measures by how much).
class CsmTechnique : public Technique {
 public:
  CsmTechnique(int terms, double damping)
      : Technique("csm", csm_basis(terms), double_storage()), terms_(terms), damping_(damping) {}
  double shadow(const FragmentInput& in) override {
    double series = 0.5;
    for (int k = 1; k <= terms_; ++k) {
      const double c = (2 * k - 1) * std::numbers::pi;
      const double weight = 2 / c * std::exp(-damping_ * double(k * k) / double(terms_ * terms_));
      const double cos_term = in.moments[2 * (k - 1)], sin_term = in.moments[2 * (k - 1) + 1];
      series += weight * (std::sin(c * in.zf) * cos_term - std::cos(c * in.zf) * sin_term);
    }
    return std::clamp(2 * series - 1, 0.0, 1.0);
  }
  double darkening_bound() const override { return std::numeric_limits<double>::infinity(); }
  std::string darkening_reason() const override {
    return "a truncated Fourier series of the shadow test rings (Gibbs)";
  }

 private:
  static Basis csm_basis(int terms) { return Basis::parse(csm_channels(terms)); }
  int terms_;
  double damping_;
};

using P = TechniqueParams;

const TechniqueOption kCsmTerms{{"csm.terms", OptionType::Integer, "8",
                                 "CSM Fourier terms M (2M channels: cos and sin of (2k - 1) pi z).",
                                 1, 16}};
const TechniqueOption kCsmDamping{
    {"csm.damping", OptionType::Number, "2",
     "CSM ringing suppression: term k scaled by exp(-damping (k/M)^2).", 0, 100}};

std::vector<std::string> csm_lp_basis(const P& p) {
  return csm_channels(p.integer(kCsmTerms));
}

std::vector<TechniqueRow> rows() {
  return {
      {.name = "csm",
       .rank = 110,
       .summary = "convolution shadow maps: a damped Fourier series of the test",
       .storage = "double",
       .bound = std::string(kNotProven) + ": truncation rings (Gibbs)",
       .options = {&kCsmTerms, &kCsmDamping},
       .make = [](const std::string&, const P& p) -> std::unique_ptr<Technique> {
         return std::make_unique<CsmTechnique>(p.integer(kCsmTerms), p.number(kCsmDamping));
       },
       .verify = VerifyRecipe{.judge = VerifyRecipe::Judge::Exceedance, .lp_basis = csm_lp_basis},
       .verify_place = 12}};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

}  // namespace mb
