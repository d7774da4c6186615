// ESM with failure classification and fall-back (seed 002 §3.3; docs/reference.md §4): where the
// exponential test's assumption (no occluder of the kernel lies behind the receiver) fails, the
// fragment is answered by the paper's 2x2 custom PCF instead of the filtered ESM value.
#include <algorithm>
#include <cmath>
#include <limits>

#include "moments/chebyshev.h"
#include "techniques/hard_rows.h"
#include "util/number_text.h"

namespace mb {

namespace {

enum class EsmClassifier { ZMax, Threshold };

class EsmFallbackTechnique : public Technique {
 public:
  EsmFallbackTechnique(std::string name, EsmClassifier classifier, double c, double zmax_offset,
                       double threshold)
      : Technique(std::move(name), Basis::parse({"exp(" + round_trip(c) + "*z)"}),
                  double_storage()),
        classifier_(classifier),
        c_(c),
        zmax_offset_(zmax_offset),
        threshold_(threshold) {}
  bool needs_distribution() const override { return true; }
  // The fall-back's 2x2 test is not the 9x9 reference's: it can be darker than PCF.
  double darkening_bound() const override { return std::numeric_limits<double>::infinity(); }
  std::string darkening_reason() const override {
    return "the 2x2 custom PCF of fragments classified as failing is not the kernel's filter";
  }
  size_t fallbacks() const override { return fallbacks_; }

  double shadow(const FragmentInput& in) override {
    if (!fails(in)) return esm_bound(in.moments[0], in.zf, c_);
    ++fallbacks_;
    return custom_pcf(in);
  }

 private:
  bool fails(const FragmentInput& in) const {
    if (classifier_ == EsmClassifier::Threshold)
      return in.moments[0] * std::exp(-c_ * in.zf) > 1 + threshold_;
    // Z-max: the deepest texel the kernel touches (weight > 0) lies behind the receiver's depth
    // plus the offset, which keeps lit receivers on their own sloped plane from being flagged.
    double zmax = -std::numeric_limits<double>::infinity();
    for (size_t t = 0; t < in.kernel_depths.size(); ++t)
      if (in.kernel_weights[t] > 0) zmax = std::max(zmax, in.kernel_depths[t]);
    return zmax > in.zf + zmax_offset_;
  }
  // The paper evaluates the unfiltered ESM test at the four nearest texels and interpolates the
  // clamped results bilinearly. A receiver sits at its texel's centre, so the four nearest texels
  // are ambiguous; momentbench takes the receiver's texel and its +x, +y and +x+y neighbours with
  // weight 1/4 each (the bilinear weights half a texel towards +x+y). Taps are row by row.
  // On a translucent map a tap's test is the mass-weighted mean of its atoms' tests (the mass
  // sums to the tap's kernel weight, docs/reference.md §7).
  double custom_pcf(const FragmentInput& in) const {
    const size_t taps =
        in.tap_offsets.empty() ? in.kernel_depths.size() : in.tap_offsets.size() - 1;
    const int size = int(std::lround(std::sqrt(double(taps))));
    const int centre = (size / 2) * size + size / 2;
    double lit = 0;
    for (int offset : {0, 1, size, size + 1}) {
      const size_t tap = size_t(centre + offset);
      if (in.tap_offsets.empty()) {
        lit += 0.25 * test(in.kernel_depths[tap], in.zf);
        continue;
      }
      double weight = 0, sum = 0;
      for (uint32_t a = in.tap_offsets[tap]; a < in.tap_offsets[tap + 1]; ++a)
        weight += in.kernel_weights[a],
            sum += in.kernel_weights[a] * test(in.kernel_depths[a], in.zf);
      lit += 0.25 * (weight > 0 ? sum / weight : 1.0);
    }
    return 1 - lit;
  }
  // The unfiltered exponential test of one depth: the light that passes it.
  double test(double z, double zf) const { return std::clamp(std::exp(c_ * (z - zf)), 0.0, 1.0); }

  EsmClassifier classifier_;
  double c_, zmax_offset_, threshold_;
  size_t fallbacks_ = 0;
};

using P = TechniqueParams;

const TechniqueOption kEsmZmaxOffset{
    {"esm.zmax_offset", OptionType::Number, "0.01",
     "esm_zmax: a fragment fails when the kernel's deepest texel lies beyond z_f plus this offset "
     "(seed 002 §3.3 gives no value; 0.01 of the depth range clears a receiver's own sloped "
     "plane).",
     0, 1}};
const TechniqueOption kEsmThreshold{
    {"esm.threshold", OptionType::Number, "0.01",
     "ESM with the threshold classifier: a fragment fails when its filtered ESM value exceeds 1 + "
     "this epsilon (seed 002 §3.3 gives no value).",
     0, 1e6}};

template <EsmClassifier kClassifier>
std::unique_ptr<Technique> make(const std::string& name, const P& p) {
  return std::make_unique<EsmFallbackTechnique>(name, kClassifier, p.number(kEsmC),
                                                p.number(kEsmZmaxOffset), p.number(kEsmThreshold));
}

std::vector<TechniqueRow> rows() {
  const std::string bound = std::string(kNotProven) + ": the fall-back's 2x2 test";
  return {
      {.name = "esm_zmax",
       .rank = 40,
       .summary = "ESM, falling back to a 2x2 custom PCF where the kernel's z_max fails (seed 002)",
       .storage = "double + z_max",
       .bound = bound,
       .options = {&kEsmC, &kEsmZmaxOffset},
       .make = make<EsmClassifier::ZMax>},
      {.name = "esm_threshold",
       .rank = 50,
       .summary = "ESM, falling back to a 2x2 custom PCF where its value exceeds 1 + eps",
       .storage = "double",
       .bound = bound,
       .options = {&kEsmC, &kEsmThreshold},
       .make = make<EsmClassifier::Threshold>}};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

}  // namespace mb
