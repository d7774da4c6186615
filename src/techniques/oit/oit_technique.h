#pragma once
// Order-independent transparency techniques (docs/transparency.md §3): each reconstructs the
// transmittance in front of every transparent fragment of a pixel, and composites with it.
// Moment-based ones (MBOIT's closed forms, `lp:<basis>`) see only the absorbance moments of the
// pixel's fragments, summed in a canonical order so that the submission order cannot change them.
#include <algorithm>
#include <cmath>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "shadow/compositing.h"
#include "techniques/technique.h"

namespace mb {

// How an MBOIT variant stores its moments (docs/transparency.md §3, "Storage").
enum class OitStorage { Double, Float, Snorm16 };

// Moment biases of one storage format: power[0..2] for 4, 6, 8 power moments, trig[0..2] for 2,
// 3, 4 trigonometric moments.
struct OitBiases {
  double power[3], trig[3];
};

// A transmittance technique's parameters. warp and depth_range are the family's oit.* options,
// whose records (techniques/oit/oit_options.h) give a default-made OitParams their defaults; a
// technique's own options (MBOIT's oit.beta, techniques/oit/mboit_row.h) are in `technique`; the
// rest are the techniques' constants.
struct OitParams {
  OitParams();
  // Moment bias of the MBOIT closed forms in double (docs/transparency.md §3, "Constants").
  // Moment biases (docs/transparency.md §3, "Constants"): double as the shadow closed forms; float
  // and 16-bit the values of the authors' code as its public ports carry them.
  OitBiases double_bias = {{1e-10, 1e-10, 1e-10}, {1e-10, 1e-10, 1e-10}};
  OitBiases float_bias = {{5e-7, 5e-6, 5e-5}, {4e-7, 8e-7, 1.5e-6}};
  OitBiases snorm16_bias = {{6e-5, 6e-4, 2.5e-3}, {4e-4, 6.5e-4, 8.5e-4}};
  // The trigonometric variants' wrapping zone in radians: 0.1 pi, the authors' code's default
  // (docs/transparency.md §5).
  double wrapping_zone = 0.1 * 3.14159265358979323846;
  // The depth warp onto [0, 1] the moments are taken of (docs/transparency.md §2; oit.warp).
  WarpKind warp;
  // The range it maps onto [0, 1] (docs/transparency.md §2; oit.depth_range).
  DepthRangeKind depth_range;
  // Each technique's own options; for lp:<basis> the LP's grid, backend and lp.beta (0: the sharp
  // bound e^{-A-}), its interval that of the warped depth, [0, 1], unless a caller widens it (the
  // closed forms' R).
  TechniqueParams technique;

 private:
  struct Defaults {};
  explicit OitParams(Defaults) {}  // the default constructor's table is made so
};

class OitTechnique {
 public:
  virtual ~OitTechnique() = default;
  const std::string& name() const { return name_; }
  // The transmittance in front of each fragment of `px` (`warped`: each fragment's depth warped
  // to [0, 1], DepthWarp), as the technique reconstructs it; not thread-safe (LP state).
  virtual void transmittance(const PixelFragments& px, std::span<const double> warped,
                             std::span<double> out) = 0;
  // Whether compositing rescales the transparent fragments' weights so that they sum to
  // 1 - T_total (MBOIT's and WBOIT's normalisation Gamma); otherwise they are used as they are.
  virtual bool normalised() const { return false; }
  // Fragments the technique could not answer (an LP that failed): T = 1 there.
  virtual size_t failures() const { return 0; }

 protected:
  explicit OitTechnique(std::string name) : name_(std::move(name)) {}

 private:
  std::string name_;
};

// The transmittance technique `name` made by its registry row (techniques/registry.h, family
// Transmittance); InputError naming the valid ones otherwise.
std::unique_ptr<OitTechnique> make_oit_technique(const std::string& name, const OitParams& params);
std::vector<std::string> oit_technique_names();  // without the family rows (lp:<basis>)

// The absorbance moments' distribution of a pixel: warped depths and absorbances (weights
// a_l / b_0), sorted by (depth, absorbance) so that any submission order gives the same sums, and
// b_0 = sum a_l.
struct AbsorbanceDistribution {
  std::vector<double> depths, weights;
  double total = 0;
  std::vector<std::pair<double, double>> scratch;  // (depth, absorbance) while sorting
};
AbsorbanceDistribution absorbance_distribution(const PixelFragments& px,
                                               std::span<const double> warped);
// The same into `d`, reusing its storage.
void absorbance_distribution(const PixelFragments& px, std::span<const double> warped,
                             AbsorbanceDistribution& d);

// A fragment's absorbance as the moment-based techniques take it: clamped to kMaxAbsorbance
// (T >= e^-10 per fragment, as MBOIT's implementation clamps it), so that an opaque fragment handed
// to them stays finite. A deep frame never hands them one: the first opaque surface ends a pixel's
// list (raster/deep_frame.h). The exact reference needs no clamp.
constexpr double kMaxAbsorbance = 10;

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

// The MBOIT rows of each storage: their name's suffix, their biases and their rank offset.
struct OitStorageVariant {
  OitStorage storage;
  const char* suffix;
  OitBiases OitParams::*biases;
  int rank;
};
inline constexpr OitStorageVariant kOitStorageVariants[] = {
    {OitStorage::Double, "", &OitParams::double_bias, 0},
    {OitStorage::Float, "_float", &OitParams::float_bias, 100},
    {OitStorage::Snorm16, "_16bit", &OitParams::snorm16_bias, 200},
};

// The LP technique with the basis of `moments` trigonometric moments as MBOIT takes them on the
// warped depth u: "lp:cos(1*s*z); sin(1*s*z); ...", s = 2 pi - wrapping_zone
// (docs/transparency.md §5).
std::string mboit_trig_lp_basis(int moments, double wrapping_zone);

// The transmittance the composite weighs each fragment with: a normalised technique's scaled by
// Gamma = (1 - T_total) / sum_l alpha_l T_l (docs/transparency.md §3), others' as given. In place.
void effective_transmittance(const OitTechnique& technique, const PixelFragments& px,
                             std::span<double> transmittance);
// The composite of a technique's transmittance (effective_transmittance, then over what lies
// behind, weighted by prod (1 - alpha_l)).
Rgb composite_with(const OitTechnique& technique, const PixelFragments& px,
                   std::span<const double> transmittance);

}  // namespace mb
