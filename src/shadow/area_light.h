#pragma once
// An area light's shadow, the soft-shadow ground truth (docs/soft-shadows.md §1): a directional
// light of angular diameter theta lights a receiver from every direction of a cone, so its shadow
// is the mean over those directions of the hard shadow each casts. Each direction is the light
// view sheared in raster space (raster/render_view.h, RasterShear); its layer 0 is that direction's
// shadow map, and the receiver takes the protocol's filtered hard test there, with its own bias
// (docs/reference.md §3). With theta = 0 every direction is the view itself and the answer is the
// hard reference, bit for bit.
#include <cstdint>
#include <vector>

#include "raster/layer_stack.h"
#include "raster/render_view.h"
#include "scene/light_view.h"
#include "scene/scene.h"
#include "shadow/fragments.h"
#include "shadow/gaussian_kernel.h"
#include "util/eigen.h"

namespace mb {

struct AreaLight {
  double angle_deg = 0;  // angular diameter of the light's disk; 0: the hard directional light
  int directions = 64;   // N, the directions averaged
};

// tan(theta / 2) times the view's texels per unit of depth: the lateral shift, in texels, of the
// light's rim direction per unit of depth. The penumbra behind a blocker at depth separation d is
// 2 d of this wide (docs/soft-shadows.md §1).
double rim_shear(const LightFrame& frame, double angle_deg);

// What a view lit by an area light keeps beyond the hard protocol's receivers, for the reports
// and for soft techniques (docs/soft-shadows.md).
struct SoftReceivers {
  double angle_deg = 0;        // 0: the view is lit by a hard directional light
  double rim_shear = 0;        // rim_shear of the view
  std::vector<double> gx, gy;  // each receiver's depth gradient, in depth per texel
  std::vector<double> hard;    // the hard reference the area light's shadow replaced
};

// The N directions as shears (texels per unit of depth): Hammersley points ((i + 1/2) / N, the
// radical inverse of i in base 2) taken to the light's disk by Shirley and Chiu's concentric map,
// scaled to the rim. Deterministic; N = 2^m puts one point in every elementary rectangle of area
// 1/N of the square (a (0, m, 2)-net), which is what makes the average converge faster than
// independent samples.
std::vector<Eigen::Vector2d> light_shears(const LightFrame& frame, const AreaLight& light);

struct AreaLightShadow {
  std::vector<double> shadow;          // per receiver: the mean of the N filtered hard tests
  std::vector<uint32_t> covered_taps;  // per receiver: taps with a surface in front, over all N
  int taps = 0;                        // kernel taps times N
  double rim_shear = 0;                // rim_shear of the view's frame at the light's angle
};

// The receivers of `fragments` (texel, z_f) with their planes' depth gradients (gx, gy, depth per
// texel) under `light`: each direction's stack is rendered, the receiver moved to its sheared
// position, tested at the nearest texel centre with its depth carried along its own plane, and
// the N answers averaged in direction order (identical for every thread count).
AreaLightShadow area_light_shadow(const Scene& scene, const LightViewDesc& view,
                                  const Fragments& fragments, const std::vector<double>& gx,
                                  const std::vector<double>& gy, const GaussianKernel& kernel,
                                  const BiasParams& bias, const AreaLight& light, int threads);

// Replaces the hard reference of `fragments` by the area light's shadow (its covered taps too, so
// ShadowRegion splits umbra, penumbra and lit) and returns what the hard protocol lacked. The
// receivers' gradients: from `central`, the view's own stack they were collected from; or given
// (a camera's receivers, which lie on no stack).
SoftReceivers light_receivers(const Scene& scene, const LightViewDesc& view,
                              const LayerStack& central, Fragments& fragments,
                              const GaussianKernel& kernel, const BiasParams& bias,
                              const AreaLight& light, int threads);
SoftReceivers light_receivers(const Scene& scene, const LightViewDesc& view, Fragments& fragments,
                              std::vector<double> gx, std::vector<double> gy,
                              const GaussianKernel& kernel, const BiasParams& bias,
                              const AreaLight& light, int threads);

}  // namespace mb
