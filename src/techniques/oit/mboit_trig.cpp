// Moment-based OIT with trigonometric moments (docs/transparency.md §5), in double, float32 and
// 16 bits.
#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <string>

#include "moments/canonical.h"
#include "moments/canonical_bound.h"
#include "techniques/oit/mboit_row.h"
#include "techniques/oit/oit_technique.h"
#include "techniques/registry.h"
#include "util/number_text.h"

namespace mb {

namespace {

// MBOIT with n trigonometric moments (docs/transparency.md §5): the warped depth u in [0, 1] is
// the angle phi = (2 pi - theta) u, leaving a wrapping zone of angle theta between the farthest
// and the nearest depth; c_k = E[e^{i k phi}], biased towards the uniform distribution (c = 0).
// A = b_0 (sum_k w_k f_k + beta w_0) over the canonical representation through phi_l: f_k = 1
// in front of phi_l, a linear ramp from 0 to 1 across the wrapping zone, 0 behind.
class MbOitTrig : public MomentOit {
 public:
  MbOitTrig(std::string name, int moments, OitStorage storage, double alpha, double beta,
            double zone)
      : MomentOit(std::move(name)),
        n_(moments),
        storage_(storage),
        alpha_(alpha),
        beta_(beta),
        zone_(zone) {}
  bool normalised() const override { return true; }

 protected:
  void reconstruct(const AbsorbanceDistribution& d, std::span<const double> warped,
                   std::span<double> out) override {
    const double scale = 2 * std::numbers::pi - zone_;
    double b[8];
    const double total = stored_moments(
        d, storage_, 2 * n_,
        [&](double u, double* row) {
          for (int k = 1; k <= n_; ++k)
            row[2 * k - 2] = std::cos(k * scale * u), row[2 * k - 1] = std::sin(k * scale * u);
        },
        b);
    std::complex<double> c[kMaxCanonicalOrder];
    for (int k = 0; k < n_; ++k) c[k] = {b[2 * k], b[2 * k + 1]};
    for (int k = 0; k < n_; ++k) c[k] *= 1 - alpha_;
    for (size_t l = 0; l < warped.size(); ++l) {
      const double phi = scale * warped[l];
      CanonicalNodes r;
      if (!canonical_trigonometric(c, n_, phi, r)) {
        out[l] = 1, ++closed_form_failures_;
        continue;
      }
      double g = beta_ * r.weights[0];
      for (int k = 1; k < r.count; ++k) {
        const double psi = r.nodes[k];
        const double f = psi < phi ? 1 : psi > scale ? std::min(1.0, (psi - scale) / zone_) : 0;
        g += f * r.weights[k];
      }
      out[l] = std::exp(-total * std::clamp(g, 0.0, 1.0));
    }
  }

 private:
  int n_;
  OitStorage storage_;
  double alpha_, beta_, zone_;
};

template <int kMoments, int kVariant>
std::unique_ptr<OitTechnique> make(const std::string& name, const OitParams& p) {
  const OitStorageVariant& v = kOitStorageVariants[kVariant];
  return std::make_unique<MbOitTrig>(name, kMoments, v.storage, (p.*v.biases).trig[kMoments - 2],
                                     p.technique.number(kMboitBeta), p.wrapping_zone);
}

// verify in double: the canonical reconstruction is never below the LP's sharp bound on the circle
// (docs/transparency.md §5), over one period with the wrapping zone behind; four moments exceed
// the certified LP engine's seven functions.
template <int kMoments>
OitVerifyRecipe verify_recipe(const OitParams& p) {
  const double s = 2 * std::numbers::pi - p.wrapping_zone;
  return {.lp_basis = mboit_trig_lp_basis(kMoments, p.wrapping_zone),
          .kind = "never below",
          .lo = 0,
          .hi = 2 * std::numbers::pi / s,
          .tolerance = 1e-7};
}

template <int kMoments, int kVariant>
TechniqueRow row() {
  return mboit_row("mboit_trig", "trigonometric", kMoments, kVariant, 60, make<kMoments, kVariant>,
                   kVariant == 0 && kMoments < 4 ? verify_recipe<kMoments> : nullptr);
}

std::vector<TechniqueRow> rows() {
  return {row<2, 0>(), row<3, 0>(), row<4, 0>(), row<2, 1>(), row<3, 1>(),
          row<4, 1>(), row<2, 2>(), row<3, 2>(), row<4, 2>()};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

std::string mboit_trig_lp_basis(int moments, double wrapping_zone) {
  const double s = 2 * std::numbers::pi - wrapping_zone;
  std::string basis = "lp:";
  for (int k = 1; k <= moments; ++k) {
    const std::string arg = std::to_string(k) + "*" + round_trip(s) + "*z";
    basis += (k > 1 ? "; " : "") + std::string("cos(") + arg + "); sin(" + arg + ")";
  }
  return basis;
}

}  // namespace mb
