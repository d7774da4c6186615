// Trigonometric moment shadow mapping in double and float32 (src/moments/tmsm.md).
#include <algorithm>
#include <cmath>

#include "moments/canonical.h"
#include "moments/tmsm.h"
#include "techniques/closed_form.h"
#include "techniques/technique.h"

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

}  // namespace

std::unique_ptr<Technique> make_tmsm(const TechniqueParams& p) {
  return std::make_unique<TmsmTechnique>("tmsm", false, p.tmsm_alpha, p.beta);
}
std::unique_ptr<Technique> make_tmsm_float(const TechniqueParams& p) {
  return std::make_unique<TmsmTechnique>("tmsm_float", true, p.tmsm_float_alpha, p.beta);
}

}  // namespace mb
