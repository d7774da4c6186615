// Fourier opacity mapping (Jansen & Bavoil 2010; seed 004 §4.1, docs/reference.md §7): the
// classic filterable map for translucent occluders. It stores the Fourier series on [0, 1] of the
// absorption density sigma(z) = sum_i A_i delta(z - z_i), A_i = -ln(1 - alpha_i), which adds up in
// any order, so no sorting is needed; the transmittance to z_f is exp(-(integral of the truncated
// series up to z_f)). Opaque occluders go to an ordinary shadow map beside it, as in Jansen &
// Bavoil (their absorbance is infinite, and a 2M + 1 term series spreads a receiver's own opaque
// surface over ~1/M of the depth range: every receiver would shadow itself): the light is the PCF
// visibility of the opaque map times the series' transmittance.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "techniques/hard_rows.h"

namespace mb {

namespace {

class FomTechnique : public Technique {
 public:
  explicit FomTechnique(int terms)
      : Technique("fom", Basis(), double_storage()), terms_(terms), a_(terms + 1), b_(terms + 1) {}
  bool needs_distribution() const override { return true; }
  double darkening_bound() const override { return std::numeric_limits<double>::infinity(); }
  std::string darkening_reason() const override {
    return "a truncated Fourier series of the absorbance rings (Gibbs) and spreads each surface "
           "over ~1/M of the depth range, and its filtering averages absorbance, not transmittance";
  }

  // The kernel's coefficients: each tap's, weighted by its kernel weight k_t, which is what
  // filtering the coefficient map gives (they are linear in the map). k_t is the tap's total
  // weight, as every texel's masses sum to 1.
  double shadow(const FragmentInput& in) override {
    std::fill(a_.begin(), a_.end(), 0.0);
    std::fill(b_.begin(), b_.end(), 0.0);
    double visible = 0;  // PCF of the opaque map: taps whose first opaque surface is behind z_f
    const size_t taps =
        in.tap_offsets.empty() ? in.kernel_depths.size() : in.tap_offsets.size() - 1;
    for (size_t t = 0; t < taps; ++t) {
      const size_t begin = in.tap_offsets.empty() ? t : in.tap_offsets[t];
      const size_t end = in.tap_offsets.empty() ? t + 1 : in.tap_offsets[t + 1];
      double weight = 0;
      for (size_t i = begin; i < end; ++i) weight += in.kernel_weights[i];
      double opaque = 1;  // the far plane where the tap has no opaque surface
      for (size_t i = begin; i < end; ++i) {
        const double alpha = in.kernel_alpha[i];
        if (alpha >= 1)
          opaque = in.kernel_depths[i];
        else if (alpha > 0)
          add_atom(weight * -std::log1p(-alpha), in.kernel_depths[i]);
      }
      visible += opaque < in.zf ? 0 : weight;
    }
    return 1 - visible * std::exp(-std::max(0.0, absorbance_to(in.zf)));
  }

 private:
  // sigma's coefficients on [0, 1]: a_k = 2 sum A cos(2 pi k z), b_k = 2 sum A sin(2 pi k z).
  void add_atom(double absorbance, double z) {
    for (int k = 0; k <= terms_; ++k) {
      const double phase = 2 * std::numbers::pi * k * z;
      a_[k] += 2 * absorbance * std::cos(phase);
      b_[k] += 2 * absorbance * std::sin(phase);
    }
  }
  // The integral from 0 to z of a_0 / 2 + sum_k a_k cos(2 pi k z) + b_k sin(2 pi k z).
  double absorbance_to(double z) const {
    double sum = a_[0] / 2 * z;
    for (int k = 1; k <= terms_; ++k) {
      const double w = 2 * std::numbers::pi * k;
      sum += (a_[k] * std::sin(w * z) + b_[k] * (1 - std::cos(w * z))) / w;
    }
    return sum;
  }

  int terms_;
  std::vector<double> a_, b_;
};

const TechniqueOption kFomTerms{
    {"fom.terms", OptionType::Integer, "3",
     "Fourier opacity mapping: terms M of the absorbance's series (2M + 1 coefficients; 3 fills "
     "two "
     "RGBA targets less one channel, the storage of two 4MSM maps; Jansen & Bavoil 2010 vary it).",
     1, 16}};

std::vector<TechniqueRow> rows() {
  return {
      {.name = "fom",
       .rank = 120,
       .summary = "Fourier opacity mapping (Jansen & Bavoil 2010): a Fourier series of the "
                  "absorbance, for translucent occluders (seed 004 §4.1)",
       .storage = "double",
       .bound = std::string(kNotProven) + ": truncation rings, and filtering averages absorbance",
       .options = {&kFomTerms},
       .make = [](const std::string&, const TechniqueParams& p) -> std::unique_ptr<Technique> {
         return std::make_unique<FomTechnique>(p.integer(kFomTerms));
       }}};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

}  // namespace mb
