// Moment-based OIT with power moments (docs/transparency.md §3), in double, float32 and 16 bits.
#include <algorithm>
#include <cmath>
#include <string>

#include "moments/canonical.h"
#include "moments/canonical_bound.h"
#include "moments/hamburger.h"
#include "techniques/oit/mboit_row.h"
#include "techniques/oit/oit_technique.h"
#include "techniques/registry.h"

namespace mb {

namespace {

// MBOIT with m power moments of the warped depth t = 2u - 1 in [-1, 1] (the seed's warp): the
// canonical representation through t_l, A = b_0 (G + beta w), G its mass in front of t_l and w
// its weight at t_l (Hamburger's bound on R, docs/transparency.md §3). Moments are biased
// towards b* (docs/transparency.md §3, "Constants"); four and six use the closed forms of
// moments/hamburger.h, eight the general construction of moments/canonical_bound.h.
class MbOitPower : public MomentOit {
 public:
  MbOitPower(std::string name, int moments, OitStorage storage, double alpha, double beta)
      : MomentOit(std::move(name)), m_(moments), storage_(storage), alpha_(alpha), beta_(beta) {}
  bool normalised() const override { return true; }

 protected:
  void reconstruct(const AbsorbanceDistribution& d, std::span<const double> warped,
                   std::span<double> out) override {
    double b[8];
    const double total = stored_moments(
        d, storage_, m_,
        [&](double u, double* row) {
          const double t = 2 * u - 1;
          double power = 1;
          for (int j = 0; j < m_; ++j) row[j] = (power *= t);
        },
        b);
    static constexpr double kStar4[4] = {0, 0.375, 0, 0.375};
    static constexpr double kStar6[6] = {0, 0.48, 0, 0.451, 0, 0.45};
    static constexpr double kStar8[8] = {0, 0.75, 0, 0.676666667, 0, 0.63, 0, 0.6003030303};
    bias_moments(b, m_, alpha_, m_ == 4 ? kStar4 : m_ == 6 ? kStar6 : kStar8);
    if (m_ == 4) return resolve4(b, total, warped, out);
    for (size_t l = 0; l < warped.size(); ++l) {
      const double t = 2 * warped[l] - 1;
      double g = 0, at = 0;
      if (m_ == 8) {
        CanonicalNodes c;
        if (!canonical_power(b, 4, t, c)) {
          out[l] = 1, ++closed_form_failures_;
          continue;
        }
        for (int k = 1; k < c.count; ++k) g += c.nodes[k] < t ? c.weights[k] : 0;
        at = c.weights[0];
      } else {
        const MsmBound<double> r = m_ == 4 ? hamburger4(b, t) : hamburger6(b, t);
        g = r.lower, at = r.at_zf;
      }
      // A closed form that loses every digit (six moments of a nearly singular Hankel matrix)
      // gives NaN: no answer, counted like the canonical representation's failures.
      if (!std::isfinite(g + beta_ * at)) {
        out[l] = 1, ++closed_form_failures_;
        continue;
      }
      out[l] = std::exp(-total * std::clamp(g + beta_ * at, 0.0, 1.0));
    }
  }

 private:
  // Four moments: every fragment of the pixel at once (moments/hamburger.h, vectorised), as
  // MBOIT's resolve pass reads one pixel's moments for all its fragments.
  void resolve4(const double* b, double total, std::span<const double> warped,
                std::span<double> out) {
    const size_t n = warped.size();
    t_.resize(n), g_.resize(n);
    for (size_t l = 0; l < n; ++l) t_[l] = 2 * warped[l] - 1;
    hamburger4_blend_batch(b, t_.data(), n, beta_, g_.data());
    for (size_t l = 0; l < n; ++l) {
      if (!std::isfinite(g_[l])) {
        out[l] = 1, ++closed_form_failures_;
        continue;
      }
      out[l] = std::exp(-total * g_[l]);
    }
  }

  int m_;
  OitStorage storage_;
  double alpha_, beta_;
  std::vector<double> t_, g_;  // per fragment of the pixel: t = 2u - 1, and A / b_0
};

template <int kMoments, int kVariant>
std::unique_ptr<OitTechnique> make(const std::string& name, const OitParams& p) {
  const OitStorageVariant& v = kOitStorageVariants[kVariant];
  return std::make_unique<MbOitPower>(name, kMoments, v.storage,
                                      (p.*v.biases).power[kMoments / 2 - 2],
                                      p.technique.number(kMboitBeta));
}

// verify in double: Hamburger's bound is invariant under the affine map t = 2u - 1, so the LP takes
// powers of u. Six moments: z^6 on a wider interval is numerically dependent with the constant,
// and the closed form loses digits on near-singular Hankel matrices (docs/reference.md §4); eight
// exceed the certified LP engine's seven functions.
template <int kMoments>
OitVerifyRecipe verify_recipe(const OitParams&) {
  const bool six = kMoments == 6;
  return {.lp_basis = six ? "lp:power6" : "lp:power4",
          .kind = "equal",
          .lo = six ? -20.0 : -400.0,
          .hi = six ? 21.0 : 401.0,
          .tolerance = six ? 1e-5 : 1e-6};
}

template <int kMoments, int kVariant>
TechniqueRow row() {
  return mboit_row("mboit_power", "power", kMoments, kVariant, 30, make<kMoments, kVariant>,
                   kVariant == 0 && kMoments < 8 ? verify_recipe<kMoments> : nullptr);
}

std::vector<TechniqueRow> rows() {
  return {row<4, 0>(), row<6, 0>(), row<8, 0>(), row<4, 1>(), row<6, 1>(),
          row<8, 1>(), row<4, 2>(), row<6, 2>(), row<8, 2>()};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

}  // namespace mb
