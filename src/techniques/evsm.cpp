// Exponential variance shadow maps in double and float32 (docs/reference.md §4).
#include <algorithm>
#include <cmath>
#include <limits>

#include "moments/chebyshev.h"
#include "techniques/technique.h"
#include "util/number_text.h"

namespace mb {

namespace {

// Exponential variance shadow maps (seed 000 §2): VSM on the warped depths w = exp(c+ z) and
// w = -exp(-c- z). Both warps increase with z, so P(Z < z_f) = P(w(Z) < w(z_f)), and Cantelli's
// bound on a warped variable is a lower bound of G; EVSM4 takes the larger of its two, EVSM2 has
// the positive one alone. The positive warp sharpens the bound in front of z_f, the negative one
// behind.
class EvsmTechnique : public Technique {
 public:
  EvsmTechnique(std::string name, bool four, bool in_float, double c_positive, double c_negative)
      : Technique(std::move(name), evsm_basis(four, c_positive, c_negative),
                  in_float ? float32_storage() : double_storage()),
        four_(four),
        in_float_(in_float),
        c_positive_(c_positive),
        c_negative_(c_negative) {}
  double shadow(const FragmentInput& in) override {
    const double* m = in.moments.data();
    double g = vsm_bound(m, std::exp(c_positive_ * in.zf), 0);
    if (four_) g = std::max(g, vsm_bound(m + 2, -std::exp(-c_negative_ * in.zf), 0));
    return std::clamp(g, 0.0, 1.0);
  }
  // In double a lower bound (each warped Cantelli bound is one); in float32 the variance
  // E[w^2] - E[w]^2 of moments that reach exp(2 c z) loses its digits to rounding.
  double darkening_bound() const override {
    return in_float_ ? std::numeric_limits<double>::infinity() : 0;
  }
  std::string darkening_reason() const override {
    return in_float_ ? "float32 moments of exp(2 c z): the variance cancels in rounding" : "";
  }

 private:
  static Basis evsm_basis(bool four, double c_positive, double c_negative) {
    const std::string p = round_trip(c_positive), n = round_trip(c_negative);
    std::vector<std::string> functions{"exp(" + p + "*z)",
                                       "exp(" + round_trip(2 * c_positive) + "*z)"};
    if (four) {
      functions.push_back("-exp(-" + n + "*z)");
      functions.push_back("exp(-" + round_trip(2 * c_negative) + "*z)");
    }
    return Basis::parse(functions);
  }
  bool four_, in_float_;
  double c_positive_, c_negative_;
};

}  // namespace

std::unique_ptr<Technique> make_evsm(const std::string& name, const TechniqueParams& p) {
  return std::make_unique<EvsmTechnique>(name, name[4] == '4', name.size() > 5, p.evsm_c_positive,
                                         p.evsm_c_negative);
}

}  // namespace mb
