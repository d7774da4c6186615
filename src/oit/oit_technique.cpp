#include "oit/oit_technique.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <numeric>

#include "moments/canonical.h"
#include "moments/canonical_bound.h"
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
    absorbance_distribution(px, warped, distribution_);
    if (!(distribution_.total > 0)) {
      std::fill(out.begin(), out.end(), 1.0);
      return;
    }
    reconstruct(distribution_, warped, out);
  }

 protected:
  // T at each fragment (`warped`: their depths on [0, 1]) from the distribution `d`.
  virtual void reconstruct(const AbsorbanceDistribution& d, std::span<const double> warped,
                           std::span<double> out) = 0;
  // Closed forms count the fragments whose moment matrix was not positive definite here.
  size_t failures() const override { return closed_form_failures_; }
  size_t closed_form_failures_ = 0;

 private:
  AbsorbanceDistribution distribution_;  // reused: no allocation per pixel
};

// The pixel's normalised moments as a storage format keeps them (docs/transparency.md §3,
// "Storage"): `basis(u, row)` fills the m real functions at u. Double: exact sums of the canonical
// order. Float: b_0 and every unnormalised sum accumulated in 32-bit floats, as a float render
// target blends them, then normalised. 16-bit: the normalised moments (in [-1, 1]) rounded to
// signed 16-bit fixed point, b_0 to float. Returns b_0 as stored.
template <class Basis>
double stored_moments(const AbsorbanceDistribution& d, OitStorage storage, int m, Basis basis,
                      double* b) {
  double row[8];
  if (storage == OitStorage::Float) {
    float total = 0, sums[8] = {};
    for (size_t i = 0; i < d.depths.size(); ++i) {
      const float a = float(d.total * d.weights[i]);
      basis(d.depths[i], row);
      total += a;
      for (int j = 0; j < m; ++j) sums[j] += a * float(row[j]);
    }
    for (int j = 0; j < m; ++j) b[j] = double(sums[j]) / double(total);
    return total;
  }
  std::fill(b, b + m, 0.0);
  for (size_t i = 0; i < d.depths.size(); ++i) {
    basis(d.depths[i], row);
    for (int j = 0; j < m; ++j) b[j] += d.weights[i] * row[j];
  }
  if (storage == OitStorage::Double) return d.total;
  for (int j = 0; j < m; ++j) b[j] = std::round(std::clamp(b[j], -1.0, 1.0) * 32767) / 32767;
  return float(d.total);
}

std::string storage_suffix(OitStorage storage) {
  return storage == OitStorage::Float ? "_float" : storage == OitStorage::Snorm16 ? "_16bit" : "";
}

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

// MBOIT with m power moments of the warped depth t = 2u - 1 in [-1, 1] (the seed's warp): the
// canonical representation through t_l, A = b_0 (G + beta w), G its mass in front of t_l and w
// its weight at t_l (Hamburger's bound on R, docs/transparency.md §3). Moments are biased
// towards b* (docs/transparency.md §3, "Constants"); four and six use the closed forms of
// moments/hamburger.h, eight the general construction of moments/canonical_bound.h.
class MbOitPower : public MomentOit {
 public:
  MbOitPower(int moments, OitStorage storage, double alpha, double beta)
      : MomentOit("mboit_power" + std::to_string(moments) + storage_suffix(storage)),
        m_(moments),
        storage_(storage),
        alpha_(alpha),
        beta_(beta) {}
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

// MBOIT with n trigonometric moments (docs/transparency.md §5): the warped depth u in [0, 1] is
// the angle phi = (2 pi - theta) u, leaving a wrapping zone of angle theta between the farthest
// and the nearest depth; c_k = E[e^{i k phi}], biased towards the uniform distribution (c = 0).
// A = b_0 (sum_k w_k f_k + beta w_0) over the canonical representation through phi_l: f_k = 1
// in front of phi_l, a linear ramp from 0 to 1 across the wrapping zone, 0 behind.
class MbOitTrig : public MomentOit {
 public:
  MbOitTrig(int moments, OitStorage storage, double alpha, double beta, double zone)
      : MomentOit("mboit_trig" + std::to_string(moments) + storage_suffix(storage)),
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

void absorbance_distribution(const PixelFragments& px, std::span<const double> warped,
                             AbsorbanceDistribution& d) {
  std::vector<std::pair<double, double>>& atoms = d.scratch;
  atoms.clear();
  for (size_t l = 0; l < px.size(); ++l) {
    const double a = std::min(absorbance(px.alpha[l]), kMaxAbsorbance);
    if (a > 0) atoms.push_back({warped[l], a});
  }
  // Canonical order: the sums below are then the same for every submission order, bit for bit.
  std::sort(atoms.begin(), atoms.end());
  d.total = 0;
  d.depths.clear(), d.weights.clear();
  for (const auto& [u, a] : atoms) d.total += a;
  for (const auto& [u, a] : atoms) d.depths.push_back(u), d.weights.push_back(a / d.total);
}

AbsorbanceDistribution absorbance_distribution(const PixelFragments& px,
                                               std::span<const double> warped) {
  AbsorbanceDistribution d;
  absorbance_distribution(px, warped, d);
  return d;
}

void effective_transmittance(const OitTechnique& technique, const PixelFragments& px,
                             std::span<double> transmittance) {
  if (!technique.normalised()) return;
  // Gamma = (1 - T_total) / sum_l alpha_l T_l (weighted blended OIT's normalisation).
  double weight = 0;
  for (size_t l = 0; l < px.size(); ++l) weight += px.alpha[l] * transmittance[l];
  const double gamma = weight > 0 ? (1 - total_transmittance(px)) / weight : 0;
  for (double& t : transmittance) t *= gamma;
}

Rgb composite_with(const OitTechnique& technique, const PixelFragments& px,
                   std::span<const double> transmittance) {
  std::vector<double> weights(transmittance.begin(), transmittance.end());
  effective_transmittance(technique, px, weights);
  return composite(px, weights, total_transmittance(px));
}

std::vector<std::string> oit_technique_names() {
  return {"exact",        "unsorted",    "wboit",       "mboit_power4", "mboit_power6",
          "mboit_power8", "mboit_trig2", "mboit_trig3", "mboit_trig4"};
}

std::unique_ptr<OitTechnique> make_oit_technique(const std::string& name, const OitParams& p) {
  if (name == "exact") return std::make_unique<BlendOit>(name, exact_transmittance);
  if (name == "unsorted") return std::make_unique<BlendOit>(name, submission_transmittance);
  if (name == "wboit") return std::make_unique<WeightedBlendedOit>();
  for (OitStorage storage : {OitStorage::Double, OitStorage::Float, OitStorage::Snorm16}) {
    const OitBiases& bias = storage == OitStorage::Double  ? p.double_bias
                            : storage == OitStorage::Float ? p.float_bias
                                                           : p.snorm16_bias;
    for (int m : {4, 6, 8})
      if (name == "mboit_power" + std::to_string(m) + storage_suffix(storage))
        return std::make_unique<MbOitPower>(m, storage, bias.power[m / 2 - 2], p.beta);
    for (int n = 2; n <= 4; ++n)
      if (name == "mboit_trig" + std::to_string(n) + storage_suffix(storage))
        return std::make_unique<MbOitTrig>(n, storage, bias.trig[n - 2], p.beta, p.wrapping_zone);
  }
  if (name.rfind("lp:", 0) == 0) return std::make_unique<LpOit>(name, p.lp);
  std::string valid;
  for (const auto& n : oit_technique_names()) valid += n + ", ";
  throw InputError("oit technique '" + name + "': expected one of " + valid + "or lp:<basis>");
}

}  // namespace mb
