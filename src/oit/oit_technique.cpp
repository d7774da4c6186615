#include "oit/oit_technique.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "moments/canonical.h"
#include "moments/hamburger.h"
#include "techniques/lp_technique.h"
#include "util/error.h"

namespace mb {

namespace {

// A fragment's absorbance as the moment-based techniques take it: clamped to kMaxAbsorbance
// (T >= e^-10 per fragment, as MBOIT's implementation clamps it), so that an opaque fragment handed
// to them stays finite. A deep frame never hands them one: the first opaque surface ends a pixel's
// list (oit/deep_frame.h). The exact reference needs no clamp.
constexpr double kMaxAbsorbance = 10;

// `exact` and `unsorted`: a blend of the fragments themselves (oit/compositing.h), no moments.
class BlendOit : public OitTechnique {
 public:
  using Blend = void (*)(const PixelFragments&, std::span<double>);
  BlendOit(std::string name, Blend blend) : OitTechnique(std::move(name)), blend_(blend) {}
  void transmittance(const PixelFragments& px, std::span<const double>,
                     std::span<double> out) override {
    blend_(px, out);
  }

 private:
  Blend blend_;
};

// The moment-based techniques: they see the pixel's absorbance distribution only; a pixel without
// absorbance (every alpha 0) lets everything through.
class MomentOit : public OitTechnique {
 public:
  using OitTechnique::OitTechnique;
  void transmittance(const PixelFragments& px, std::span<const double> warped,
                     std::span<double> out) final {
    const AbsorbanceDistribution d = absorbance_distribution(px, warped);
    if (!(d.total > 0)) {
      std::fill(out.begin(), out.end(), 1.0);
      return;
    }
    reconstruct(d, warped, out);
  }

 protected:
  // T at each fragment (`warped`: their depths on [0, 1]) from the distribution `d`.
  virtual void reconstruct(const AbsorbanceDistribution& d, std::span<const double> warped,
                           std::span<double> out) = 0;
};

// Weighted blended OIT (McGuire and Bavoil 2013, their weight function (7) of the view depth z):
// w = alpha max(1e-2, min(3e3, 10 / (1e-5 + (z / 5)^2 + (z / 200)^6))). The composite normalises
// the weights, so only their ratios matter; the scenes' depths (2-20 units) lie where the
// function falls steadily.
class WeightedBlendedOit : public OitTechnique {
 public:
  WeightedBlendedOit() : OitTechnique("wboit") {}
  bool normalised() const override { return true; }
  void transmittance(const PixelFragments& px, std::span<const double>,
                     std::span<double> out) override {
    for (size_t l = 0; l < px.size(); ++l) {
      const double z = std::abs(px.depth[l]);
      const double falloff = 10 / (1e-5 + std::pow(z / 5, 2) + std::pow(z / 200, 6));
      out[l] = px.alpha[l] * std::clamp(falloff, 1e-2, 3e3);
    }
  }
};

// MBOIT with m power moments of the warped depth t = 2u - 1 in [-1, 1] (the seed's warp),
// Hamburger's canonical bound through t_l (moments/hamburger.h): A = b_0 (G + beta w), w the
// canonical weight at t_l. Moments are biased towards b* (docs/transparency.md §3, "Constants").
class MbOitPower : public MomentOit {
 public:
  MbOitPower(int moments, double alpha, double beta)
      : MomentOit("mboit_power" + std::to_string(moments)),
        m_(moments),
        alpha_(alpha),
        beta_(beta) {}
  bool normalised() const override { return true; }

 protected:
  void reconstruct(const AbsorbanceDistribution& d, std::span<const double> warped,
                   std::span<double> out) override {
    double b[6] = {};
    for (size_t i = 0; i < d.depths.size(); ++i) {
      const double t = 2 * d.depths[i] - 1;
      double power = 1;
      for (int j = 0; j < m_; ++j) b[j] += d.weights[i] * (power *= t);
    }
    static constexpr double kStar4[4] = {0, 0.375, 0, 0.375};
    static constexpr double kStar6[6] = {0, 0.48, 0, 0.451, 0, 0.45};
    bias_moments(b, m_, alpha_, m_ == 4 ? kStar4 : kStar6);
    for (size_t l = 0; l < warped.size(); ++l) {
      const double t = 2 * warped[l] - 1;
      const MsmBound<double> r = m_ == 4 ? hamburger4(b, t) : hamburger6(b, t);
      const double g = std::clamp(r.lower + beta_ * r.at_zf, 0.0, 1.0);
      out[l] = std::exp(-d.total * g);
    }
  }

 private:
  int m_;
  double alpha_, beta_;
};

// lp:<basis> on the warped depth u in [0, 1]: Problem 1 on the grid and the pixel's own fragment
// depths (techniques/lp_technique.h), A = b_0 G with G the sharp lower bound, or with lp.beta the
// blend towards the LP's maximum. e^{-A} >= T_ref at every fragment when lp.beta = 0.
class LpOit : public MomentOit {
 public:
  LpOit(const std::string& name, const TechniqueParams& params)
      : MomentOit(name), technique_(make_lp_technique(name, params)) {}
  size_t failures() const override { return technique_->failures(); }

 protected:
  void reconstruct(const AbsorbanceDistribution& d, std::span<const double> warped,
                   std::span<double> out) override {
    FragmentInput in;
    in.kernel_depths = d.depths;
    in.kernel_weights = d.weights;
    for (size_t l = 0; l < warped.size(); ++l) {
      in.zf = warped[l];
      const size_t before = technique_->failures();
      const double g = technique_->shadow(in);
      out[l] = technique_->failures() > before ? 1.0 : std::exp(-d.total * g);
    }
  }

 private:
  std::unique_ptr<Technique> technique_;
};

}  // namespace

AbsorbanceDistribution absorbance_distribution(const PixelFragments& px,
                                               std::span<const double> warped) {
  std::vector<std::pair<double, double>> atoms;
  for (size_t l = 0; l < px.size(); ++l) {
    const double a = std::min(absorbance(px.alpha[l]), kMaxAbsorbance);
    if (a > 0) atoms.push_back({warped[l], a});
  }
  // Canonical order: the sums below are then the same for every submission order, bit for bit.
  std::sort(atoms.begin(), atoms.end());
  AbsorbanceDistribution d;
  for (const auto& [u, a] : atoms) d.total += a;
  for (const auto& [u, a] : atoms) d.depths.push_back(u), d.weights.push_back(a / d.total);
  return d;
}

Rgb composite_with(const OitTechnique& technique, const PixelFragments& px,
                   std::span<const double> transmittance) {
  const double total = total_transmittance(px);
  if (!technique.normalised()) return composite(px, transmittance, total);
  // Gamma = (1 - T_total) / sum_l alpha_l T_l (weighted blended OIT's normalisation).
  double weight = 0;
  for (size_t l = 0; l < px.size(); ++l) weight += px.alpha[l] * transmittance[l];
  std::vector<double> scaled(transmittance.begin(), transmittance.end());
  const double gamma = weight > 0 ? (1 - total) / weight : 0;
  for (double& t : scaled) t *= gamma;
  return composite(px, scaled, total);
}

std::vector<std::string> oit_technique_names() {
  return {"exact", "unsorted", "wboit", "mboit_power4", "mboit_power6"};
}

std::unique_ptr<OitTechnique> make_oit_technique(const std::string& name, const OitParams& p) {
  if (name == "exact") return std::make_unique<BlendOit>(name, exact_transmittance);
  if (name == "unsorted") return std::make_unique<BlendOit>(name, submission_transmittance);
  if (name == "wboit") return std::make_unique<WeightedBlendedOit>();
  if (name == "mboit_power4") return std::make_unique<MbOitPower>(4, p.power4_alpha, p.beta);
  if (name == "mboit_power6") return std::make_unique<MbOitPower>(6, p.power6_alpha, p.beta);
  if (name.rfind("lp:", 0) == 0) return std::make_unique<LpOit>(name, p.lp);
  std::string valid;
  for (const auto& n : oit_technique_names()) valid += n + ", ";
  throw InputError("oit technique '" + name + "': expected one of " + valid + "or lp:<basis>");
}

}  // namespace mb
