#pragma once
// Filtered resampling of the light's map into the rectified map (docs/scattering.md §3.1;
// seed 004 §2.3, its Algorithm 1). The rectified map needs the light depth of every rectified
// texel's light ray turned into an inclination, a non-linear warp that no filtered depth survives
// (the mean of two depths warps to neither surface's inclination). The seed filters a moment map
// instead: a trilinear sample of the light map's power moments over the rectified texel's
// footprint is turned back into two depths and weights matching its first three moments, each
// depth is warped on its own, and the two warped depths with their weights are what the rectified
// row then sums (any basis: b = w_2 b(d_2) + w_3 b(d_3)). The seed's moment map holds four
// moments because it also serves the hard shadows; Algorithm 1 reads three (its z_1 has gone to
// infinity, taking the fourth moment's match with it), so this map holds three.
#include <vector>

#include "techniques/scatter/scatter_technique.h"

namespace mb {

// A distribution of at most two depths: depth[0] <= depth[1], weights >= 0 summing to 1; a
// single depth has weight[1] = 0 and depth[1] = depth[0].
struct TwoDepths {
  double depth[2] = {0, 0};
  double weight[2] = {1, 0};
};

// Seed 004 §2.3's Algorithm 1: the two depths and weights whose first three power moments are
// b1, b2, b3 (the fourth is not matched). Where the variance b2 - b1² is not above
// kMinResampleVariance (a sample over one depth, up to rounding), the single depth b1 with weight
// 1, as the seed handles a variance that is not positive.
TwoDepths two_depths(double b1, double b2, double b3);

// Below it, a sample's variance (in the light's raster depth, [0, 1] over the scene's depth range)
// counts as one depth. Rounding leaves ~1e-16 in b2 - b1² of one depth, and Algorithm 1's depths
// lose digits as the variance shrinks; merging a sample into its mean moves it by a transport
// (Wasserstein-1) distance of at most sqrt(variance). At 1e-10 the distribution returned for
// any two-depth sample lies within 1e-5 of the depth range of the true one, in transport distance
// (tests/techniques_moment_resample_test.cpp), far below a light texel's depth step.
inline constexpr double kMinResampleVariance = 1e-10;

// The light map's moments (z, z², z³) per texel of layer 0's raster depth z and their mip chain
// (each level the mean of 2 x 2 texels of the one below). A texel without a surface, and
// everything outside the map, counts as depth 1, the far end of the light's depth range (where a
// cleared depth buffer stands); the scene's surfaces lie before it by the light frame's margin.
class LightMomentMap {
 public:
  explicit LightMomentMap(const LightDepthMap& light);
  int levels() const { return int(levels_.size()); }
  // The trilinear sample at raster (x, y) of a footprint `footprint` light texels wide: the level
  // of detail log2(footprint) (at most 0: bilinear in level 0, the magnification filter) blends
  // bilinear samples of the two levels around it, as a GPU's trilinear filter does.
  void sample(double x, double y, double footprint, double out[3]) const;

 private:
  struct Level {
    int size = 0;
    std::vector<double> moments;  // 3 per texel, row-major
  };
  std::vector<Level> levels_;
  void bilinear(int level, double x, double y, double out[3]) const;
};

}  // namespace mb
