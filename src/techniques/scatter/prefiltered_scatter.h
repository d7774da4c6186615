#pragma once
// What the prefiltered rows (pss_*) share (docs/scattering.md §3.1-3.2; seed 004 §2.2): each
// builds the rectified map of the light view and camera in `prepare` (its cost is the technique's),
// then answers a view ray as the seed does: the largest in-scattering of the ray, ∫_0^s
// exp(-sigma_t t) dt, times one minus the shadowed fraction the technique reconstructs from the
// ray's row up to its end, at its depth.
#include <algorithm>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "techniques/scatter/rectified_map.h"
#include "techniques/scatter/scatter_technique.h"

namespace mb {

// How `verify` checks a prefiltered row against pss_lp on the same row-prefiltered moments
// (docs/scattering.md §6; verify/scatter_verification.h).
struct ScatterVerifyRecipe {
  std::string lp_technique;  // the pss_lp: row it is compared with, at the same scatter.beta
  double lo = 0, hi = 1;     // the LP's interval of normalised depth: holds Hamburger's nodes
  double tolerance = 0;      // in the shadowed fraction
};

class PrefilteredScatter : public ScatterTechnique {
 public:
  void prepare(const ScatterSetup& setup) override {
    if (!setup.rectify_light || !setup.camera_desc)
      throw std::logic_error(name() + ": prepare without the light map or the camera to rectify");
    setup_ = setup;
    map_ = std::make_unique<RectifiedMap>(*setup.rectify_light, *setup.camera_desc,
                                          setup.extinction, settings_);
    prefilter(*map_);
  }
  double lit_length(const ScatterRay& ray) const override {
    const double all = transmittance_integral(0, ray.length, setup_.extinction);
    if (!(all > 0)) return 0;
    const double shadowed = shadowed_fraction(map_->locate(ray.direction, ray.length));
    return all * (1 - std::clamp(shadowed, 0.0, 1.0));
  }
  const RectifiedMap& map() const { return *map_; }
  // Its verify recipe; none: verify does not check the row.
  virtual std::optional<ScatterVerifyRecipe> verify_recipe() const { return std::nullopt; }
  // The shadowed fraction the technique reconstructs for a view ray, before lit_length clamps it:
  // what verify judges against pss_lp's (verify/scatter_verification.h); thread-safe.
  double shadowed(const ScatterRay& ray) const {
    return shadowed_fraction(map_->locate(ray.direction, ray.length));
  }

 protected:
  PrefilteredScatter(std::string name, const ScatterParams& params)
      : ScatterTechnique(std::move(name)),
        settings_{params.light_resolution, params.guard_band, params.resample} {}
  // Once per map: the technique's prefix sums.
  virtual void prefilter(const RectifiedMap& map) = 0;
  // The shadowed fraction of the ray's part of its row, in [0, 1]; thread-safe.
  virtual double shadowed_fraction(const RectifiedRay& ray) const = 0;

 private:
  RectifiedSettings settings_;
  std::unique_ptr<RectifiedMap> map_;
};

}  // namespace mb
