#pragma once
// A camera's deep frame (docs/transparency.md): under every pixel, the transparent fragments in
// front of the nearest opaque surface, each with its view depth, opacity and shaded colour, in the
// order a GPU would submit them (scene triangle order), and the colour behind them (the opaque
// surface, or the background). Fragments behind the first opaque surface are hidden in every
// compositing method (opaque geometry is drawn first and depth-tested), so they are not kept.
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "scene/camera.h"
#include "scene/scene.h"

namespace mb {

using Rgb = std::array<float, 3>;

struct DeepFrame {
  std::string camera;
  int width = 0, height = 0;
  std::vector<uint64_t> offsets;  // pixel p's fragments are [offsets[p], offsets[p + 1])
  // Per fragment, in submission order within a pixel:
  std::vector<double> depth;  // distance along the camera's view direction
  std::vector<double> alpha;  // opacity in [0, 1)
  std::vector<Rgb> color;     // shaded colour, linear RGB
  std::vector<Rgb> behind;    // per pixel: the opaque surface's shaded colour, or kBackground
  std::vector<double> behind_depth;  // per pixel: the opaque surface's depth; infinity: background
  size_t pixels() const { return offsets.empty() ? 0 : offsets.size() - 1; }
  size_t fragments() const { return depth.size(); }
  // The transparent geometry's depth range (nearest and farthest fragment), for the warp.
  double nearest() const;
  double farthest() const;
  // The depth range of the bounding sphere of the scene's transparent triangles along the view,
  // [d_c - r, d_c + r] with its near end at least the camera's near plane (seed 003 §3.2's range
  // for the warp, oit.depth_range: bounding_sphere); NaN when unknown (a frame read from a file).
  double sphere_near = std::numeric_limits<double>::quiet_NaN();
  double sphere_far = std::numeric_limits<double>::quiet_NaN();
};

// What a pixel shows where no opaque surface lies under it.
constexpr Rgb kBackground = {0.9f, 0.9f, 0.9f};

// Renders `camera` of `scene` with the CPU rasterizer; colours are each part's `color` lit by the
// first light view's direction, Lambert with an ambient term (kOitAmbient), two-sided surfaces
// from the side the camera sees.
constexpr float kOitAmbient = 0.3f;
DeepFrame render_deep_frame(const Scene& scene, const CameraDesc& camera, int threads);

}  // namespace mb
