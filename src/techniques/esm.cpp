// Exponential shadow maps: Markov's inequality on exp(c z) (docs/reference.md §4).
#include <algorithm>
#include <cmath>

#include "moments/chebyshev.h"
#include "techniques/hard_rows.h"
#include "util/number_text.h"

namespace mb {

namespace {

class EsmTechnique : public Technique {
 public:
  explicit EsmTechnique(double c)
      : Technique("esm", Basis::parse({"exp(" + round_trip(c) + "*z)"}), double_storage()), c_(c) {}
  double shadow(const FragmentInput& in) override { return esm_bound(in.moments[0], in.zf, c_); }

 private:
  double c_;
};

// verify's LP for ESM: e^{cz} needs points far enough below 0 that e^{cz} ~ 0 (Markov's extremal
// mass sits at -infinity; at z = -4, e^{c (z - z_f)} <= e^{-40} for c = 10); the LP uses
// e^{c(z-1)}, the same span scaled by e^{-c}, whose values stay <= 1 (the LP recomputes the moments
// from the distribution, so the scale of the closed form's moment does not matter).
std::vector<std::string> esm_basis(const TechniqueParams& p) {
  return {"exp(" + round_trip(p.number(kEsmC)) + "*(z-1))"};
}

std::vector<TechniqueRow> rows() {
  return {{.name = "esm",
           .rank = 30,
           .summary = "exponential shadow maps: Markov on exp(c z)",
           .storage = "double",
           .bound = kProvenBound,
           .options = {&kEsmC},
           .default_run = true,
           .make = [](const std::string&, const TechniqueParams& p) -> std::unique_ptr<Technique> {
             return std::make_unique<EsmTechnique>(p.number(kEsmC));
           },
           .verify = VerifyRecipe{.lp_basis = esm_basis, .lo = -4},
           .verify_place = 5,
           .sweep_references = {{.expectation = "one exponential moment: far behind (seed 000 "
                                                "Figure 4)",
                                 .place = 2}}}};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

const TechniqueOption kEsmC{{"esm.c", OptionType::Number, "80", "ESM exponent c.", 1e-6, 700}};

}  // namespace mb
