#pragma once
// Compositing a pixel's transparent fragments (docs/transparency.md): the exact transmittance of
// sorted blending, the composite of any per-fragment transmittance, and the depth warp that maps
// the fragments' depths to the interval on which the moments are taken.
#include <span>
#include <string>
#include <vector>

#include "raster/deep_frame.h"

namespace mb {

// One pixel of a deep frame: its transparent fragments in submission order, and what lies behind.
struct PixelFragments {
  std::span<const double> depth, alpha;
  std::span<const Rgb> color;
  Rgb behind = kBackground;
  size_t size() const { return depth.size(); }
};
PixelFragments pixel_of(const DeepFrame& frame, size_t p);

// The depth warp (docs/transparency.md §2) between the transparent geometry's nearest and
// farthest depth, onto [0, 1]: the seed's logarithmic u(z) = (ln z - ln near) / (ln far - ln
// near), or linear u(z) = (z - near) / (far - near) (oit.warp, to measure what the seed's choice
// gains). A range of zero width (every fragment at one depth) maps every depth to 0, which keeps
// every order-independent method exact there (no fragment lies in front of another).
enum class WarpKind { Logarithmic, Linear };
struct DepthWarp {
  double near = 0, range = 0;  // of ln z (logarithmic) or z (linear)
  bool linear = false;
  static DepthWarp between(double nearest, double farthest, WarpKind kind = WarpKind::Logarithmic);
  double operator()(double z) const;
};
// "logarithmic" or "linear" (oit.warp).
WarpKind warp_kind(const std::string& name);

// Where the warp's range comes from (oit.depth_range, docs/transparency.md §2): the frame's
// nearest and farthest fragment, or seed 003's bounding sphere of the scene's transparent geometry
// (DeepFrame::sphere_near, sphere_far), widened to the fragments' range should rounding leave one
// outside, so that every fragment warps into [0, 1].
enum class DepthRangeKind { Fragments, BoundingSphere };
// "fragments" or "bounding_sphere" (oit.depth_range).
DepthRangeKind depth_range_kind(const std::string& name);
DepthWarp frame_warp(const DeepFrame& frame, WarpKind kind, DepthRangeKind range);

// -ln(1 - alpha): a fragment's absorbance. Infinite for alpha = 1 (an opaque fragment ends the
// pixel's transparent list, DeepFrame).
double absorbance(double alpha);

// Exact sorted blending: T(z_l) = prod over fragments strictly in front (z_k < z_l) of (1 -
// alpha_k).
void exact_transmittance(const PixelFragments& px, std::span<double> transmittance);
// Blending in submission order without sorting (a GPU's "over" with the depth test off): fragment
// l is covered by every fragment submitted after it, T_l = prod_{k > l} (1 - alpha_k).
void submission_transmittance(const PixelFragments& px, std::span<double> transmittance);
// prod (1 - alpha_l) over the pixel: what reaches the surface behind.
double total_transmittance(const PixelFragments& px);

// sum_l L_l alpha_l T_l + total * behind.
Rgb composite(const PixelFragments& px, std::span<const double> transmittance, double total);

}  // namespace mb
