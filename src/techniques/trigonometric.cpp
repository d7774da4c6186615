// Trigonometric moment shadow mapping in double and float32 (src/moments/tmsm.md).
#include <algorithm>
#include <cmath>

#include "moments/canonical.h"
#include "moments/tmsm.h"
#include "techniques/closed_form.h"
#include "techniques/hard_rows.h"

namespace mb {

namespace {

// Trigonometric moment shadow mapping (moments/tmsm.md): bias towards the uniform distribution.
class TmsmTechnique : public ClosedFormTechnique {
 public:
  TmsmTechnique(std::string name, bool in_float, double alpha, double beta)
      : ClosedFormTechnique(std::move(name), Basis::parse({"trig4"}),
                            in_float ? float32_storage() : double_storage()),
        in_float_(in_float),
        alpha_(alpha),
        beta_(beta) {}
  double shadow(const FragmentInput& in) override {
    if (in_float_) return finish(solve<float>(in));
    return finish(solve<double>(in));
  }
  // The bias pulls towards the uniform distribution on [0, 1], whose mass below z_f is at most 1.
  double darkening_bound() const override { return closed_form_bound(alpha_, beta_); }
  std::string darkening_reason() const override { return closed_form_reason(beta_); }

 private:
  template <class Real>
  double solve(const FragmentInput& in) const {
    Real b[4];
    for (int j = 0; j < 4; ++j) b[j] = Real(in.moments[j]);
    bias_trigonometric_moments(b, Real(alpha_));
    MsmBound<Real> r = tmsm(b, Real(in.zf), false);
    return double(r.lower + Real(beta_) * r.at_zf);
  }
  bool in_float_;
  double alpha_, beta_;
};

using P = TechniqueParams;

const TechniqueOption kTmsmAlpha{
    .spec = {"tmsm.alpha", OptionType::Number, "1e-10",
             "Moment bias of trigonometric MSM in double (towards 0).", 0, 1},
    .moment_bias = true};
const TechniqueOption kTmsmFloatAlpha{
    .spec = {"tmsm_float.alpha", OptionType::Number, "5e-5",
             "Moment bias of trigonometric MSM in float32 (measured: tmsm.md §6).", 0, 1},
    .moment_bias = true};

std::vector<TechniqueRow> rows() {
  return {{.name = "tmsm",
           .rank = 180,
           .summary = "trigonometric MSM (src/moments/tmsm.md), double",
           .storage = "double",
           .bound = kAlphaBound,
           .options = {&kTmsmAlpha, &kHamburgerBeta},
           .default_run = true,
           .make = [](const std::string& name, const P& p) -> std::unique_ptr<Technique> {
             return std::make_unique<TmsmTechnique>(name, false, p.number(kTmsmAlpha),
                                                    p.number(kHamburgerBeta));
           },
           .verify = VerifyRecipe{.lp_basis = fixed_lp_basis<kTrig4>},
           .verify_place = 3,
           .sweep_references = {{.expectation = "the trigonometric closed form: equal to lp:trig4 "
                                                "up to the LP's grid",
                                 .place = 5}}},
          {.name = "tmsm_float",
           .rank = 190,
           .summary = "trigonometric MSM, float32",
           .storage = "float32",
           .bound = std::string(kNotProven) + ": rounding of the moments",
           .options = {&kTmsmFloatAlpha, &kHamburgerBeta},
           .default_run = true,
           .make = [](const std::string& name, const P& p) -> std::unique_ptr<Technique> {
             return std::make_unique<TmsmTechnique>(name, true, p.number(kTmsmFloatAlpha),
                                                    p.number(kHamburgerBeta));
           },
           .verify = storage_box(fixed_lp_basis<kTrig4>, 0, 1, false, &kTmsmFloatAlpha),
           .verify_place = 9}};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

}  // namespace mb
