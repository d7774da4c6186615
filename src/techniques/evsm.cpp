// Exponential variance shadow maps in double and float32 (docs/reference.md §4).
#include <algorithm>
#include <cmath>
#include <limits>

#include "moments/chebyshev.h"
#include "techniques/hard_rows.h"
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

using P = TechniqueParams;

const TechniqueOption kEvsmCPositive{
    {"evsm.c_positive", OptionType::Number, "40",
     "EVSM exponent of the positive warp exp(c z) (exp(2 c z) must fit float32 for "
     "evsm*_float: c <= 44).",
     1e-6, 300}};
const TechniqueOption kEvsmCNegative{{"evsm.c_negative", OptionType::Number, "5",
                                      "EVSM4 exponent of the negative warp -exp(-c z).", 1e-6,
                                      300}};

template <bool kFour, bool kFloat>
std::unique_ptr<Technique> make(const std::string& name, const P& p) {
  return std::make_unique<EvsmTechnique>(name, kFour, kFloat, p.number(kEvsmCPositive),
                                         p.number(kEvsmCNegative));
}

// verify's LP: the warps scaled by their values at z = 1, so that the LP's columns stay <= 1
// (esm.cpp).
std::vector<std::string> evsm2_basis(const P& p) {
  const double c = p.number(kEvsmCPositive);
  return {"exp(" + round_trip(c) + "*(z-1))", "exp(" + round_trip(2 * c) + "*(z-1))"};
}
std::vector<std::string> evsm4_basis(const P& p) {
  std::vector<std::string> functions = evsm2_basis(p);
  const double c = p.number(kEvsmCNegative);
  functions.push_back("-exp(-" + round_trip(c) + "*z)");
  functions.push_back("exp(-" + round_trip(2 * c) + "*z)");
  return functions;
}

std::vector<TechniqueRow> rows() {
  const std::string float_bound =
      std::string(kNotProven) + ": the variance of exp(2 c z) cancels in float32";
  return {
      {.name = "evsm2",
       .rank = 60,
       .summary = "exponential VSM, positive warp exp(c z)",
       .storage = "double",
       .bound = kProvenBound,
       .options = {&kEvsmCPositive},
       .make = make<false, false>,
       .verify = VerifyRecipe{.judge = VerifyRecipe::Judge::LowerBound, .lp_basis = evsm2_basis},
       .verify_place = 10},
      {.name = "evsm4",
       .rank = 70,
       .summary = "exponential VSM, both warps, the larger bound",
       .storage = "double",
       .bound = kProvenBound,
       .options = {&kEvsmCPositive, &kEvsmCNegative},
       .make = make<true, false>,
       .verify = VerifyRecipe{.judge = VerifyRecipe::Judge::LowerBound, .lp_basis = evsm4_basis},
       .verify_place = 11},
      {.name = "evsm2_float",
       .rank = 80,
       .summary = "evsm2 with float32 moments",
       .storage = "float32",
       .bound = float_bound,
       .options = {&kEvsmCPositive},
       .make = make<false, true>},
      {.name = "evsm4_float",
       .rank = 90,
       .summary = "evsm4 with float32 moments",
       .storage = "float32",
       .bound = float_bound,
       .options = {&kEvsmCPositive, &kEvsmCNegative},
       .make = make<true, true>}};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

}  // namespace mb
